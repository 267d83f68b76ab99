#include "test_models.hpp"

#include <paddy/errors.hpp>
#include <paddy/plane_wall.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <cmath>

using namespace paddy;
using Catch::Matchers::Contains;

TEST_CASE("an unknown contact model lists the available ones", "[engine][errors]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  InteractionSpec spec;
  spec.normal = "hertz_typo";
  spec.damping = spec.tangential = "";
  REQUIRE_THROWS_WITH(sim.setInteraction(mud, mud, spec),
                      Contains("unknown normal contact model 'hertz_typo'") && Contains("linear_spring"));
}

TEST_CASE("parameters are checked by name and range", "[engine][errors]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  auto spec = test::linearSpring();
  spec.params["stiffnes"] = 1.0;
  REQUIRE_THROWS_WITH(sim.setInteraction(mud, mud, spec), Contains("'stiffnes'") && Contains("accept: stiffness"));
  spec.params.clear();
  spec.params["stiffness"] = -5.0;
  REQUIRE_THROWS_WITH(sim.setInteraction(mud, mud, spec),
                      Contains("'stiffness' = -5") && Contains("allowed range [0, 1e+12]"));
  REQUIRE_THROWS_WITH(sim.addMaterial(Material{"clay", 1500.0, 1e6, 0.7}), Contains("clay.poisson") && Contains("0.5"));
}

TEST_CASE("materials that meet without an interaction are reported", "[engine][errors]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  const int sand = sim.addMaterial(Material{"sand", 2600.0, 1e7, 0.3});
  auto spec = test::linearSpring();
  sim.setInteraction(mud, mud, spec);
  sim.addParticle(Vec3(0, 0, 0), 1e-3, mud);
  sim.addParticle(Vec3(1.9e-3, 0, 0), 1e-3, sand);
  REQUIRE_THROWS_WITH(sim.step(1), Contains("'mud' and 'sand'") || Contains("'sand' and 'mud'"));
}

TEST_CASE("an exploding contact is caught before it explodes", "[engine][errors][stability]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  auto spec = test::linearSpring(1e-3);  // far too soft for the impact speed
  sim.setInteraction(mud, mud, spec);
  sim.setGravity(Vec3::Zero());
  sim.addParticle(Vec3(-1.1e-3, 0, 0), 1e-3, mud, Vec3(5.0, 0, 0));
  sim.addParticle(Vec3(1.1e-3, 0, 0), 1e-3, mud, Vec3(-5.0, 0, 0));
  REQUIRE_THROWS_AS(sim.step(200), InstabilityError);
  Simulation again(test::testPlugins());
  try {
    const int m = again.addMaterial(test::mud());
    again.setInteraction(m, m, spec);
    again.setGravity(Vec3::Zero());
    again.addParticle(Vec3(-1.1e-3, 0, 0), 1e-3, m, Vec3(5.0, 0, 0));
    again.addParticle(Vec3(1.1e-3, 0, 0), 1e-3, m, Vec3(-5.0, 0, 0));
    again.step(200);
    FAIL("no instability reported");
  } catch (const InstabilityError& e) {
    REQUIRE_THAT(e.what(), Contains("% of the particle radius") && Contains("time step"));
    // The message names the two particles (their persistent ids 0 and 1), where they are and how fast.
    REQUIRE_THAT(e.what(), (Contains("particle 0 at (") && Contains("and particle 1 at (")) ||
                               (Contains("particle 1 at (") && Contains("and particle 0 at (")));
    REQUIRE_THAT(e.what(), Contains("m/s, radius 0.001 m"));
    // Caught at the step that crossed the 50 % threshold: the overlap is still below 80 %
    // of the radius (unchecked, the spheres would pass through each other).
    const auto& x = again.particles().position;
    REQUIRE(std::abs(x[1].x() - x[0].x()) > 2e-3 - 0.8e-3);
  }
}

TEST_CASE("a sphere pressed into a wall is caught and named with the wall", "[engine][errors][stability]") {
  // A far too soft contact: a sphere thrown at 5 m/s into a static floor, and a lid driven at
  // 5 m/s onto a sphere resting on that floor. The message must name the particle (persistent id,
  // position, speed, radius) and the wall by its name, not another wall or another particle.
  for (const bool moving_lid : {false, true}) {
    DYNAMIC_SECTION((moving_lid ? "a lid pressed onto a sphere" : "a sphere thrown into the floor")) {
      Simulation sim(test::testPlugins());
      const int mud = sim.addMaterial(test::mud());
      const int steel = sim.addMaterial(Material{"steel", 7800.0, 7e9, 0.3});
      auto spec = test::linearSpring(1e-3);
      sim.setInteraction(mud, mud, spec);
      sim.setInteraction(mud, steel, spec);
      sim.setGravity(Vec3::Zero());
      sim.addWall(std::make_unique<PlaneWall>("side wall", steel, Vec3(-0.05, 0, 0), Vec3::UnitX()));  // never touched
      sim.addWall(std::make_unique<PlaneWall>("paddy floor", steel, Vec3::Zero(), Vec3::UnitZ()));
      if (moving_lid)
        sim.addWall(std::make_unique<PlaneWall>("pressing lid", steel, Vec3(0.01, 0, 2.05e-3), -Vec3::UnitZ(),
                                                Vec3(0, 0, -5.0)));
      // id 0: a smaller sphere far aside under the lid, which the lid reaches only 0.95 mm later
      sim.addParticle(Vec3(0.02, 0.02, 0.6e-3), 0.5e-3, mud);
      sim.addParticle(Vec3(0.01, 0, moving_lid ? 1e-3 : 1.1e-3), 1e-3, mud,
                      moving_lid ? Vec3::Zero() : Vec3(0, 0, -5.0));  // id 1
      try {
        sim.step(2000);
        FAIL("no instability reported");
      } catch (const InstabilityError& e) {
        const std::string what = e.what();
        INFO(what);
        CHECK_THAT(what, Contains("% of the particle radius") && Contains("time step"));
        CHECK_THAT(what, Contains("particle 1 at (0.01, ") && Contains(" m, speed ") && Contains("m/s, radius 0.001 m"));
        CHECK_THAT(what, !Contains("particle 0"));
        if (moving_lid)  // the lid's overlap grows fastest: the sphere has barely started to move
          CHECK_THAT(what, Contains("wall 2 'pressing lid'"));
        else
          CHECK_THAT(what, Contains("wall 1 'paddy floor'"));
        CHECK_THAT(what, !Contains("side wall"));
        // Caught before the sphere went through the wall.
        CHECK(sim.particles().position[1].z() > 0.0);
      }
    }
  }
}

TEST_CASE("particles created overlapping are reported before the first step", "[engine][errors]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  auto spec = test::linearSpring();
  sim.setInteraction(mud, mud, spec);
  sim.addParticle(Vec3(4e-3, 0, 0), 1e-3, mud);  // apart from the others: not the pair named
  sim.addParticle(Vec3(0, 0, 0), 1e-3, mud);
  sim.addParticle(Vec3(0.5e-3, 0, 0), 1e-3, mud);
  // Named: the overlapping pair (ids 1 and 2) and where they are, not the lone sphere (id 0).
  REQUIRE_THROWS_WITH(sim.step(1), Contains("created overlapping") &&
                                       ((Contains("particle 1 at (0, 0, 0) m") && Contains("and particle 2 at (0.0005, 0, 0) m")) ||
                                        (Contains("particle 2 at (0.0005, 0, 0) m") && Contains("and particle 1 at (0, 0, 0) m"))));
}
