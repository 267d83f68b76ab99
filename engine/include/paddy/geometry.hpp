// Geometry: triangle meshes for walls, and the builders plugins register for them.
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

}  // namespace paddy
