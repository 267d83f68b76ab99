// Changes of motion (Motion::change / MeshWall::changeKinematics): a wall translated, then
// rotated, then translated again ends at the closed-form pose; a vane whose speed is changed
// mid-run turns through a continuous angle; load samples keep accumulating distance and angle.
#include <paddy/errors.hpp>
#include <paddy/geometry/kinematics.hpp>
#include <paddy/geometry/mesh_wall.hpp>
#include <paddy/geometry/parts.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace paddy;
using namespace paddy::geometry;
using Catch::Matchers::Contains;

namespace {
Eigen::Matrix3d rotZ(double a) { return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix(); }
}  // namespace

TEST_CASE("geometry motion change: translate, rotate, translate again ends at the closed-form pose") {
  // Placement: turned 90° about x, at x0. A: 0.2 m/s along +x from t = 0. B (from t1 = 0.5):
  // 2 rad/s about +z through p. C (from t2 = 1.25): along −z with speed ramping 0 → 0.2 m/s
  // over 1 s, i.e. distance 0.1 (t − t2)².
  Pose place;
  place.R = Eigen::AngleAxisd(std::acos(-1.0) / 2, Vec3::UnitX()).toRotationMatrix();
  place.x = Vec3(0.1, 0.0, 0.02);
  const double t1 = 0.5, t2 = 1.25;
  const Vec3 p(0.3, 0.1, 0.0);
  MeshWall w("vane", 0, buildVane(), place, Kinematics::translation(Vec3(0.2, 0, 0)));
  w.moveTo(t1);
  w.changeKinematics(t1, Kinematics::rotation(p, Vec3(0, 0, 1), SpeedSchedule::constant(2.0)));
  w.moveTo(t2);
  Kinematics c;
  c.direction = Vec3(0, 0, -1);
  c.speed = SpeedSchedule({{t2, 0.0}, {t2 + 1.0, 0.2}});
  w.changeKinematics(t2, c);
  CHECK(w.motion().segmentCount() == 3);

  auto expected = [&](const Vec3& X, double t) {
    Vec3 y = place.R * X + place.x + Vec3(0.2 * std::min(t, t1), 0, 0);  // A
    if (t <= t1) return y;
    y = rotZ(2.0 * (std::min(t, t2) - t1)) * (y - p) + p;                  // B
    if (t <= t2) return y;
    return Vec3(y - Vec3(0, 0, 0.1 * (t - t2) * (t - t2)));                // C
  };
  for (double t : {0.0, 0.3, t1, 0.9, t2, 1.6, 2.0}) {
    w.moveTo(t);
    INFO("t = " << t);
    for (std::size_t v = 0; v < w.bodyMesh().vertices.size(); v += 13) {
      const Vec3 X = w.bodyMesh().vertices[v];
      REQUIRE((w.pose().apply(X) - expected(X, t)).norm() < 1e-14);
    }
  }
  // At t = 2: accumulated distance (A + C), angle (B) and translation (A + C).
  const double dc = 0.1 * 0.75 * 0.75;
  CHECK(w.distanceTravelled() == Approx(0.1 + dc).epsilon(1e-14));
  CHECK(w.angleTurned() == Approx(1.5).epsilon(1e-14));
  CHECK((w.translationTravelled() - Vec3(0.1, 0, -dc)).norm() < 1e-15);
  CHECK((w.velocityAt(Vec3(1, 2, 3)) - Vec3(0, 0, -0.2 * 0.75)).norm() < 1e-15);
  CHECK(w.angularVelocity().norm() == 0.0);
  // During B the point velocity is ω ẑ × (x − p) and the torque origin is p.
  w.moveTo(1.0);
  const Vec3 q = w.pose().apply(w.bodyMesh().vertices[7]);
  CHECK((w.velocityAt(q) - 2.0 * Vec3::UnitZ().cross(q - p)).norm() < 1e-14);
  CHECK((w.torqueOrigin() - p).norm() < 1e-15);
  CHECK((w.axis() - Vec3::UnitZ()).norm() < 1e-15);
  // The pose is continuous at the switches.
  for (double ts : {t1, t2}) {
    w.moveTo(ts - 1e-9);
    const Vec3 before = w.pose().apply(w.bodyMesh().vertices[3]);
    w.moveTo(ts);
    CHECK((w.pose().apply(w.bodyMesh().vertices[3]) - before).norm() < 1e-9);
  }
}

TEST_CASE("geometry motion change: a vane's speed changed mid-run turns through a continuous angle") {
  // Ramp to 5 rad/s over 0.05 s; at ts = 0.3 s switch to 2 rad/s. θ(ts) = 0.125 + 5 (ts − 0.05).
  const Vec3 a0(0, 0, 0.003);
  Pose place;
  place.x = a0;
  MeshWall vane("vane", 0, buildVane(), place,
                Kinematics::rotation(a0, Vec3(0, 0, 1), SpeedSchedule({{0, 0}, {0.05, 5.0}})));
  const double ts = 0.3, theta_s = 0.125 + 5.0 * (ts - 0.05);
  const double dt = 1e-4;
  for (int i = 0; i <= 3000; ++i) {  // step-by-step like the engine
    vane.moveTo(i * dt);
    vane.recordLoads(i * dt);
  }
  REQUIRE(vane.time() == Approx(ts));
  vane.changeKinematics(vane.time(), Kinematics::rotation(vane.pose().x, Vec3(0, 0, 1), SpeedSchedule::constant(2.0)));
  vane.recordLoads(vane.time());  // same instant, after the change: the same angle
  const double t_switch = vane.time();
  for (int i = 3001; i <= 5000; ++i) {
    vane.moveTo(i * dt);
    vane.recordLoads(i * dt);
  }
  const auto& h = vane.loadHistory();
  REQUIRE(h.size() == 5002);
  CHECK(h[3000].angle == Approx(theta_s).epsilon(1e-13));
  CHECK(h[3001].angle == h[3000].angle);
  for (std::size_t k = 1; k < h.size(); ++k) {
    INFO("sample " << k << " at t = " << h[k].t);
    const double omega = h[k].t <= 0.05 ? 5.0 * h[k].t / 0.05 : (h[k].t <= t_switch ? 5.0 : 2.0);
    REQUIRE(std::abs(h[k].angle - h[k - 1].angle) <= omega * dt + 1e-12);
  }
  const double theta_end = theta_s + 2.0 * (0.5 - t_switch);
  CHECK(h.back().angle == Approx(theta_end).epsilon(1e-13));
  CHECK((vane.pose().R - rotZ(theta_end)).norm() < 1e-13);
  CHECK((vane.pose().x - a0).norm() < 1e-15);
  CHECK((vane.angularVelocity() - Vec3(0, 0, 2.0)).norm() < 1e-15);
}

TEST_CASE("geometry motion change: windows, later changes and a full reset") {
  MeshWall w("plate", 0, buildPlate(), Pose{}, Kinematics::translation(Vec3(0, 0, 1.0)));
  // A new motion whose window started in the past acts only from the switch (no jump).
  w.moveTo(1.0);
  w.changeKinematics(1.0, Kinematics::translation(Vec3(1.0, 0, 0), /*t_start=*/0.0));
  CHECK(w.kinematics().t_start == 1.0);
  CHECK((w.pose().x - Vec3(0, 0, 1.0)).norm() < 1e-15);
  w.moveTo(1.5);
  CHECK((w.pose().x - Vec3(0.5, 0, 1.0)).norm() < 1e-15);
  // A window starting later: the wall waits at its pose of the switch, then moves.
  w.changeKinematics(1.5, Kinematics::translation(Vec3(0, 1.0, 0), 2.0, 3.0));
  w.moveTo(1.9);
  CHECK((w.pose().x - Vec3(0.5, 0, 1.0)).norm() < 1e-15);
  CHECK(w.velocityAt(Vec3::Zero()).norm() == 0.0);
  w.moveTo(4.0);
  CHECK((w.pose().x - Vec3(0.5, 1.0, 1.0)).norm() < 1e-15);
  CHECK(w.distanceTravelled() == Approx(1.0 + 0.5 + 1.0));
  CHECK(w.motion().segmentCount() == 3);
  // A change at an earlier time replaces the later ones.
  w.changeKinematics(1.2, Kinematics::still());
  CHECK(w.motion().segmentCount() == 3);
  CHECK((w.pose().x - Vec3(0.2, 0, 1.0)).norm() < 1e-15);
  w.changeKinematics(0.5, Kinematics::still());
  CHECK(w.motion().segmentCount() == 2);
  CHECK((w.pose().x - Vec3(0, 0, 0.5)).norm() < 1e-15);
  // The past before a change is still the old motion.
  w.moveTo(0.25);
  CHECK((w.pose().x - Vec3(0, 0, 0.25)).norm() < 1e-15);
  // setKinematics measures the whole motion from the placement again.
  w.setKinematics(Kinematics::translation(Vec3(0, 0, -1.0)));
  w.moveTo(2.0);
  CHECK(w.motion().segmentCount() == 1);
  CHECK((w.pose().x - Vec3(0, 0, -2.0)).norm() < 1e-15);
  CHECK_THROWS_WITH(w.changeKinematics(std::nan(""), Kinematics::still()), Contains("switch time"));
  Kinematics bad;
  bad.axis = Vec3::Zero();
  CHECK_THROWS_WITH(w.changeKinematics(3.0, bad), Contains("rotation axis"));
  CHECK(w.motion().segmentCount() == 1);  // a refused change leaves the motion as it was
}
