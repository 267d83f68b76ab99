// Slump-flow (spread diameter): image route (circle fit) and ruler route (perpendicular diameters).
// Definitions in paddy/measure/slump_flow.hpp and docs/measurement.md.
#include <paddy/errors.hpp>
#include <paddy/measure/slump_flow.hpp>

#include <cmath>
#include <limits>
#include <numbers>

namespace paddy::measure {

namespace {

// Edge-to-edge extent of the mask along direction u through c: pixels whose centres lie within
// half a pixel of the line.
double extentAlong(const TopViewImage& g, const std::vector<std::uint8_t>& mask, const Vec2& c, double angle) {
  const Vec2 u(std::cos(angle), std::sin(angle)), v(-u.y(), u.x());
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      if (!mask[g.index(i, j)]) continue;
      const Vec2 d = g.pixelCentre(i, j) - c;
      if (std::abs(v.dot(d)) > 0.5 * g.pixel) continue;
      const double s = u.dot(d);
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
  return hi >= lo ? hi - lo + g.pixel : 0.0;
}

}  // namespace

RulerDiameters rulerDiameters(const TopViewImage& g, const std::vector<std::uint8_t>& mask, const Vec2& centre,
                              RulerMode mode, double angle) {
  if (mask.size() != static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny))
    throw InputError("rulerDiameters: mask size does not match the image");
  if (!centre.allFinite() || !std::isfinite(angle)) throw InputError("rulerDiameters: centre and angle must be finite");
  RulerDiameters d;
  if (mode == RulerMode::Axes) {
    d.angle = angle;
  } else {
    double best = -1.0;
    for (int k = 0; k < 180; ++k) {
      const double a = k * std::numbers::pi / 180.0;
      const double e = extentAlong(g, mask, centre, a);
      if (e > best) {
        best = e;
        d.angle = a;
      }
    }
  }
  d.d1 = extentAlong(g, mask, centre, d.angle);
  d.d2 = extentAlong(g, mask, centre, d.angle + 0.5 * std::numbers::pi);
  d.mean = 0.5 * (d.d1 + d.d2);
  return d;
}

SlumpFlowResult slumpFlow(const std::vector<Vec3>& x, const std::vector<double>& r, const SlumpFlowOptions& o) {
  checkParticles(x, r, "slumpFlow");
  if (!std::isfinite(o.closing_radius)) throw InputError("slumpFlow: closing_radius must be finite");
  if (!(o.view.pixel > 0.0) || !std::isfinite(o.view.pixel))
    throw InputError("slumpFlow: pixel = " + std::to_string(o.view.pixel) + " m must be > 0");
  const double closing_m = o.closing_radius < 0.0 ? meanRadius(r) : o.closing_radius;
  const double closing_px = closing_m / o.view.pixel;

  SlumpFlowResult res;
  TopViewOptions view = o.view;
  view.margin_pixels = std::max(view.margin_pixels, static_cast<int>(std::ceil(closing_px)) + 2);
  res.image = renderTopView(x, r, view);
  const TopViewImage& g = res.image;

  std::vector<std::uint8_t> m = closing(g.mask, g.nx, g.ny, closing_px);
  m = largestComponent(m, g.nx, g.ny, nullptr);
  m = fillHoles(m, g.nx, g.ny);
  Vec2 sum = Vec2::Zero();
  std::size_t count = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i)
      if (m[g.index(i, j)]) {
        sum += g.pixelCentre(i, j);
        ++count;
      }
  if (count == 0)
    throw InputError("slumpFlow: no pile in the top view (is min_thickness = " + std::to_string(o.view.min_thickness) +
                     " m above every particle top?)");
  res.component_pixels = count;
  res.centroid = sum / static_cast<double>(count);
  res.diameter_area = std::sqrt(4.0 * static_cast<double>(count) * g.pixel * g.pixel / std::numbers::pi);

  const auto boundary = traceBoundary(m, g.nx, g.ny);
  res.contour = boundaryEdgePoints(g, m, boundary);
  res.circle = fitCircle(res.contour);
  res.diameter_fit = res.circle.diameter();
  res.ruler = rulerDiameters(g, m, res.centroid, o.ruler, o.ruler_angle);
  res.component = std::move(m);
  return res;
}

}  // namespace paddy::measure
