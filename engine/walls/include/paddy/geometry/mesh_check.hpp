// Mesh checks and measures (plain C++, no CGAL): validation with messages that name the file and
// the offending vertex/triangle/edge, connected components, bounds, area, signed volume.
//
// Signed volume uses the divergence theorem: V = Σ_t (a_t · (b_t × c_t)) / 6 over the triangles
// (a, b, c) of a closed, outward-oriented surface; for an open surface whose rim lies in one
// plane, taking the tetrahedra from a point of that plane gives the volume it encloses with that
// plane (the "capacity" of a cup).
#pragma once

#include <paddy/geometry.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace paddy::geometry {

// Polygons of any size (as read from OBJ/OFF, or built by a part builder before triangulation).
struct PolygonSoup {
  std::vector<Vec3> points;
  std::vector<std::vector<std::uint32_t>> polygons;
};

// Whether a part must be closed (a solid: every edge between exactly two triangles).
enum class Closure { Auto, Open, Closed };

struct MeshCheckOptions {
  std::string source = "mesh";  // file or part name used in every message
  Closure closure = Closure::Auto;
  // A triangle is degenerate if 2·area <= tolerance · (longest edge)², i.e. its smallest angle
  // is below ~tolerance radians (or two of its corners are the same vertex).
  double degenerate_tolerance = 1e-10;
};

struct MeshReport {
  std::size_t components = 0;         // connected through shared edges
  std::size_t closed_components = 0;  // no boundary edge
  std::size_t boundary_edges = 0;
  std::size_t nonmanifold_edges = 0;  // > 2 triangles (allowed only in open components)
};

// Throws InputError "<source>: <what> <where>" for: no triangles, a non-finite coordinate
// (vertex index), a vertex index out of range, a degenerate triangle (triangle index), two
// triangles on the same three vertices (both indices), a non-manifold edge in a closed component
// or in any component when closure == Closed, a boundary edge when closure == Closed.
MeshReport validateMesh(const TriangleMesh& mesh, const MeshCheckOptions& options);

// Component id (0..count-1) per triangle; triangles sharing an edge are connected.
std::vector<std::uint32_t> connectedComponents(const TriangleMesh& mesh, std::size_t* count = nullptr);
// Splits/merges meshes (vertices are re-indexed; unused vertices dropped by `extract`).
TriangleMesh extractTriangles(const TriangleMesh& mesh, const std::vector<std::uint32_t>& triangle_ids);
void append(TriangleMesh& to, const TriangleMesh& from);

struct Bounds {
  Vec3 lo, hi;
  Vec3 size() const { return hi - lo; }
};
Bounds bounds(const TriangleMesh& mesh);
double surfaceArea(const TriangleMesh& mesh);
// Σ a·(b×c)/6 with all vertices taken relative to `apex` (see header comment).
double signedVolume(const TriangleMesh& mesh, const Vec3& apex = Vec3::Zero());
Vec3 triangleNormal(const TriangleMesh& mesh, std::size_t t);  // unit, right-hand rule

// Rigid transform + scale applied in place: x ← R·(scale·x) + t. A negative-determinant R is
// refused (it would turn the mesh inside out).
void transformMesh(TriangleMesh& mesh, double scale, const Eigen::Matrix3d& R, const Vec3& t);
// Rotation of `angle` radians about `axis` (need not be unit), right-hand rule.
Eigen::Matrix3d axisRotation(const Vec3& axis, double angle);

}  // namespace paddy::geometry
