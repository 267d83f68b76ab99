// Geometry: triangle meshes for walls, and what plugins register for them: parameterised parts
// (GeometryInfo) and mesh-file readers (MeshReaderInfo). The engine itself does not parse mesh
// files (it does not link CGAL); `sim:add_mesh_wall{file = ...}` asks the reader registered for
// the file's extension, then applies scale and placement itself (the same as for parts).
#pragma once

#include <paddy/contact_model.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace paddy {

struct TriangleMesh {
  std::vector<Vec3> vertices;                          // [m]
  std::vector<std::array<std::uint32_t, 3>> triangles; // counter-clockwise seen from outside
};

// A parameterised part a geometry plugin can build (slump cone, plate, vane, cup...).
struct GeometryInfo {
  std::string name;
  std::string description;
  std::vector<ParamSpec> params;  // validated like contact parameters
  std::function<TriangleMesh(const ParamValues&)> build;
};

// A mesh-file reader a plugin provides for some file extensions. `read` returns the mesh in the
// file's own units and coordinates (no scaling or placement), validated and oriented; a broken
// file is refused with InputError whose message starts with the path.
struct MeshReaderInfo {
  std::string name;                     // e.g. "cgal"
  std::vector<std::string> extensions;  // lower case with the dot: ".stl", ".off", ".obj"
  std::function<TriangleMesh(const std::string& path)> read;
};

}  // namespace paddy
