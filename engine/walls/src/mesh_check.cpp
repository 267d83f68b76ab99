// Mesh validation and measures (see mesh_check.hpp). Edges are found by sorting the 3·T
// (min vertex, max vertex, triangle) records; components by union-find over shared edges.
#include <paddy/util/union_find.hpp>
#include <paddy/errors.hpp>
#include <paddy/geometry/mesh_check.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <cmath>
#include <numeric>
#include <sstream>

namespace paddy::geometry {
namespace {

struct EdgeRec {
  std::uint64_t key;  // (min << 32) | max
  std::uint32_t tri;
  bool operator<(const EdgeRec& o) const { return key < o.key || (key == o.key && tri < o.tri); }
};

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

std::vector<EdgeRec> sortedEdges(const TriangleMesh& m) {
  std::vector<EdgeRec> e;
  e.reserve(3 * m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] != tri[(k + 1) % 3]) e.push_back({edgeKey(tri[k], tri[(k + 1) % 3]), static_cast<std::uint32_t>(t)});
  }
  std::sort(e.begin(), e.end());
  return e;
}

using DisjointSets = paddy::UnionFind<std::uint32_t>;

std::string vec(const Vec3& v) {
  std::ostringstream s;
  s << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return s.str();
}

}  // namespace

std::vector<std::uint32_t> connectedComponents(const TriangleMesh& mesh, std::size_t* count) {
  const auto edges = sortedEdges(mesh);
  DisjointSets uf(mesh.triangles.size());
  for (std::size_t i = 1; i < edges.size(); ++i)
    if (edges[i].key == edges[i - 1].key) uf.unite(edges[i].tri, edges[i - 1].tri);
  std::vector<std::uint32_t> comp(mesh.triangles.size());
  std::vector<std::uint32_t> label(mesh.triangles.size(), UINT32_MAX);
  std::uint32_t n = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t r = uf.find(static_cast<std::uint32_t>(t));
    if (label[r] == UINT32_MAX) label[r] = n++;
    comp[t] = label[r];
  }
  if (count) *count = n;
  return comp;
}

MeshReport validateMesh(const TriangleMesh& m, const MeshCheckOptions& o) {
  const std::string& src = o.source;
  if (m.triangles.empty() || m.vertices.empty())
    throw InputError(src + ": empty mesh (no triangles)");
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    if (!m.vertices[v].allFinite())
      throw InputError(src + ": vertex " + std::to_string(v) + " has a non-finite coordinate " + vec(m.vertices[v]));
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (std::uint32_t v : m.triangles[t])
      if (v >= m.vertices.size())
        throw InputError(src + ": triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) +
                         ", but there are only " + std::to_string(m.vertices.size()) + " vertices");
  // Degenerate triangles.
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    const Vec3 &a = m.vertices[tri[0]], &b = m.vertices[tri[1]], &c = m.vertices[tri[2]];
    const double l2 = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    const double twice_area = (b - a).cross(c - a).norm();
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0] || !(twice_area > o.degenerate_tolerance * l2))
      throw InputError(src + ": triangle " + std::to_string(t) + " is degenerate (zero area; vertices " +
                       std::to_string(tri[0]) + ", " + std::to_string(tri[1]) + ", " + std::to_string(tri[2]) +
                       " at " + vec(a) + ", " + vec(b) + ", " + vec(c) + ")");
  }
  // Duplicate triangles (same three vertices, either orientation).
  {
    std::vector<std::pair<std::array<std::uint32_t, 3>, std::uint32_t>> sorted;
    sorted.reserve(m.triangles.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      auto k = m.triangles[t];
      std::sort(k.begin(), k.end());
      sorted.push_back({k, static_cast<std::uint32_t>(t)});
    }
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 1; i < sorted.size(); ++i)
      if (sorted[i].first == sorted[i - 1].first)
        throw InputError(src + ": triangles " + std::to_string(sorted[i - 1].second) + " and " +
                         std::to_string(sorted[i].second) + " are duplicates (same vertices " +
                         std::to_string(sorted[i].first[0]) + ", " + std::to_string(sorted[i].first[1]) + ", " +
                         std::to_string(sorted[i].first[2]) + ")");
  }
  // Edges: boundary (1 triangle), manifold (2), non-manifold (> 2); per component.
  std::size_t ncomp = 0;
  const auto comp = connectedComponents(m, &ncomp);
  const auto edges = sortedEdges(m);
  std::vector<std::uint8_t> comp_open(ncomp, 0);
  struct Bad { std::uint64_t key; std::uint32_t tri; std::size_t count; };
  std::vector<Bad> nonmanifold, boundary;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j].key == edges[i].key) ++j;
    const std::size_t n = j - i;
    if (n == 1) {
      comp_open[comp[edges[i].tri]] = 1;
      boundary.push_back({edges[i].key, edges[i].tri, n});
    } else if (n > 2) {
      nonmanifold.push_back({edges[i].key, edges[i].tri, n});
    }
    i = j;
  }
  auto edgeName = [](std::uint64_t key) {
    return "(" + std::to_string(key >> 32) + ", " + std::to_string(key & 0xffffffffu) + ")";
  };
  for (const Bad& b : nonmanifold)
    if (o.closure == Closure::Closed || !comp_open[comp[b.tri]])
      throw InputError(src + ": non-manifold edge " + edgeName(b.key) + " is shared by " + std::to_string(b.count) +
                       " triangles (first: triangle " + std::to_string(b.tri) + ") in a closed part");
  if (o.closure == Closure::Closed && !boundary.empty())
    throw InputError(src + ": the part must be closed, but edge " + edgeName(boundary.front().key) + " of triangle " +
                     std::to_string(boundary.front().tri) + " is a boundary edge (" +
                     std::to_string(boundary.size()) + " boundary edges in all)");
  MeshReport r;
  r.components = ncomp;
  r.closed_components = static_cast<std::size_t>(std::count(comp_open.begin(), comp_open.end(), 0));
  r.boundary_edges = boundary.size();
  r.nonmanifold_edges = nonmanifold.size();
  return r;
}

TriangleMesh extractTriangles(const TriangleMesh& mesh, const std::vector<std::uint32_t>& ids) {
  TriangleMesh out;
  std::vector<std::uint32_t> map(mesh.vertices.size(), UINT32_MAX);
  for (std::uint32_t t : ids) {
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = mesh.triangles[t][k];
      if (map[v] == UINT32_MAX) {
        map[v] = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[v]);
      }
      tri[k] = map[v];
    }
    out.triangles.push_back(tri);
  }
  return out;
}

void append(TriangleMesh& to, const TriangleMesh& from) {
  const auto off = static_cast<std::uint32_t>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), from.vertices.begin(), from.vertices.end());
  for (auto t : from.triangles) to.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
}

Bounds bounds(const TriangleMesh& m) {
  Bounds b{Vec3::Constant(std::numeric_limits<double>::infinity()), Vec3::Constant(-std::numeric_limits<double>::infinity())};
  for (const Vec3& v : m.vertices) {
    b.lo = b.lo.cwiseMin(v);
    b.hi = b.hi.cwiseMax(v);
  }
  return b;
}

double surfaceArea(const TriangleMesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles)
    a += 0.5 * (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]).norm();
  return a;
}

double signedVolume(const TriangleMesh& m, const Vec3& apex) {
  double v = 0.0;
  for (const auto& t : m.triangles)
    v += (m.vertices[t[0]] - apex).dot((m.vertices[t[1]] - apex).cross(m.vertices[t[2]] - apex));
  return v / 6.0;
}

Vec3 triangleNormal(const TriangleMesh& m, std::size_t t) {
  const auto& tri = m.triangles[t];
  return (m.vertices[tri[1]] - m.vertices[tri[0]]).cross(m.vertices[tri[2]] - m.vertices[tri[0]]).normalized();
}

Eigen::Matrix3d axisRotation(const Vec3& axis, double angle) {
  if (!(axis.norm() > 0.0) || !axis.allFinite() || !std::isfinite(angle))
    throw InputError("rotation: the axis must be a finite non-zero vector and the angle finite");
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

void transformMesh(TriangleMesh& m, double scale, const Eigen::Matrix3d& R, const Vec3& t) {
  checkRange("scale", scale, 1e-12, 1e12);
  if (!(R.determinant() > 0.0)) throw InputError("transform: the rotation must have a positive determinant");
  for (Vec3& v : m.vertices) v = R * (scale * v) + t;
}

}  // namespace paddy::geometry
