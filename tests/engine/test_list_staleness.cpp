// When the particle neighbour list is stale. A pair left out of the list at its build was farther
// apart than its range + skin, so it can reach contact only after the two particles have closed by
// more than the skin. The list must be rebuilt before that, whatever else refreshes the contact
// search in between (the walls' candidate lists are refreshed on their own when a wall moves),
// and it need not be rebuilt while the particles move together (a falling pour).
#include "test_models.hpp"

#include <paddy/plane_wall.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

using namespace paddy;

namespace {

struct PairRun {
  int checked = 0;   // steps at which the pair's contact was checked
  bool touched = false;
  std::size_t builds = 0;  // neighbour-list builds and wall refreshes until the first touch
};

// Two spheres on the x axis closing on each other at v each, both also drifting at `drift` along
// x; optionally a plane wall far below them moving away at wall_speed (it never touches them, but
// its motion refreshes the walls' candidate lists between the list's builds). Steps until the
// spheres overlap and checks at every step that the contact is listed exactly when they overlap.
PairRun closingPair(double gap0, double v, double drift, double wall_speed) {
  const double r = 1e-3;
  Simulation sim(test::testPlugins());
  const auto [mud, steel] = test::mudAndSteelSprings(sim);
  if (wall_speed > 0.0)
    sim.addWall(std::make_unique<PlaneWall>("floor", steel, Vec3(0, 0, -0.1), Vec3::UnitZ(), Vec3(0, 0, -wall_speed)));
  sim.addParticle(Vec3(-r - 0.5 * gap0, 0, 0), r, mud, Vec3(drift + v, 0, 0));
  sim.addParticle(Vec3(r + 0.5 * gap0, 0, 0), r, mud, Vec3(drift - v, 0, 0));
  PairRun run;
  for (int s = 0; s < 100000 && !run.touched; ++s) {
    sim.step(1);
    const auto& x = sim.particles().position;
    const double overlap = 2.0 * r - (x[1] - x[0]).norm();
    if (std::abs(overlap) < 1e-9 * r) continue;  // at the rounding of the contact's own overlap
    std::size_t pair_contacts = 0;
    for (const auto& c : sim.contacts()) pair_contacts += c.wall ? 0 : 1;
    INFO("gap " << gap0 << " m, step " << s << ", overlap " << overlap << " m");
    REQUIRE(pair_contacts == (overlap > 0.0 ? 1u : 0u));
    run.touched = overlap > 0.0;
    ++run.checked;
  }
  run.builds = sim.neighbourListBuilds();
  return run;
}

}  // namespace

TEST_CASE("two spheres closing on each other touch at the first step they overlap while a moving wall "
          "refreshes the walls' candidate lists in between", "[engine][neighbour]") {
  // The wall moves 1.1 times as fast as each sphere: the walls' lists go stale (a sphere and the
  // wall together one skin) just before the particle list would (each sphere half a skin), and are
  // refreshed alone. Counting the particle list's staleness from that refresh instead of from its
  // build let the spheres close by almost two skins unseen; gaps of 1–2 skins catch it.
  const double r = 1e-3, skin = 0.4 * r, v = 0.05;
  int checked = 0;
  for (int phase = 0; phase < 24; ++phase) {
    const double gap0 = skin * (1.02 + 0.96 * phase / 23.0);
    const PairRun run = closingPair(gap0, v, 0.0, 1.1 * v);
    REQUIRE(run.touched);
    checked += run.checked;
  }
  REQUIRE(checked > 1000);
}

TEST_CASE("particles moving together do not make the neighbour list stale: the builds follow the "
          "relative motion, not the drift", "[engine][neighbour]") {
  const double r = 1e-3, skin = 0.4 * r, v = 0.05;
  for (int phase = 0; phase < 8; ++phase) {
    const double gap0 = skin * (1.5 + 2.0 * phase / 7.0);
    const PairRun still = closingPair(gap0, v, 0.0, 0.0);
    // A common drift 20 times the closing speed: the spheres travel tens of skins before they
    // touch, which the largest displacement alone (2 max|Δx| > skin) would answer with a build
    // every half skin of travel.
    const PairRun drifting = closingPair(gap0, v, 20.0 * v, 0.0);
    REQUIRE(still.touched);
    REQUIRE(drifting.touched);
    INFO("gap " << gap0 << " m: builds " << still.builds << " still, " << drifting.builds << " drifting");
    REQUIRE(drifting.builds == still.builds);
    // One build at the start and one per skin the spheres close by (the list's own rule).
    REQUIRE(still.builds <= 2 + static_cast<std::size_t>(gap0 / skin));
  }
}
