// Checkpoint in HDF5: every array of the state, including the neighbour list and the contact
// history on its slots, so a restarted run continues bit for bit (same thread count). Reading it
// back, with the checks of every dataset: checkpoint_load.cpp.
#include "checkpoint_format.hpp"
#include "simulation_impl.hpp"
#include <paddy/io/h5_file.hpp>

#include <paddy/errors.hpp>

#include <filesystem>
#include <stdexcept>

namespace paddy {

namespace {

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out(v.size() * 3);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int c = 0; c < 3; ++c) out[3 * i + c] = v[i][c];
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
    f.write("list/owner_bounds", std::vector<std::uint64_t>(impl_->owner_bounds.begin(), impl_->owner_bounds.end()));
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

}  // namespace paddy
