// The pair loop (forces.cpp) tests an owner's list slots in chunks of 64 before it evaluates the
// pairs in range. A large sphere among small ones owns more slots than one chunk: every contact
// of every chunk must be found with its force, and every pair that separates must forget its
// history, whichever chunk its slot is in.
#include "test_models.hpp"

#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

using namespace paddy;

namespace {
constexpr double kBig = 8e-3, kSmall = 1e-3, kOverlap = 2e-5, kGap = 1e-4;
// A soft spring: the contacts register with a force, but nothing moves by more than nanometres.
constexpr double kStiffness = 1e-3;
constexpr int kSmallCount = 150;  // slots 0–63, 64–127, 128–149 of the large sphere: three chunks

// Small sphere k (1-based, its id) touches the large one in an irregular pattern.
bool touches(int k) { return (k * 37) % 7 < 4; }

// Direction of small sphere k: a Fibonacci lattice on the unit sphere (neighbours 2.6 mm apart at
// the small spheres' centres, so they do not touch each other).
Vec3 direction(int k) {
  const double z = 1.0 - (2.0 * k - 1.0) / kSmallCount;
  const double phi = k * 2.399963229728653;  // golden angle
  const double s = std::sqrt(1.0 - z * z);
  return Vec3(s * std::cos(phi), s * std::sin(phi), z);
}

Vec3 place(int k, bool in_contact) {
  return (kBig + kSmall + (in_contact ? -kOverlap : kGap)) * direction(k);
}

std::unique_ptr<Simulation> cluster(int threads) {
  auto sim = std::make_unique<Simulation>(test::testPlugins());
  const int mud = sim->addMaterial(test::mud());
  auto spec = test::linearSpring(kStiffness);
  spec.extras = {"contact_age"};
  sim->setInteraction(mud, mud, spec);
  sim->setGravity(Vec3::Zero());
  sim->addParticle(Vec3::Zero(), kBig, mud);  // the smallest id: it owns all its pairs
  for (int k = 1; k <= kSmallCount; ++k) sim->addParticle(place(k, touches(k)), kSmall, mud);
  sim->setThreads(threads);
  return sim;
}

// Small sphere id → its contact with the large one (the large sphere has id 0).
std::map<std::uint64_t, ContactRecord> contactsOfBig(Simulation& sim) {
  std::map<std::uint64_t, ContactRecord> out;
  for (const auto& c : sim.contacts()) {
    REQUIRE_FALSE(c.wall);
    REQUIRE((c.id_i == 0 || c.id_j == 0));  // the small spheres do not touch each other
    if (c.fn > 0.0) out[c.id_i == 0 ? c.id_j : c.id_i] = c;
  }
  return out;
}

void moveTo(Simulation& sim, std::uint64_t id, const Vec3& x) {
  auto& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.id[i] == id) p.position[i] = x, p.velocity[i] = Vec3::Zero();
}
}  // namespace

TEST_CASE("an owner with more list slots than one chunk finds every contact and forgets every separated one",
          "[engine][neighbour][history]") {
  for (int threads : {1, 2}) {
    INFO(threads << " threads");
    auto sim = cluster(threads);
    // Every touching sphere of the three chunks is in contact, with the spring's force.
    auto found = contactsOfBig(*sim);
    int expected = 0, late = 0;
    for (int k = 1; k <= kSmallCount; ++k) {
      if (!touches(k)) {
        CHECK(found.count(static_cast<std::uint64_t>(k)) == 0);
        continue;
      }
      ++expected;
      late += k > 64 ? 1 : 0;
      REQUIRE(found.count(static_cast<std::uint64_t>(k)) == 1);
      CHECK(found[static_cast<std::uint64_t>(k)].fn == Approx(kStiffness * kOverlap).epsilon(1e-6));
    }
    REQUIRE(late > 40);  // contacts in the second and third chunks
    CHECK(static_cast<int>(found.size()) == expected);

    sim->step(20);
    const double dt = sim->timeStep();
    found = contactsOfBig(*sim);
    REQUIRE(static_cast<int>(found.size()) == expected);
    for (const auto& [id, c] : found) CHECK(c.history[0] == Approx(20 * dt).epsilon(1e-9));

    // Every third touching sphere leaves (out of range, still on the list: the gap is well
    // inside the skin) for one step and comes back: its contact starts again from zero age.
    std::vector<int> leaving;
    for (int k = 1, n = 0; k <= kSmallCount; ++k)
      if (touches(k) && n++ % 3 == 0) leaving.push_back(k);
    for (int k : leaving) moveTo(*sim, static_cast<std::uint64_t>(k), place(k, false));
    sim->step(1);
    for (int k : leaving) moveTo(*sim, static_cast<std::uint64_t>(k), place(k, true));
    sim->step(5);
    found = contactsOfBig(*sim);
    REQUIRE(static_cast<int>(found.size()) == expected);
    int restarted = 0, restarted_late = 0;
    for (const auto& [id, c] : found) {
      const bool left = std::find(leaving.begin(), leaving.end(), static_cast<int>(id)) != leaving.end();
      INFO("small sphere " << id);
      CHECK(c.history[0] == Approx((left ? 5 : 26) * dt).epsilon(1e-9));
      restarted += left ? 1 : 0;
      restarted_late += left && id > 64 ? 1 : 0;
    }
    CHECK(restarted == static_cast<int>(leaving.size()));
    CHECK(restarted_late > 10);
  }
}
