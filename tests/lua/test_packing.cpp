// Unit tests of sim:fill's packing algorithms (engine/lua/src/packing.hpp).
#include "packing.hpp"

#include <paddy/errors.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace paddy;
using namespace paddy::lua;

namespace {

bool anyOverlap(const std::vector<Sphere>& s) {
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j)
      if ((s[i].x - s[j].x).norm() < s[i].r + s[j].r - 1e-12) return true;
  return false;
}

Region box() {
  Region r;
  r.type = Region::Type::Box;
  r.min = Vec3(0, 0, 0);
  r.max = Vec3(0.02, 0.02, 0.03);
  return r;
}

}  // namespace

TEST_CASE("lua: random fill is inside, non-overlapping and deterministic", "[lua][packing]") {
  FillRequest q;
  q.region = box();
  q.radius.a = 0.001;
  q.count = 300;
  q.seed = 42;
  const auto a = fillRegion(q, {});
  REQUIRE(a.size() == 300);
  CHECK_FALSE(anyOverlap(a));
  for (const auto& s : a) CHECK(q.region.containsSphere(s.x, s.r));
  const auto b = fillRegion(q, {});
  REQUIRE(b.size() == a.size());
  for (std::size_t i = 0; i < a.size(); ++i) CHECK(a[i].x == b[i].x);  // bitwise equal
  q.seed = 43;
  CHECK(fillRegion(q, {})[0].x != a[0].x);
}

TEST_CASE("lua: random fill by volume fraction with a radius distribution", "[lua][packing]") {
  FillRequest q;
  q.region.type = Region::Type::Cylinder;
  q.region.radius = 0.015;
  q.region.height = 0.03;
  q.radius.type = RadiusDistribution::Type::Uniform;
  q.radius.min = 0.0008;
  q.radius.max = 0.0012;
  q.volume_fraction = 0.2;
  const auto s = fillRegion(q, {});
  double v = 0;
  for (const auto& p : s) {
    CHECK(p.r >= 0.0008);
    CHECK(p.r <= 0.0012);
    CHECK(q.region.containsSphere(p.x, p.r));
    v += 4.0 / 3.0 * std::numbers::pi * std::pow(p.r, 3);
  }
  CHECK_FALSE(anyOverlap(s));
  CHECK(v / q.region.volume() == Approx(0.2).margin(0.02));
}

TEST_CASE("lua: fill avoids existing particles", "[lua][packing]") {
  FillRequest q;
  q.region = box();
  q.radius.a = 0.001;
  q.count = 200;
  std::vector<Sphere> existing{{Vec3(0.01, 0.01, 0.01), 0.004}};
  for (const auto& s : fillRegion(q, existing)) CHECK((s.x - existing[0].x).norm() >= s.r + 0.004);
  q.packing = FillRequest::Packing::Hexagonal;
  q.count.reset();
  for (const auto& s : fillRegion(q, existing)) CHECK((s.x - existing[0].x).norm() >= s.r + 0.004);
}

TEST_CASE("lua: lattice fills are dense, bottom-up and respect count", "[lua][packing]") {
  FillRequest q;
  q.region = box();
  q.radius.a = 0.001;
  q.packing = FillRequest::Packing::Cubic;
  const auto cubic = fillRegion(q, {});
  CHECK(cubic.size() == 10 * 10 * 15);
  q.packing = FillRequest::Packing::Hexagonal;
  const auto hex = fillRegion(q, {});
  CHECK(hex.size() > cubic.size());
  CHECK_FALSE(anyOverlap(hex));
  q.count = 50;
  q.jitter = 1.0;
  q.spacing = 1.1;
  const auto few = fillRegion(q, {});
  REQUIRE(few.size() == 50);
  CHECK_FALSE(anyOverlap(few));
  for (const auto& s : few) CHECK(s.x.z() < 0.006);  // the lowest layers first
}

TEST_CASE("lua: cone region contains spheres away from the slanted side", "[lua][packing]") {
  Region cone;
  cone.type = Region::Type::Cone;
  cone.radius = 0.1;
  cone.radius_top = 0.05;
  cone.height = 0.3;
  CHECK(cone.containsSphere(Vec3(0, 0, 0.15), 0.01));
  CHECK_FALSE(cone.containsSphere(Vec3(0.07, 0, 0.29), 0.005));
  CHECK(cone.containsSphere(Vec3(0.09, 0, 0.012), 0.005));
  CHECK(cone.volume() == Approx(std::numbers::pi * 0.3 / 3 * (0.01 + 0.005 + 0.0025)));
}

TEST_CASE("lua: bad fill requests are input errors", "[lua][packing]") {
  FillRequest q;
  q.region = box();
  q.radius.a = 0.001;
  CHECK_THROWS_AS(fillRegion(q, {}), InputError);  // random needs count or volume_fraction
  q.count = 10;
  q.radius.a = -1;
  CHECK_THROWS_AS(fillRegion(q, {}), InputError);
  q.radius.a = 0.001;
  q.region.max = Vec3(-1, 0, 0);
  CHECK_THROWS_AS(fillRegion(q, {}), InputError);
}
