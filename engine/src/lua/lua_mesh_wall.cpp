// Mesh walls from Lua: parts and mesh files as moving walls, their motion and their loads.
//
//   sim:add_mesh_wall{name=, material=, part="slump_cone", params={...}  or  file="x.stl",
//                     scale=1, rotate={axis={0,0,1}, angle=deg}, translate={x,y,z}, motion={...}}
//                                                        → wall index (as sim:add_wall)
//   sim:set_motion(w, motion)        replaces the motion (start defaults to the current time)
//   sim:wall_force(w) → {fx,fy,fz}   sim:wall_torque(w) → {tx,ty,tz} (about the torque origin)
//   sim:wall_axial_torque(w)         sim:wall_position(w) → translation offset {x,y,z}
//   sim:record_wall_loads([w])       appends a load sample (all mesh walls without w)
//   sim:write_wall_loads(w, "f.csv") → path (atomic; relative paths inside paddy.out_dir)
//   paddy.parts()                    → {{name=, description=, params={{name=, default=, ...}}}}
//
// Motion tables: {type="fixed"}, {type="translate", velocity={..} | direction={..} schedule=...,
// start=, stop=}, {type="rotate", point=, axis=, speed=rad/s | rpm= | schedule={{t,ω},...},
// start=, stop=}. Schedules are piecewise linear in absolute time (two knots at one time: a step).
// The mesh file is read by the reader a plugin registered for its extension (the engine does
// not link CGAL); scale and placement are applied here, identically for parts and files.
#include "lua/lua_util.hpp"
#include "lua/registry.hpp"
#include "lua/runtime_state.hpp"
#include "lua/sim_handle.hpp"

#include <paddy/errors.hpp>
#include <paddy/geometry.hpp>
#include <paddy/geometry/mesh_check.hpp>
#include <paddy/geometry/mesh_wall.hpp>
#include <paddy/plugin_manager.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <sstream>

namespace paddy::lua {

namespace {
namespace fs = std::filesystem;
using geometry::Kinematics;
using geometry::SpeedSchedule;

constexpr double kInf = std::numeric_limits<double>::infinity();

void pushVec3(lua_State* L, const Vec3& v) { pushNumberArray(L, {v.x(), v.y(), v.z()}); }

// Wall argument: the index returned by sim:add_wall / sim:add_mesh_wall, or the wall's name.
int wallArg(lua_State* L, SimHandle& h, int idx, const std::string& fn) {
  const int n = static_cast<int>(h.sim->wallCount());
  if (lua_type(L, idx) == LUA_TSTRING) {
    const std::string name = lua_tostring(L, idx);
    for (int w = 0; w < n; ++w)
      if (h.sim->wall(w).name() == name) return w;
    throw InputError(fn + ": no wall named '" + name + "'");
  }
  const double x = toNumber(L, idx, fn + ": wall");
  if (x != std::floor(x) || x < 0 || x >= n) {
    std::ostringstream m;
    m << fn << ": wall " << x << " does not exist (" << n << " walls";
    if (n > 0) m << ", indices 0.." << n - 1 << " or their names";
    m << ")";
    throw InputError(m.str());
  }
  return static_cast<int>(x);
}

MeshWall& meshWallArg(lua_State* L, SimHandle& h, int idx, const std::string& fn) {
  Wall& w = h.sim->wall(wallArg(L, h, idx, fn));
  auto* m = dynamic_cast<MeshWall*>(&w);
  if (!m) throw InputError(fn + ": wall '" + w.name() + "' is not a mesh wall (sim:add_mesh_wall)");
  return *m;
}

// {{t0, v0}, {t1, v1}, ...} → SpeedSchedule (times non-decreasing, checked by SpeedSchedule).
SpeedSchedule readSchedule(lua_State* L, int idx, const std::string& what, double factor) {
  idx = lua_absindex(L, idx);
  if (lua_type(L, idx) != LUA_TTABLE) throw InputError(what + " must be a list of {time, value} pairs");
  std::vector<std::pair<double, double>> knots;
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, idx));
  if (n == 0) throw InputError(what + " is empty (give {time, value} pairs)");
  for (lua_Integer k = 1; k <= n; ++k) {
    lua_rawgeti(L, idx, k);
    if (lua_type(L, -1) != LUA_TTABLE || lua_rawlen(L, -1) != 2) {
      lua_pop(L, 1);
      throw InputError(what + " entry " + std::to_string(k) + " must be a pair {time, value}");
    }
    lua_rawgeti(L, -1, 1);
    lua_rawgeti(L, -2, 2);
    const std::string entry = what + " entry " + std::to_string(k);
    const double t = toNumber(L, -2, entry + " time");
    const double v = toNumber(L, -1, entry + " value");
    lua_pop(L, 3);
    knots.emplace_back(t, v * factor);
  }
  try {
    return SpeedSchedule(std::move(knots));
  } catch (const InputError& e) {
    throw InputError(what + ": " + e.what());
  }
}

// A motion table (see the header comment). `default_point` is the rotation axis point when none
// is given (the wall's placement), `default_start` the start time.
Kinematics readMotion(lua_State* L, int idx, const std::string& ctx, const Vec3& default_point,
                      double default_start) {
  OptionTable opt(L, idx, ctx);
  const std::string type = opt.string("type");
  Kinematics k;
  if (type == "fixed") {
    opt.finish();
    return Kinematics::still();
  }
  k.t_start = opt.number("start", default_start);
  k.t_end = opt.number("stop", kInf);
  if (type == "translate") {
    if (opt.has("schedule")) {
      k.direction = opt.vec3("direction");
      opt.push("schedule");
      k.speed = readSchedule(L, -1, ctx + " schedule", 1.0);
      lua_pop(L, 1);
    } else {
      const Vec3 v = opt.vec3("velocity");
      if (v.norm() > 0.0) {
        k.direction = v.normalized();
        k.speed = SpeedSchedule::constant(v.norm());
      }
    }
  } else if (type == "rotate") {
    k.axis_point = opt.vec3("point", default_point);
    k.axis = opt.vec3("axis", Vec3::UnitZ());
    const int given = int(opt.has("speed")) + int(opt.has("rpm")) + int(opt.has("schedule"));
    if (given != 1) throw InputError(ctx + ": give exactly one of speed [rad/s], rpm or schedule {{t, rad/s}, ...}");
    if (opt.has("speed")) k.angular_speed = SpeedSchedule::constant(opt.number("speed"));
    if (opt.has("rpm")) k.angular_speed = SpeedSchedule::constant(opt.number("rpm") * 2.0 * std::numbers::pi / 60.0);
    if (opt.has("schedule")) {
      opt.push("schedule");
      k.angular_speed = readSchedule(L, -1, ctx + " schedule", 1.0);
      lua_pop(L, 1);
    }
  } else {
    throw InputError(ctx + ": motion type '" + type + "' is not available (available: fixed, translate, rotate)");
  }
  opt.finish();
  k.validate();
  return k;
}

bool hasMoved(const MeshWall& w) {
  const double scale = 1.0 + w.placement().x.norm();
  return (w.pose().x - w.placement().x).norm() > 1e-12 * scale ||
         (w.pose().R - w.placement().R).norm() > 1e-12;
}

// Part parameters: defaults of the ParamSpecs, overridden by `params`, checked against the ranges.
ParamValues partParams(lua_State* L, OptionTable& opt, const GeometryInfo& g) {
  ParamValues values;
  for (const auto& s : g.params)
    if (!s.required) values[s.name] = s.default_value;
  const std::string ctx = "sim:add_mesh_wall: part '" + g.name + "'";
  if (opt.push("params") != LUA_TNIL) {
    if (lua_type(L, -1) != LUA_TTABLE) throw InputError(ctx + ": params must be a table");
    const int t = lua_absindex(L, -1);
    lua_pushnil(L);
    while (lua_next(L, t) != 0) {
      const std::string key = lua_type(L, -2) == LUA_TSTRING ? lua_tostring(L, -2) : std::string("<non-name key>");
      const ParamSpec* spec = nullptr;
      for (const auto& s : g.params)
        if (s.name == key) spec = &s;
      if (!spec) {
        std::ostringstream m;
        m << ctx << " has no parameter '" << key << "' (accepted:";
        for (const auto& s : g.params) m << ' ' << s.name;
        m << ")";
        throw InputError(m.str());
      }
      const double v = toNumber(L, -1, ctx + " parameter '" + key + "'");
      lua_pop(L, 1);
      checkRange(g.name + "." + key, v, spec->min, spec->max, spec->unit);  // "parameter 'cup.diameter' = ..."
      values[key] = v;
    }
  }
  lua_pop(L, 1);
  for (const auto& s : g.params)
    if (!values.count(s.name)) throw InputError(ctx + " needs parameter '" + s.name + "'");
  return values;
}

int addMeshWall(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  RuntimeState& st = runtimeState(L);
  OptionTable opt(L, 2, "sim:add_mesh_wall");
  const bool has_part = opt.has("part"), has_file = opt.has("file");
  if (has_part == has_file) throw InputError("sim:add_mesh_wall: give either part = \"<name>\" or file = \"<mesh file>\"");
  auto plugins = st.pluginManager();

  TriangleMesh mesh;
  std::string default_name;
  if (has_part) {
    const std::string part = opt.string("part");
    const GeometryInfo& g = plugins->geometry(part);  // throws, listing the available parts
    const ParamValues values = partParams(L, opt, g);
    mesh = g.build(values);
    st.models_used.insert("geometry:" + part);
    default_name = part;
  } else {
    fs::path path = opt.string("file");
    if (path.is_relative()) {
      // The script's directory first; then the working directory (e.g. a file the script wrote
      // into a relative paddy.out_dir).
      const fs::path beside = fs::absolute(st.script).parent_path() / path;
      std::error_code ec;
      path = (!fs::exists(beside, ec) && fs::exists(path, ec)) ? fs::absolute(path) : beside;
    }
    path = path.lexically_normal();
    const MeshReaderInfo& reader = plugins->meshReader(path.extension().string());
    mesh = reader.read(path.string());
    st.models_used.insert("mesh_reader:" + reader.name);
    default_name = path.stem().string();
  }

  const double scale = opt.number("scale", 1.0);
  checkRange("sim:add_mesh_wall: scale", scale, 1e-12, 1e12);
  geometry::Pose placement;
  if (opt.push("rotate") != LUA_TNIL) {
    OptionTable rot(L, -1, "sim:add_mesh_wall: rotate");
    const Vec3 axis = rot.vec3("axis", Vec3::UnitZ());
    const double angle_deg = rot.number("angle");
    rot.finish();
    if (!(axis.norm() > 0.0)) throw InputError("sim:add_mesh_wall: rotate axis must not be zero");
    placement.R = geometry::axisRotation(axis, angle_deg * std::numbers::pi / 180.0);
  }
  lua_pop(L, 1);
  placement.x = opt.vec3("translate", Vec3::Zero());
  if (scale != 1.0) geometry::transformMesh(mesh, scale, Eigen::Matrix3d::Identity(), Vec3::Zero());

  opt.push("material");
  const int material = materialArg(L, h, -1, "sim:add_mesh_wall: material");
  lua_pop(L, 1);
  const std::string name = opt.string("name", default_name);
  Kinematics kin = Kinematics::still();
  if (opt.push("motion") != LUA_TNIL) kin = readMotion(L, -1, "sim:add_mesh_wall '" + name + "' motion", placement.x, 0.0);
  lua_pop(L, 1);
  opt.finish();
  lua_pushinteger(L, h.sim->addWall(std::make_unique<MeshWall>(name, material, std::move(mesh), placement, kin)));
  return 1;
}

int setMotion(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  MeshWall& w = meshWallArg(L, h, 2, "sim:set_motion");
  const double now = h.sim->time();
  const std::string ctx = "sim:set_motion '" + w.name() + "'";
  Kinematics k = readMotion(L, 3, ctx, w.placement().x, now);
  const bool fixed = k.speed.knots().empty() && k.angular_speed.knots().empty() && std::isinf(k.t_end) && k.t_start == 0.0;
  if (hasMoved(w)) {
    if (fixed) {
      // Stop where it is: the old motion, ended now.
      k = w.kinematics();
      k.t_end = std::max(k.t_start, std::min(k.t_end, now));
    } else {
      throw InputError(ctx + ": the wall has moved since it was placed; a new motion would start again from "
                       "its placement and make it jump. Give the whole motion at once (a schedule), or "
                       "call set_motion before the wall moves ({type=\"fixed\"} stops it where it is)");
    }
  }
  w.setKinematics(std::move(k));
  return 0;
}

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
  const MeshWall& w = meshWallArg(L, h, 2, "sim:wall_position");
  pushVec3(L, w.kinematics().unitDirection() * w.kinematics().distance(w.time()));
  return 1;
}

int recordWallLoads(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  const double t = h.sim->time();
  if (lua_isnoneornil(L, 2)) {
    for (std::size_t k = 0; k < h.sim->wallCount(); ++k)
      if (auto* m = dynamic_cast<MeshWall*>(&h.sim->wall(static_cast<int>(k)))) m->recordLoads(t);
  } else {
    meshWallArg(L, h, 2, "sim:record_wall_loads").recordLoads(t);
  }
  return 0;
}

int writeWallLoads(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  const MeshWall& w = meshWallArg(L, h, 2, "sim:write_wall_loads");
  fs::path path = toString(L, 3, "sim:write_wall_loads(wall, path): path");
  if (path.is_relative()) {
    const fs::path& out = runtimeState(L).out_dir;
    if (out.empty()) throw InputError("sim:write_wall_loads: no output directory for a relative path");
    path = out / path;
  }
  w.writeLoadHistoryCsv(path.string());
  lua_pushstring(L, path.string().c_str());
  return 1;
}

// paddy.parts() → the registered parts with their parameters.
int parts(lua_State* L) {
  auto plugins = runtimeState(L).pluginManager();
  const auto names = plugins->geometryNames();
  lua_createtable(L, static_cast<int>(names.size()), 0);
  int k = 0;
  for (const auto& n : names) {
    const GeometryInfo& g = plugins->geometry(n);
    lua_createtable(L, 0, 3);
    lua_pushstring(L, g.name.c_str());
    lua_setfield(L, -2, "name");
    lua_pushstring(L, g.description.c_str());
    lua_setfield(L, -2, "description");
    lua_createtable(L, static_cast<int>(g.params.size()), 0);
    int j = 0;
    for (const auto& s : g.params) {
      lua_createtable(L, 0, 6);
      lua_pushstring(L, s.name.c_str());
      lua_setfield(L, -2, "name");
      if (!s.required) {
        lua_pushnumber(L, s.default_value);
        lua_setfield(L, -2, "default");
      }
      lua_pushnumber(L, s.min);
      lua_setfield(L, -2, "min");
      lua_pushnumber(L, s.max);
      lua_setfield(L, -2, "max");
      lua_pushstring(L, s.unit.c_str());
      lua_setfield(L, -2, "unit");
      lua_pushstring(L, s.description.c_str());
      lua_setfield(L, -2, "description");
      lua_rawseti(L, -2, ++j);
    }
    lua_setfield(L, -2, "params");
    lua_rawseti(L, -2, ++k);
  }
  return 1;
}

const SimulationMethod reg_add{"add_mesh_wall", &guarded<addMeshWall>};
const SimulationMethod reg_motion{"set_motion", &guarded<setMotion>};
const SimulationMethod reg_force{"wall_force", &guarded<wallForce>};
const SimulationMethod reg_torque{"wall_torque", &guarded<wallTorque>};
const SimulationMethod reg_axial{"wall_axial_torque", &guarded<wallAxialTorque>};
const SimulationMethod reg_position{"wall_position", &guarded<wallPosition>};
const SimulationMethod reg_record{"record_wall_loads", &guarded<recordWallLoads>};
const SimulationMethod reg_write{"write_wall_loads", &guarded<writeWallLoads>};
const ModuleFunction reg_parts{"parts", &guarded<parts>};

}  // namespace

}  // namespace paddy::lua
