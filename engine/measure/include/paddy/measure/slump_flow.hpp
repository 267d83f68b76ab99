// Slump-flow (spread diameter) of the virtual slump test, measured two ways.
//
// a) As the laboratory (GB/T 50080-2016 spread, read from a top photograph as in the reference
//    study): top-view image → binarise → closing → largest component → fill holes → outer contour
//    → least-squares circle (Kåsa start, Levenberg–Marquardt geometric fit) → diameter.
// b) As a ruler: two perpendicular diameters through the component's centroid, edge to edge, and
//    their mean. RulerMode::Axes measures along x and y (rotated by ruler_angle);
//    RulerMode::MaxAndPerpendicular takes the largest diameter over directions (1° steps) and the
//    one perpendicular to it, as GB/T 50080 prescribes for the slump-flow.
// Also the area-equivalent diameter sqrt(4A/π) of the component.
// Known bias: the projection of the edge spheres extends the spread by about one particle radius
// beyond their centres; the contour is accurate to ~pixel/2. See docs/measurement.md.
#pragma once

#include <paddy/measure/circle_fit.hpp>
#include <paddy/measure/top_view.hpp>

#include <filesystem>
#include <string>

namespace paddy::measure {

enum class RulerMode { Axes, MaxAndPerpendicular };

struct SlumpFlowOptions {
  TopViewOptions view;             // axis, base_z, pixel (0.5 mm), min_thickness, window
  double closing_radius = -1.0;    // [m]; < 0 = one mean particle radius; 0 = no closing
  RulerMode ruler = RulerMode::Axes;
  double ruler_angle = 0.0;        // [rad] direction of the first ruler diameter (Axes mode)
};

struct RulerDiameters {
  double d1 = 0.0, d2 = 0.0;  // the two perpendicular diameters [m]
  double mean = 0.0;          // (d1 + d2)/2 [m]
  double angle = 0.0;         // direction of d1 [rad]
};

struct SlumpFlowResult {
  CircleFit circle;             // geometric least-squares circle of the contour
  double diameter_fit = 0.0;    // 2 × circle radius [m]
  RulerDiameters ruler;         // b) the ruler reading
  double diameter_area = 0.0;   // sqrt(4 A / π) of the cleaned component [m]
  Vec2 centroid = Vec2::Zero(); // centroid of the component [m]
  std::size_t component_pixels = 0;
  std::vector<Vec2> contour;    // sub-pixel contour points in tracing order [m]
  TopViewImage image;           // the rendered image (height, covered, raw mask)
  std::vector<std::uint8_t> component;  // the cleaned component mask (same grid)
};

// Throws InputError for bad particle data or options, or when no pile is found.
SlumpFlowResult slumpFlow(const std::vector<Vec3>& positions, const std::vector<double>& radii,
                          const SlumpFlowOptions& options = {});

// Ruler diameters of a mask (helper of slumpFlow, exposed for tests).
RulerDiameters rulerDiameters(const TopViewImage& geometry, const std::vector<std::uint8_t>& mask,
                              const Vec2& centre, RulerMode mode, double angle = 0.0);

// ---- pictures --------------------------------------------------------------------------------
enum class PgmLayer { Height, Mask, Component };
// Writes a binary PGM (P5), row 0 at the top (north up). Height: plate white, mud grey, higher
// darker; Mask/Component: mud black on white. Throws std::runtime_error naming the file.
void writePgm(const SlumpFlowResult& result, const std::filesystem::path& file,
              PgmLayer layer = PgmLayer::Height);
// Writes <stem>_contour.dat and <stem>_circle.dat (x y in mm) beside `png` and, with gnuplot,
// the PNG: top view in grey, the contour and the fitted circle, axes in mm. Throws
// std::runtime_error if gnuplot cannot be run or fails (message names the script).
void plotSlumpFlow(const SlumpFlowResult& result, const std::filesystem::path& png,
                   const std::string& title = "");

}  // namespace paddy::measure
