// Lua bindings of the measurement layer (paddy::measure, docs/measurement.md; Lua API in
// docs/experiments.md). Three groups, all self-registered (registry.hpp):
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
//   require("paddy.measure") — the same three (measure.slump_height(sim, {...}), ...) and the
//     array functions: herschel_bulkley, herschel_bulkley_stress, vane_torque_factor,
//     vane_shear_stress, vane_torque, vane_shear_rate, vane_flow_curve, vane_torque_hb,
//     rpm_to_rad, steady_torque, vane_startup, slump_yield_stress, slump_of_yield_stress,
//     slump, relative_error, relative_errors, coarse_grain, scaling_laws,
//     rayleigh_time, jkr_pull_off_force.
//   paddy.coarse_grain{alpha=, params={...}, laws={name = exponent | {exponent=, reason=} |
//                      "law name"}} → scaled params, rows (one per parameter). A law name is
//                      first looked up among the registered contact sub-models' parameters (the
//                      law each declares in its ParamSpec), then among the built-in laws; a
//                      parameter without a law falls back to the built-in law whose name is its
//                      longest '_' suffix (kept for scripts that give no laws).
//
// Lengths are SI (metres); relative picture paths are taken inside paddy.out_dir.
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"
#include "sim_handle.hpp"

#include <paddy/errors.hpp>
#include <paddy/lua/runtime.hpp>
#include <paddy/measure/measure.hpp>
#include <paddy/plugin_manager.hpp>
#include <paddy/measure/slump_yield_stress.hpp>
#include <paddy/measure/steady_torque.hpp>
#include <paddy/measure/vane_startup.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace paddy::lua {

namespace {

namespace fs = std::filesystem;
namespace pm = paddy::measure;

// ---- small readers / writers ------------------------------------------------------------------

// A Lua array of numbers at idx → vector (InputError naming `what`).
std::vector<double> toNumberArray(lua_State* L, int idx, const std::string& what) {
  idx = lua_absindex(L, idx);
  if (lua_type(L, idx) != LUA_TTABLE) throw InputError(what + " must be an array of numbers");
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, idx));
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(n));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, idx, i);
    const bool ok = lua_type(L, -1) == LUA_TNUMBER;
    const double v = lua_tonumber(L, -1);
    lua_pop(L, 1);
    if (!ok) throw InputError(what + "[" + std::to_string(i) + "] is not a number");
    out.push_back(v);
  }
  return out;
}

void setNumber(lua_State* L, const char* key, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, key);
}
void setInteger(lua_State* L, const char* key, long long v) {
  lua_pushinteger(L, static_cast<lua_Integer>(v));
  lua_setfield(L, -2, key);
}

// {x, y} or {x, y, z} (z ignored) → Vec2.
pm::Vec2 readAxis(lua_State* L, OptionTable& opt) {
  if (!opt.has("axis")) return pm::Vec2::Zero();
  opt.push("axis");
  const int idx = lua_gettop(L);
  const auto n = lua_type(L, idx) == LUA_TTABLE ? lua_rawlen(L, idx) : 0;
  if (n != 2 && n != 3) {
    lua_pop(L, 1);
    throw InputError(opt.context() + " option 'axis' must be {x, y} (or {x, y, z})");
  }
  pm::Vec2 a;
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
    lua_createtable(L, 0, 7);
    setNumber(L, "r_inner", bins[k].r_inner);
    setNumber(L, "r_outer", bins[k].r_outer);
    setNumber(L, "r", bins[k].r_centre);
    setNumber(L, "h", bins[k].height);
    setNumber(L, "coverage", bins[k].coverage);
    setInteger(L, "particles", static_cast<long long>(bins[k].particles));
    setInteger(L, "cells", static_cast<long long>(bins[k].cells));
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 1;
}

// ---- rheometer --------------------------------------------------------------------------------

// Vane geometry from a table {diameter=, height=, cup_diameter= (default ∞), sheared_ends=2}.
pm::VaneGeometry readVane(lua_State* L, int idx, const std::string& what) {
  OptionTable opt(L, idx, what + " vane");
  pm::VaneGeometry v;
  v.diameter = opt.number("diameter");
  v.height = opt.number("height");
  v.cup_diameter = opt.number("cup_diameter", std::numeric_limits<double>::infinity());
  v.sheared_ends = static_cast<int>(opt.integer("sheared_ends", 2));
  opt.finish();
  pm::vaneTorqueFactor(v);  // validates
  return v;
}

pm::HerschelBulkley readModel(lua_State* L, int idx, const std::string& what) {
  OptionTable opt(L, idx, what + " model");
  pm::HerschelBulkley m;
  m.tau0 = opt.number("tau0");
  m.K = opt.number("K");
  m.n = opt.number("n");
  for (const char* k : {"r2", "rmse", "evaluations"}) opt.accept(k);  // a fit result is a model too
  opt.finish();
  return m;
}

void pushFit(lua_State* L, const pm::HerschelBulkleyFit& f) {
  lua_createtable(L, 0, 6);
  setNumber(L, "tau0", f.model.tau0);
  setNumber(L, "K", f.model.K);
  setNumber(L, "n", f.model.n);
  setNumber(L, "r2", f.r2);
  setNumber(L, "rmse", f.rmse);
  setInteger(L, "evaluations", f.evaluations);
}

// herschel_bulkley{shear_rate={...}, stress={...}, n_min=0.05, n_max=2} → {tau0, K, n, r2, rmse, evaluations}
int herschelBulkley(lua_State* L) {
  OptionTable opt(L, 1, "measure.herschel_bulkley");
  pm::HerschelBulkleyOptions o;
  o.n_min = opt.number("n_min", o.n_min);
  o.n_max = opt.number("n_max", o.n_max);
  opt.push("shear_rate");
  const auto rate = toNumberArray(L, -1, "measure.herschel_bulkley: shear_rate");
  lua_pop(L, 1);
  opt.push("stress");
  const auto stress = toNumberArray(L, -1, "measure.herschel_bulkley: stress");
  lua_pop(L, 1);
  opt.finish();
  pushFit(L, pm::fitHerschelBulkley(rate, stress, o));
  return 1;
}

// herschel_bulkley_stress({tau0=, K=, n=}, shear_rate) → τ [Pa]
int herschelBulkleyStress(lua_State* L) {
  const auto m = readModel(L, 1, "measure.herschel_bulkley_stress");
  lua_pushnumber(L, m.stress(toNumber(L, 2, "measure.herschel_bulkley_stress: shear_rate")));
  return 1;
}

int vaneTorqueFactor(lua_State* L) {
  lua_pushnumber(L, pm::vaneTorqueFactor(readVane(L, 1, "measure.vane_torque_factor")));
  return 1;
}
int vaneShearStress(lua_State* L) {
  const auto v = readVane(L, 1, "measure.vane_shear_stress");
  lua_pushnumber(L, pm::vaneShearStress(toNumber(L, 2, "measure.vane_shear_stress: torque"), v));
  return 1;
}
int vaneTorque(lua_State* L) {
  const auto v = readVane(L, 1, "measure.vane_torque");
  lua_pushnumber(L, pm::vaneTorque(toNumber(L, 2, "measure.vane_torque: shear_stress"), v));
  return 1;
}
// vane_shear_rate(vane, omega [rad/s], n = 1)
int vaneShearRate(lua_State* L) {
  const auto v = readVane(L, 1, "measure.vane_shear_rate");
  const double omega = toNumber(L, 2, "measure.vane_shear_rate: omega");
  const double n = lua_isnoneornil(L, 3) ? 1.0 : toNumber(L, 3, "measure.vane_shear_rate: n");
  lua_pushnumber(L, pm::vaneShearRate(omega, v, n));
  return 1;
}
// vane_flow_curve{vane={...}, omega={...} [rad/s], torque={...} [N m]}
//   → {shear_rate={...}, shear_stress={...}, n_local={...}, fit={tau0, K, n, r2, rmse, evaluations}}
int vaneFlowCurve(lua_State* L) {
  OptionTable opt(L, 1, "measure.vane_flow_curve");
  opt.push("vane");
  const auto v = readVane(L, -1, "measure.vane_flow_curve");
  lua_pop(L, 1);
  opt.push("omega");
  const auto omega = toNumberArray(L, -1, "measure.vane_flow_curve: omega");
  lua_pop(L, 1);
  opt.push("torque");
  const auto torque = toNumberArray(L, -1, "measure.vane_flow_curve: torque");
  lua_pop(L, 1);
  opt.finish();
  const pm::VaneFlowCurve c = pm::vaneFlowCurve(omega, torque, v);
  lua_createtable(L, 0, 4);
  pushNumberArray(L, c.shear_rate);
  lua_setfield(L, -2, "shear_rate");
  pushNumberArray(L, c.shear_stress);
  lua_setfield(L, -2, "shear_stress");
  pushNumberArray(L, c.n_local);
  lua_setfield(L, -2, "n_local");
  pushFit(L, c.fit);
  lua_setfield(L, -2, "fit");
  return 1;
}
// vane_torque_hb(vane, {tau0=, K=, n=}, omega) → torque [N m] (forward model)
int vaneTorqueHb(lua_State* L) {
  const auto v = readVane(L, 1, "measure.vane_torque_hb");
  const auto m = readModel(L, 2, "measure.vane_torque_hb");
  lua_pushnumber(L, pm::vaneTorqueHerschelBulkley(toNumber(L, 3, "measure.vane_torque_hb: omega"), m, v));
  return 1;
}
// steady_torque{angle={...} [rad from the step start], torque={...} [N m], window_angle=, windows=,
//               min_angle=, alpha=, drift_tolerance=}
//   → {steady, reason, angle, complete_windows, compared_windows, mean, standard_error, trend,
//      trend_standard_error, trend_p_value, drift, window_means={...}}   (steady_torque.hpp)
int steadyTorque(lua_State* L) {
  OptionTable opt(L, 1, "measure.steady_torque");
  pm::SteadyTorqueOptions o;
  o.window_angle = opt.number("window_angle", o.window_angle);
  o.windows = static_cast<int>(opt.integer("windows", o.windows));
  o.min_angle = opt.number("min_angle", o.min_angle);
  o.alpha = opt.number("alpha", o.alpha);
  o.drift_tolerance = opt.number("drift_tolerance", o.drift_tolerance);
  opt.push("angle");
  const auto angle = toNumberArray(L, -1, "measure.steady_torque: angle");
  lua_pop(L, 1);
  opt.push("torque");
  const auto torque = toNumberArray(L, -1, "measure.steady_torque: torque");
  lua_pop(L, 1);
  opt.finish();
  const pm::SteadyTorqueResult r = pm::steadyTorque(angle, torque, o);
  lua_createtable(L, 0, 12);
  lua_pushboolean(L, r.steady);
  lua_setfield(L, -2, "steady");
  lua_pushstring(L, r.reason.c_str());
  lua_setfield(L, -2, "reason");
  setNumber(L, "angle", r.angle);
  setInteger(L, "complete_windows", r.complete_windows);
  setInteger(L, "compared_windows", r.compared_windows);
  setNumber(L, "mean", r.mean);
  setNumber(L, "standard_error", r.standard_error);
  setNumber(L, "trend", r.trend);
  setNumber(L, "trend_standard_error", r.trend_standard_error);
  setNumber(L, "trend_p_value", r.trend_p_value);
  setNumber(L, "drift", r.drift);
  pushNumberArray(L, r.window_means);
  lua_setfield(L, -2, "window_means");
  return 1;
}
// vane_startup{vane={...}, angle={...} [rad], torque={...} [N m], smoothing_angle=, drop_fraction=,
//              plateau_angle=} → {peak_torque, peak_angle, peak_reached, final_torque,
//              yield_stress, smoothed={...}}   (vane_startup.hpp)
int vaneStartup(lua_State* L) {
  OptionTable opt(L, 1, "measure.vane_startup");
  opt.push("vane");
  const auto v = readVane(L, -1, "measure.vane_startup");
  lua_pop(L, 1);
  pm::VaneStartupOptions o;
  o.smoothing_angle = opt.number("smoothing_angle", o.smoothing_angle);
  o.drop_fraction = opt.number("drop_fraction", o.drop_fraction);
  o.plateau_angle = opt.number("plateau_angle", o.plateau_angle);
  opt.push("angle");
  const auto angle = toNumberArray(L, -1, "measure.vane_startup: angle");
  lua_pop(L, 1);
  opt.push("torque");
  const auto torque = toNumberArray(L, -1, "measure.vane_startup: torque");
  lua_pop(L, 1);
  opt.finish();
  const pm::VaneStartupResult r = pm::vaneStartup(angle, torque, v, o);
  lua_createtable(L, 0, 6);
  setNumber(L, "peak_torque", r.peak_torque);
  setNumber(L, "peak_angle", r.peak_angle);
  lua_pushboolean(L, r.peak_reached);
  lua_setfield(L, -2, "peak_reached");
  setNumber(L, "final_torque", r.final_torque);
  setNumber(L, "yield_stress", r.yield_stress);
  pushNumberArray(L, r.smoothed);
  lua_setfield(L, -2, "smoothed");
  return 1;
}
// Slump mould {height=0.3, top_diameter=0.1, bottom_diameter=0.2} (GB/T 50080 cone by default)
// read from the same table as density= and gravity=9.81.
pm::SlumpMould readMould(OptionTable& opt) {
  pm::SlumpMould m;
  m.height = opt.number("height", m.height);
  m.top_diameter = opt.number("top_diameter", m.top_diameter);
  m.bottom_diameter = opt.number("bottom_diameter", m.bottom_diameter);
  return m;
}
// slump_yield_stress{slump= [m], density= [kg/m^3], gravity=9.81, height=, top_diameter=,
//                    bottom_diameter=} → τ_y [Pa]   (slump_yield_stress.hpp)
int slumpYieldStress(lua_State* L) {
  OptionTable opt(L, 1, "measure.slump_yield_stress");
  const double s = opt.number("slump");
  const double rho = opt.number("density");
  const double g = opt.number("gravity", 9.81);
  const pm::SlumpMould m = readMould(opt);
  opt.finish();
  lua_pushnumber(L, pm::yieldStressFromSlump(s, rho, g, m));
  return 1;
}
// slump_of_yield_stress{yield_stress= [Pa], density=, gravity=9.81, height=, ...} → slump [m]
int slumpOfYieldStress(lua_State* L) {
  OptionTable opt(L, 1, "measure.slump_of_yield_stress");
  const double tau = opt.number("yield_stress");
  const double rho = opt.number("density");
  const double g = opt.number("gravity", 9.81);
  const pm::SlumpMould m = readMould(opt);
  opt.finish();
  lua_pushnumber(L, pm::slumpFromYieldStress(tau, rho, g, m));
  return 1;
}

int rpmToRad(lua_State* L) {
  lua_pushnumber(L, pm::rpmToRadPerSecond(toNumber(L, 1, "measure.rpm_to_rad: rpm")));
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

// ---- coarse graining ----------------------------------------------------------------------------

// The built-in law whose name is the longest suffix of `name` ("mud_mud_rolling_friction" →
// rolling_friction, "jkr_surface_energy" → surface_energy, "particle_diameter" → diameter).
const pm::ScalingLaw* lawBySuffix(const std::string& name) {
  const pm::ScalingLaw* best = nullptr;
  for (const auto& l : pm::CoarseGraining::laws()) {
    const std::string& s = l.name;
    const bool whole = name == s;
    const bool suffix = name.size() > s.size() + 1 && name.compare(name.size() - s.size(), s.size(), s) == 0 &&
                        name[name.size() - s.size() - 1] == '_';
    if ((whole || suffix) && (!best || s.size() > best->name.size())) best = &l;
  }
  return best;
}

// The coarse-graining law a registered contact sub-model declares for its parameter `param`
// (ParamSpec::coarse_graining_exponent, beside the model that defines the parameter).
std::optional<pm::ScalingLaw> declaredContactLaw(lua_State* L, const std::string& param) {
  const auto plugins = runtimeState(L).pluginManager();
  for (SubModelKind kind : {SubModelKind::Normal, SubModelKind::Damping, SubModelKind::Tangential,
                            SubModelKind::Rolling, SubModelKind::Twisting, SubModelKind::Extra})
    for (const SubModelInfo* info : plugins->subModels(kind))
      for (const ParamSpec& p : info->params)
        if (p.name == param)
          return pm::ScalingLaw{param, p.coarse_graining_exponent,
                                std::string(toString(kind)) + " '" + info->name + "': " + p.coarse_graining_reason};
  return std::nullopt;
}

// paddy.coarse_grain{alpha=, params={name=value,...}, laws={name = exponent | "law" |
//                    {exponent=, reason=}}} → scaled {name=value}, rows {{name, law, reference,
//                    scaled, factor, exponent, changed, reason}, ...} (rows in name order)
int coarseGrain(lua_State* L) {
  OptionTable opt(L, 1, "coarse_grain");
  const double alpha = opt.number("alpha");
  // Explicit laws first.
  std::map<std::string, pm::ScalingLaw> explicit_laws;
  std::map<std::string, std::string> law_names;  // parameter → law name given as a string
  if (opt.push("laws") != LUA_TNIL) {
    if (!lua_istable(L, -1)) throw InputError("coarse_grain option 'laws' must be a table");
    const int t = lua_gettop(L);
    lua_pushnil(L);
    while (lua_next(L, t) != 0) {
      if (lua_type(L, -2) != LUA_TSTRING) throw InputError("coarse_grain: laws keys must be parameter names");
      const std::string name = lua_tostring(L, -2);
      pm::ScalingLaw law{name, 0.0, "given by the script"};
      if (lua_type(L, -1) == LUA_TNUMBER) {
        law.exponent = lua_tonumber(L, -1);
      } else if (lua_type(L, -1) == LUA_TSTRING) {
        // A contact sub-model's parameter name (its declared law) first, then a built-in law.
        const std::string law_name = lua_tostring(L, -1);
        if (const auto declared = declaredContactLaw(L, law_name)) {
          law.exponent = declared->exponent;
          law.reason = law_name + " (" + declared->reason + ")";
        } else {
          const pm::ScalingLaw& known = pm::CoarseGraining::law(law_name);
          law.exponent = known.exponent;
          law.reason = known.name + ": " + known.reason;
        }
        law_names[name] = law_name;
      } else if (lua_istable(L, -1)) {
        OptionTable lt(L, -1, "coarse_grain laws." + name);
        law.exponent = lt.number("exponent");
        law.reason = lt.string("reason", law.reason);
        lt.finish();
      } else {
        throw InputError("coarse_grain: laws." + name + " must be an exponent, a law name or {exponent=, reason=}");
      }
      explicit_laws[name] = law;
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
  ParamValues params;
  if (opt.push("params") != LUA_TTABLE) throw InputError("coarse_grain needs option 'params' (a table name = value)");
  const int t = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, t) != 0) {
    if (lua_type(L, -2) != LUA_TSTRING || lua_type(L, -1) != LUA_TNUMBER)
      throw InputError("coarse_grain: params must map names to numbers");
    params[lua_tostring(L, -2)] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  opt.finish();

  std::vector<pm::ScalingLaw> extra;
  std::map<std::string, std::string> law_of;  // parameter → law it follows
  for (const auto& [name, value] : params) {
    (void)value;
    if (auto it = explicit_laws.find(name); it != explicit_laws.end()) {
      extra.push_back(it->second);
      law_of[name] = law_names.count(name) ? law_names[name] : "given";
    } else if (const pm::ScalingLaw* l = lawBySuffix(name)) {
      if (l->name != name) extra.push_back({name, l->exponent, l->name + ": " + l->reason});
      law_of[name] = l->name;
    } else {
      std::string known;
      for (const auto& l : pm::CoarseGraining::laws()) known += (known.empty() ? "" : ", ") + l.name;
      throw InputError("coarse_grain: no scaling law for parameter '" + name + "' (known, also as a suffix " +
                       "'<prefix>_<law>': " + known + "); pass laws = {" + name + " = exponent}");
    }
  }
  const pm::ScaledParameters s = pm::scaleParameters(params, alpha, extra);
  lua_createtable(L, 0, static_cast<int>(s.values.size()));
  for (const auto& [name, value] : s.values) setNumber(L, name.c_str(), value);
  lua_createtable(L, static_cast<int>(s.table.size()), 0);
  for (std::size_t k = 0; k < s.table.size(); ++k) {
    const pm::ScalingRow& row = s.table[k];
    lua_createtable(L, 0, 8);
    lua_pushstring(L, row.name.c_str());
    lua_setfield(L, -2, "name");
    lua_pushstring(L, law_of[row.name].c_str());
    lua_setfield(L, -2, "law");
    setNumber(L, "reference", row.reference);
    setNumber(L, "scaled", row.scaled);
    setNumber(L, "factor", row.factor);
    setNumber(L, "exponent", row.exponent);
    lua_pushboolean(L, row.scaled != row.reference);
    lua_setfield(L, -2, "changed");
    lua_pushstring(L, row.reason.c_str());
    lua_setfield(L, -2, "reason");
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 2;
}

// scaling_laws() → {{name=, exponent=, reason=}, ...}
int scalingLaws(lua_State* L) {
  const auto& laws = pm::CoarseGraining::laws();
  lua_createtable(L, static_cast<int>(laws.size()), 0);
  for (std::size_t k = 0; k < laws.size(); ++k) {
    lua_createtable(L, 0, 3);
    lua_pushstring(L, laws[k].name.c_str());
    lua_setfield(L, -2, "name");
    setNumber(L, "exponent", laws[k].exponent);
    lua_pushstring(L, laws[k].reason.c_str());
    lua_setfield(L, -2, "reason");
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 1;
}

// ---- registration -----------------------------------------------------------------------------

const luaL_Reg kModule[] = {
    {"slump_height", &guarded<measureSlump>},
    {"slump_flow", &guarded<measureSlumpFlow>},
    {"pile_profile", &guarded<measureProfile>},
    {"herschel_bulkley", &guarded<herschelBulkley>},
    {"herschel_bulkley_stress", &guarded<herschelBulkleyStress>},
    {"vane_torque_factor", &guarded<vaneTorqueFactor>},
    {"vane_shear_stress", &guarded<vaneShearStress>},
    {"vane_torque", &guarded<vaneTorque>},
    {"vane_shear_rate", &guarded<vaneShearRate>},
    {"vane_flow_curve", &guarded<vaneFlowCurve>},
    {"vane_torque_hb", &guarded<vaneTorqueHb>},
    {"rpm_to_rad", &guarded<rpmToRad>},
    {"steady_torque", &guarded<steadyTorque>},
    {"vane_startup", &guarded<vaneStartup>},
    {"slump_yield_stress", &guarded<slumpYieldStress>},
    {"slump_of_yield_stress", &guarded<slumpOfYieldStress>},
    {"slump", &guarded<slumpOf>},
    {"relative_error", &guarded<relativeError>},
    {"relative_errors", &guarded<relativeErrors>},
    {"coarse_grain", &guarded<coarseGrain>},
    {"scaling_laws", &guarded<scalingLaws>},
    {"rayleigh_time", &guarded<rayleighTime>},
    {"jkr_pull_off_force", &guarded<jkrPullOff>},
    {nullptr, nullptr},
};

int openMeasure(lua_State* L) {
  luaL_newlib(L, kModule);
  return 1;
}

// require("paddy.measure"): registered at load time like the bindings below.
struct RegisterModule {
  RegisterModule() { addPreload("paddy.measure", &openMeasure); }
};
const RegisterModule reg_module;

const ModuleFunction reg_coarse_grain{"coarse_grain", &guarded<coarseGrain>};
const SimulationMethod reg_methods[] = {
    {"measure_slump", &guarded<measureSlump>},
    {"measure_slump_flow", &guarded<measureSlumpFlow>},
    {"measure_profile", &guarded<measureProfile>},
};

}  // namespace

}  // namespace paddy::lua
