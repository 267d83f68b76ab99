// CGAL input: polygon soups from STL/OFF/OBJ, duplicate-point merging, polygon triangulation.
// (One of the two translation units that include CGAL; see cgal_ops.hpp.)
#include <paddy/geometry/cgal_ops.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <iterator>

namespace paddy::geometry::cgal {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
namespace PMP = CGAL::Polygon_mesh_processing;
}  // namespace

bool readPolygonSoup(const std::string& path, PolygonSoup& soup) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
  } catch (const std::exception&) {
    ok = false;
  }
  if (!ok) return false;
  soup.points.clear();
  soup.polygons.clear();
  soup.points.reserve(points.size());
  for (const Point& p : points) soup.points.emplace_back(p.x(), p.y(), p.z());
  soup.polygons.reserve(polygons.size());
  for (const auto& poly : polygons) soup.polygons.emplace_back(poly.begin(), poly.end());
  return true;
}

void mergeDuplicatePoints(PolygonSoup& soup) {
  std::vector<Point> points;
  points.reserve(soup.points.size());
  for (const Vec3& p : soup.points) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(soup.polygons.size());
  for (const auto& poly : soup.polygons) polygons.emplace_back(poly.begin(), poly.end());
  PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  soup.points.clear();
  for (const Point& p : points) soup.points.emplace_back(p.x(), p.y(), p.z());
  for (std::size_t i = 0; i < polygons.size(); ++i)
    soup.polygons[i].assign(polygons[i].begin(), polygons[i].end());
}

bool triangulatePolygon(const std::vector<Vec3>& corners, std::vector<std::array<std::uint32_t, 3>>& out) {
  std::vector<Point> poly;
  poly.reserve(corners.size());
  for (const Vec3& p : corners) poly.emplace_back(p.x(), p.y(), p.z());
  std::vector<CGAL::Triple<int, int, int>> patch;
  PMP::triangulate_hole_polyline(poly, std::back_inserter(patch));
  if (patch.size() + 2 != corners.size()) return false;
  for (const auto& t : patch)
    out.push_back({static_cast<std::uint32_t>(t.first), static_cast<std::uint32_t>(t.second),
                   static_cast<std::uint32_t>(t.third)});
  return true;
}

}  // namespace paddy::geometry::cgal
