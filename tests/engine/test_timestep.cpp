#include "test_models.hpp"

#include <paddy/errors.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

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
