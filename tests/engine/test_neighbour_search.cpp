// The neighbour list's pair search against a brute-force search over all pairs (white box: the
// list is engine-internal, engine/core/src/neighbour_list.hpp). The list must hold exactly the
// pairs with |x_i − x_j| < R_i + R_j + maxSeparation(R*) + skin, once each under the smaller id,
// in partner-id order, whatever the search's cells: polydisperse spheres, pair laws of different
// reach, spheres on the cells' boundaries, far from the origin, flung far apart (the grid grows
// its cells), in a flat layer, and on any number of threads.
#include "test_models.hpp"

#include "../../engine/core/src/contact_law.hpp"
#include "../../engine/core/src/neighbour_list.hpp"

#include <catch2/catch.hpp>

#include <limits>
#include <random>
#include <set>
#include <tuple>

using namespace paddy;

namespace {

// An extra that acts across a gap of `gap_per_radius` × R* (does nothing else): a pair law whose
// reach grows with the pair's effective radius, as a liquid bridge's does.
class GapReach final : public SubModel {
 public:
  explicit GapReach(double k) : k_(k) {}
  double maxSeparation(double r_eff) const override { return k_ * r_eff; }
  void compute(ContactBatch&, std::size_t) const override {}

 private:
  double k_;
};

std::shared_ptr<PluginManager> plugins() {
  auto pm = test::testPlugins();
  SubModelInfo gap;
  gap.name = "gap_reach";
  gap.kind = SubModelKind::Extra;
  gap.params = {{"gap_per_radius", 0.5, 0.0, 10.0, "-", "reach beyond contact / R*", false, 0.0, "test only"}};
  gap.create = [](const ParamValues& p, const MaterialPair&) { return std::make_unique<GapReach>(p.at("gap_per_radius")); };
  gap.provides = kRangeBeyondContact;
  pm->addSubModel(gap);
  return pm;
}

// Two materials: a–a and b–b plain springs, a–b with a gap reach of 0.5 R*.
struct Laws {
  std::shared_ptr<PluginManager> pm = plugins();
  std::vector<Material> materials{test::mud(), Material{"clay", 1800.0, 2e6, 0.45}};
  std::vector<ContactLaw> laws;
  std::vector<int> index;  // law of material pair (a, b): index[a * 2 + b]
  Laws() {
    const InteractionSpec plain = test::linearSpring();
    InteractionSpec reach = test::linearSpring();
    reach.extras = {"gap_reach"};
    reach.params["gap_per_radius"] = 0.5;
    laws.emplace_back(*pm, plain, MaterialPair::of(materials[0], materials[0]));
    laws.emplace_back(*pm, plain, MaterialPair::of(materials[1], materials[1]));
    laws.emplace_back(*pm, reach, MaterialPair::of(materials[0], materials[1]));
    index = {0, 2, 2, 1};
  }
};

ParticleArrays particles(const std::vector<Vec3>& x, const std::vector<double>& r, std::mt19937_64& rng) {
  ParticleArrays p;
  const std::size_t n = x.size();
  // Ids shuffled against the storage order (as after a spatial sort), materials mixed.
  std::vector<std::uint64_t> ids(n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = 3 * i + 1;
  std::shuffle(ids.begin(), ids.end(), rng);
  for (std::size_t i = 0; i < n; ++i) {
    p.id.push_back(ids[i]);
    p.material.push_back(static_cast<int>(rng() % 2));
    p.radius.push_back(r[i]);
    p.mass.push_back(1.0);
    p.inertia.push_back(1.0);
    p.position.push_back(x[i]);
    for (auto* v : {&p.velocity, &p.omega, &p.force, &p.torque}) v->push_back(Vec3::Zero());
    p.resisting_torque.push_back(0.0);
  }
  return p;
}

using Slot = std::tuple<std::uint64_t, std::uint64_t, int, double>;  // owner id, partner id, law, range²

// Every pair within reach, by brute force, with the list's own arithmetic.
std::set<Slot> bruteForce(const ParticleArrays& p, const Laws& L, double skin) {
  std::set<Slot> out;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (p.id[j] <= p.id[i]) continue;
      const int law = L.index[static_cast<std::size_t>(p.material[i] * 2 + p.material[j])];
      const double ri = p.radius[i], rj = p.radius[j];
      const double reach = ri + rj + L.laws[static_cast<std::size_t>(law)].maxSeparation(ri * rj / (ri + rj));
      const double reach_skin = reach + skin;
      if ((p.position[i] - p.position[j]).squaredNorm() < reach_skin * reach_skin) out.insert({p.id[i], p.id[j], law, reach * reach});
    }
  return out;
}

// The list's slots, checked for order and consistency on the way.
std::set<Slot> listed(const ParticleArrays& p, const Laws& L, double skin, int threads, std::size_t* count) {
  NeighbourList list;
  const std::vector<std::size_t> prev(p.size(), std::numeric_limits<std::size_t>::max());
  list.build(p, prev, skin, 0, L.laws, L.index, L.materials, threads);
  std::set<Slot> out;
  REQUIRE(list.start.size() == p.size() + 1);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t k = list.start[i]; k < list.start[i + 1]; ++k) {
      const std::uint32_t j = list.partner[k];
      REQUIRE(list.partner_id[k] == p.id[j]);
      if (k > list.start[i]) REQUIRE(list.partner_id[k - 1] < list.partner_id[k]);  // sorted, no repeats
      out.insert({p.id[i], p.id[j], list.law[k], list.range2[k]});
    }
  *count = list.slots();
  return out;
}

void checkAgainstBruteForce(const std::vector<Vec3>& x, const std::vector<double>& r, std::uint64_t seed,
                            std::size_t min_pairs) {
  Laws L;
  std::mt19937_64 rng(seed);
  const ParticleArrays p = particles(x, r, rng);
  double rmax = 0.0;
  for (double v : r) rmax = std::max(rmax, v);
  for (double skin_fraction : {0.0, 0.05, 0.4, 1.5}) {
    const double skin = skin_fraction * rmax;
    const std::set<Slot> expected = bruteForce(p, L, skin);
    INFO("skin " << skin_fraction << " R_max, " << p.size() << " spheres, seed " << seed);
    if (skin_fraction == 1.5) REQUIRE(expected.size() >= min_pairs);  // the case has pairs to find
    for (int threads : {1, 2, 3}) {
      INFO(threads << " threads");
      std::size_t count = 0;
      const std::set<Slot> found = listed(p, L, skin, threads, &count);
      CHECK(count == found.size());  // no pair twice
      CHECK(found == expected);
    }
  }
}

}  // namespace

TEST_CASE("the list's search finds exactly the pairs within reach + skin (random polydisperse spheres)",
          "[engine][neighbour]") {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(-0.01, 0.01), rad(0.2e-3, 1.5e-3);
    std::vector<Vec3> x;
    std::vector<double> r;
    for (int k = 0; k < 1500; ++k) {
      x.emplace_back(pos(rng), pos(rng), pos(rng));
      r.push_back(rad(rng));
    }
    checkAgainstBruteForce(x, r, seed, 500);
  }
}

TEST_CASE("the list's search holds pairs across the cells' boundaries: a lattice at the cells' spacing, far from the origin",
          "[engine][neighbour]") {
  // Equal spheres on a cubic lattice: with skin s the cells are 2R + 0.5 R*·(a–b law) + s wide,
  // a quarter of that along x; lattice spacings equal to a cell and to a quarter cell put spheres
  // on the cells' faces, and the offset puts the whole far from the origin (rounding of the
  // coordinates). Pairs at exactly the reach are outside it (strict <) in both searches.
  const double R = 1e-3;
  for (double offset : {0.0, 1000.0, -37.5}) {
    for (double spacing : {2.0 * R + 0.25 * R + 0.4 * R, (2.0 * R + 0.25 * R + 0.4 * R) / 4.0 + 1e-4, 1.9 * R}) {
      std::vector<Vec3> x;
      std::vector<double> r;
      for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j)
          for (int k = 0; k < 9; ++k) {
            x.emplace_back(offset + i * spacing, offset - j * spacing, k * spacing);
            r.push_back(R);
          }
      checkAgainstBruteForce(x, r, 11, 200);
    }
  }
}

TEST_CASE("the list's search with spheres flung far apart, in a flat layer and in a line", "[engine][neighbour]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> pos(0.0, 0.01), rad(0.5e-3, 1.0e-3);
  // A cluster and a few spheres kilometres away: the grid's cell count is capped, its cells grow.
  std::vector<Vec3> x;
  std::vector<double> r;
  for (int k = 0; k < 800; ++k) {
    x.emplace_back(pos(rng), pos(rng), pos(rng));
    r.push_back(rad(rng));
  }
  x.emplace_back(3000.0, -2000.0, 500.0), r.push_back(1e-3);
  x.emplace_back(3000.0005, -2000.0, 500.0), r.push_back(1e-3);  // a pair far out
  checkAgainstBruteForce(x, r, 5, 300);
  // A flat layer (one cell high) and a line along x (one row of cells).
  std::vector<Vec3> layer, line;
  std::vector<double> r_layer, r_line;
  for (int k = 0; k < 900; ++k) {
    layer.emplace_back(pos(rng) * 3.0, pos(rng) * 3.0, 0.0);
    r_layer.push_back(rad(rng));
    line.emplace_back(pos(rng) * 20.0, 0.0, 0.0);
    r_line.push_back(rad(rng));
  }
  checkAgainstBruteForce(layer, r_layer, 6, 300);
  checkAgainstBruteForce(line, r_line, 7, 300);
}
