// The stress across a disc and a cylinder (surface_stress.hpp) on contact sets whose answer is
// known by hand: which contacts cross, which side is near, the sign of compression and of the
// azimuthal shear, the area.
#include <paddy/errors.hpp>
#include <paddy/measure/surface_stress.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace paddy::measure;
using paddy::InputError;
using Catch::Matchers::Contains;

namespace {
constexpr double pi = std::numbers::pi;

// A contact between centres a and b whose force on a is f.
ContactForce contact(const Vec3& a, const Vec3& b, const Vec3& f) { return {a, b, f}; }
}  // namespace

TEST_CASE("measure: disc stress sums the forces that cross the disc", "[measure][stress]") {
  // Disc z = 0.1 m, 0.01 <= r < 0.05 m about the axis (0.2, 0.3): area π (0.05² − 0.01²).
  const DiscSurface disc{Vec2(0.2, 0.3), 0.1, 0.01, 0.05};
  const double area = pi * (0.05 * 0.05 - 0.01 * 0.01);
  std::vector<ContactForce> c;
  // Upper sphere i on lower sphere j, crossing at r = 0.03: the lower is pushed down by 2 N.
  c.push_back(contact({0.23, 0.3, 0.105}, {0.23, 0.3, 0.095}, {0, 0, 2.0}));
  // The same kind of contact written the other way round (i below): force on i (lower) −3 N.
  c.push_back(contact({0.2, 0.33, 0.095}, {0.2, 0.33, 0.104}, {0, 0, -3.0}));
  // A slanted branch: centres at r = 0.02 and 0.04 either side of the plane, crossing at its middle
  // (r = 0.03): counted; its 0.5 N along +θ at the crossing point (θ̂ = +y at (0.23, 0.3)).
  c.push_back(contact({0.22, 0.3, 0.11}, {0.24, 0.3, 0.09}, {0, -0.5, 1.0}));
  // Not counted: crossing inside r_min (r = 0.005), outside r_max (r = 0.06), not crossing.
  c.push_back(contact({0.205, 0.3, 0.105}, {0.205, 0.3, 0.095}, {0, 0, 100.0}));
  c.push_back(contact({0.26, 0.3, 0.105}, {0.26, 0.3, 0.095}, {0, 0, 100.0}));
  c.push_back(contact({0.23, 0.3, 0.115}, {0.23, 0.3, 0.105}, {0, 0, 100.0}));
  const SurfaceStress s = discStress(c, disc);
  CHECK(s.crossings == 3);
  CHECK(s.area == Approx(area).epsilon(1e-14));
  // Force on the lower side: −2 (first), −3 (second), −1 (third: −force_on_i, i above) → 6 N down.
  CHECK(s.normal == Approx(6.0 / area).epsilon(1e-12));
  // Third contact: force on the lower particle (0, +0.5, −1); θ̂ at (0.23, 0.3) is +y.
  CHECK(s.shear == Approx(0.5 / area).epsilon(1e-12));
  // A contact in tension (JKR pull) counts negative.
  c.push_back(contact({0.23, 0.31, 0.105}, {0.23, 0.31, 0.095}, {0, 0, -1.0}));
  CHECK(discStress(c, disc).normal == Approx(5.0 / area).epsilon(1e-12));
}

TEST_CASE("measure: cylinder stress counts each branch once, with the inside as the near side", "[measure][stress]") {
  const double R = 0.025, zl = 0.03, zh = 0.09;
  const CylinderSurface cyl{Vec2::Zero(), R, zl, zh};
  const double area = 2 * pi * R * (zh - zl);
  std::vector<ContactForce> c;
  // Eight radial branches across r = R at 45° steps, z = 0.06: the outer sphere pushes the inner
  // one inward by 1.5 N and along +θ by 0.2 N. Odd k: the inner sphere is j (force on i outward).
  for (int k = 0; k < 8; ++k) {
    const double a = k * pi / 4;
    const Vec3 rhat(std::cos(a), std::sin(a), 0), that(-std::sin(a), std::cos(a), 0);
    const Vec3 in = (R - 0.004) * rhat + Vec3(0, 0, 0.06), out = (R + 0.004) * rhat + Vec3(0, 0, 0.06);
    const Vec3 on_inner = -1.5 * rhat + 0.2 * that;
    if (k % 2 == 0) c.push_back(contact(in, out, on_inner));
    else c.push_back(contact(out, in, -on_inner));
  }
  // Not counted: crossing below z_min; both ends outside (a chord: crosses twice); both inside.
  c.push_back(contact({R - 0.004, 0, 0.02}, {R + 0.004, 0, 0.02}, {-50, 0, 0}));
  c.push_back(contact({0.024, 0.01, 0.06}, {0.024, -0.01, 0.06}, {-50, 0, 0}));
  c.push_back(contact({0.01, 0, 0.06}, {0.015, 0, 0.06}, {-50, 0, 0}));
  const SurfaceStress s = cylinderStress(c, cyl);
  CHECK(s.crossings == 8);
  CHECK(s.area == Approx(area).epsilon(1e-14));
  CHECK(s.normal == Approx(8 * 1.5 / area).epsilon(1e-12));
  CHECK(s.shear == Approx(8 * 0.2 / area).epsilon(1e-12));
  // A slanted branch: crossing point where |x_xy| = R, z interpolated along it. From (0.02, 0, 0.02)
  // to (0.03, 0, 0.1): crosses r = 0.025 halfway, at z = 0.06 — inside [z_min, z_max): counted.
  std::vector<ContactForce> one{contact({0.02, 0, 0.02}, {0.03, 0, 0.1}, {-1, 0, 0})};
  CHECK(cylinderStress(one, cyl).crossings == 1);
  CHECK(cylinderStress(one, cyl).normal == Approx(1.0 / area).epsilon(1e-12));
  // From (0.02, 0, 0.0) to (0.03, 0, 0.05): crosses at z = 0.025, below z_min: not counted.
  std::vector<ContactForce> low{contact({0.02, 0, 0.0}, {0.03, 0, 0.05}, {-1, 0, 0})};
  CHECK(cylinderStress(low, cyl).crossings == 0);
}

TEST_CASE("measure: surface stress refuses bad surfaces and contacts", "[measure][stress][errors]") {
  const std::vector<ContactForce> none;
  CHECK_THROWS_WITH(discStress(none, DiscSurface{Vec2::Zero(), 0.1, 0.05, 0.05}), Contains("allowed: 0 <= r_min < r_max"));
  CHECK_THROWS_WITH(discStress(none, DiscSurface{Vec2::Zero(), NAN, 0, 0.05}), Contains("z must be finite"));
  CHECK_THROWS_WITH(cylinderStress(none, CylinderSurface{Vec2::Zero(), 0.0, 0, 1}), Contains("radius > 0"));
  CHECK_THROWS_WITH(cylinderStress(none, CylinderSurface{Vec2::Zero(), 0.1, 1, 1}), Contains("z_max > z_min"));
  const std::vector<ContactForce> bad{contact({0, 0, 0}, {0, 0, INFINITY}, {0, 0, 1})};
  CHECK_THROWS_WITH(discStress(bad, DiscSurface{Vec2::Zero(), 0.1, 0, 0.05}), Contains("contact 0"));
  // No contact crosses: zero stress, zero crossings (not an error: an empty region carries nothing).
  const SurfaceStress s = discStress(none, DiscSurface{Vec2::Zero(), 0.1, 0, 0.05});
  CHECK(s.crossings == 0);
  CHECK(s.normal == 0.0);
}
