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
  ParticleView view{p.size(), p.position.data(), p.radius.data(), s.threads_};
  // Scratch buffers are members: no allocation once they have grown to the step's size.
  std::vector<WallContact>& found = wall_scratch_found;
  std::vector<WallContact>& tmp = wall_scratch_tmp;
  std::vector<WallContactOrder>& order = wall_scratch_order;
  found.clear();
  order.clear();
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
      order.push_back({p.id[c.particle], static_cast<std::uint32_t>(w), c.key, static_cast<std::uint32_t>(found.size())});
      found.push_back(c);
    }
  }
  // Order by (particle id, wall, key): the same comparisons as a tuple order, on keys gathered once.
  std::sort(order.begin(), order.end(), [](const WallContactOrder& a, const WallContactOrder& b) {
    if (a.particle_id != b.particle_id) return a.particle_id < b.particle_id;
    if (a.wall != b.wall) return a.wall < b.wall;
    return a.key < b.key;
  });
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
