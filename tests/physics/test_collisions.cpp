// Two-sphere collisions through the whole engine.
#include "physics_fixture.hpp"

#include <catch2/catch.hpp>

using namespace paddy;

namespace {
// Two mud spheres under JKR + Hertz-Mindlin damping + Mindlin, without gravity.
void mudPairLaw(Simulation& sim, int mud, double e, double mu, double gamma) {
  InteractionSpec spec;
  spec.normal = "jkr";
  spec.damping = "hertz_mindlin";
  spec.tangential = "mindlin";
  spec.params = {{"restitution", e}, {"friction", mu}, {"surface_energy", gamma}};
  sim.setInteraction(mud, mud, spec);
  sim.setGravity(Vec3::Zero());
}
}  // namespace

TEST_CASE("without damping a cohesive collision conserves energy", "[physics][energy]") {
  Simulation sim(test::shippedPlugins());
  const int mud = sim.addMaterial(test::mudMaterial());
  mudPairLaw(sim, mud, 1.0, 0.0, 0.02);
  sim.setTimeStepFraction(0.01);
  const double R = 1e-3, v = 0.5;
  // Offset the line of centres slightly so the collision is oblique.
  sim.addParticle(Vec3(-1.2e-3, 0.1e-3, 0), R, mud, Vec3(v, 0, 0));
  sim.addParticle(Vec3(1.2e-3, -0.1e-3, 0), R, mud, Vec3(-v, 0, 0));
  const double e0 = sim.kineticEnergy();
  bool touched = false;
  for (int k = 0; k < 400 && !(touched && sim.contacts().empty()); ++k) {
    sim.run(1e-5);
    touched = touched || !sim.contacts().empty();
  }
  REQUIRE(touched);
  REQUIRE(sim.contacts().empty());
  REQUIRE(sim.kineticEnergy() == Approx(e0).epsilon(1e-4));
  // Momentum is conserved exactly (Newton's third law in the kernel).
  const auto& p = sim.particles();
  REQUIRE((p.mass[0] * p.velocity[0] + p.mass[1] * p.velocity[1]).norm() < 1e-12 * p.mass[0] * v);
}

TEST_CASE("a slow cohesive collision sticks", "[physics][jkr]") {
  Simulation sim(test::shippedPlugins());
  const int mud = sim.addMaterial(test::mudMaterial());
  mudPairLaw(sim, mud, 0.13, 0.15, 0.096);
  sim.addParticle(Vec3(-1.1e-3, 0, 0), 1e-3, mud, Vec3(0.05, 0, 0));
  sim.addParticle(Vec3(1.1e-3, 0, 0), 1e-3, mud, Vec3(-0.05, 0, 0));
  sim.run(0.05);
  REQUIRE(sim.contacts().size() == 1);
  REQUIRE(sim.kineticEnergy() < 1e-3 * 0.5 * 2 * sim.particles().mass[0] * 0.05 * 0.05);
}
