// CGAL-backed mesh operations behind a CGAL-free interface (CGAL is compiled only in
// src/cgal_mesh.cpp and src/cgal_io.cpp). Kernel: Exact_predicates_inexact_constructions_kernel;
// meshes: CGAL::Surface_mesh; algorithms: Polygon_mesh_processing (PMP).
#pragma once

#include <paddy/geometry/mesh_check.hpp>

#include <string>

namespace paddy::geometry::cgal {

// ---- cgal_io.cpp ---------------------------------------------------------------------------
// CGAL::IO::read_polygon_soup (chooses the reader from the extension: .stl ASCII or binary,
// .off, .obj). Returns false if CGAL cannot parse the file.
bool readPolygonSoup(const std::string& path, PolygonSoup& soup);
// PMP::merge_duplicate_points_in_polygon_soup: identical coordinates become one vertex.
void mergeDuplicatePoints(PolygonSoup& soup);
// PMP::triangulate_hole_polyline on a polygon's corners (works for non-convex planar polygons).
// Returns false if CGAL finds no triangulation.
bool triangulatePolygon(const std::vector<Vec3>& corners, std::vector<std::array<std::uint32_t, 3>>& out);

// ---- cgal_mesh.cpp -------------------------------------------------------------------------
// Part builders: polygons (any size, consistently oriented by the builder or not) → triangle
// mesh. PMP::orient_polygon_soup + polygon_soup_to_polygon_mesh, PMP::triangulate_faces; a part
// declared closed is checked with CGAL::is_closed and oriented outwards
// (PMP::orient_to_bound_a_volume); an open part keeps the builder's orientation.
// Throws InputError naming `name` if the polygons do not form a valid (closed) surface.
TriangleMesh finalizePart(const PolygonSoup& polygons, bool closed, const std::string& name);
// Makes each connected component consistently oriented (PMP::orient_polygon_soup) and closed
// components outward (PMP::is_outward_oriented / reverse_face_orientations).
void orientComponents(TriangleMesh& mesh, const std::string& name);
bool isClosed(const TriangleMesh& mesh);
bool isOutwardOriented(const TriangleMesh& mesh);  // closed meshes only
double volume(const TriangleMesh& mesh);           // PMP::volume (closed meshes only)
double area(const TriangleMesh& mesh);             // PMP::area
bool selfIntersects(const TriangleMesh& mesh);     // PMP::does_self_intersect

}  // namespace paddy::geometry::cgal
