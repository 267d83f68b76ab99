// Slump height, slump and pile profile on synthetic piles with known answers.
#include "synthetic_piles.hpp"

#include <paddy/errors.hpp>
#include <paddy/measure/clusters.hpp>
#include <paddy/measure/slump.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace paddy::measure;
using paddy::InputError;
using Catch::Matchers::Contains;

namespace {
constexpr double H = 0.06, R = 0.10, d = 0.002, r = d / 2;
// Highest sphere top on the axis of test::conePile (lattice z = r + k d below the inset surface).
double coneTop() {
  const double s = std::sqrt(1.0 + (H / R) * (H / R));
  const double k = std::floor((H - r * s - r) / d);
  return r + k * d + r;
}
}  // namespace

TEST_CASE("measure: slump height of a cone pile is its apex", "[measure][slump]") {
  const auto pile = test::conePile(H, R, d);
  const auto h = slumpHeight(pile.x, pile.r);
  CHECK(h.height == Approx(coneTop()).margin(1e-12));
  CHECK(H - h.height >= 0.0);
  CHECK(H - h.height <= d);  // lattice + inset: within one diameter of the analytic apex
  CHECK(h.ignored == 0);
  CHECK(h.column >= 10);
  CHECK(slump(0.300, h.height) == Approx(0.300 - coneTop()));
}

TEST_CASE("measure: slump height ignores loose particles; the quantile option", "[measure][slump]") {
  auto pile = test::conePile(H, R, d, Vec2(0.01, -0.02));
  pile.add(Vec3(0.01, -0.02, H + 0.05), r);  // a particle hovering above the axis
  test::addNoise(pile, 20, 0.2, 0.3, r, Vec2(0.01, -0.02));
  SlumpHeightOptions o;
  o.axis = Vec2(0.01, -0.02);
  const auto h = slumpHeight(pile.x, pile.r, o);
  CHECK(h.height == Approx(coneTop()).margin(1e-12));
  CHECK(h.ignored == 21);

  o.largest_cluster = false;  // without clustering the loose particle is the "top"
  CHECK(slumpHeight(pile.x, pile.r, o).height == Approx(H + 0.05 + r));
  o.quantile = 0.98;          // a high quantile ignores it, with a downward bias
  const auto q = slumpHeight(pile.x, pile.r, o);
  CHECK(q.height < coneTop());
  CHECK(q.height > coneTop() - 0.05 * H - d);
}

TEST_CASE("measure: slump column widens until it holds enough particles", "[measure][slump]") {
  const auto pile = test::conePile(H, R, d);
  SlumpHeightOptions o;
  o.r_axis = 1e-4;
  o.min_particles = 30;
  const auto h = slumpHeight(pile.x, pile.r, o);
  CHECK(h.r_axis > 1e-4);
  CHECK(h.column >= 30);
  CHECK(h.height == Approx(coneTop()).margin(1e-12));
}

TEST_CASE("measure: pile profile of a cone follows its analytic line", "[measure][profile]") {
  const auto pile = test::conePile(H, R, d);
  ProfileOptions o;
  o.bin_width = 2 * d;
  const auto bins = pileProfile(pile.x, pile.r, o);
  REQUIRE(bins.size() >= 20);
  // Expected bias: tops sit r(s−1) … r(s−1)+d below the cone (inset + lattice); the highest top of a
  // cell is near its inner edge, slope·Δr/2 above the line at the bin centre.
  const double tol = d + (H / R) * o.bin_width / 2;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int m = 0;
  for (const auto& b : bins) {
    if (b.r_outer > R - 4 * d) break;  // the base rim is thinner than a sphere
    const double line = H * (1 - b.r_centre / R);
    INFO("r = " << b.r_centre << " h = " << b.height << " line = " << line);
    CHECK(std::abs(b.height - line) <= tol);
    CHECK(b.coverage > 0.9);
    sx += b.r_centre;
    sy += b.height;
    sxx += b.r_centre * b.r_centre;
    sxy += b.r_centre * b.height;
    ++m;
  }
  REQUIRE(m >= 15);
  const double slope = (sxy - sx * sy / m) / (sxx - sx * sx / m);
  CHECK(slope == Approx(-H / R).epsilon(0.05));
  // Beyond the pile the profile is zero.
  o.r_max = 2 * R;
  const auto wide = pileProfile(pile.x, pile.r, o);
  CHECK(wide.back().height == 0.0);
  CHECK(wide.back().coverage == 0.0);
  CHECK(wide.back().mean_height == 0.0);
}

TEST_CASE("measure: the ring-mean height of the profile moves with the pile's edge, the median jumps", "[measure][profile]") {
  // One ring (r 0.1 ... 0.11 m) of equal spheres on the plate covering an arc of angle phi:
  // mean height = d * (cells holding a sphere) / cells, near d * phi / 2 pi; the median is 0 below
  // half coverage and d above.
  const double rad = 0.105, dd = 0.004;
  ProfileOptions o;
  o.bin_width = 0.01;
  o.r_max = 0.11;
  o.cell_arc = 0.01;
  double last_mean = -1.0;
  for (double frac : {0.1, 0.3, 0.45, 0.55, 0.7, 0.9}) {
    std::vector<Vec3> x;
    std::vector<double> r;
    const int n = static_cast<int>(frac * 2 * std::numbers::pi * rad / (dd / 2));
    for (int i = 0; i < n; ++i) {
      const double phi = (i + 0.5) * (dd / 2) / rad;
      x.emplace_back(rad * std::cos(phi), rad * std::sin(phi), dd / 2);
      r.push_back(dd / 2);
    }
    const auto bins = pileProfile(x, r, o);
    const auto& ring = bins.back();
    INFO("covered fraction " << frac << ": mean " << ring.mean_height << ", median " << ring.height << ", coverage " << ring.coverage);
    CHECK(ring.r_inner == Approx(0.1));
    CHECK(ring.mean_height == Approx(dd * ring.coverage).epsilon(1e-12));
    CHECK(ring.coverage == Approx(frac).margin(2.0 / static_cast<double>(ring.cells)));
    CHECK(ring.height == (ring.coverage > 0.5 ? Approx(dd) : Approx(0.0)));
    CHECK(ring.mean_height > last_mean);
    last_mean = ring.mean_height;
  }
}

TEST_CASE("measure: connected clusters", "[measure][slump]") {
  std::vector<Vec3> x{{0, 0, 0}, {0.002, 0, 0}, {0.004, 0, 0}, {0.1, 0, 0}, {0.1, 0.0021, 0}};
  std::vector<double> rad(5, 0.001);
  auto c = connectedClusters(x, rad, 0.0);
  CHECK(c.size.size() == 3);  // the last two are 0.1 mm apart
  CHECK(c.size[static_cast<std::size_t>(c.largest)] == 3);
  c = connectedClusters(x, rad, 2e-4);
  CHECK(c.size.size() == 2);
}

TEST_CASE("measure: slump measures reject bad input", "[measure][slump]") {
  const auto pile = test::conePile(H, R, d);
  CHECK_THROWS_WITH(slumpHeight({}, {}), Contains("no particles"));
  auto x = pile.x;
  auto rad = pile.r;
  rad.pop_back();
  CHECK_THROWS_WITH(slumpHeight(x, rad), Contains("radii"));
  rad = pile.r;
  rad[3] = -1.0;
  CHECK_THROWS_WITH(slumpHeight(x, rad), Contains("radii > 0"));
  x[5].z() = std::nan("");
  CHECK_THROWS_AS(pileProfile(x, pile.r), InputError);
  SlumpHeightOptions o;
  o.quantile = 1.5;
  CHECK_THROWS_WITH(slumpHeight(pile.x, pile.r, o), Contains("quantile"));
  CHECK_THROWS_AS(slump(0.3, std::nan("")), InputError);
}
