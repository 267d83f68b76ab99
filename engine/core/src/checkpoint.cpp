// Checkpoint / restart in HDF5: every array of the state, including the neighbour list and the
// contact history on its slots, so a restarted run continues bit for bit (same thread count).
#include "simulation_impl.hpp"
#include <paddy/io/h5_file.hpp>

#include <paddy/errors.hpp>

#include <filesystem>
#include <stdexcept>

namespace paddy {

namespace {
constexpr int kCheckpointVersion = 2;  // 2: wall candidates refreshed apart from the list

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out(v.size() * 3);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int c = 0; c < 3; ++c) out[3 * i + c] = v[i][c];
  return out;
}
std::vector<Vec3> unflatten(const std::vector<double>& d) {
  std::vector<Vec3> out(d.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec3(d[3 * i], d[3 * i + 1], d[3 * i + 2]);
  return out;
}
}  // namespace

void Simulation::saveCheckpoint(const std::string& path) const {
  const std::string tmp = path + ".tmp";
  // Written to "<path>.tmp", then renamed: a kill, a full disk or `ulimit -f` never leaves a
  // half-written checkpoint under the real name (and the earlier one stays).
  try {
    h5::File f = h5::File::create(tmp);
    f.writeAttr("version", kCheckpointVersion);
    f.writeAttr("time", time_);
    f.writeAttr("dt", dt_);
    f.writeAttr("steps", static_cast<double>(steps_));
    f.writeAttr("next_id", static_cast<double>(next_id_));
    f.writeAttr("list_builds", static_cast<double>(list_builds_));
    f.writeAttr("threads", static_cast<double>(threads_));
    f.writeAttr("materials", static_cast<double>(materials_.size()));
    f.writeAttr("history_stride", static_cast<double>(impl_->history_stride));
    f.writeAttr("list_valid", impl_->list_valid ? 1.0 : 0.0);
    f.writeAttr("forces_valid", impl_->forces_valid ? 1.0 : 0.0);
    f.writeAttr("skin", impl_->skin);
    f.writeAttr("list_build_time", impl_->list_build_time);
    f.writeAttr("walls_refreshed", impl_->walls_refreshed ? 1.0 : 0.0);
    f.writeAttr("wall_refresh_time", impl_->wall_refresh_time);
    f.write("particles/id", p_.id);
    f.write("particles/material", std::vector<std::int64_t>(p_.material.begin(), p_.material.end()));
    f.write("particles/radius", p_.radius);
    f.write("particles/mass", p_.mass);
    f.write("particles/inertia", p_.inertia);
    f.write("particles/position", flatten(p_.position), 3);
    f.write("particles/velocity", flatten(p_.velocity), 3);
    f.write("particles/omega", flatten(p_.omega), 3);
    f.write("particles/force", flatten(p_.force), 3);
    f.write("particles/torque", flatten(p_.torque), 3);
    f.write("particles/resisting_torque", p_.resisting_torque);
    f.write("particles/prev_index", std::vector<std::uint64_t>(impl_->prev_index.begin(), impl_->prev_index.end()));
    const NeighbourList& l = impl_->list;
    f.write("list/start", std::vector<std::uint64_t>(l.start.begin(), l.start.end()));
    f.write("list/partner", std::vector<std::uint64_t>(l.partner.begin(), l.partner.end()));
    f.write("list/partner_id", l.partner_id);
    f.write("list/range2", l.range2);
    f.write("list/law", std::vector<std::int64_t>(l.law.begin(), l.law.end()));
    f.write("list/history", l.history);
    f.write("list/live", std::vector<std::uint64_t>(l.live.begin(), l.live.end()));
    f.write("list/x_at_build", flatten(l.x_at_build), 3);
    f.write("walls/x_at_refresh", flatten(impl_->walls_refreshed ? impl_->x_at_wall_refresh : l.x_at_build), 3);
    f.writeAttr("cell_size", l.cell_size);
    std::vector<std::uint64_t> wid, wwall, wkey;
    for (const auto& w : impl_->wall_state) {
      wid.push_back(w.particle_id);
      wwall.push_back(w.wall);
      wkey.push_back(w.key);
    }
    f.write("walls/particle_id", wid);
    f.write("walls/wall", wwall);
    f.write("walls/key", wkey);
    f.write("walls/history", impl_->wall_history);
    f.close();
  } catch (const std::exception& e) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error("cannot write checkpoint '" + path + "': " + e.what());
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    throw std::runtime_error("cannot write checkpoint '" + path + "': renaming '" + tmp + "': " + ec.message());
  }
}

void Simulation::loadCheckpoint(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError("checkpoint '" + path + "' does not exist");
  h5::File f = h5::File::open(path);
  if (static_cast<int>(f.readAttr("version")) != kCheckpointVersion)
    throw InputError("checkpoint '" + path + "' has an unsupported version");
  if (static_cast<std::size_t>(f.readAttr("materials")) != materials_.size())
    throw InputError("checkpoint '" + path + "' was written with " +
                     std::to_string(static_cast<int>(f.readAttr("materials"))) +
                     " materials; the script defines " + std::to_string(materials_.size()));
  if (static_cast<std::size_t>(f.readAttr("history_stride")) != impl_->history_stride)
    throw InputError("checkpoint '" + path + "' was written with other contact models (history size differs)");
  time_ = f.readAttr("time");
  dt_ = f.readAttr("dt");
  impl_->dt_explicit = true;
  steps_ = static_cast<std::uint64_t>(f.readAttr("steps"));
  next_id_ = static_cast<std::uint64_t>(f.readAttr("next_id"));
  list_builds_ = static_cast<std::size_t>(f.readAttr("list_builds"));
  impl_->skin = f.readAttr("skin");
  impl_->list_build_time = f.readAttr("list_build_time");
  impl_->walls_refreshed = f.readAttr("walls_refreshed") != 0.0;
  impl_->wall_refresh_time = f.readAttr("wall_refresh_time");
  p_.id = f.read<std::uint64_t>("particles/id");
  auto mat = f.read<std::int64_t>("particles/material");
  p_.material.assign(mat.begin(), mat.end());
  p_.radius = f.read<double>("particles/radius");
  p_.mass = f.read<double>("particles/mass");
  p_.inertia = f.read<double>("particles/inertia");
  p_.position = unflatten(f.read<double>("particles/position"));
  p_.velocity = unflatten(f.read<double>("particles/velocity"));
  p_.omega = unflatten(f.read<double>("particles/omega"));
  p_.force = unflatten(f.read<double>("particles/force"));
  p_.torque = unflatten(f.read<double>("particles/torque"));
  p_.resisting_torque = f.read<double>("particles/resisting_torque");
  if (p_.resisting_torque.size() != p_.id.size()) throw InputError("checkpoint '" + path + "' is corrupt (resisting_torque)");
  auto prev = f.read<std::uint64_t>("particles/prev_index");
  impl_->prev_index.assign(prev.begin(), prev.end());
  NeighbourList& l = impl_->list;
  auto start = f.read<std::uint64_t>("list/start");
  l.start.assign(start.begin(), start.end());
  auto partner = f.read<std::uint64_t>("list/partner");
  l.partner.assign(partner.begin(), partner.end());
  l.partner_id = f.read<std::uint64_t>("list/partner_id");
  l.range2 = f.read<double>("list/range2");
  auto law = f.read<std::int64_t>("list/law");
  l.law.assign(law.begin(), law.end());
  l.history = f.read<double>("list/history");
  auto live = f.read<std::uint64_t>("list/live");
  l.live.assign(live.begin(), live.end());
  l.x_at_build = unflatten(f.read<double>("list/x_at_build"));
  impl_->x_at_wall_refresh.clear();
  if (impl_->walls_refreshed) impl_->x_at_wall_refresh = unflatten(f.read<double>("walls/x_at_refresh"));
  l.cell_size = f.readAttr("cell_size");
  l.stride = impl_->history_stride;
  for (int m : p_.material)
    if (m < 0 || m >= static_cast<int>(materials_.size())) throw InputError("checkpoint '" + path + "' is corrupt (material id)");
  for (auto lw : l.law)
    if (lw < 0 || lw >= static_cast<int>(impl_->laws.size())) throw InputError("checkpoint '" + path + "' refers to a contact law the script does not define");
  auto wid = f.read<std::uint64_t>("walls/particle_id");
  auto wwall = f.read<std::uint64_t>("walls/wall");
  auto wkey = f.read<std::uint64_t>("walls/key");
  impl_->wall_state.resize(wid.size());
  for (std::size_t k = 0; k < wid.size(); ++k)
    impl_->wall_state[k] = {wid[k], static_cast<std::uint32_t>(wwall[k]), static_cast<std::uint32_t>(wkey[k])};
  impl_->wall_history = f.read<double>("walls/history");
  impl_->list_valid = f.readAttr("list_valid") != 0.0;
  impl_->forces_valid = f.readAttr("forces_valid") != 0.0;
  if (impl_->list_valid && !walls_.empty()) {
    // Wall candidate lists are not stored: rebuild them exactly as they were built, from the
    // positions and wall poses at their last refresh (the list build, or a refresh of the walls
    // alone after it).
    double rmax = 0.0, sep = 0.0;
    for (double r : p_.radius) rmax = std::max(rmax, r);
    for (const auto& lw : impl_->laws) sep = std::max(sep, lw.maxSeparation(rmax));
    impl_->wall_max_gap = sep;
    const bool refreshed = impl_->walls_refreshed;
    for (auto& w : walls_) w->moveTo(refreshed ? impl_->wall_refresh_time : impl_->list_build_time);
    impl_->buildWallCandidates(*this, refreshed ? impl_->x_at_wall_refresh : l.x_at_build);
  }
  for (auto& w : walls_) w->moveTo(time_);
}

}  // namespace paddy
