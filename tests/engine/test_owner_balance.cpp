// The particle–particle loop's owners split among the threads by their work (forces.cpp): list
// slots + 16 × pairs in range at the step before. Half the spheres here are packed in contact,
// half spaced within the list's skin but apart, so both halves have about the same list slots
// and very different work: a split by slots (the pass after a list build) leaves one thread
// several times the other's work, the split by work evens it out from the next pass on.
#include "test_models.hpp"

#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <algorithm>

using namespace paddy;

namespace {
double imbalance(const std::vector<std::uint64_t>& work) {
  REQUIRE(work.size() == 2);
  const auto [lo, hi] = std::minmax(work[0], work[1]);
  REQUIRE(lo > 0);
  return static_cast<double>(hi) / static_cast<double>(lo);
}

void fill(Simulation& sim, int mud) {
  const double r = 1e-3;
  const int side = 12;
  // dense block (spacing 1.999 r: every neighbour in contact) below a loose one (2.2 r: within
  // the skin of 0.4 r, not in contact), one above the other along z
  for (int k = 0; k < 2 * side; ++k) {
    const bool dense = k < side;
    const double a = dense ? 1.999 * r : 2.2 * r;
    const double z0 = dense ? 0.0 : side * 1.999 * r + 0.5 * r;
    const int kk = dense ? k : k - side;
    for (int i = 0; i < side; ++i)
      for (int j = 0; j < side; ++j) sim.addParticle(Vec3(i * a, j * a, z0 + kk * a), r, mud);
  }
}
}  // namespace

TEST_CASE("the owners' split evens the threads' work where contacts are uneven", "[engine][threads]") {
  Simulation sim(test::testPlugins());
  const auto [mud, steel] = test::mudAndSteelSprings(sim);
  (void)steel;
  sim.setGravity(Vec3::Zero());
  fill(sim, mud);
  sim.setThreads(2);
  sim.step(1);  // the list build and the initial pass split by slots, the step's pass by work
  const auto after = sim.pairWorkPerThread();
  CHECK(imbalance(after) < 1.15);
  sim.step(5);
  CHECK(imbalance(sim.pairWorkPerThread()) < 1.15);

  // the same state split by slots: the first pass after a list build
  Simulation fresh(test::testPlugins());
  const auto [mud2, steel2] = test::mudAndSteelSprings(fresh);
  (void)steel2;
  fresh.setGravity(Vec3::Zero());
  fill(fresh, mud2);
  fresh.setThreads(2);
  fresh.step(0);  // the initial pass only
  CHECK(imbalance(fresh.pairWorkPerThread()) > 2.0);

  Simulation one(test::testPlugins());
  const auto [mud1, steel1] = test::mudAndSteelSprings(one);
  (void)steel1;
  one.setGravity(Vec3::Zero());
  fill(one, mud1);
  one.step(1);
  CHECK(one.pairWorkPerThread().empty());
}
