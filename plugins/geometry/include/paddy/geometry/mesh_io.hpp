// Mesh files: import (STL ASCII/binary, OFF, OBJ through CGAL IO) with units and a placement
// transform, validated (broken meshes are refused with InputError naming the file and the
// offending vertex/triangle/edge); export as STL (binary or ASCII), OFF.
//
// Import pipeline: CGAL::IO::read_polygon_soup → non-finite check (vertex index; for text files
// the line number too) → scale, rotate, translate → merge identical points → triangulate
// polygons with > 3 corners (PMP::triangulate_hole_polyline) → validateMesh → orient each
// connected component (closed ones outwards).
#pragma once

#include <paddy/geometry/mesh_check.hpp>

#include <string>

namespace paddy::geometry {

struct ImportOptions {
  double scale = 1.0;                        // file units → metres (0.001 for a mm file)
  Vec3 rotation_axis = Vec3::UnitZ();        // rotation about an axis through the origin ...
  double rotation_angle = 0.0;               // ... by this angle [rad], applied after scaling
  Vec3 translation = Vec3::Zero();           // [m], applied last
  Closure closure = Closure::Auto;           // Closed: the part must be a solid
  bool orient = true;                        // orient components (closed ones outwards)
};

TriangleMesh readMesh(const std::string& path, const ImportOptions& options = {});

// Binary STL: 80-byte header, uint32 count, per triangle 12 float32 (normal, 3 corners) + uint16.
void writeStl(const std::string& path, const TriangleMesh& mesh, bool binary = true,
              const std::string& solid_name = "paddy");
void writeOff(const std::string& path, const TriangleMesh& mesh);

}  // namespace paddy::geometry
