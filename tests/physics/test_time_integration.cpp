// The two time integration schemes on a sphere and a steel plane (Hertz + Hertz-Mindlin damping):
// semi-implicit Euler conserves the energy of an undamped bounce (no drift over many bounces,
// as velocity Verlet), and its restitution converges to the setting at first order in the step.
#include "physics_fixture.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace paddy;

namespace {
// Rebound speed / impact speed of a sphere (R = 1 mm) hitting the floor at 0.5 m/s without
// gravity, averaged over 16 starting gaps: where the contact begins within a step moves a single
// impact's result by up to ±2 % at 0.1 T_R, the mean over the gaps keeps the step's own error.
double restitution(TimeIntegration scheme, double e, double dt_fraction) {
  double sum = 0.0;
  for (int k = 0; k < 16; ++k) {
    auto s = test::mudOnSteelFloor(test::hertzMindlin(e, 0.0));
    const double R = 1e-3, v0 = 0.5;
    s.sim->setGravity(Vec3::Zero());
    s.sim->setTimeIntegration(scheme);
    s.sim->setTimeStepFraction(dt_fraction);
    s.sim->addParticle(Vec3(0, 0, R + 1e-5 * (1.0 + 0.0637 * k)), R, s.mud, Vec3(0, 0, -v0));
    s.sim->run(2e-3);
    REQUIRE(s.sim->contacts().empty());
    sum += s.sim->particles().velocity[0].z() / v0;
  }
  return sum / 16.0;
}
}  // namespace

// Dropped from 20 mm with e = 1 (no damping) at 0.2 T_R: every bounce's apex. Semi-implicit Euler
// is symplectic, so the energy error stays bounded; an integrator that drifts would climb or sink
// a little at every contact (forward Euler, drifting with the old velocity, gains about ω²dt²/2 of
// the energy per step of contact).
TEST_CASE("semi-implicit Euler: an undamped bounce keeps its height over 30 bounces, as velocity Verlet", "[physics][integrator]") {
  for (TimeIntegration scheme : {TimeIntegration::SymplecticEuler, TimeIntegration::VelocityVerlet}) {
    auto s = test::mudOnSteelFloor(test::hertzMindlin(1.0, 0.0));
    const double R = 1e-3, h0 = 0.02;
    s.sim->setTimeIntegration(scheme);
    s.sim->setTimeStepFraction(0.2);
    s.sim->addParticle(Vec3(0, 0, R + h0), R, s.mud);
    std::vector<double> apex;
    double prev_vz = 0.0, top = 0.0;
    s.sim->run(
        4.5,
        [&](Simulation& sim) {
          const double z = sim.particles().position[0].z(), vz = sim.particles().velocity[0].z();
          top = std::max(top, z);
          if (prev_vz > 0.0 && vz <= 0.0) {
            apex.push_back(top - R);
            top = 0.0;
          }
          prev_vz = vz;
          return apex.size() < 30;
        },
        1e-5);
    INFO(timeIntegrationName(scheme) << ": " << apex.size() << " bounces, last apex " << (apex.empty() ? 0.0 : apex.back()));
    REQUIRE(apex.size() == 30);
    // Each apex within 1 % of the drop height (the contact's onset within a step moves it by up to
    // 0.6 %), and no drift: the last ten bounces' mean within 0.3 % of the first ten's.
    for (double h : apex) REQUIRE(h == Approx(h0).epsilon(0.01));
    double first = 0.0, last = 0.0;
    for (std::size_t k = 0; k < 10; ++k) first += apex[k] / 10.0, last += apex[apex.size() - 1 - k] / 10.0;
    REQUIRE(last == Approx(first).epsilon(3e-3));
  }
}

// Restitution against the plane: its error falls in proportion to the step (first order: the
// error at 0.08, 0.04, 0.02, 0.01 T_R halves from each to the next; velocity Verlet's falls
// faster) and is within 1 % at 0.01 T_R.
TEST_CASE("semi-implicit Euler: restitution converges at first order in the step", "[physics][integrator]") {
  for (double e : {0.13, 0.3, 0.5}) {
    std::vector<double> err;
    for (double f : {0.08, 0.04, 0.02, 0.01}) err.push_back(restitution(TimeIntegration::SymplecticEuler, e, f) / e - 1.0);
    INFO("e = " << e << ": relative error at 0.08, 0.04, 0.02, 0.01 T_R " << err[0] << ", " << err[1] << ", " << err[2]
                << ", " << err[3]);
    REQUIRE(std::abs(err[0]) > 0.005);  // a first-order scheme's error is visible at 0.08 T_R
    for (std::size_t k = 0; k + 1 < err.size(); ++k) REQUIRE(err[k] / err[k + 1] == Approx(2.0).margin(0.35));
    REQUIRE(std::abs(err[3]) < 0.01);
  }
}

// A spatial re-sort between list builds reorders every particle array (positions, velocities,
// spins, forces, torques, resisting torques) and the contacts' history, and velocity Verlet's
// force pass then damps each contact with the velocities predicted for its two spheres. A damped
// pile of spheres (Hertz-Mindlin damping and friction: forces that depend on the velocities) falls
// onto the floor, once re-sorted at every list build and once never. The sums run in another
// order, so the two runs agree to rounding, not bit for bit. An array left behind by a re-sort
// moves a sphere with another's data and is off by far more than 1e-12 m. (A prediction computed
// before the re-sort and not permuted with it failed by 0.36 µm.)
TEST_CASE("a spatial re-sort changes a damped pile only by rounding", "[physics][integrator]") {
  auto run = [](int sort_interval, std::size_t* builds) {
    auto s = test::mudOnSteelFloor(test::hertzMindlin(0.3, 0.5));
    s.sim->setGravity(Vec3(0, 0, -9.81));
    s.sim->setSkinFraction(0.05);  // a list build every few steps
    s.sim->setSortInterval(sort_interval);
    s.sim->setTimeStepFraction(0.2);
    const double R = 1e-3;
    for (int k = 0; k < 5; ++k)
      for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i) {
          // a fixed jitter, and the spheres added top layer first (the re-sort reorders them)
          const double e = 2e-4 * R * std::sin(1.0 + i * 7.1 + j * 3.3 + k * 5.7);
          s.sim->addParticle(Vec3(i * 2.05 * R + e, j * 2.05 * R - e, (10.0 - 2.05 * k) * R + e), R, s.mud);
        }
    s.sim->run(0.03);  // the bottom layer lands after 15 ms, the others on it
    *builds = s.sim->neighbourListBuilds();
    // the layers have landed on each other and rebound (damped sphere-sphere and floor contacts)
    double up = 0.0;
    for (const Vec3& v : s.sim->particles().velocity) up = std::max(up, v.z());
    REQUIRE(up > 1e-3);
    REQUIRE(s.sim->contacts().size() >= 25);
    std::vector<Vec3> x(s.sim->particles().size());
    for (std::size_t i = 0; i < x.size(); ++i) x[s.sim->particles().id[i]] = s.sim->particles().position[i];
    return x;
  };
  std::size_t builds_sorted = 0, builds_unsorted = 0;
  const auto sorted = run(1, &builds_sorted);
  const auto unsorted = run(0, &builds_unsorted);
  REQUIRE(builds_sorted > 20);
  double worst = 0.0;
  for (std::size_t i = 0; i < sorted.size(); ++i) worst = std::max(worst, (sorted[i] - unsorted[i]).norm());
  CHECK(worst < 1e-12);
}
