// CGAL mesh operations on Surface_mesh: part finalisation (triangulation, orientation,
// closedness), orientation of imported components, volume, area, self-intersection.
// (One of the two translation units that include CGAL; see cgal_ops.hpp.)
#include <paddy/errors.hpp>
#include <paddy/geometry/cgal_ops.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

namespace paddy::geometry::cgal {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using SMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

using Polys = std::vector<std::vector<std::size_t>>;

void toSoup(const TriangleMesh& m, std::vector<Point>& pts, Polys& polys) {
  pts.clear();
  polys.clear();
  for (const Vec3& v : m.vertices) pts.emplace_back(v.x(), v.y(), v.z());
  for (const auto& t : m.triangles) polys.push_back({t[0], t[1], t[2]});
}

bool toSurfaceMesh(const std::vector<Point>& pts, const Polys& polys, SMesh& sm) {
  if (!PMP::is_polygon_soup_a_polygon_mesh(polys)) return false;
  PMP::polygon_soup_to_polygon_mesh(pts, polys, sm);
  return true;
}

bool toSurfaceMesh(const TriangleMesh& m, SMesh& sm) {
  std::vector<Point> pts;
  Polys polys;
  toSoup(m, pts, polys);
  return toSurfaceMesh(pts, polys, sm);
}

// Surface_mesh → TriangleMesh (all faces must be triangles).
TriangleMesh fromSurfaceMesh(const SMesh& sm) {
  TriangleMesh out;
  std::vector<std::uint32_t> index(sm.number_of_vertices() + sm.number_of_removed_vertices(), 0);
  for (auto v : sm.vertices()) {
    index[v.idx()] = static_cast<std::uint32_t>(out.vertices.size());
    const Point& p = sm.point(v);
    out.vertices.emplace_back(p.x(), p.y(), p.z());
  }
  for (auto f : sm.faces()) {
    std::array<std::uint32_t, 3> tri{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      if (k < 3) tri[k] = index[v.idx()];
      ++k;
    }
    if (k != 3) throw std::logic_error("fromSurfaceMesh: face is not a triangle");
    out.triangles.push_back(tri);
  }
  return out;
}
}  // namespace

TriangleMesh finalizePart(const PolygonSoup& soup, bool closed, const std::string& name) {
  std::vector<Point> pts;
  for (const Vec3& v : soup.points) pts.emplace_back(v.x(), v.y(), v.z());
  Polys polys;
  for (const auto& p : soup.polygons) polys.emplace_back(p.begin(), p.end());
  if (!PMP::is_polygon_soup_a_polygon_mesh(polys)) {
    // Builders emit consistently oriented polygons; fix orientation only if they did not.
    if (!PMP::orient_polygon_soup(pts, polys) || !PMP::is_polygon_soup_a_polygon_mesh(polys))
      throw InputError(name + ": the generated polygons do not form a manifold surface");
  }
  SMesh sm;
  PMP::polygon_soup_to_polygon_mesh(pts, polys, sm);
  if (!PMP::triangulate_faces(sm)) throw InputError(name + ": could not triangulate the generated polygons");
  if (closed) {
    if (!CGAL::is_closed(sm)) throw InputError(name + ": the generated solid is not closed");
    PMP::orient_to_bound_a_volume(sm);
  }
  return fromSurfaceMesh(sm);
}

void orientComponents(TriangleMesh& mesh, const std::string& name) {
  std::size_t count = 0;
  const auto comp = connectedComponents(mesh, &count);
  TriangleMesh result;
  for (std::size_t c = 0; c < count; ++c) {
    std::vector<std::uint32_t> ids;
    for (std::size_t t = 0; t < comp.size(); ++t)
      if (comp[t] == c) ids.push_back(static_cast<std::uint32_t>(t));
    TriangleMesh part = extractTriangles(mesh, ids);
    std::vector<Point> pts;
    Polys polys;
    toSoup(part, pts, polys);
    // Flip the whole component back if orient_polygon_soup reversed most of it (it starts from
    // an arbitrary seed): keep the author's orientation where it was consistent.
    const Polys before = polys;
    PMP::orient_polygon_soup(pts, polys);
    std::size_t reversed = 0;
    for (std::size_t i = 0; i < polys.size(); ++i) {
      const auto& a = before[i];
      const auto& b = polys[i];
      if (a.size() == 3 && b.size() == 3 && pts.size() == part.vertices.size()) {
        // same cyclic order ⇔ b is a rotation of a
        const bool same = (a[0] == b[0] && a[1] == b[1]) || (a[0] == b[1] && a[1] == b[2]) ||
                          (a[0] == b[2] && a[1] == b[0]);
        if (!same) ++reversed;
      }
    }
    if (2 * reversed > polys.size())
      for (auto& p : polys) std::reverse(p.begin(), p.end());
    SMesh sm;
    if (toSurfaceMesh(pts, polys, sm) && CGAL::is_closed(sm) && !PMP::is_outward_oriented(sm))
      for (auto& p : polys) std::reverse(p.begin(), p.end());
    TriangleMesh oriented;
    for (const Point& p : pts) oriented.vertices.emplace_back(p.x(), p.y(), p.z());
    for (const auto& p : polys) {
      if (p.size() != 3) throw InputError(name + ": orientation produced a non-triangle");
      oriented.triangles.push_back({static_cast<std::uint32_t>(p[0]), static_cast<std::uint32_t>(p[1]),
                                    static_cast<std::uint32_t>(p[2])});
    }
    append(result, oriented);
  }
  mesh = std::move(result);
}

bool isClosed(const TriangleMesh& mesh) {
  SMesh sm;
  return toSurfaceMesh(mesh, sm) && CGAL::is_closed(sm);
}

bool isOutwardOriented(const TriangleMesh& mesh) {
  SMesh sm;
  if (!toSurfaceMesh(mesh, sm) || !CGAL::is_closed(sm)) return false;
  return PMP::is_outward_oriented(sm);
}

double volume(const TriangleMesh& mesh) {
  SMesh sm;
  if (!toSurfaceMesh(mesh, sm) || !CGAL::is_closed(sm))
    throw InputError("volume: the mesh is not a closed manifold surface");
  return PMP::volume(sm);
}

double area(const TriangleMesh& mesh) {
  SMesh sm;
  if (!toSurfaceMesh(mesh, sm)) throw InputError("area: the mesh is not a manifold surface");
  return PMP::area(sm);
}

bool selfIntersects(const TriangleMesh& mesh) {
  SMesh sm;
  if (!toSurfaceMesh(mesh, sm)) throw InputError("selfIntersects: the mesh is not a manifold surface");
  return PMP::does_self_intersect(sm);
}

}  // namespace paddy::geometry::cgal
