// Output from a simulation: HDF5 snapshots into the run's output directory, checkpoints.
//
//   sim:snapshot() → path of the file written (DIR/snapshots/snap_NNNNNN.h5, + particles.xmf)
//   sim:checkpoint(path)  — full state; a relative path is taken inside paddy.out_dir
//   sim:restart(path)     — relative paths: the working directory first, then paddy.out_dir
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"
#include "sim_handle.hpp"

#include "wall_args.hpp"

#include <paddy/errors.hpp>
#include <paddy/geometry/mesh_wall.hpp>

namespace paddy::lua {

namespace fs = std::filesystem;

fs::path writeSnapshot(lua_State* L, SimHandle& h) {
  if (runtimeState(L).out_dir.empty()) throw InputError("no output directory: snapshots are disabled");
  if (!h.snapshots) h.snapshots = std::make_unique<io::SnapshotWriter>(h.snapshot_dir);
  // The mesh walls (cone, vane, cup...) where they are now, so a viewer shows them moving.
  std::vector<io::WallSurface> walls;
  for (int k : allMeshWalls(*h.sim)) {
    const auto& w = dynamic_cast<const MeshWall&>(h.sim->wall(k));
    walls.push_back({w.name(), w.worldMesh()});
  }
  return h.snapshots->write(*h.sim, walls);
}

namespace {

int snapshot(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  lua_pushstring(L, writeSnapshot(L, h).string().c_str());
  return 1;
}

int checkpoint(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  fs::path path = toString(L, 2, "sim:checkpoint(path): path");
  if (path.is_relative()) path = runtimeState(L).out_dir / path;
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  h.sim->saveCheckpoint(path.string());
  lua_pushstring(L, path.string().c_str());
  return 1;
}

int restart(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  fs::path path = toString(L, 2, "sim:restart(path): path");
  if (path.is_relative() && !fs::exists(path) && fs::exists(runtimeState(L).out_dir / path))
    path = runtimeState(L).out_dir / path;
  if (!fs::exists(path)) throw InputError("sim:restart: checkpoint '" + path.string() + "' does not exist");
  h.sim->loadCheckpoint(path.string());
  return 0;
}

const SimulationMethod reg_output[] = {
    {"snapshot", &guarded<snapshot>},
    {"checkpoint", &guarded<checkpoint>},
    {"restart", &guarded<restart>},
};

}  // namespace

}  // namespace paddy::lua
