// Lua bindings of the measurement layer (paddy::measure, docs/measurement.md; Lua API in
// docs/experiments.md), self-registered (registry.hpp):
//
//   sim methods — measures read the simulation's particles directly (no Lua arrays):
//     sim:measure_slump{cone_height=0.3, axis={x,y}, base_z=0, r_axis=, min_particles=10,
//                       quantile=1, largest_cluster=true, contact_gap=, material=}
//       → {slump, pile_height, r_axis, column, cluster, ignored}                      [m]
//     sim:measure_slump_flow{axis=, base_z=, pixel=5e-4, min_thickness=0, window_half_width=0,
//                            closing_radius=, ruler="axes"|"max_perpendicular", ruler_angle=0,
//                            material=, png=, title=, pgm=, pgm_layer="height"|"mask"|"component"}
//       → {diameter_fit, diameter_area, ruler={d1,d2,mean,angle}, circle={x,y,radius,rms,
//          iterations,converged}, centroid={x,y}, pixels, image={nx,ny,pixel}, png=, pgm=}
//     sim:measure_profile{axis=, base_z=, bin_width=, r_max=, cell_arc=, cell_quantile=0.5,
//                         largest_cluster=false, contact_gap=, material=}
//       → array of {r_inner, r_outer, r, h, coverage, particles, cells}
//   require("paddy.measure") — the same three (measure.slump_height(sim, {...}), ...), the
//     scalars slump, relative_error, relative_errors, rayleigh_time, jkr_pull_off_force, and the
//     rheometer (lua_rheometer.cpp) and coarse-graining (lua_coarse_graining.cpp) functions
//     (measure_module.hpp).
//
// Lengths are SI (metres); relative picture paths are taken inside paddy.out_dir.
#include "lua_util.hpp"
#include "measure_module.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"
#include "sim_handle.hpp"

#include <paddy/errors.hpp>
#include <paddy/lua/runtime.hpp>
#include <paddy/measure/measure.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace paddy::lua {

// Declared in measure_module.hpp.
Eigen::Vector2d readAxis(lua_State* L, OptionTable& opt) {
  if (!opt.has("axis")) return Eigen::Vector2d::Zero();
  opt.push("axis");
  const int idx = lua_gettop(L);
  const auto n = lua_type(L, idx) == LUA_TTABLE ? lua_rawlen(L, idx) : 0;
  if (n != 2 && n != 3) {
    lua_pop(L, 1);
    throw InputError(opt.context() + " option 'axis' must be {x, y} (or {x, y, z})");
  }
  Eigen::Vector2d a;
  bool ok = true;
  for (int k = 0; k < 2; ++k) {
    lua_rawgeti(L, idx, k + 1);
    ok = ok && lua_type(L, -1) == LUA_TNUMBER;
    a[k] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  if (!ok) throw InputError(opt.context() + " option 'axis' must hold numbers");
  return a;
}

namespace {

namespace fs = std::filesystem;
namespace pm = paddy::measure;

// ---- small readers / writers ------------------------------------------------------------------

// The simulation's particles (optionally of one material) as the measures take them.
struct Particles {
  std::vector<pm::Vec3> x;
  std::vector<double> r;
};

Particles readParticles(lua_State* L, SimHandle& h, OptionTable& opt) {
  std::optional<int> material;
  if (opt.has("material")) {
    opt.push("material");
    try {
      material = materialArg(L, h, -1, opt.context() + " option 'material'");
    } catch (...) {
      lua_pop(L, 1);
      throw;
    }
    lua_pop(L, 1);
  }
  const ParticleArrays& p = h.sim->particles();
  Particles out;
  out.x.reserve(p.size());
  out.r.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (material && p.material[i] != *material) continue;
    out.x.push_back(p.position[i]);
    out.r.push_back(p.radius[i]);
  }
  if (out.x.empty()) throw InputError(opt.context() + ": no particles to measure");
  return out;
}

fs::path outputPath(lua_State* L, const std::string& file) {
  fs::path path = file;
  if (path.is_relative()) {
    const fs::path& dir = runtimeState(L).out_dir;
    if (dir.empty()) throw InputError("no output directory: cannot write '" + file + "'");
    path = dir / path;
  }
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  return path;
}

// ---- particle measures (sim at 1, options at 2) -----------------------------------------------

int measureSlump(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  if (lua_isnoneornil(L, 2)) {
    lua_settop(L, 1);
    lua_newtable(L);
  }
  OptionTable opt(L, 2, "measure_slump");
  pm::SlumpHeightOptions o;
  const double cone_height = opt.number("cone_height", 0.3);
  o.axis = readAxis(L, opt);
  o.base_z = opt.number("base_z", 0.0);
  o.r_axis = opt.number("r_axis", 0.0);
  const long long minp = opt.integer("min_particles", 10);
  if (minp < 1) throw InputError("measure_slump: min_particles must be >= 1");
  o.min_particles = static_cast<std::size_t>(minp);
  o.quantile = opt.number("quantile", 1.0);
  o.largest_cluster = opt.boolean("largest_cluster", true);
  o.contact_gap = opt.number("contact_gap", -1.0);
  const Particles p = readParticles(L, h, opt);
  opt.finish();
  const pm::SlumpHeightResult res = pm::slumpHeight(p.x, p.r, o);
  lua_createtable(L, 0, 6);
  setNumber(L, "slump", pm::slump(cone_height, res.height));
  setNumber(L, "pile_height", res.height);
  setNumber(L, "r_axis", res.r_axis);
  setInteger(L, "column", static_cast<long long>(res.column));
  setInteger(L, "cluster", static_cast<long long>(res.cluster));
  setInteger(L, "ignored", static_cast<long long>(res.ignored));
  return 1;
}

int measureSlumpFlow(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  if (lua_isnoneornil(L, 2)) {
    lua_settop(L, 1);
    lua_newtable(L);
  }
  OptionTable opt(L, 2, "measure_slump_flow");
  pm::SlumpFlowOptions o;
  o.view.axis = readAxis(L, opt);
  o.view.base_z = opt.number("base_z", 0.0);
  o.view.pixel = opt.number("pixel", o.view.pixel);
  o.view.min_thickness = opt.number("min_thickness", 0.0);
  o.view.window_half_width = opt.number("window_half_width", 0.0);
  o.closing_radius = opt.number("closing_radius", -1.0);
  const std::string ruler = opt.string("ruler", "axes");
  if (ruler == "axes") o.ruler = pm::RulerMode::Axes;
  else if (ruler == "max_perpendicular") o.ruler = pm::RulerMode::MaxAndPerpendicular;
  else throw InputError("measure_slump_flow: ruler '" + ruler + "' is not one of axes, max_perpendicular");
  o.ruler_angle = opt.number("ruler_angle", 0.0);
  const std::string png = opt.string("png", "");
  const std::string title = opt.string("title", "");
  const std::string pgm = opt.string("pgm", "");
  const std::string layer = opt.string("pgm_layer", "height");
  pm::PgmLayer pgm_layer = pm::PgmLayer::Height;
  if (layer == "mask") pgm_layer = pm::PgmLayer::Mask;
  else if (layer == "component") pgm_layer = pm::PgmLayer::Component;
  else if (layer != "height")
    throw InputError("measure_slump_flow: pgm_layer '" + layer + "' is not one of height, mask, component");
  const Particles p = readParticles(L, h, opt);
  opt.finish();

  const pm::SlumpFlowResult res = pm::slumpFlow(p.x, p.r, o);
  std::string png_path, pgm_path;
  if (!png.empty()) {
    const fs::path path = outputPath(L, png);
    pm::plotSlumpFlow(res, path, title);
    png_path = path.string();
  }
  if (!pgm.empty()) {
    const fs::path path = outputPath(L, pgm);
    pm::writePgm(res, path, pgm_layer);
    pgm_path = path.string();
  }
  lua_createtable(L, 0, 10);
  setNumber(L, "diameter_fit", res.diameter_fit);
  setNumber(L, "diameter_area", res.diameter_area);
  lua_createtable(L, 0, 4);
  setNumber(L, "d1", res.ruler.d1);
  setNumber(L, "d2", res.ruler.d2);
  setNumber(L, "mean", res.ruler.mean);
  setNumber(L, "angle", res.ruler.angle);
  lua_setfield(L, -2, "ruler");
  lua_createtable(L, 0, 6);
  setNumber(L, "x", res.circle.centre.x());
  setNumber(L, "y", res.circle.centre.y());
  setNumber(L, "radius", res.circle.radius);
  setNumber(L, "rms", res.circle.rms);
  setInteger(L, "iterations", res.circle.iterations);
  lua_pushboolean(L, res.circle.converged);
  lua_setfield(L, -2, "converged");
  lua_setfield(L, -2, "circle");
  lua_createtable(L, 0, 2);
  setNumber(L, "x", res.centroid.x());
  setNumber(L, "y", res.centroid.y());
  lua_setfield(L, -2, "centroid");
  setInteger(L, "pixels", static_cast<long long>(res.component_pixels));
  lua_createtable(L, 0, 3);
  setInteger(L, "nx", res.image.nx);
  setInteger(L, "ny", res.image.ny);
  setNumber(L, "pixel", res.image.pixel);
  lua_setfield(L, -2, "image");
  if (!png_path.empty()) lua_pushstring(L, png_path.c_str()), lua_setfield(L, -2, "png");
  if (!pgm_path.empty()) lua_pushstring(L, pgm_path.c_str()), lua_setfield(L, -2, "pgm");
  return 1;
}

int measureProfile(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  if (lua_isnoneornil(L, 2)) {
    lua_settop(L, 1);
    lua_newtable(L);
  }
  OptionTable opt(L, 2, "measure_profile");
  pm::ProfileOptions o;
  o.axis = readAxis(L, opt);
  o.base_z = opt.number("base_z", 0.0);
  o.bin_width = opt.number("bin_width", 0.0);
  o.r_max = opt.number("r_max", 0.0);
  o.cell_arc = opt.number("cell_arc", 0.0);
  o.cell_quantile = opt.number("cell_quantile", 0.5);
  o.largest_cluster = opt.boolean("largest_cluster", false);
  o.contact_gap = opt.number("contact_gap", -1.0);
  const Particles p = readParticles(L, h, opt);
  opt.finish();
  const auto bins = pm::pileProfile(p.x, p.r, o);
  lua_createtable(L, static_cast<int>(bins.size()), 0);
  for (std::size_t k = 0; k < bins.size(); ++k) {
    lua_createtable(L, 0, 8);
    setNumber(L, "r_inner", bins[k].r_inner);
    setNumber(L, "r_outer", bins[k].r_outer);
    setNumber(L, "r", bins[k].r_centre);
    setNumber(L, "h", bins[k].height);
    setNumber(L, "h_mean", bins[k].mean_height);
    setNumber(L, "coverage", bins[k].coverage);
    setInteger(L, "particles", static_cast<long long>(bins[k].particles));
    setInteger(L, "cells", static_cast<long long>(bins[k].cells));
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 1;
}

// ---- scalars, errors ----------------------------------------------------------------------------

int slumpOf(lua_State* L) {
  lua_pushnumber(L, pm::slump(toNumber(L, 1, "measure.slump: cone_height"),
                              toNumber(L, 2, "measure.slump: pile_height")));
  return 1;
}
int relativeError(lua_State* L) {
  lua_pushnumber(L, pm::relativeError(toNumber(L, 1, "measure.relative_error: measured"),
                                      toNumber(L, 2, "measure.relative_error: simulated")));
  return 1;
}
// relative_errors(measured={...}, simulated={...}) → {per_point={...}, mean, max}
int relativeErrors(lua_State* L) {
  const auto m = toNumberArray(L, 1, "measure.relative_errors: measured");
  const auto s = toNumberArray(L, 2, "measure.relative_errors: simulated");
  const pm::RelativeErrors e = pm::relativeErrors(m, s);
  lua_createtable(L, 0, 3);
  pushNumberArray(L, e.per_point);
  lua_setfield(L, -2, "per_point");
  setNumber(L, "mean", e.mean);
  setNumber(L, "max", e.max);
  return 1;
}
int rayleighTime(lua_State* L) {
  lua_pushnumber(L, pm::CoarseGraining::rayleighTime(toNumber(L, 1, "measure.rayleigh_time: radius"),
                                                     toNumber(L, 2, "measure.rayleigh_time: density"),
                                                     toNumber(L, 3, "measure.rayleigh_time: shear_modulus"),
                                                     toNumber(L, 4, "measure.rayleigh_time: poisson")));
  return 1;
}
int jkrPullOff(lua_State* L) {
  lua_pushnumber(L, pm::CoarseGraining::jkrPullOffForce(toNumber(L, 1, "measure.jkr_pull_off_force: surface_energy"),
                                                        toNumber(L, 2, "measure.jkr_pull_off_force: r_eff")));
  return 1;
}

// ---- registration -----------------------------------------------------------------------------

const luaL_Reg kModule[] = {
    {"slump_height", &guarded<measureSlump>},
    {"slump_flow", &guarded<measureSlumpFlow>},
    {"pile_profile", &guarded<measureProfile>},
    {"slump", &guarded<slumpOf>},
    {"relative_error", &guarded<relativeError>},
    {"relative_errors", &guarded<relativeErrors>},
    {"rayleigh_time", &guarded<rayleighTime>},
    {"jkr_pull_off_force", &guarded<jkrPullOff>},
    {nullptr, nullptr},
};

int openMeasure(lua_State* L) {
  luaL_newlib(L, kModule);
  luaL_setfuncs(L, kRheometerFunctions, 0);
  luaL_setfuncs(L, kCoarseGrainingFunctions, 0);
  return 1;
}

// require("paddy.measure"): registered at load time like the bindings below.
struct RegisterModule {
  RegisterModule() { addPreload("paddy.measure", &openMeasure); }
};
const RegisterModule reg_module;

const SimulationMethod reg_methods[] = {
    {"measure_slump", &guarded<measureSlump>},
    {"measure_slump_flow", &guarded<measureSlumpFlow>},
    {"measure_profile", &guarded<measureProfile>},
};

}  // namespace

}  // namespace paddy::lua
