#include "test_models.hpp"

#include <paddy/errors.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

using namespace paddy;

TEST_CASE("Rayleigh time step follows T_R = pi R / (0.163 nu + 0.877) sqrt(rho / G)", "[engine][timestep]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  sim.addParticle(Vec3(0, 0, 0), 1e-3, mud);
  sim.addParticle(Vec3(1, 0, 0), 0.5e-3, mud);  // the smallest particle decides
  const double expected = std::numbers::pi * 0.5e-3 / (0.163 * 0.5 + 0.877) * std::sqrt(1680.0 / 1e6);
  REQUIRE(sim.rayleighTime() == Approx(expected).epsilon(1e-14));
  REQUIRE(sim.maxStableTimeStep() == Approx(0.5 * expected).epsilon(1e-14));
}

TEST_CASE("a time step above the stable limit is refused with the limit in the message", "[engine][timestep]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  sim.addParticle(Vec3(0, 0, 0), 1e-3, mud);
  const double limit = sim.maxStableTimeStep();
  REQUIRE_NOTHROW(sim.setTimeStep(0.99 * limit));
  try {
    sim.setTimeStep(1.01 * limit);
    FAIL("no error");
  } catch (const InputError& e) {
    const std::string msg = e.what();
    REQUIRE(msg.find("stable limit") != std::string::npos);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", limit);
    REQUIRE(msg.find(buf) != std::string::npos);
  }
  REQUIRE_THROWS_AS(sim.setTimeStepFraction(0.6), InputError);
}

TEST_CASE("default time step is 0.2 Rayleigh times and is applied at the first step", "[engine][timestep]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  auto spec = test::linearSpring();
  sim.setInteraction(mud, mud, spec);
  sim.addParticle(Vec3(0, 0, 0), 1e-3, mud);
  sim.step(1);
  REQUIRE(sim.timeStep() == Approx(TimeStepPolicy::kDefaultRayleighFraction * sim.rayleighTime()).epsilon(1e-14));
  REQUIRE(sim.time() == Approx(sim.timeStep()));
}

TEST_CASE("free fall under gravity is integrated exactly by velocity Verlet", "[engine][integrator]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  auto spec = test::linearSpring();
  sim.setInteraction(mud, mud, spec);
  sim.addParticle(Vec3(0, 0, 1), 1e-3, mud, Vec3(0.1, 0, 0));
  sim.run(0.1);
  const double t = sim.time();
  const Vec3 x = sim.particles().position[0];
  REQUIRE(x.z() == Approx(1.0 - 0.5 * 9.81 * t * t).epsilon(1e-12));
  REQUIRE(x.x() == Approx(0.1 * t).epsilon(1e-12));
}

// Semi-implicit Euler under gravity alone: v_n = v0 − g n dt, x_n = x0 + v0 n dt − g dt² n(n+1)/2
// (each drift uses the velocity after the step's kick). Velocity Verlet would give the exact
// x0 + v0 t − g t²/2, which differs by g t dt / 2 (1e-5 m here, 1e-5 of the height).
TEST_CASE("free fall under gravity follows the closed form of semi-implicit Euler", "[engine][integrator]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  sim.setInteraction(mud, mud, test::linearSpring());
  sim.addParticle(Vec3(0, 0, 1), 1e-3, mud, Vec3(0.1, 0, 0.2));
  REQUIRE(std::string(timeIntegrationName(sim.timeIntegration())) == "velocity_verlet");
  sim.setTimeIntegration(TimeIntegration::SymplecticEuler);
  REQUIRE(std::string(timeIntegrationName(sim.timeIntegration())) == "euler");
  sim.run(0.1);
  const double dt = sim.timeStep(), g = 9.81;
  const auto n = static_cast<double>(sim.stepCount());
  const double t = n * dt;
  const Vec3 x = sim.particles().position[0], v = sim.particles().velocity[0];
  INFO("steps " << n << ", dt " << dt);
  REQUIRE(n > 100);
  REQUIRE(v.z() == Approx(0.2 - g * n * dt).epsilon(1e-12));
  REQUIRE(x.z() == Approx(1.0 + 0.2 * t - 0.5 * g * dt * dt * n * (n + 1)).epsilon(1e-12));
  REQUIRE(std::abs(x.z() - (1.0 + 0.2 * t - 0.5 * g * t * t)) > 0.4 * g * t * dt);  // not Verlet's
  REQUIRE(x.x() == Approx(0.1 * t).epsilon(1e-12));
}

// The scheme may change between runs: each run ends with positions, velocities and forces
// consistent, so Verlet, then Euler, then Verlet again follow their closed forms piece by piece.
TEST_CASE("the integration scheme can change between runs", "[engine][integrator]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  sim.setInteraction(mud, mud, test::linearSpring());
  sim.addParticle(Vec3(0, 0, 1), 1e-3, mud);
  const double g = 9.81;
  sim.step(0);
  const double dt = sim.timeStep();
  double z = 1.0, w = 0.0;  // expected position and velocity
  struct Piece { TimeIntegration scheme; int steps; };
  for (const Piece& piece : {Piece{TimeIntegration::VelocityVerlet, 300}, Piece{TimeIntegration::SymplecticEuler, 200},
                             Piece{TimeIntegration::VelocityVerlet, 100}}) {
    sim.setTimeIntegration(piece.scheme);
    sim.step(static_cast<std::uint64_t>(piece.steps));
    const double n = piece.steps, t = n * dt;
    z += w * t - (piece.scheme == TimeIntegration::SymplecticEuler ? 0.5 * g * dt * dt * n * (n + 1) : 0.5 * g * t * t);
    w -= g * t;
    INFO(timeIntegrationName(piece.scheme) << " for " << piece.steps << " steps");
    REQUIRE(sim.particles().velocity[0].z() == Approx(w).epsilon(1e-12));
    REQUIRE(sim.particles().position[0].z() == Approx(z).epsilon(1e-12));
  }
}
