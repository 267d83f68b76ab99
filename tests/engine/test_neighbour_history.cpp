#include "test_models.hpp"

#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <set>

using namespace paddy;

namespace {
InteractionSpec springWithAge() {
  auto spec = test::linearSpring();
  spec.extras = {"contact_age"};
  return spec;
}
}  // namespace

TEST_CASE("the neighbour list finds exactly the overlapping pairs (brute force)", "[engine][neighbour]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  sim.setInteraction(mud, mud, springWithAge());
  sim.setGravity(Vec3::Zero());
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(0.0, 0.02), rad(0.4e-3, 1.2e-3);
  for (int k = 0; k < 600; ++k) sim.addParticle(Vec3(pos(rng), pos(rng), pos(rng)), rad(rng), mud);
  // Separate strongly overlapping pairs so the configuration is admissible.
  const auto& p = sim.particles();
  std::vector<bool> drop(p.size(), false);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      if (!drop[i] && !drop[j] && (p.position[i] - p.position[j]).norm() < 0.7 * (p.radius[i] + p.radius[j])) drop[j] = true;
  sim.removeParticles([&](std::size_t i) { return drop[i]; });

  std::set<std::pair<std::uint64_t, std::uint64_t>> expected;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j)
      if (p.id[i] < p.id[j] && (p.position[i] - p.position[j]).norm() < p.radius[i] + p.radius[j])
        expected.insert({p.id[i], p.id[j]});
  std::set<std::pair<std::uint64_t, std::uint64_t>> found;
  for (const auto& c : sim.contacts()) {
    REQUIRE_FALSE(c.wall);
    found.insert({std::min(c.id_i, c.id_j), std::max(c.id_i, c.id_j)});
  }
  REQUIRE(expected.size() > 50);
  REQUIRE(found == expected);
}

TEST_CASE("contact history survives neighbour-list rebuilds and spatial re-sorting", "[engine][neighbour][history]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  auto spec = springWithAge();
  spec.params["stiffness"] = 0.0;  // contacts register but exert no force: the lattice stays put
  sim.setInteraction(mud, mud, spec);
  sim.setGravity(Vec3::Zero());
  sim.setSkinFraction(0.05);  // rebuild every few steps
  sim.setSortInterval(1);     // and re-sort at every rebuild
  // A simple cubic lattice with overlapping neighbours, inserted in shuffled order, all
  // translating together: the contact set never changes, so each contact's age must equal the
  // elapsed time exactly as if no rebuild had happened.
  const double r = 1e-3, spacing = 1.98e-3;
  std::vector<Vec3> sites;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 8; ++k) sites.emplace_back(i * spacing, j * spacing, k * spacing);
  std::shuffle(sites.begin(), sites.end(), std::mt19937_64(3));
  const Vec3 v(0.3, -0.2, 0.1);
  for (const auto& x : sites) sim.addParticle(x, r, mud, v);
  // The lattice moving as one does not make the list stale (the builds follow relative motion):
  // a lone sphere well away from it, moving the other way, does.
  sim.addParticle(Vec3(-20e-3, -20e-3, -20e-3), r, mud, -v);
  sim.step(300);
  REQUIRE(sim.neighbourListBuilds() > 50);
  const auto contacts = sim.contacts();
  REQUIRE(contacts.size() == 3u * 7u * 8u * 8u);  // lattice bonds
  for (const auto& c : contacts) {
    REQUIRE(c.history.size() == 2);
    REQUIRE(c.history[0] == Approx(sim.time()).epsilon(1e-9));
  }
}

TEST_CASE("history is forgotten when a contact ends and starts again", "[engine][history]") {
  Simulation sim(test::testPlugins());
  const int mud = sim.addMaterial(test::mud());
  auto spec = springWithAge();
  spec.params["stiffness"] = 50.0;
  sim.setInteraction(mud, mud, spec);
  sim.setGravity(Vec3::Zero());
  // Two spheres collide, separate and fly apart; then we bring them back for a second touch.
  sim.addParticle(Vec3(-1.5e-3, 0, 0), 1e-3, mud, Vec3(0.01, 0, 0));
  sim.addParticle(Vec3(1.5e-3, 0, 0), 1e-3, mud, Vec3(-0.01, 0, 0));
  double in_contact = 0.0;
  bool touched = false;
  for (int s = 0; s < 20000; ++s) {
    sim.step(1);
    const auto c = sim.contacts();
    if (!c.empty() && c[0].fn > 0.0) {
      in_contact += sim.timeStep();
      touched = true;
      REQUIRE(c[0].history[0] == Approx(in_contact).epsilon(1e-9));
    } else if (touched) {
      break;
    }
  }
  REQUIRE(touched);
  // Fly apart well beyond the skin, then reverse both velocities for a second contact.
  sim.run(0.3);
  REQUIRE(sim.contacts().empty());
  for (auto& v : sim.particles().velocity) v = -v;
  double second = 0.0;
  bool again = false;
  for (int s = 0; s < 200000 && !again; ++s) {
    sim.step(1);
    const auto c = sim.contacts();
    if (!c.empty() && c[0].fn > 0.0) {
      second += sim.timeStep();
      again = true;
      REQUIRE(c[0].history[0] == Approx(second).epsilon(1e-9));  // restarted from zero
    }
  }
  REQUIRE(again);
}
