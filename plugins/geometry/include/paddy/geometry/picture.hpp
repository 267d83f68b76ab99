// Pictures of parts for the docs: the triangles are written as polygons for gnuplot's
// `splot ... with polygons` (pm3d depth ordering, flat shading by facet orientation) and gnuplot
// renders a PNG. Returns false (and leaves no PNG) if gnuplot is missing or fails.
#pragma once

#include <paddy/geometry.hpp>

#include <string>

namespace paddy::geometry {

struct PictureOptions {
  std::string title;
  int width = 800, height = 600;
  double view_rot_x = 65.0, view_rot_z = 30.0;  // gnuplot `set view rot_x, rot_z`
};

bool writePicture(const TriangleMesh& mesh, const std::string& png_path, const PictureOptions& options = {});

}  // namespace paddy::geometry
