// XDMF index of the snapshot files (a temporal collection ParaView can open at any time).
#include <paddy/io/snapshot.hpp>

#include <iomanip>
#include <sstream>

namespace paddy::io {

namespace {

struct Field {
  const char* name;
  const char* type;  // Scalar / Vector
  const char* number_type;
  int precision;
  int components;
};

constexpr Field kFields[] = {
    {"id", "Scalar", "UInt", 8, 1},         {"material", "Scalar", "Int", 4, 1},
    {"radius", "Scalar", "Float", 8, 1},    {"velocity", "Vector", "Float", 8, 3},
    {"omega", "Vector", "Float", 8, 3},     {"force", "Vector", "Float", 8, 3},
};

void dataItem(std::ostream& out, const SnapshotEntry& e, const char* dataset, const char* number_type,
              int precision, int components, const char* indent) {
  out << indent << "<DataItem Dimensions=\"" << e.particles;
  if (components > 1) out << ' ' << components;
  out << "\" NumberType=\"" << number_type << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << e.file
      << ":/particles/" << dataset << "</DataItem>\n";
}

}  // namespace

std::string xdmfText(const std::vector<SnapshotEntry>& entries) {
  std::ostringstream out;
  out << std::setprecision(17);
  out << "<?xml version=\"1.0\" ?>\n"
         "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
         "<Xdmf Version=\"3.0\">\n"
         "  <Domain>\n"
         "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const SnapshotEntry& e : entries) {
    out << "      <Grid Name=\"" << e.file << "\" GridType=\"Uniform\">\n"
        << "        <Time Value=\"" << e.time << "\"/>\n"
        << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << e.particles
        << "\" NodesPerElement=\"1\">\n";
    // Explicit connectivity (one vertex cell per particle): ParaView makes cells only from it.
    dataItem(out, e, "vertex", "Int", 8, 1, "          ");
    out << "        </Topology>\n"
        << "        <Geometry GeometryType=\"XYZ\">\n";
    dataItem(out, e, "position", "Float", 8, 3, "          ");
    out << "        </Geometry>\n";
    for (const Field& f : kFields) {
      out << "        <Attribute Name=\"" << f.name << "\" AttributeType=\"" << f.type << "\" Center=\"Node\">\n";
      dataItem(out, e, f.name, f.number_type, f.precision, f.components, "          ");
      out << "        </Attribute>\n";
    }
    out << "      </Grid>\n";
  }
  out << "    </Grid>\n"
         "  </Domain>\n"
         "</Xdmf>\n";
  return out.str();
}

std::string wallsXdmfText(const std::vector<SnapshotEntry>& entries) {
  std::ostringstream out;
  out << std::setprecision(17);
  bool any = false;
  for (const SnapshotEntry& e : entries) {
    if (e.wall_triangles == 0) continue;
    if (!any) {
      out << "<?xml version=\"1.0\" ?>\n"
             "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
             "<Xdmf Version=\"3.0\">\n"
             "  <Domain>\n"
             "    <Grid Name=\"walls\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
      any = true;
    }
    // One grid per snapshot: the triangles of every finite wall, with the cell attribute `wall`
    // (the wall's index in the file's /walls names).
    out << "      <Grid Name=\"" << e.file << "\" GridType=\"Uniform\">\n"
        << "        <Time Value=\"" << e.time << "\"/>\n"
        << "        <Topology TopologyType=\"Triangle\" NumberOfElements=\"" << e.wall_triangles << "\">\n"
        << "          <DataItem Dimensions=\"" << e.wall_triangles
        << " 3\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">" << e.file << ":/walls/triangles</DataItem>\n"
        << "        </Topology>\n"
        << "        <Geometry GeometryType=\"XYZ\">\n"
        << "          <DataItem Dimensions=\"" << e.wall_vertices
        << " 3\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << e.file << ":/walls/vertices</DataItem>\n"
        << "        </Geometry>\n"
        << "        <Attribute Name=\"wall\" AttributeType=\"Scalar\" Center=\"Cell\">\n"
        << "          <DataItem Dimensions=\"" << e.wall_triangles
        << "\" NumberType=\"Int\" Precision=\"4\" Format=\"HDF\">" << e.file << ":/walls/wall</DataItem>\n"
        << "        </Attribute>\n"
        << "      </Grid>\n";
  }
  if (!any) return {};
  out << "    </Grid>\n"
         "  </Domain>\n"
         "</Xdmf>\n";
  return out.str();
}

}  // namespace paddy::io
