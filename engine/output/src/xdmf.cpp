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

}  // namespace paddy::io
