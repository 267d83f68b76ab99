// The walls' candidate lists between refreshes of the contact search: a wall contact must be found
// at the first step the sphere overlaps the wall, however far the sphere and the wall have moved
// towards each other since the last refresh (up to one skin together, the refresh rule of the time
// loop). A candidate range short of radius + largest gap + skin misses the contact at some phase
// of the refresh cycle.
#include "test_models.hpp"

#include <paddy/plane_wall.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

using namespace paddy;

TEST_CASE("a sphere and a wall closing on each other touch at the first step they overlap, whatever the "
          "phase of the contact search's refreshes", "[engine][walls]") {
  const double r = 1e-3, v = 0.05;  // sphere radius [m]; sphere and wall speed towards each other [m/s]
  const double skin = 0.4 * r;      // the default skin fraction
  int checked = 0;
  for (int phase = 0; phase < 24; ++phase) {
    Simulation sim(test::testPlugins());
    const auto [mud, steel] = test::mudAndSteelSprings(sim);
    // The floor rises at v, the sphere falls at v: the gap closes by 2 v per unit time while the
    // refreshes come every half skin of the sphere's travel, i.e. every skin of the gap.
    auto floor = std::make_unique<PlaneWall>("floor", steel, Vec3::Zero(), Vec3::UnitZ(), Vec3(0, 0, v));
    const PlaneWall* f = floor.get();
    sim.addWall(std::move(floor));
    const double gap0 = 2.0 * skin + skin * phase / 24.0;
    sim.addParticle(Vec3(0, 0, r + gap0), r, mud, Vec3(0, 0, -v));
    bool touched = false;
    for (int s = 0; s < 100000 && !touched; ++s) {
      sim.step(1);
      const double overlap = r - (sim.particles().position[0].z() - f->origin().z());
      if (std::abs(overlap) < 1e-9 * r) continue;  // at the rounding of the contact's own overlap
      std::size_t wall_contacts = 0;
      for (const auto& c : sim.contacts()) wall_contacts += c.wall ? 1 : 0;
      INFO("phase " << phase << ", step " << s << ", overlap " << overlap << " m");
      REQUIRE(wall_contacts == (overlap > 0.0 ? 1u : 0u));
      touched = overlap > 0.0;
      ++checked;
    }
    REQUIRE(touched);
  }
  REQUIRE(checked > 1000);
}
