// Restart from an HDF5 checkpoint (written by checkpoint.cpp). A checkpoint is outside input: a
// file may be truncated, come from another script or another version, or be made by hand. Every
// dataset and attribute is read into local arrays and checked before the simulation is touched:
// element kind, shape, particle counts that agree between datasets, finite values, radii, masses
// and inertias that match the script's materials, the neighbour list's indices, ids, order and
// contact laws, the wall contacts' order and walls, a time step within the stable limit. A
// refusal is an InputError naming the file, the dataset or attribute and the cause; a refused
// checkpoint leaves the simulation as it was. Fuzzed by tests/fuzz/fuzz_checkpoint.cpp.
#include "checkpoint_format.hpp"
#include "simulation_impl.hpp"

#include <paddy/errors.hpp>
#include <paddy/io/h5_file.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <sstream>
#include <tuple>

namespace paddy {

namespace {

constexpr double kMaxCount = 9007199254740992.0;  // 2^53: counts are stored as doubles

class Reader {
 public:
  explicit Reader(const std::string& path) : path_(path), f_(h5::File::open(path)) {}

  [[noreturn]] void refuse(const std::string& what, const std::string& why) const {
    throw InputError("checkpoint '" + path_ + "': " + what + " " + why);
  }
  template <class V>
  static std::string str(V v) {
    std::ostringstream o;
    o.precision(17);
    o << v;
    return o.str();
  }

  double finite(const char* name) const {
    const double v = f_.readAttr(name);
    if (!std::isfinite(v)) refuse(std::string("attribute '") + name + "'", "is " + str(v) + ", not a finite number");
    return v;
  }
  double atLeast(const char* name, double lo) const {
    const double v = finite(name);
    if (v < lo) refuse(std::string("attribute '") + name + "'", "is " + str(v) + ", below " + str(lo));
    return v;
  }
  // A whole number in [0, 2^53].
  std::uint64_t count(const char* name) const {
    const double v = f_.readAttr(name);
    if (!(v >= 0.0 && v <= kMaxCount) || v != std::floor(v))
      refuse(std::string("attribute '") + name + "'", "is " + str(v) + ", not a whole number from 0 to 2^53");
    return static_cast<std::uint64_t>(v);
  }
  bool flag(const char* name) const {
    const double v = f_.readAttr(name);
    if (v != 0.0 && v != 1.0) refuse(std::string("attribute '") + name + "'", "is " + str(v) + ", not 0 or 1");
    return v == 1.0;
  }

  // A dataset of `columns` columns; `rows` = the row count it must have (kAnyRows: any).
  static constexpr std::size_t kAnyRows = std::numeric_limits<std::size_t>::max();
  template <class T>
  std::vector<T> table(const std::string& name, std::size_t rows, hsize_t columns = 1) const {
    std::vector<T> v = f_.read<T>(name, columns);
    const std::size_t n = v.size() / columns;
    if (rows != kAnyRows && n != rows)
      refuse("dataset '" + name + "'", "has " + str(n) + " rows where " + str(rows) + " are expected (" +
                                           (columns == 3 ? "one per particle" : "counts disagree between datasets") + ")");
    if constexpr (std::is_floating_point_v<T>)
      for (std::size_t k = 0; k < v.size(); ++k)
        if (!std::isfinite(v[k])) refuse("dataset '" + name + "'", "holds " + str(v[k]) + " at row " + str(k / columns));
    return v;
  }
  std::vector<Vec3> vectors(const std::string& name, std::size_t rows) const {
    const auto d = table<double>(name, rows, 3);
    std::vector<Vec3> out(d.size() / 3);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec3(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
    return out;
  }

 private:
  const std::string& path_;
  h5::File f_;
};

bool nearlyEqual(double a, double b) { return std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b)); }

}  // namespace

void Simulation::loadCheckpoint(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError("checkpoint '" + path + "' does not exist");
  const Reader r(path);
  using S = std::string;

  // ---- attributes ----------------------------------------------------------------------------
  const double version = r.finite("version");
  if (version != kCheckpointVersion)
    r.refuse("attribute 'version'", "is " + Reader::str(version) + ": this paddy reads checkpoint version " +
                                        std::to_string(kCheckpointVersion));
  const std::uint64_t n_materials = r.count("materials");
  if (n_materials != materials_.size())
    r.refuse("attribute 'materials'", "says it was written with " + std::to_string(n_materials) +
                                          " materials; the script defines " + std::to_string(materials_.size()));
  const std::uint64_t stride = r.count("history_stride");
  if (stride != impl_->history_stride)
    r.refuse("attribute 'history_stride'", "is " + std::to_string(stride) + ": it was written with other contact models "
                                               "(history size " + std::to_string(impl_->history_stride) + " here)");
  const double time = r.finite("time");
  const double dt = r.finite("dt");
  if (!(dt > 0.0)) r.refuse("attribute 'dt'", "is " + Reader::str(dt) + ", not a time step > 0");
  const std::uint64_t steps = r.count("steps");
  const std::uint64_t next_id = r.count("next_id");
  const std::uint64_t list_builds = r.count("list_builds");
  const double skin = r.atLeast("skin", 0.0);
  const double list_build_time = r.finite("list_build_time");
  const bool walls_refreshed = r.flag("walls_refreshed");
  const double wall_refresh_time = r.finite("wall_refresh_time");
  const double cell_size = r.atLeast("cell_size", 0.0);
  const bool list_valid = r.flag("list_valid");
  const bool forces_valid = r.flag("forces_valid");

  // ---- particles -----------------------------------------------------------------------------
  ParticleArrays p;
  p.id = r.table<std::uint64_t>("particles/id", Reader::kAnyRows);
  const std::size_t n = p.id.size();
  {
    std::vector<std::uint64_t> sorted(p.id);
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0 && sorted[k] == sorted[k - 1]) r.refuse("dataset 'particles/id'", "holds the id " + std::to_string(sorted[k]) + " twice");
      if (sorted[k] >= next_id)
        r.refuse("dataset 'particles/id'", "holds the id " + std::to_string(sorted[k]) + ", not below attribute 'next_id' = " +
                                               std::to_string(next_id));
    }
  }
  const auto material = r.table<std::int64_t>("particles/material", n);
  for (std::size_t i = 0; i < n; ++i)
    if (material[i] < 0 || material[i] >= static_cast<std::int64_t>(materials_.size()))
      r.refuse("dataset 'particles/material'", "holds material " + std::to_string(material[i]) + " at row " + std::to_string(i) +
                                                   "; the script defines " + std::to_string(materials_.size()));
  p.material.assign(material.begin(), material.end());
  p.radius = r.table<double>("particles/radius", n);
  p.mass = r.table<double>("particles/mass", n);
  p.inertia = r.table<double>("particles/inertia", n);
  for (std::size_t i = 0; i < n; ++i) {
    const S which = " of particle " + std::to_string(p.id[i]) + " (row " + std::to_string(i) + ")";
    if (!(p.radius[i] >= 1e-9 && p.radius[i] <= 1e3))
      r.refuse("dataset 'particles/radius'", "holds " + Reader::str(p.radius[i]) + " m" + which + ", outside [1e-9, 1e3] m");
    const Material& m = materials_[static_cast<std::size_t>(p.material[i])];
    const double rad = p.radius[i];
    const double mass = m.density * 4.0 / 3.0 * std::numbers::pi * rad * rad * rad;
    if (!nearlyEqual(p.mass[i], mass))
      r.refuse("dataset 'particles/mass'", "holds " + Reader::str(p.mass[i]) + " kg" + which + "; its radius and the density of material '" +
                                               m.name + "' give " + Reader::str(mass) + " kg");
    if (!nearlyEqual(p.inertia[i], 0.4 * mass * rad * rad))
      r.refuse("dataset 'particles/inertia'", "holds " + Reader::str(p.inertia[i]) + which + "; a sphere of its mass and radius has " +
                                                  Reader::str(0.4 * mass * rad * rad));
  }
  p.position = r.vectors("particles/position", n);
  p.velocity = r.vectors("particles/velocity", n);
  p.omega = r.vectors("particles/omega", n);
  p.force = r.vectors("particles/force", n);
  p.torque = r.vectors("particles/torque", n);
  p.resisting_torque = r.table<double>("particles/resisting_torque", n);
  for (std::size_t i = 0; i < n; ++i)
    if (p.resisting_torque[i] < 0.0)
      r.refuse("dataset 'particles/resisting_torque'", "holds " + Reader::str(p.resisting_torque[i]) + " at row " + std::to_string(i) + ", below 0");
  if (n > 0) {
    // The time step within the stable limit of these particles (the run would refuse it, naming no file).
    std::swap(p_, p);
    const double limit = maxStableTimeStep();
    std::swap(p_, p);
    if (dt > limit)
      r.refuse("attribute 'dt'", "is " + Reader::str(dt) + " s, above the stable limit " + Reader::str(limit) + " s of its particles");
  }

  // ---- neighbour list ------------------------------------------------------------------------
  // When the list is valid its owners are the particles; otherwise it is the list of an earlier
  // build (particles added or removed since), kept for the history carry-over at the next build.
  const auto start = r.table<std::uint64_t>("list/start", list_valid ? n + 1 : Reader::kAnyRows);
  const auto partner = r.table<std::uint64_t>("list/partner", Reader::kAnyRows);
  const std::size_t slots = partner.size();
  if (start.empty()) r.refuse("dataset 'list/start'", "is empty (it holds one row more than the list's owners)");
  const std::size_t owners = start.size() - 1;
  if (start.front() != 0) r.refuse("dataset 'list/start'", "does not begin with 0");
  for (std::size_t i = 0; i < owners; ++i)
    if (start[i + 1] < start[i] || start[i + 1] > slots)
      r.refuse("dataset 'list/start'", "row " + std::to_string(i + 1) + " = " + std::to_string(start[i + 1]) +
                                           " is not between the row before and the " + std::to_string(slots) + " rows of 'list/partner'");
  if (start.back() != slots)
    r.refuse("dataset 'list/start'", "ends at " + std::to_string(start.back()) + "; 'list/partner' has " + std::to_string(slots) + " rows");
  const auto partner_id = r.table<std::uint64_t>("list/partner_id", slots);
  const auto range2 = r.table<double>("list/range2", slots);
  const auto law = r.table<std::int64_t>("list/law", slots);
  const auto history = r.table<double>("list/history", slots * stride);
  const auto live = r.table<std::uint64_t>("list/live", slots);
  const auto x_at_build = r.vectors("list/x_at_build", list_valid ? n : Reader::kAnyRows);
  // The threads' split of the owners: none, or 0 = b_0 <= b_1 <= ... <= b_T = n.
  const auto owner_bounds = r.table<std::uint64_t>("list/owner_bounds", Reader::kAnyRows);
  if (!owner_bounds.empty()) {
    bool ok = owner_bounds.size() >= 2 && owner_bounds.front() == 0 && owner_bounds.back() == n;
    for (std::size_t k = 1; ok && k < owner_bounds.size(); ++k) ok = owner_bounds[k - 1] <= owner_bounds[k];
    if (!ok) r.refuse("dataset 'list/owner_bounds'", "is not a split of the " + Reader::str(n) + " particles (0 = b_0 <= ... <= b_T = n)");
  }
  const int nmat = static_cast<int>(materials_.size());
  for (std::size_t i = 0; i < owners; ++i) {
    for (std::size_t k = start[i]; k < start[i + 1]; ++k) {
      const S slot = " at row " + std::to_string(k);
      if (k > start[i] && partner_id[k] <= partner_id[k - 1])
        r.refuse("dataset 'list/partner_id'", "is not in increasing order within owner " + std::to_string(i) + slot);
      if (live[k] > 1) r.refuse("dataset 'list/live'", "holds " + std::to_string(live[k]) + slot + ", not 0 or 1");
      if (range2[k] < 0.0) r.refuse("dataset 'list/range2'", "holds " + Reader::str(range2[k]) + slot + ", below 0");
      if (law[k] < 0 || law[k] >= static_cast<std::int64_t>(impl_->laws.size()))
        r.refuse("dataset 'list/law'", "holds contact law " + std::to_string(law[k]) + slot + "; the script defines " +
                                           std::to_string(impl_->laws.size()));
      if (!list_valid) continue;
      const std::uint64_t j = partner[k];
      if (j >= n) r.refuse("dataset 'list/partner'", "holds particle row " + std::to_string(j) + slot + "; there are " + std::to_string(n));
      if (partner_id[k] != p.id[j] || p.id[i] >= p.id[j])
        r.refuse("dataset 'list/partner_id'", "holds " + std::to_string(partner_id[k]) + slot + ": not the id of its partner (" +
                                                  std::to_string(p.id[j]) + ") above its owner's (" + std::to_string(p.id[i]) + ")");
      const int expected = impl_->law_index[static_cast<std::size_t>(p.material[i] * nmat + p.material[j])];
      if (law[k] != expected)
        r.refuse("dataset 'list/law'", "holds contact law " + std::to_string(law[k]) + slot + "; the script's law for the pair's materials is " +
                                           std::to_string(expected));
      // The interaction range as the list build computes it (NeighbourList::build).
      const double ri = p.radius[i], rj = p.radius[j];
      const double reach = ri + rj + impl_->laws[static_cast<std::size_t>(law[k])].maxSeparation(ri * rj / (ri + rj));
      if (!nearlyEqual(range2[k], reach * reach))
        r.refuse("dataset 'list/range2'", "holds " + Reader::str(range2[k]) + slot + "; the pair's radii and contact law give " +
                                              Reader::str(reach * reach));
    }
  }
  const auto prev_index = r.table<std::uint64_t>("particles/prev_index", n);
  {
    std::vector<std::uint64_t> seen;
    for (std::size_t i = 0; i < n; ++i) {
      if (prev_index[i] == std::numeric_limits<std::uint64_t>::max()) continue;  // added since the build
      if (prev_index[i] >= owners)
        r.refuse("dataset 'particles/prev_index'", "holds " + std::to_string(prev_index[i]) + " at row " + std::to_string(i) +
                                                       "; the list has " + std::to_string(owners) + " owners");
      seen.push_back(prev_index[i]);
    }
    std::sort(seen.begin(), seen.end());
    if (std::adjacent_find(seen.begin(), seen.end()) != seen.end())
      r.refuse("dataset 'particles/prev_index'", "names one earlier row twice");
  }
  std::vector<Vec3> x_at_wall_refresh;
  if (walls_refreshed) x_at_wall_refresh = r.vectors("walls/x_at_refresh", list_valid ? n : Reader::kAnyRows);

  // ---- wall contacts -------------------------------------------------------------------------
  const auto wid = r.table<std::uint64_t>("walls/particle_id", Reader::kAnyRows);
  const auto wwall = r.table<std::uint64_t>("walls/wall", wid.size());
  const auto wkey = r.table<std::uint64_t>("walls/key", wid.size());
  const auto wall_history = r.table<double>("walls/history", wid.size() * stride);
  std::vector<WallContactState> wall_state(wid.size());
  {
    std::vector<std::uint64_t> ids(p.id);
    std::sort(ids.begin(), ids.end());
    for (std::size_t k = 0; k < wid.size(); ++k) {
      const S row = " at row " + std::to_string(k);
      if (wwall[k] >= walls_.size())
        r.refuse("dataset 'walls/wall'", "holds wall " + std::to_string(wwall[k]) + row + "; the script defines " + std::to_string(walls_.size()));
      if (wkey[k] > std::numeric_limits<std::uint32_t>::max())
        r.refuse("dataset 'walls/key'", "holds " + std::to_string(wkey[k]) + row + ", above 2^32 - 1");
      if (!std::binary_search(ids.begin(), ids.end(), wid[k]))
        r.refuse("dataset 'walls/particle_id'", "holds " + std::to_string(wid[k]) + row + ", the id of no particle");
      wall_state[k] = {wid[k], static_cast<std::uint32_t>(wwall[k]), static_cast<std::uint32_t>(wkey[k])};
      if (k > 0 && std::make_tuple(wall_state[k - 1].particle_id, wall_state[k - 1].wall, wall_state[k - 1].key) >
                       std::make_tuple(wall_state[k].particle_id, wall_state[k].wall, wall_state[k].key))
        r.refuse("dataset 'walls/particle_id'", "is not in increasing order of (particle id, wall, key)" + row);
    }
  }

  // ---- accepted: the state is replaced -------------------------------------------------------
  p_ = std::move(p);
  time_ = time;
  dt_ = dt;
  impl_->dt_explicit = true;
  steps_ = steps;
  next_id_ = next_id;
  list_builds_ = list_builds;
  impl_->skin = skin;
  impl_->list_build_time = list_build_time;
  impl_->walls_refreshed = walls_refreshed;
  impl_->wall_refresh_time = wall_refresh_time;
  impl_->prev_index.assign(prev_index.begin(), prev_index.end());
  NeighbourList& l = impl_->list;
  l.start.assign(start.begin(), start.end());
  l.partner.assign(partner.begin(), partner.end());
  l.partner_id = partner_id;
  l.range2 = range2;
  l.law.assign(law.begin(), law.end());
  l.history = history;
  l.live.assign(live.begin(), live.end());
  l.x_at_build = x_at_build;
  impl_->owner_bounds.assign(owner_bounds.begin(), owner_bounds.end());
  l.cell_size = cell_size;
  l.stride = impl_->history_stride;
  impl_->x_at_wall_refresh = std::move(x_at_wall_refresh);
  impl_->wall_state = std::move(wall_state);
  impl_->wall_history = wall_history;
  impl_->list_valid = list_valid;
  impl_->forces_valid = forces_valid;
  if (impl_->list_valid && !walls_.empty()) {
    // Wall candidate lists are not stored: rebuild them exactly as they were built, from the
    // positions and wall poses at their last refresh (the list build, or a refresh of the walls
    // alone after it).
    double rmax = 0.0, sep = 0.0;
    for (double rad : p_.radius) rmax = std::max(rmax, rad);
    for (const auto& lw : impl_->laws) sep = std::max(sep, lw.maxSeparation(rmax));
    impl_->wall_max_gap = sep;
    const bool refreshed = impl_->walls_refreshed;
    for (auto& w : walls_) w->moveTo(refreshed ? impl_->wall_refresh_time : impl_->list_build_time);
    impl_->buildWallCandidates(*this, refreshed ? impl_->x_at_wall_refresh : l.x_at_build);
  }
  for (auto& w : walls_) w->moveTo(time_);
}

}  // namespace paddy
