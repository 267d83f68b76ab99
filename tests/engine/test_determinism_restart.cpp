#include "test_models.hpp"

#include <paddy/plane_wall.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>

using namespace paddy;

namespace {
// A few hundred spheres dropped on a floor: contacts form, break, lists are rebuilt and sorted.
// With `receding_lid`, a plane wall above the spheres moves up and away at 2 m/s (like the slump
// test's hopper once emptied): it never touches them, but it moves past the skin every few steps, so
// the contact search is refreshed often with the particle list still valid (walls alone refreshed).
// With `count_evaluations`, the contacts also count in their history how often they were evaluated.
std::unique_ptr<Simulation> makeGranularGas(int threads, bool receding_lid = false, bool count_evaluations = false) {
  auto sim = std::make_unique<Simulation>(test::testPlugins());
  const int mud = sim->addMaterial(test::mud());
  const int steel = sim->addMaterial(Material{"steel", 7800.0, 7e9, 0.3});
  auto spec = test::linearSpring();
  spec.extras = {"contact_age"};
  if (count_evaluations) spec.extras.push_back("evaluation_count");
  spec.params["stiffness"] = 200.0;
  sim->setInteraction(mud, mud, spec);
  sim->setInteraction(mud, steel, spec);
  sim->addWall(std::make_unique<PlaneWall>("floor", steel, Vec3::Zero(), Vec3::UnitZ()));
  if (receding_lid)
    sim->addWall(std::make_unique<PlaneWall>("lid", steel, Vec3(0, 0, 0.03), -Vec3::UnitZ(), Vec3(0, 0, 2.0)));
  sim->setThreads(threads);
  sim->setSortInterval(3);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> jitter(-0.2e-3, 0.2e-3), vel(-0.05, 0.05);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 6; ++k)
        sim->addParticle(Vec3(i * 2.5e-3 + jitter(rng), j * 2.5e-3 + jitter(rng), 1.5e-3 + k * 2.5e-3 + jitter(rng)),
                         0.9e-3 + 0.2e-3 * ((i + j + k) % 3) / 2.0, mud, Vec3(vel(rng), vel(rng), vel(rng)));
  return sim;
}

bool sameState(const Simulation& a, const Simulation& b) {
  const auto& p = a.particles();
  const auto& q = b.particles();
  if (p.size() != q.size()) return false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.id[i] != q.id[i]) return false;
    if (p.position[i] != q.position[i] || p.velocity[i] != q.velocity[i] || p.omega[i] != q.omega[i]) return false;
  }
  return a.time() == b.time() && a.stepCount() == b.stepCount();
}
}  // namespace

TEST_CASE("same set-up and thread count give bitwise identical results", "[engine][determinism]") {
  for (int threads : {1, 2}) {
    auto a = makeGranularGas(threads);
    auto b = makeGranularGas(threads);
    a->step(1500);
    b->step(1500);
    REQUIRE(a->neighbourListBuilds() > 3);
    REQUIRE(sameState(*a, *b));
  }
}

TEST_CASE("a restarted run reproduces the uninterrupted run bit for bit", "[engine][checkpoint]") {
  const auto dir = std::filesystem::temp_directory_path() / "paddy_test_restart";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "state.h5").string();
  for (int threads : {1, 2}) {
    auto full = makeGranularGas(threads);
    full->step(1200);

    auto first = makeGranularGas(threads);
    first->step(600);
    first->saveCheckpoint(path);
    auto resumed = makeGranularGas(threads);
    resumed->loadCheckpoint(path);
    REQUIRE(sameState(*first, *resumed));
    resumed->step(600);
    REQUIRE(full->contacts().size() > 20);
    REQUIRE(sameState(*full, *resumed));
    // The floor's load is part of the state too.
    REQUIRE(full->wall(0).force() == resumed->wall(0).force());
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("walls refreshed apart from the particle list: a wall moving away changes nothing, and a restart "
          "reproduces the run bit for bit", "[engine][checkpoint][walls]") {
  const auto dir = std::filesystem::temp_directory_path() / "paddy_test_restart_lid";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "state.h5").string();
  for (int threads : {1, 2}) {
    // The lid never touches a sphere, but it makes the contact search refresh far more often.
    auto still = makeGranularGas(threads);
    still->step(1200);
    auto full = makeGranularGas(threads, true);
    full->step(1200);
    REQUIRE(full->neighbourListBuilds() > still->neighbourListBuilds() + 10);
    REQUIRE(full->wall(1).force() == Vec3::Zero());

    // Restart from a state saved after walls-only refreshes.
    auto first = makeGranularGas(threads, true);
    first->step(600);
    first->saveCheckpoint(path);
    auto resumed = makeGranularGas(threads, true);
    resumed->loadCheckpoint(path);
    REQUIRE(sameState(*first, *resumed));
    resumed->step(600);
    REQUIRE(sameState(*full, *resumed));
    REQUIRE(full->wall(0).force() == resumed->wall(0).force());
  }
  std::filesystem::remove_all(dir);
}

TEST_CASE("asking for the contacts between steps changes neither the run nor the stored contact history",
          "[engine][history][walls]") {
  for (int threads : {1, 2}) {
    auto asked = makeGranularGas(threads, false, true);
    auto plain = makeGranularGas(threads, false, true);
    std::size_t asked_records = 0;
    for (int s = 0; s < 400; ++s) {
      asked->step(1);
      asked_records += asked->contacts().size();  // a dry pass after every step
    }
    plain->step(400);
    REQUIRE(asked_records > 1000);
    REQUIRE(sameState(*asked, *plain));
    const auto a = asked->contacts(), p = plain->contacts();
    REQUIRE(a.size() == p.size());
    bool wall_seen = false;
    for (std::size_t k = 0; k < a.size(); ++k) {
      wall_seen = wall_seen || a[k].wall;
      REQUIRE(a[k].id_i == p[k].id_i);
      REQUIRE(a[k].id_j == p[k].id_j);
      REQUIRE(a[k].wall == p[k].wall);
      REQUIRE(a[k].history == p[k].history);  // the evaluation count of the steps alone
      REQUIRE(a[k].history[2] <= 400.0);
    }
    REQUIRE(wall_seen);
  }
}
