// Prescribed kinematics (translation, rotation, speed schedules, time window) against closed
// forms; displacement bound; loads → axial torque on a vane; load history CSV.
#include "test_util.hpp"

#include <paddy/errors.hpp>
#include <paddy/geometry/kinematics.hpp>
#include <paddy/geometry/mesh_wall.hpp>
#include <paddy/geometry/parts.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

using namespace paddy;
using namespace paddy::geometry;
using Catch::Matchers::Contains;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST_CASE("geometry speed schedule: steps and ramps, exact integral") {
  // Rheometer-like protocol: ramp 0 → 1 rad/s over 2 s, hold to 5 s, step to 2 rad/s, ramp down
  // to 0 at 9 s.
  const SpeedSchedule s({{0, 0}, {2, 1}, {5, 1}, {5, 2}, {9, 0}});
  CHECK(s.value(-1) == 0.0);
  CHECK(s.value(1) == Approx(0.5));
  CHECK(s.value(4.999) == Approx(1.0));
  CHECK(s.value(5) == Approx(2.0));  // right-continuous at the step
  CHECK(s.value(7) == Approx(1.0));
  CHECK(s.value(100) == 0.0);
  auto F = [](double t) {  // closed-form integral from 0
    if (t <= 0) return 0.0;
    if (t <= 2) return 0.25 * t * t;
    if (t <= 5) return 1.0 + (t - 2);
    if (t <= 9) return 4.0 + 2.0 * (t - 5) - 0.25 * (t - 5) * (t - 5);
    return 8.0;
  };
  for (double a : {-1.0, 0.0, 0.7, 2.0, 4.2, 5.0, 6.1, 8.9, 12.0})
    for (double b : {0.0, 1.3, 2.0, 4.99, 5.0, 5.01, 7.5, 9.0, 15.0}) {
      INFO(a << " → " << b);
      CHECK(s.integral(a, b) == Approx(F(b) - F(a)).margin(1e-12));
    }
  CHECK(SpeedSchedule::constant(0.05).integral(1, 3) == Approx(0.1));
  CHECK_THROWS_WITH(SpeedSchedule({{1, 0}, {0.5, 1}}), Contains("knot 1"));
  // Numerical integration of the ramp agrees with the exact one.
  double sum = 0.0;
  const int n = 90000;
  for (int i = 0; i < n; ++i) sum += s.value((i + 0.5) * 9.0 / n) * 9.0 / n;
  CHECK(sum == Approx(8.0).epsilon(1e-6));
}

TEST_CASE("geometry translating wall (cone lift at 0.05 m/s) follows the closed form in its window") {
  MeshWall cone("cone", 1, buildSlumpCone(), Pose{}, Kinematics::translation(Vec3(0, 0, 0.05), 0.5, 4.5));
  CHECK(cone.material() == 1);
  for (double t : {0.0, 0.25, 0.5, 1.0, 2.7, 4.5, 6.0}) {
    cone.moveTo(t);
    const double lift = 0.05 * std::clamp(t - 0.5, 0.0, 4.0);
    INFO("t = " << t);
    CHECK((cone.pose().x - Vec3(0, 0, lift)).norm() < 1e-15);
    CHECK((cone.pose().R - Eigen::Matrix3d::Identity()).norm() == 0.0);
    const Vec3 v = (t >= 0.5 && t < 4.5) ? Vec3(0, 0, 0.05) : Vec3::Zero();
    CHECK((cone.velocityAt(Vec3(0.3, -2, 7)) - v).norm() < 1e-15);
    CHECK(cone.angularVelocity().norm() == 0.0);
    const TriangleMesh w = cone.worldMesh();
    CHECK(w.vertices[0].z() == Approx(cone.bodyMesh().vertices[0].z() + lift));
  }
  // Displacement since the last list build.
  cone.moveTo(1.0);
  cone.markListBuilt();
  CHECK(cone.displacementSinceListBuild() == 0.0);
  cone.moveTo(1.02);
  CHECK(cone.displacementSinceListBuild() == Approx(0.001).epsilon(1e-9));
}

TEST_CASE("geometry rotating wall: pose, point velocity and displacement bound vs closed form") {
  // Vane rotating about the vertical axis through (0.1, 0.2, 0) while translating downwards.
  const Vec3 a0(0.1, 0.2, 0.0);
  Pose place;
  place.x = a0;
  Kinematics k = Kinematics::rotation(a0, Vec3(0, 0, 2), SpeedSchedule({{0, 0}, {1, 3}}), 0.0);
  k.direction = Vec3(0, 0, -1);
  k.speed = SpeedSchedule::constant(0.01);
  MeshWall vane("vane", 0, buildVane(), place, k);
  for (double t : {0.0, 0.4, 1.0, 2.5}) {
    vane.moveTo(t);
    const double theta = t <= 1 ? 1.5 * t * t : 1.5 + 3 * (t - 1);
    const double omega = std::min(3.0 * t, 3.0);
    const Vec3 axis_pt = a0 + Vec3(0, 0, -0.01 * t);
    INFO("t = " << t);
    CHECK((vane.torqueOrigin() - axis_pt).norm() < 1e-15);
    const Eigen::Matrix3d Q = Eigen::AngleAxisd(theta, Vec3::UnitZ()).toRotationMatrix();
    for (std::size_t v = 0; v < vane.bodyMesh().vertices.size(); v += 17) {
      const Vec3 X = vane.bodyMesh().vertices[v];
      const Vec3 expected = Q * X + axis_pt;
      REQUIRE((vane.pose().apply(X) - expected).norm() < 1e-14);
      const Vec3 vel = Vec3(0, 0, -0.01) + omega * Vec3::UnitZ().cross(expected - axis_pt);
      REQUIRE((vane.velocityAt(expected) - vel).norm() < 1e-14);
    }
    CHECK((vane.angularVelocity() - Vec3(0, 0, omega)).norm() < 1e-15);
    // Velocity is the time derivative of the position (central difference).
    const Vec3 X = vane.bodyMesh().vertices[5];
    MeshWall probe("p", 0, buildVane(), place, k);
    const double dt = 1e-6;
    probe.moveTo(t + dt);
    const Vec3 xp = probe.pose().apply(X);
    probe.moveTo(std::max(0.0, t - dt));
    const Vec3 xm = probe.pose().apply(X);
    const Vec3 fd = (xp - xm) / ((t + dt) - std::max(0.0, t - dt));
    CHECK((fd - vane.velocityAt(vane.pose().apply(X))).norm() < 1e-6);
  }
  // The displacement since the list build is the largest vertex displacement.
  vane.moveTo(1.0);
  vane.markListBuilt();
  const TriangleMesh before = vane.worldMesh();
  vane.moveTo(1.01);
  const TriangleMesh after = vane.worldMesh();
  double actual = 0.0;
  for (std::size_t v = 0; v < before.vertices.size(); ++v) actual = std::max(actual, (after.vertices[v] - before.vertices[v]).norm());
  CHECK(vane.displacementSinceListBuild() == Approx(actual).epsilon(1e-12));
}

TEST_CASE("geometry kinematics refuse bad input") {
  CHECK_THROWS_AS(Kinematics::rotation(Vec3::Zero(), Vec3::Zero(), SpeedSchedule::constant(1)), InputError);
  CHECK_THROWS_AS(Kinematics::translation(Vec3(0, 0, 1), 2.0, 1.0), InputError);
  TriangleMesh empty;
  CHECK_THROWS_WITH(MeshWall("w", 0, empty), Contains("mesh wall 'w'"));
}

TEST_CASE("geometry known tangential loads on vane blades give axial torque = sum of r x F along the axis") {
  const Vec3 a0(0.02, -0.01, 0.03);
  Pose place;
  place.x = a0;
  MeshWall vane("vane", 0, buildVane(), place,
                Kinematics::rotation(a0, Vec3(0, 0, 1), SpeedSchedule::constant(0.5)));
  vane.moveTo(0.7);
  vane.resetLoads();
  // Tangential forces on the four blade tips at mid-height (world), plus a random radial and
  // axial component that must not change the axial torque.
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 axis = vane.axis();
  double expected = 0.0;
  Vec3 total = Vec3::Zero();
  for (int b = 0; b < 4; ++b) {
    const double phi = 0.5 * 0.7 + b * kPi / 2;  // blades have turned by ω t
    const Vec3 radial(std::cos(phi), std::sin(phi), 0);
    const Vec3 tangent = axis.cross(radial);
    const Vec3 p = a0 + 0.025 * radial + Vec3(0, 0, 0.03);
    const double ft = 0.5 + 0.25 * b;  // N
    const Vec3 f = ft * tangent + u(rng) * radial + u(rng) * axis;
    vane.addLoad(f, p);
    expected += 0.025 * ft;
    total += f;
  }
  CHECK(vane.axialTorque() == Approx(expected).epsilon(1e-12));
  CHECK((vane.force() - total).norm() < 1e-14);
  // Shear stress from the torque with the documented vane relation.
  CHECK(vaneShearStress(vane.axialTorque(), 0.05, 0.06) == Approx(expected / (kPi * 0.05 * 0.05 / 2 * (0.06 + 0.05 / 3))));

  // History CSV (atomic: no temporary left behind).
  test::TempDir dir;
  vane.recordLoads(0.7);
  vane.resetLoads();
  vane.recordLoads(0.8);
  const std::string csv = dir.file("vane_loads.csv");
  vane.writeLoadHistoryCsv(csv);
  CHECK_FALSE(std::filesystem::exists(csv + ".tmp"));
  std::ifstream f(csv);
  std::string l1, l2, l3, l4;
  std::getline(f, l1);
  std::getline(f, l2);
  std::getline(f, l3);
  std::getline(f, l4);
  CHECK(l1 == "# wall: vane");
  CHECK(l2 == "t,Fx,Fy,Fz,Tx,Ty,Tz,T_axis,distance,angle");
  CHECK_THAT(l3, Contains("0.7,"));
  REQUIRE(vane.loadHistory().size() == 2);
  CHECK(vane.loadHistory()[0].axial_torque == Approx(expected));
  CHECK(vane.loadHistory()[0].angle == Approx(0.35));
  CHECK(vane.loadHistory()[1].axial_torque == 0.0);
}
