// Particle–wall contacts: gather them from the walls, order them by (particle id, wall, key) and
// match each to its stored history (merge of two sorted lists).
#include "simulation_impl.hpp"

#include <paddy/errors.hpp>

#include <algorithm>
#include <numeric>
#include <tuple>

namespace paddy {

namespace {
auto keyOf(const WallContactState& s) { return std::make_tuple(s.particle_id, s.wall, s.key); }
}  // namespace

void Simulation::Impl::collectWallContacts(Simulation& s, double max_gap, std::vector<double>& history_out) {
  const ParticleArrays& p = s.p_;
  const int nmat = static_cast<int>(s.materials_.size());
  ParticleView view{p.size(), p.position.data(), p.radius.data()};
  std::vector<WallContact> found;
  std::vector<std::uint32_t> owner;
  std::vector<WallContact> tmp;
  for (std::size_t w = 0; w < s.walls_.size(); ++w) {
    tmp.clear();
    s.walls_[w]->findContacts(view, max_gap, tmp);
    for (const auto& c : tmp) {
      const int law = law_index[static_cast<std::size_t>(p.material[c.particle] * nmat + s.walls_[w]->material())];
      if (law < 0)
        throw InputError("no interaction is defined between materials '" + s.materials_[p.material[c.particle]].name +
                         "' and '" + s.materials_[s.walls_[w]->material()].name + "' (wall '" +
                         s.walls_[w]->name() + "')");
      if (c.overlap < -laws[static_cast<std::size_t>(law)].maxSeparation(p.radius[c.particle])) continue;
      found.push_back(c);
      owner.push_back(static_cast<std::uint32_t>(w));
    }
  }
  std::vector<std::size_t> order(found.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::make_tuple(p.id[found[a].particle], owner[a], found[a].key) <
           std::make_tuple(p.id[found[b].particle], owner[b], found[b].key);
  });
  wall_found.resize(found.size());
  wall_of_found.resize(found.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    wall_found[k] = found[order[k]];
    wall_of_found[k] = owner[order[k]];
  }

  const std::size_t stride = history_stride;
  history_out.assign(wall_found.size() * stride, 0.0);
  if (stride == 0) return;
  std::size_t o = 0;
  for (std::size_t k = 0; k < wall_found.size(); ++k) {
    const auto key = std::make_tuple(p.id[wall_found[k].particle], wall_of_found[k], wall_found[k].key);
    while (o < wall_state.size() && keyOf(wall_state[o]) < key) ++o;
    if (o < wall_state.size() && keyOf(wall_state[o]) == key)
      std::copy_n(&wall_history[o * stride], stride, &history_out[k * stride]);
  }
}

void Simulation::Impl::storeWallHistory(const Simulation& s, const std::vector<double>& history_in) {
  // Called right after collectWallContacts() of the same step, so particle indices are current.
  wall_history = history_in;
  wall_state.resize(wall_found.size());
  for (std::size_t k = 0; k < wall_found.size(); ++k) {
    wall_state[k].particle_id = s.p_.id[wall_found[k].particle];
    wall_state[k].wall = wall_of_found[k];
    wall_state[k].key = wall_found[k].key;
  }
}

}  // namespace paddy
