// Mesh walls from Lua: parts and mesh files as moving walls, and their motion. Their loads are
// in lua_wall_loads.cpp.
//
//   sim:add_mesh_wall{name=, material=, part="slump_cone", params={...}  or  file="x.stl",
//                     scale=1, rotate={axis={0,0,1}, angle=deg}, translate={x,y,z}, motion={...}}
//                                                        → wall index (as sim:add_wall)
//   sim:set_motion(w, motion)        from now on follow `motion`, starting from the current pose
//                                    (start defaults to the current time)
//   sim:wall_pose(w) → {origin={x,y,z}, rotation={{..},{..},{..}}, distance=, angle=}
//   paddy.parts()                    → {{name=, description=, params={{name=, default=, ...}}}}
//
// Motion tables: {type="fixed"}, {type="translate", velocity={..} | direction={..} schedule=...,
// start=, stop=}, {type="rotate", point=, axis=, speed=rad/s | rpm= | schedule={{t,ω},...},
// start=, stop=}. Schedules are piecewise linear in absolute time (two knots at one time: a step).
// set_motion re-bases the wall (geometry::Motion::change): the new motion moves it from the pose
// it has now, exactly (closed forms, no time-stepping error), and distance and angle keep
// accumulating. "fixed" keeps the torque origin and axis, so a stopped vane still reports its
// axial torque.
// The mesh file is read by the reader a plugin registered for its extension (the engine does
// not link CGAL); scale and placement are applied here, identically for parts and files.
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"
#include "sim_handle.hpp"
#include "wall_args.hpp"

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
                      double default_start, bool* fixed = nullptr) {
  OptionTable opt(L, idx, ctx);
  const std::string type = opt.string("type");
  if (fixed) *fixed = type == "fixed";
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
  // The rotation point defaults to where the wall's origin is now.
  bool fixed = false;
  Kinematics k = readMotion(L, 3, ctx, w.pose().x, now, &fixed);
  if (fixed) {
    // Stop where it is, keeping the torque origin and axis (axial torque of a stopped vane).
    k.axis_point = w.torqueOrigin();
    k.axis = w.axis();
  }
  w.changeKinematics(now, std::move(k));
  return 0;
}

// sim:wall_pose(w): body → world (world = rotation · X + origin) and the accumulated motion.
int wallPose(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  const MeshWall& w = meshWallArg(L, h, 2, "sim:wall_pose");
  const geometry::Pose& p = w.pose();
  lua_createtable(L, 0, 4);
  pushVec3(L, p.x);
  lua_setfield(L, -2, "origin");
  lua_createtable(L, 3, 0);
  for (int r = 0; r < 3; ++r) {
    pushNumberArray(L, {p.R(r, 0), p.R(r, 1), p.R(r, 2)});
    lua_rawseti(L, -2, r + 1);
  }
  lua_setfield(L, -2, "rotation");
  lua_pushnumber(L, w.distanceTravelled());
  lua_setfield(L, -2, "distance");
  lua_pushnumber(L, w.angleTurned());
  lua_setfield(L, -2, "angle");
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
const SimulationMethod reg_pose{"wall_pose", &guarded<wallPose>};
const ModuleFunction reg_parts{"parts", &guarded<parts>};

}  // namespace

}  // namespace paddy::lua
