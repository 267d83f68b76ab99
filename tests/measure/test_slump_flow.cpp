// Slump-flow on synthetic piles: disc, disc + far noise, ellipse; image-processing pieces; pictures.
#include "synthetic_piles.hpp"

#include <paddy/errors.hpp>
#include <paddy/measure/slump_flow.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

using namespace paddy::measure;
using paddy::InputError;
using Catch::Matchers::Contains;

namespace {
constexpr double d = 0.002, r = d / 2, pixel = 0.5e-3;
const Vec2 centre(0.012, -0.007);

SlumpFlowOptions options() {
  SlumpFlowOptions o;
  o.view.axis = centre;
  o.view.pixel = pixel;
  return o;
}
}  // namespace

TEST_CASE("measure: slump-flow of a flat disc", "[measure][slumpflow]") {
  constexpr double Rd = 0.05;  // centres within Rd; the spheres reach Rd + r
  const auto pile = test::discPile(Rd, d, 2, centre);
  const auto res = slumpFlow(pile.x, pile.r, options());
  INFO("D_fit = " << res.diameter_fit << " rms = " << res.circle.rms << " ruler " << res.ruler.d1 << ", "
                  << res.ruler.d2 << " area D = " << res.diameter_area);
  // Expected bias: the edge spheres extend the disc by up to r; the contour is good to pixel/2.
  CHECK(res.circle.radius >= Rd - pixel / 2);
  CHECK(res.circle.radius <= Rd + r + pixel / 2);
  CHECK(res.circle.rms < r);
  CHECK((res.circle.centre - centre).norm() < pixel / 2);
  CHECK(res.circle.converged);
  for (double dd : {res.ruler.d1, res.ruler.d2, res.diameter_area}) {
    CHECK(dd >= 2 * Rd - pixel);
    CHECK(dd <= 2 * (Rd + r) + pixel);
  }
  CHECK(res.ruler.mean == Approx(0.5 * (res.ruler.d1 + res.ruler.d2)));
  CHECK(res.contour.size() > 500);
}

TEST_CASE("measure: slump-flow image route is unbiased to a fraction of a pixel", "[measure][slumpflow]") {
  // One big sphere: its top view is an exact disc of radius Rs (no lattice, no edge spheres).
  constexpr double Rs = 0.02;
  const std::vector<Vec3> x{Vec3(centre.x() + 0.3e-3, centre.y() - 0.1e-3, Rs)};
  const std::vector<double> rad{Rs};
  const auto res = slumpFlow(x, rad, options());
  INFO("R_fit - Rs = " << res.circle.radius - Rs << " area D - 2Rs = " << res.diameter_area - 2 * Rs);
  CHECK(res.circle.radius == Approx(Rs).margin(pixel / 10));  // crack points: no half-pixel shrink
  CHECK((res.circle.centre - x[0].head<2>()).norm() < pixel / 10);
  CHECK(res.diameter_area == Approx(2 * Rs).margin(pixel / 10));
  CHECK(res.ruler.d1 == Approx(2 * Rs).margin(pixel));
  CHECK(res.ruler.d2 == Approx(2 * Rs).margin(pixel));
  CHECK(res.circle.rms < pixel / 2);
}

TEST_CASE("measure: slump-flow ignores 20 particles scattered far away", "[measure][slumpflow]") {
  constexpr double Rd = 0.05;
  auto pile = test::discPile(Rd, d, 2, centre);
  const auto clean = slumpFlow(pile.x, pile.r, options());
  test::addNoise(pile, 20, 0.15, 0.25, r, centre, 7);
  const auto noisy = slumpFlow(pile.x, pile.r, options());
  CHECK(noisy.image.nx > clean.image.nx);  // the noise is in the picture...
  CHECK(noisy.diameter_fit == Approx(clean.diameter_fit).epsilon(1e-12));  // ...but not in the result
  CHECK((noisy.circle.centre - clean.circle.centre).norm() < 1e-12);
  CHECK(noisy.ruler.d1 == Approx(clean.ruler.d1).epsilon(1e-12));
  CHECK(noisy.ruler.d2 == Approx(clean.ruler.d2).epsilon(1e-12));
  CHECK(noisy.component_pixels == clean.component_pixels);
}

TEST_CASE("measure: slump-flow of an ellipse", "[measure][slumpflow]") {
  constexpr double a = 0.06, b = 0.04;
  SECTION("axes along x and y") {
    const auto pile = test::ellipsePile(a, b, d, 1, centre);
    const auto res = slumpFlow(pile.x, pile.r, options());
    INFO("d1 = " << res.ruler.d1 << " d2 = " << res.ruler.d2 << " fit " << res.diameter_fit);
    CHECK(res.ruler.d1 >= 2 * a - pixel);
    CHECK(res.ruler.d1 <= 2 * (a + r) + pixel);
    CHECK(res.ruler.d2 >= 2 * b - pixel);
    CHECK(res.ruler.d2 <= 2 * (b + r) + pixel);
    CHECK(res.diameter_fit > res.ruler.d2);
    CHECK(res.diameter_fit < res.ruler.d1);
    CHECK(res.circle.rms > 10 * pixel);  // a circle does not fit an ellipse
  }
  SECTION("rotated by 30 degrees: the largest diameter and its perpendicular") {
    const double angle = std::numbers::pi / 6;
    const auto pile = test::ellipsePile(a, b, d, 1, centre, angle);
    auto o = options();
    o.ruler = RulerMode::MaxAndPerpendicular;
    const auto res = slumpFlow(pile.x, pile.r, o);
    INFO("angle = " << res.ruler.angle << " d1 = " << res.ruler.d1 << " d2 = " << res.ruler.d2);
    CHECK(std::abs(res.ruler.angle - angle) <= 3 * std::numbers::pi / 180);
    CHECK(res.ruler.d1 >= 2 * a - 2 * pixel);
    CHECK(res.ruler.d1 <= 2 * (a + r) + 2 * pixel);
    CHECK(res.ruler.d2 >= 2 * b - 2 * pixel);
    CHECK(res.ruler.d2 <= 2 * (b + r) + 2 * pixel);
  }
}

TEST_CASE("measure: minimum-thickness threshold drops a thin rim", "[measure][slumpflow]") {
  // A thick core disc (3 layers, radius 30 mm) inside a one-layer disc of radius 50 mm.
  auto pile = test::discPile(0.05, d, 1, centre);
  const auto core = test::ellipsePile(0.03, 0.03, d, 3, centre);
  for (std::size_t k = 0; k < core.x.size(); ++k)
    if (core.x[k].z() > r) pile.add(core.x[k], core.r[k]);
  auto o = options();
  o.view.min_thickness = 2.5 * d;  // only the 3-layer core is this thick
  const auto res = slumpFlow(pile.x, pile.r, o);
  CHECK(res.circle.radius == Approx(0.03 + r / 2).margin(r / 2 + pixel));
}

TEST_CASE("measure: image cleanup pieces", "[measure][slumpflow]") {
  const int nx = 12, ny = 10;
  std::vector<std::uint8_t> m(nx * ny, 0);
  auto set = [&](int i, int j) { m[static_cast<std::size_t>(j) * nx + i] = 1; };
  for (int j = 2; j <= 7; ++j)
    for (int i = 2; i <= 8; ++i)
      if (!(i == 5)) set(i, j);  // a 7x6 block split by a one-pixel slit at i = 5
  set(5, 4);                     // one bridge
  set(10, 9);                    // a speck
  std::size_t pixels = 0;
  const auto big = largestComponent(m, nx, ny, &pixels);
  CHECK(pixels == 37);
  CHECK(big[9 * nx + 10] == 0);
  const auto closed = closing(big, nx, ny, 1.0);
  CHECK(closed[3 * nx + 5] == 1);  // the slit is closed
  CHECK(closed[1 * nx + 5] == 0);  // nothing grows outside
  std::vector<std::uint8_t> ring(nx * ny, 0);
  for (int j = 1; j <= 5; ++j)
    for (int i = 1; i <= 5; ++i)
      if (i == 1 || i == 5 || j == 1 || j == 5) ring[static_cast<std::size_t>(j) * nx + i] = 1;
  const auto filled = fillHoles(ring, nx, ny);
  CHECK(filled[3 * nx + 3] == 1);
  CHECK(filled[0] == 0);
  // Moore tracing of a 3x3 square visits its 8 border pixels once.
  std::vector<std::uint8_t> sq(nx * ny, 0);
  for (int j = 3; j <= 5; ++j)
    for (int i = 3; i <= 5; ++i) sq[static_cast<std::size_t>(j) * nx + i] = 1;
  CHECK(traceBoundary(sq, nx, ny).size() == 8);
  // Erosion treats the outside as background; dilation by 0 is the identity.
  std::vector<std::uint8_t> full(nx * ny, 1);
  CHECK(erosion(full, nx, ny, 1.0)[0] == 0);
  CHECK(erosion(full, nx, ny, 1.0)[5 * nx + 5] == 1);
  CHECK(dilation(sq, nx, ny, 0.0) == sq);
}

TEST_CASE("measure: circle fits", "[measure][slumpflow]") {
  std::vector<Vec2> pts;
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int k = 0; k < 60; ++k) {
    const double t = 0.1 + 1.6 * k / 59.0;  // an arc of ~90 degrees, radius 2, noise 0.5 %
    pts.emplace_back(3.0 + 2.0 * std::cos(t) + noise(rng), -1.0 + 2.0 * std::sin(t) + noise(rng));
  }
  const auto geo = fitCircle(pts);
  CHECK(geo.converged);
  CHECK(geo.radius == Approx(2.0).epsilon(0.01));
  CHECK(geo.rms <= fitCircleKasa(pts).rms + 1e-12);  // the geometric fit minimises rms
  CHECK_THROWS_WITH(fitCircle({{0, 0}, {1, 1}}), Contains("at least 3"));
  CHECK_THROWS_WITH(fitCircle({{0, 0}, {1, 1}, {2, 2}, {3, 3}}), Contains("collinear"));
}

TEST_CASE("measure: slump-flow pictures (PGM and gnuplot PNG)", "[measure][slumpflow]") {
  const auto pile = test::ellipsePile(0.03, 0.025, d, 2, centre);
  const auto res = slumpFlow(pile.x, pile.r, options());
  const char* bin = std::getenv("PADDY_BINARY_DIR");
  const std::filesystem::path dir =
      std::filesystem::path(bin ? bin : std::filesystem::temp_directory_path().string()) / "measure_pictures";
  std::filesystem::create_directories(dir);
  writePgm(res, dir / "top.pgm");
  writePgm(res, dir / "component.pgm", PgmLayer::Component);
  std::ifstream pgm(dir / "top.pgm", std::ios::binary);
  std::string magic;
  pgm >> magic;
  CHECK(magic == "P5");
  CHECK(std::filesystem::file_size(dir / "top.pgm") > static_cast<std::uintmax_t>(res.image.nx * res.image.ny));
  plotSlumpFlow(res, dir / "slump_flow.png", "synthetic ellipse");
  std::ifstream png(dir / "slump_flow.png", std::ios::binary);
  char head[4] = {};
  png.read(head, 4);
  CHECK(std::string(head + 1, 3) == "PNG");
  CHECK(std::filesystem::exists(dir / "slump_flow_contour.dat"));
}

TEST_CASE("measure: slump-flow rejects bad input", "[measure][slumpflow]") {
  const auto pile = test::discPile(0.01, d, 1);
  auto o = options();
  o.view.pixel = 0.0;
  CHECK_THROWS_WITH(slumpFlow(pile.x, pile.r, o), Contains("pixel"));
  o = options();
  o.view.min_thickness = 1.0;
  CHECK_THROWS_WITH(slumpFlow(pile.x, pile.r, o), Contains("no pile"));
  o = options();
  o.view.pixel = 1e-7;
  CHECK_THROWS_WITH(slumpFlow(pile.x, pile.r, o), Contains("pixels"));
  CHECK_THROWS_AS(slumpFlow({}, {}, options()), InputError);
}
