// The particle–particle loop's owners split among the threads by their work (forces.cpp): list
// slots + 16 × pairs in range at the step before. Half the spheres here are packed in contact,
// half spaced within the list's skin but apart, so both halves have about the same list slots
// and very different work: a split by slots (the pass after a list build) leaves one thread
// several times the other's work, the split by work evens it out from the next pass on.
#include "test_models.hpp"

#include <paddy/plane_wall.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

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
      for (int j = 0; j < side; ++j) {
        // a jitter of up to 2e-4 r (fixed by the indices): no force cancels exactly by symmetry,
        // so a change in the order of a sum shows in the last bits
        const double e = 2e-4 * r * std::sin(1.0 + i * 7.1 + j * 3.3 + k * 5.7);
        sim.addParticle(Vec3(i * a + e, j * a - e, z0 + kk * a + 0.5 * e), r, mud);
      }
  }
}

// The two blocks above, without gravity (mudAndSteelSprings), on `threads` threads.
std::unique_ptr<Simulation> blocks(int threads) {
  auto sim = std::make_unique<Simulation>(test::testPlugins());
  fill(*sim, test::mudAndSteelSprings(*sim).first);
  sim->setThreads(threads);
  return sim;
}
}  // namespace

TEST_CASE("the owners' split evens the threads' work where contacts are uneven", "[engine][threads]") {
  auto sim = blocks(2);
  sim->step(1);  // the list build and the initial pass split by slots, the step's pass by work
  CHECK(imbalance(sim->pairWorkPerThread()) < 1.15);
  sim->step(5);
  CHECK(imbalance(sim->pairWorkPerThread()) < 1.15);

  // the same state split by slots: the first pass after a list build
  auto fresh = blocks(2);
  fresh->step(0);  // the initial pass only
  CHECK(imbalance(fresh->pairWorkPerThread()) > 2.0);

  auto one = blocks(1);
  one->step(1);
  CHECK(one->pairWorkPerThread().empty());
}

// The split comes from the pass before, so a checkpoint carries it: a run resumed between two list
// builds sums its forces in the same order as the run that was not stopped, bit for bit. A pile
// settling on a floor keeps its contacts (a checkpoint without the split gives another state).
TEST_CASE("a run resumed on two threads between list builds continues bit for bit", "[engine][threads][checkpoint]") {
  const auto dir = std::filesystem::temp_directory_path() / "paddy_test_owner_balance";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "state.h5").string();
  auto make = [] {
    auto sim = std::make_unique<Simulation>(test::testPlugins());
    const auto [mud, steel] = test::mudAndSteelSprings(*sim);
    sim->setGravity(Vec3(0, 0, -9.81));
    sim->addWall(std::make_unique<PlaneWall>("floor", steel, Vec3::Zero(), Vec3::UnitZ()));
    const double r = 1e-3;
    for (int k = 0; k < 16; ++k)
      for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) {
          const double e = 2e-4 * r * std::sin(1.0 + i * 7.1 + j * 3.3 + k * 5.7);
          sim->addParticle(Vec3(i * 1.998 * r + e, j * 1.998 * r - e, 0.999 * r + k * 1.998 * r + e), r, mud);
        }
    sim->setThreads(2);
    return sim;
  };
  auto full = make();
  full->step(400);
  for (int at : {200, 201, 203, 207}) {
    auto first = make();
    first->step(static_cast<std::uint64_t>(at));
    first->saveCheckpoint(path);
    auto resumed = make();
    resumed->loadCheckpoint(path);
    resumed->step(static_cast<std::uint64_t>(400 - at));
    INFO("checkpoint after step " << at << ", list builds " << first->neighbourListBuilds());
    const auto& p = full->particles();
    const auto& q = resumed->particles();
    REQUIRE(p.size() == q.size());
    bool same = true;
    for (std::size_t i = 0; i < p.size(); ++i) same = same && p.position[i] == q.position[i] && p.velocity[i] == q.velocity[i];
    CHECK(same);
  }
  REQUIRE(full->contacts().size() > 500);
  std::filesystem::remove_all(dir);
}

// The per-particle loops (the kicks and drift, the velocity prediction, the force reduction) run
// over each thread's owners, which here split the particles very unevenly (the dense block's
// owners cost several times the loose one's). Every particle must be moved and summed exactly
// once: on 2 and 3 threads the blocks falling under gravity follow the 1-thread run to rounding
// (a particle left out of a thread's range, or moved twice, is off by g t² or by its velocity ×
// dt after one step: millimetres, against the 1e-9 r allowed).
TEST_CASE("every particle is moved and summed once on an uneven owners' split", "[engine][threads]") {
  auto run = [](int threads) {
    auto sim = blocks(threads);
    sim->setGravity(Vec3(0, 0, -9.81));
    sim->step(60);
    return sim;
  };
  const auto one = run(1);
  for (int threads : {2, 3}) {
    const auto many = run(threads);
    INFO(threads << " threads");
    if (threads == 2) CHECK(imbalance(many->pairWorkPerThread()) < 1.15);  // the split by work is in use
    const auto& p = one->particles();
    const auto& q = many->particles();
    REQUIRE(p.size() == q.size());
    double worst = 0.0, moved = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      REQUIRE(p.id[i] == q.id[i]);
      worst = std::max(worst, (p.position[i] - q.position[i]).norm());
      worst = std::max(worst, (p.velocity[i] - q.velocity[i]).norm() * 1e-3);  // m/s × 1 ms
      moved = std::max(moved, std::abs(q.velocity[i].z()));
    }
    CHECK(worst < 1e-9 * 1e-3);
    CHECK(moved > 1e-3);  // the blocks did fall (60 steps of g)
  }
}
