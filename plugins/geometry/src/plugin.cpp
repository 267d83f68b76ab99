// Plugin entry point: registers the parts of parts.hpp (slump_cone, plate, cup, vane) and the
// mesh-file reader (STL ASCII/binary, OFF, OBJ through CGAL, mesh_io.hpp). The reader returns the
// file's mesh as it is (checked and oriented, no scale or placement): the engine applies those,
// the same way for parts and files.
#include <paddy/geometry.hpp>
#include <paddy/geometry/mesh_io.hpp>
#include <paddy/geometry/parts.hpp>
#include <paddy/plugin.hpp>

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry) {
  for (const auto& part : paddy::geometry::partCatalogue()) registry->addGeometry(part);
  paddy::MeshReaderInfo reader;
  reader.name = "cgal";
  reader.extensions = {".stl", ".off", ".obj"};
  reader.read = [](const std::string& path) { return paddy::geometry::readMesh(path); };
  registry->addMeshReader(reader);
  return PADDY_PLUGIN_ABI_VERSION;
}
