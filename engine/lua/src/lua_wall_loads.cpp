// Wall loads from Lua: the force and torque the particles exert on walls, and the load history
// of mesh walls (geometry::LoadSample: t, force, torque, axial torque, distance, angle).
//
//   sim:wall_force(w) → {fx,fy,fz}   sim:wall_torque(w) → {tx,ty,tz} (about the torque origin)
//   sim:wall_axial_torque(w)         sim:wall_position(w) → translation travelled {x,y,z}
//   sim:record_wall_loads([w])       appends a load sample (all mesh walls without w); the engine
//                                    records by itself with sim:run{record_loads_every = T}
//   sim:wall_load_history(w)         → {{t=, force={..}, torque={..}, axial_torque=, distance=,
//                                        angle=}, ...}
//   sim:write_wall_loads(w, path)    → path: CSV, or HDF5 when path ends in .h5/.hdf5
//   sim:write_wall_loads(path)       → path: every mesh wall into one HDF5 file, a group per wall
// Files are written atomically (temporary + rename); relative paths go inside paddy.out_dir.
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"
#include "sim_handle.hpp"
#include "wall_args.hpp"

#include <paddy/errors.hpp>
#include <paddy/geometry/load_history.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace paddy::lua {

namespace {
namespace fs = std::filesystem;

void pushVec3(lua_State* L, const Vec3& v) { pushNumberArray(L, {v.x(), v.y(), v.z()}); }

int wallForce(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  pushVec3(L, h.sim->wall(wallArg(L, h, 2, "sim:wall_force")).force());
  return 1;
}

int wallTorque(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  pushVec3(L, h.sim->wall(wallArg(L, h, 2, "sim:wall_torque")).torque());
  return 1;
}

int wallAxialTorque(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  lua_pushnumber(L, meshWallArg(L, h, 2, "sim:wall_axial_torque").axialTorque());
  return 1;
}

int wallPosition(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  pushVec3(L, meshWallArg(L, h, 2, "sim:wall_position").translationTravelled());
  return 1;
}

int recordWallLoads(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  const double t = h.sim->time();
  if (lua_isnoneornil(L, 2)) {
    for (int k : allMeshWalls(*h.sim)) dynamic_cast<MeshWall&>(h.sim->wall(k)).recordLoads(t);
  } else {
    meshWallArg(L, h, 2, "sim:record_wall_loads").recordLoads(t);
  }
  return 0;
}

int wallLoadHistory(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  const auto& samples = meshWallArg(L, h, 2, "sim:wall_load_history").loadHistory();
  lua_createtable(L, static_cast<int>(samples.size()), 0);
  int k = 0;
  for (const geometry::LoadSample& s : samples) {
    lua_createtable(L, 0, 6);
    lua_pushnumber(L, s.t);
    lua_setfield(L, -2, "t");
    pushVec3(L, s.force);
    lua_setfield(L, -2, "force");
    pushVec3(L, s.torque);
    lua_setfield(L, -2, "torque");
    lua_pushnumber(L, s.axial_torque);
    lua_setfield(L, -2, "axial_torque");
    lua_pushnumber(L, s.distance);
    lua_setfield(L, -2, "distance");
    lua_pushnumber(L, s.angle);
    lua_setfield(L, -2, "angle");
    lua_rawseti(L, -2, ++k);
  }
  return 1;
}

bool isHdf5Path(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".h5" || ext == ".hdf5";
}

// sim:write_wall_loads(w, path) or sim:write_wall_loads(path) / (nil, path): all mesh walls.
int writeWallLoads(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  const bool all = lua_gettop(L) <= 2 || lua_isnil(L, 2);
  const int path_idx = lua_gettop(L) <= 2 ? 2 : 3;
  fs::path path = toString(L, path_idx, all ? "sim:write_wall_loads(path): path" : "sim:write_wall_loads(wall, path): path");
  if (path.is_relative()) {
    const fs::path& out = runtimeState(L).out_dir;
    if (out.empty()) throw InputError("sim:write_wall_loads: no output directory for a relative path");
    path = out / path;
  }
  const bool h5 = isHdf5Path(path);
  if (all) {
    if (!h5)
      throw InputError("sim:write_wall_loads(path): the loads of all mesh walls go into one HDF5 file, so the "
                       "path must end in .h5 or .hdf5 (got '" + path.filename().string() +
                       "'); for CSV give the wall: sim:write_wall_loads(w, path)");
    std::vector<geometry::NamedLoadHistory> walls;
    for (int k : allMeshWalls(*h.sim)) {
      const auto& w = dynamic_cast<const MeshWall&>(h.sim->wall(k));
      walls.push_back({w.name(), &w.loadHistory()});
    }
    if (walls.empty()) throw InputError("sim:write_wall_loads: the simulation has no mesh walls (sim:add_mesh_wall)");
    geometry::writeLoadHistoryH5(path.string(), walls);
  } else {
    const MeshWall& w = meshWallArg(L, h, 2, "sim:write_wall_loads");
    if (h5) w.writeLoadHistoryH5(path.string());
    else w.writeLoadHistoryCsv(path.string());
  }
  lua_pushstring(L, path.string().c_str());
  return 1;
}

const SimulationMethod reg_force{"wall_force", &guarded<wallForce>};
const SimulationMethod reg_torque{"wall_torque", &guarded<wallTorque>};
const SimulationMethod reg_axial{"wall_axial_torque", &guarded<wallAxialTorque>};
const SimulationMethod reg_position{"wall_position", &guarded<wallPosition>};
const SimulationMethod reg_record{"record_wall_loads", &guarded<recordWallLoads>};
const SimulationMethod reg_history{"wall_load_history", &guarded<wallLoadHistory>};
const SimulationMethod reg_write{"write_wall_loads", &guarded<writeWallLoads>};

}  // namespace

}  // namespace paddy::lua
