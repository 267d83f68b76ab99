// Top-view image of a pile: the "photograph" of the slump-flow measurement.
//
// Rendering: orthographic projection of the spheres onto a pixel grid. A pixel is covered when
// its centre lies inside the projected disc of some sphere; its value is the height of the top
// surface there, max over spheres of z + sqrt(r² − ρ²) − base_z (ρ = horizontal distance of the
// pixel centre from the sphere centre). The grid is anchored at the axis point (pixel edges at
// axis + k·pixel), so adding particles far away never shifts the pixels of the pile.
// Binarisation: covered and height ≥ min_thickness.
// Cleanup: morphological closing with a disc (dilation then erosion, exact Euclidean distance
// transform of Felzenszwalb & Huttenlocher 2012, Theory of Computing 8:415), then keep the largest
// 8-connected component, then fill its holes (background not 4-connected to the border).
// Contour: Moore-neighbour tracing of the component's outer boundary (stops when the first move
// start → second pixel would repeat, a form of Jacob's stopping criterion;
// Gonzalez & Woods, Digital Image Processing, §11.1); each traced pixel contributes the midpoints
// of its edges facing the background (sub-pixel "crack" points, unbiased for a centre-sampled disc).
#pragma once

#include <paddy/measure/common.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace paddy::measure {

struct TopViewImage {
  int nx = 0, ny = 0;            // columns (x), rows (y)
  double pixel = 0.0;            // pixel size [m]
  double x0 = 0.0, y0 = 0.0;     // lower-left corner of pixel (0, 0) [m]
  std::vector<float> height;     // top-surface height above base [m]; 0 where uncovered
  std::vector<std::uint8_t> covered;  // 1 where some sphere covers the pixel centre
  std::vector<std::uint8_t> mask;     // binarised: covered and height ≥ min_thickness

  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * nx + i; }
  Vec2 pixelCentre(int i, int j) const { return {x0 + (i + 0.5) * pixel, y0 + (j + 0.5) * pixel}; }
};

struct TopViewOptions {
  Vec2 axis = Vec2::Zero();        // grid anchor and window centre (x, y) [m]
  double base_z = 0.0;             // plate surface [m]
  double pixel = 0.5e-3;           // pixel size [m]
  double min_thickness = 0.0;      // binarisation threshold on the surface height [m]
  double window_half_width = 0.0;  // > 0: image axis ± this; 0 = bounding square of all particles
  int margin_pixels = 0;           // extra border (the slump-flow measure adds the closing radius)
  std::size_t max_pixels = 200'000'000;  // refuse larger images (InputError)
};

TopViewImage renderTopView(const std::vector<Vec3>& positions, const std::vector<double>& radii,
                           const TopViewOptions& options = {});

// Binary morphology on an nx × ny mask (1 = foreground). Pixels outside the image count as
// background. radius in pixels (a disc of pixel centres within `radius`).
std::vector<std::uint8_t> dilation(const std::vector<std::uint8_t>& mask, int nx, int ny, double radius);
std::vector<std::uint8_t> erosion(const std::vector<std::uint8_t>& mask, int nx, int ny, double radius);
std::vector<std::uint8_t> closing(const std::vector<std::uint8_t>& mask, int nx, int ny, double radius);
// Largest 8-connected component (all zeros if the mask is empty); `pixels` receives its size.
std::vector<std::uint8_t> largestComponent(const std::vector<std::uint8_t>& mask, int nx, int ny,
                                           std::size_t* pixels = nullptr);
// Sets background pixels that are not 4-connected to the image border.
std::vector<std::uint8_t> fillHoles(const std::vector<std::uint8_t>& mask, int nx, int ny);

// Ordered outer boundary of the component containing the first foreground pixel in raster order,
// as (i, j) pixel indices (Moore-neighbour tracing). Empty for an empty mask.
std::vector<Eigen::Vector2i> traceBoundary(const std::vector<std::uint8_t>& mask, int nx, int ny);
// Sub-pixel edge points [m] of a traced boundary: midpoints of the pixel edges facing background.
std::vector<Vec2> boundaryEdgePoints(const TopViewImage& geometry, const std::vector<std::uint8_t>& mask,
                                     const std::vector<Eigen::Vector2i>& boundary);

}  // namespace paddy::measure
