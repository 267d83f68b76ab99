// Lua bindings of the rheometer relations (paddy::measure vane, Herschel–Bulkley, steady torque,
// vane start-up, slump yield stress; docs/measurement.md), part of require("paddy.measure")
// (measure_module.hpp): herschel_bulkley, herschel_bulkley_stress, vane_torque_factor,
// vane_shear_stress, vane_torque, vane_shear_rate, vane_flow_curve, vane_torque_hb, rpm_to_rad,
// steady_torque, vane_startup, slump_yield_stress, slump_of_yield_stress.
#include "lua_util.hpp"
#include "measure_module.hpp"

#include <paddy/errors.hpp>
#include <paddy/measure/measure.hpp>
#include <paddy/measure/slump_yield_stress.hpp>
#include <paddy/measure/steady_torque.hpp>
#include <paddy/measure/vane_startup.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace paddy::lua {

namespace {

namespace pm = paddy::measure;

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

}  // namespace

const luaL_Reg kRheometerFunctions[] = {
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
    {nullptr, nullptr},
};

}  // namespace paddy::lua
