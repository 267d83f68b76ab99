// Private parts of MeshWall shared by its source files (engine/walls/src/mesh_wall*.cpp):
//   mesh_wall.cpp             construction (validation, then topology and the initial pose)
//   mesh_wall_topology.cpp    normals, edge/vertex adjacency, smooth regions, pseudo-normals
//   mesh_wall_motion.cpp      pose, velocities and the displacement bound of the moving mesh
//   mesh_wall_grid.cpp        the cell grid over the body-frame triangles and the per-particle
//                             candidate triangle lists (buildCandidates)
//   mesh_wall_contacts.cpp    sphere–triangle closest hits (findContacts, contactsOfSphere)
//   mesh_wall_reduce.cpp      hits → contacts: normals, overlaps, clustering, merging, keys
//   mesh_wall_loads.cpp       the wall's load history (recordLoads, CSV/HDF5 output)
// The algorithm as a whole is described in mesh_wall.hpp. Not installed: include only from
// engine/walls/src.
#pragma once

#include <paddy/geometry/closest_point.hpp>
#include <paddy/geometry/mesh_wall.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace paddy {

// One triangle within reach of a sphere centre, in the body frame (closestHits → reduce).
struct MeshWall::Hit {
  std::uint32_t tri = 0;
  std::uint32_t region = 0;
  geometry::TriFeature feature = geometry::TriFeature::Face;
  double d = 0.0;        // |centre − q|
  double overlap = 0.0;  // radius − d (radius + d for a centre inside a solid)
  Vec3 q = Vec3::Zero(), n = Vec3::Zero();  // closest point, normal (wall → centre), body frame
  std::uint32_t key = 0;
  bool behind = false;   // the sign test puts the centre inside the closed component (reduce)
};

// Uniform cell grid over the body-frame mesh in CSR form: the triangles of cell c are
// items[start[c] .. start[c + 1]).
struct MeshWall::Grid {
  Vec3 lo = Vec3::Zero();
  double h = 0.0;
  int nx = 0, ny = 0, nz = 0;
  double built_for = 0.0;  // query radius the cell size was chosen for
  std::vector<std::uint32_t> start, items;
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(ny) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(nx) + static_cast<std::size_t>(i);
  }
};

namespace mesh_wall_detail {
// Below this many particles (candidate search) or candidates (contacts) a wall's search runs on
// one thread: a parallel region costs a few µs, about as much as ~100 candidates.
inline constexpr long kParallelMin = 256;

inline double cosDeg(double deg) {
  constexpr double kPi = 3.14159265358979323846;
  return std::cos(deg * kPi / 180.0);
}
}  // namespace mesh_wall_detail

}  // namespace paddy
