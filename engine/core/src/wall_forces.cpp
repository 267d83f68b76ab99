// Particle–wall contacts: gather them from the walls, order them by (particle id, wall, key) and
// match each to its stored history (merge of two sorted lists).
//
// The order is taken every step, so it is a radix sort on one 64-bit key per contact,
//   sort_key = (rank(id) · n_walls + wall) · 2^32 + key,
// with rank(id) the place of the particle's id among all ids (ranked at list builds): the same
// order as comparing (id, wall, key), in a few linear passes instead of a comparison sort.
#include "simulation_impl.hpp"

#include <paddy/errors.hpp>

#include <algorithm>
#include <array>
#include <numeric>
#include <tuple>

namespace paddy {

namespace {
auto keyOf(const WallContactState& s) { return std::make_tuple(s.particle_id, s.wall, s.key); }

// Stable LSD radix sort by sort_key, a byte a pass; bytes in which all keys agree are skipped.
template <class Order>
void radixSort(std::vector<Order>& a, std::vector<Order>& tmp) {
  std::uint64_t any = 0, all = ~std::uint64_t{0};
  for (const auto& e : a) any |= e.sort_key, all &= e.sort_key;
  const std::uint64_t varying = any ^ all;
  tmp.resize(a.size());
  for (int shift = 0; shift < 64; shift += 8) {
    if (((varying >> shift) & 0xffu) == 0) continue;
    std::array<std::size_t, 257> start{};
    for (const auto& e : a) ++start[((e.sort_key >> shift) & 0xffu) + 1];
    for (std::size_t b = 0; b < 256; ++b) start[b + 1] += start[b];
    for (const auto& e : a) tmp[start[(e.sort_key >> shift) & 0xffu]++] = e;
    a.swap(tmp);
  }
}
}  // namespace

void Simulation::Impl::rankIds(const ParticleArrays& p) {
  const std::size_t n = p.size();
  if (id_rank.size() == n && id_rank_ids == p.id) return;
  std::vector<std::uint32_t> by_id(n);
  std::iota(by_id.begin(), by_id.end(), std::uint32_t{0});
  std::sort(by_id.begin(), by_id.end(), [&](std::uint32_t a, std::uint32_t b) { return p.id[a] < p.id[b]; });
  id_rank.resize(n);
  for (std::size_t r = 0; r < n; ++r) id_rank[by_id[r]] = static_cast<std::uint32_t>(r);
  id_rank_ids = p.id;
}

void Simulation::Impl::collectWallContacts(Simulation& s, double max_gap, std::vector<double>& history_out) {
  const ParticleArrays& p = s.p_;
  const int nmat = static_cast<int>(s.materials_.size());
  ParticleView view{p.size(), p.position.data(), p.radius.data(), s.threads_};
  // Scratch buffers are members: no allocation once they have grown to the step's size.
  std::vector<WallContact>& found = wall_scratch_found;
  std::vector<WallContact>& tmp = wall_scratch_tmp;
  std::vector<WallContactOrder>& order = wall_scratch_order;
  found.clear();
  order.clear();
  if (id_rank.size() != p.size()) rankIds(p);  // ranked at every list build (rebuild)
  const std::uint64_t n_walls = s.walls_.size();
  // The largest gap of the contact's law for its particle's radius, computed again only when the
  // law or the radius differs from the previous contact's (once for a monodisperse fill).
  int gap_law = -1;
  double gap_radius = 0.0, gap = 0.0;
  for (std::size_t w = 0; w < s.walls_.size(); ++w) {
    tmp.clear();
    s.walls_[w]->findContacts(view, max_gap, tmp);
    for (const auto& c : tmp) {
      const int law = law_index[static_cast<std::size_t>(p.material[c.particle] * nmat + s.walls_[w]->material())];
      if (law < 0)
        throw InputError("no interaction is defined between materials '" + s.materials_[p.material[c.particle]].name +
                         "' and '" + s.materials_[s.walls_[w]->material()].name + "' (wall '" +
                         s.walls_[w]->name() + "')");
      const double radius = p.radius[c.particle];
      if (law != gap_law || radius != gap_radius) {
        gap_law = law;
        gap_radius = radius;
        gap = laws[static_cast<std::size_t>(law)].maxSeparation(radius);
      }
      if (c.overlap < -gap) continue;
      const std::uint64_t major = std::uint64_t{id_rank[c.particle]} * n_walls + w;
      order.push_back({(major << 32) | c.key, p.id[c.particle], static_cast<std::uint32_t>(w), c.key,
                       static_cast<std::uint32_t>(found.size())});
      found.push_back(c);
    }
  }
  // Order by (particle id, wall, key). The packed key holds rank · n_walls + wall in 32 bits
  // (fewer than 2^32 / n_walls particles); beyond that, a comparison sort on the fields.
  if (static_cast<std::uint64_t>(p.size()) * std::max<std::uint64_t>(n_walls, 1) < (std::uint64_t{1} << 32)) {
    radixSort(order, wall_scratch_order_tmp);
  } else {
    std::sort(order.begin(), order.end(), [](const WallContactOrder& a, const WallContactOrder& b) {
      if (a.particle_id != b.particle_id) return a.particle_id < b.particle_id;
      if (a.wall != b.wall) return a.wall < b.wall;
      return a.key < b.key;
    });
  }
  wall_found.resize(found.size());
  wall_of_found.resize(found.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    wall_found[k] = found[order[k].index];
    wall_of_found[k] = order[k].wall;
  }

  const std::size_t stride = history_stride;
  history_out.assign(wall_found.size() * stride, 0.0);
  if (stride == 0) return;
  std::size_t o = 0;
  for (std::size_t k = 0; k < wall_found.size(); ++k) {
    const auto key = std::make_tuple(order[k].particle_id, order[k].wall, order[k].key);
    while (o < wall_state.size() && keyOf(wall_state[o]) < key) ++o;
    if (o < wall_state.size() && keyOf(wall_state[o]) == key)
      std::copy_n(&wall_history[o * stride], stride, &history_out[k * stride]);
  }
}

void Simulation::Impl::storeWallHistory(const Simulation& s, const std::vector<double>& history_in) {
  // Called right after collectWallContacts() of the same step, so particle indices are current.
  wall_history.assign(history_in.begin(), history_in.end());
  wall_state.resize(wall_found.size());
  for (std::size_t k = 0; k < wall_found.size(); ++k) {
    wall_state[k].particle_id = s.p_.id[wall_found[k].particle];
    wall_state[k].wall = wall_of_found[k];
    wall_state[k].key = wall_found[k].key;
  }
}

}  // namespace paddy
