#include <paddy/lua/doe.hpp>

#include "paddy/doe/box_behnken.hpp"
#include "paddy/doe/central_composite.hpp"
#include "paddy/doe/csv.hpp"
#include "paddy/doe/discovery_json.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/factorial.hpp"
#include "paddy/doe/plackett_burman.hpp"
#include "paddy/doe/plots.hpp"
#include "paddy/doe/surrogate_calibration.hpp"
#include "paddy/doe/report_json.hpp"

#include <cmath>
#include <cstdio>
#include <lua.hpp>

namespace paddy::doe {
namespace {

using nlohmann::json;

void push(lua_State* L, const json& j) {
  switch (j.type()) {
    case json::value_t::null: lua_pushnil(L); break;
    case json::value_t::boolean: lua_pushboolean(L, j.get<bool>()); break;
    case json::value_t::number_integer:
    case json::value_t::number_unsigned: lua_pushinteger(L, j.get<lua_Integer>()); break;
    case json::value_t::number_float: lua_pushnumber(L, j.get<double>()); break;
    case json::value_t::string: lua_pushstring(L, j.get<std::string>().c_str()); break;
    case json::value_t::array: {
      lua_createtable(L, static_cast<int>(j.size()), 0);
      lua_Integer i = 1;
      for (const auto& e : j) {
        push(L, e);
        lua_rawseti(L, -2, i++);
      }
      break;
    }
    case json::value_t::object: {
      lua_createtable(L, 0, static_cast<int>(j.size()));
      for (const auto& [k, v] : j.items()) {
        push(L, v);
        lua_setfield(L, -2, k.c_str());
      }
      break;
    }
    default: lua_pushnil(L);
  }
}

json toJson(lua_State* L, int idx, int depth = 0) {
  idx = lua_absindex(L, idx);
  if (depth > 50) throw DoeError("table nesting too deep");
  switch (lua_type(L, idx)) {
    case LUA_TNIL: return nullptr;
    case LUA_TBOOLEAN: return lua_toboolean(L, idx) != 0;
    case LUA_TNUMBER:
      if (lua_isinteger(L, idx)) return static_cast<long long>(lua_tointeger(L, idx));
      return lua_tonumber(L, idx);
    case LUA_TSTRING: return std::string(lua_tostring(L, idx));
    case LUA_TTABLE: {
      const auto n = lua_rawlen(L, idx);
      bool isArray = n > 0;
      json obj = json::object();
      lua_pushnil(L);
      while (lua_next(L, idx) != 0) {
        std::string key;
        if (lua_type(L, -2) == LUA_TSTRING) {
          key = lua_tostring(L, -2);
          isArray = false;
        } else if (lua_type(L, -2) == LUA_TNUMBER) {
          char buf[64];
          std::snprintf(buf, sizeof buf, "%.17g", static_cast<double>(lua_tonumber(L, -2)));
          key = buf;
        } else {
          lua_pop(L, 2);
          throw DoeError("table keys must be strings or numbers");
        }
        obj[key] = toJson(L, -1, depth + 1);
        lua_pop(L, 1);
      }
      if (!isArray) return obj;
      json arr = json::array();
      for (lua_Integer i = 1; i <= static_cast<lua_Integer>(n); ++i) {
        lua_rawgeti(L, idx, i);
        arr.push_back(toJson(L, -1, depth + 1));
        lua_pop(L, 1);
      }
      return arr;
    }
    default: throw DoeError(std::string("unsupported Lua value of type ") + lua_typename(L, lua_type(L, idx)));
  }
}

json options(lua_State* L) {
  if (lua_type(L, 1) != LUA_TTABLE) throw DoeError("expected one table of options");
  return toJson(L, 1);
}

std::vector<std::string> strings(const json& j, const std::string& what) {
  std::vector<std::string> v;
  if (j.is_string()) return {j.get<std::string>()};
  if (!j.is_array()) throw DoeError(what + " must be a list of names");
  for (const auto& e : j) {
    if (!e.is_string()) throw DoeError(what + " must contain strings");
    v.push_back(e.get<std::string>());
  }
  return v;
}

double number(const json& j, const std::string& what) {
  if (!j.is_number()) throw DoeError(what + " must be a number");
  return j.get<double>();
}

std::pair<double, double> range(const json& j, const std::string& what) {
  if (!j.is_array() || j.size() != 2) throw DoeError(what + " must be {low, high}");
  return {number(j[0], what), number(j[1], what)};
}

json design(const json& o) {
  const std::string type = o.value("type", "");
  std::vector<std::string> names;
  if (o.contains("names")) names = strings(o["names"], "names");
  const int k = names.empty() ? o.value("factors", 0) : static_cast<int>(names.size());
  if (k < 1) throw DoeError("give factors=N or names={...}");
  Design d;
  if (type == "pb") d = plackettBurman(o.value("runs", plackettBurmanRunsFor(k)), k);
  else if (type == "bbd") d = boxBehnken(k, 0);
  else if (type == "factorial")
    d = o.contains("generators") ? fractionalFactorial(k, strings(o["generators"], "generators")) : fullFactorial(k);
  else if (type == "ccd") {
    CcdOptions c;
    const std::string t = o.value("ccd_type", "circumscribed");
    if (t == "inscribed") c.type = CcdType::Inscribed;
    else if (t == "face") c.type = CcdType::FaceCentred;
    else if (t != "circumscribed") throw DoeError("ccd_type must be circumscribed, inscribed or face");
    if (o.contains("alpha")) {
      if (o["alpha"].is_number()) c.alpha = o["alpha"].get<double>();
      else if (o["alpha"] == "face") c.type = CcdType::FaceCentred;
      else if (o["alpha"] != "rotatable") throw DoeError("alpha must be a number, \"rotatable\" or \"face\"");
    }
    if (o.contains("generators")) c.generators = strings(o["generators"], "generators");
    d = centralComposite(k, c);
  } else throw DoeError("type must be pb, bbd, ccd or factorial");
  addCenterPoints(d, o.value("center", 0));
  auto f = defaultFactors(k);
  for (int j = 0; j < k && !names.empty(); ++j) f[j].name = names[j];
  if (o.contains("levels"))
    for (const auto& [name, lv] : o["levels"].items()) {
      bool found = false;
      for (auto& x : f)
        if (x.name == name) {
          std::tie(x.low, x.high) = range(lv, "levels." + name);
          found = true;
        }
      if (!found) throw DoeError("levels given for unknown factor '" + name + "'");
    }
  setFactors(d, f);
  d = replicate(d, o.value("replicates", 1));
  if (o.contains("seed")) randomize(d, static_cast<std::uint64_t>(o["seed"].get<long long>()));
  return designToJson(d);
}

json analyze(const json& o) {
  AnalysisRequest req;
  req.factors = strings(o.value("factors", json::array()), "factors");
  req.responses = strings(o.value("responses", json::array()), "responses");
  req.model = o.value("model", "linear");
  if (o.contains("levels"))
    for (const auto& [name, lv] : o["levels"].items()) req.levels[name] = range(lv, "levels." + name);
  if (!o.contains("data") || !o["data"].is_array()) throw DoeError("data must be an array of rows");
  Table t;
  t.source = "data";
  t.columns = req.factors;
  t.columns.insert(t.columns.end(), req.responses.begin(), req.responses.end());
  int row = 0;
  for (const auto& r : o["data"]) {
    ++row;
    std::vector<std::string> cells;
    for (const auto& c : t.columns) {
      if (!r.is_object() || !r.contains(c) || r[c].is_null())
        throw DoeError("data row " + std::to_string(row) + ": missing value for '" + c + "'");
      if (!r[c].is_number())
        throw DoeError("data row " + std::to_string(row) + ", column '" + c + "': not a number");
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.17g", r[c].get<double>());
      cells.push_back(buf);
    }
    t.cells.push_back(cells);
    t.lines.push_back(row);
  }
  const Analysis a = analyzeTable(t, req);
  json out = analysisToJson(a);
  if (o.contains("plots")) out["plots"] = plotAnalysis(o["plots"].get<std::string>(), a);
  return out;
}

json optimize(const json& o) {
  if (!o.contains("fit")) throw DoeError("fit (the result of analyze) is required");
  const FitModels fit = fitFromJson(o["fit"]);
  std::vector<GoalSpec> goals;
  for (const auto& g : o.value("goals", json::array())) {
    if (g.is_string()) {
      const std::string s = g.get<std::string>();
      const auto& r = fit.response(s.substr(0, s.find('=')));
      goals.push_back(parseGoal(s, r.yMin, r.yMax));
      continue;
    }
    GoalSpec gs;
    gs.response = g.value("response", "");
    const auto& r = fit.response(gs.response);
    const std::string kind = g.value("goal", "target");
    if (kind == "target") gs.goal = Goal::Target;
    else if (kind == "max" || kind == "maximize") gs.goal = Goal::Maximize;
    else if (kind == "min" || kind == "minimize") gs.goal = Goal::Minimize;
    else if (kind == "range") gs.goal = Goal::InRange;
    else throw DoeError("goal must be target, max, min or range");
    gs.lower = g.value("lower", r.yMin);
    gs.upper = g.value("upper", r.yMax);
    gs.target = g.value("target", 0.5 * (gs.lower + gs.upper));
    gs.weight1 = g.value("weight", 1.0);
    gs.weight2 = g.value("weight2", gs.weight1);
    gs.importance = g.value("importance", 3);
    goals.push_back(gs);
  }
  const int k = static_cast<int>(fit.factors.size());
  OptimizeOptions opt;
  opt.starts = o.value("starts", 40);
  opt.seed = o.value("seed", 12345ULL);
  opt.lowerCoded.resize(k);
  opt.upperCoded.resize(k);
  for (int j = 0; j < k; ++j) {
    auto [lo, hi] = std::pair{fit.dataMin[j], fit.dataMax[j]};
    if (o.contains("bounds") && o["bounds"].contains(fit.factors[j].name))
      std::tie(lo, hi) = range(o["bounds"][fit.factors[j].name], "bounds." + fit.factors[j].name);
    opt.lowerCoded(j) = fit.factors[j].toCoded(lo);
    opt.upperCoded(j) = fit.factors[j].toCoded(hi);
  }
  json out = solutionsToJson(fit, goals, optimizeDesirability(fit.factors, fit.responses, goals, opt));
  if (o.contains("plots")) out["plots"] = plotDesirabilityRamps(o["plots"].get<std::string>(), goals);
  return out;
}

std::vector<Factor> boxFactors(const json& o) {
  std::vector<Factor> f;
  for (const auto& x : o.value("factors", json::array())) {
    Factor fx{x.value("name", ""), number(x.value("low", json()), "factors[].low"), number(x.value("high", json()), "factors[].high")};
    if (fx.name.empty()) throw DoeError("every factor needs a name");
    if (!(fx.high > fx.low)) throw DoeError("factor '" + fx.name + "': high must be greater than low");
    f.push_back(fx);
  }
  if (f.empty()) throw DoeError("factors = {{name =, low =, high =}, ...} is required");
  return f;
}

// Rows of factor values → unit-cube coordinates of the factors' box.
Eigen::MatrixXd unitPoints(const json& rows, const std::vector<Factor>& f, const std::string& what) {
  if (!rows.is_array()) throw DoeError(what + " must be an array of rows");
  Eigen::MatrixXd X(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(f.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string where = what + " row " + std::to_string(i + 1);
    for (std::size_t j = 0; j < f.size(); ++j) {
      if (!rows[i].contains(f[j].name)) throw DoeError(where + ": missing value for '" + f[j].name + "'");
      const double x = number(rows[i][f[j].name], where + ", " + f[j].name);
      X(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = (x - f[j].low) / (f[j].high - f[j].low);
    }
  }
  return X;
}

// Rows' values of the responses → one column per response.
Eigen::MatrixXd responseColumns(const json& rows, const std::vector<std::string>& responses) {
  Eigen::MatrixXd Y(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(responses.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string where = "data row " + std::to_string(i + 1);
    for (std::size_t r = 0; r < responses.size(); ++r) {
      if (!rows[i].contains(responses[r])) throw DoeError(where + ": missing value for '" + responses[r] + "'");
      Y(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(r)) = number(rows[i][responses[r]], where + ", " + responses[r]);
    }
  }
  return Y;
}

json hyperJson(const GpHyperparameters& h, const std::vector<Factor>& f) {
  json jh{{"signal_variance", h.signal_variance}, {"noise_variance", h.noise_variance}};
  for (std::size_t j = 0; j < f.size(); ++j) {
    const auto k = static_cast<Eigen::Index>(j);
    jh["length_scales"][f[j].name] = h.length_scales(k);
    if (h.warp_a.size() != 0) jh["warp_a"][f[j].name] = h.warp_a(k), jh["warp_b"][f[j].name] = h.warp_b(k);
  }
  return jh;
}

GpHyperparameters hyperFromJson(const json& j, const std::vector<Factor>& f) {
  GpHyperparameters h;
  const auto d = static_cast<Eigen::Index>(f.size());
  h.length_scales.resize(d);
  const bool warped = j.contains("warp_a");
  if (warped) h.warp_a.resize(d), h.warp_b.resize(d);
  for (Eigen::Index k = 0; k < d; ++k) {
    const std::string& name = f[static_cast<std::size_t>(k)].name;
    if (!j.contains("length_scales") || !j["length_scales"].contains(name))
      throw DoeError("hyperparameters.length_scales: no value for '" + name + "'");
    h.length_scales(k) = number(j["length_scales"][name], "hyperparameters.length_scales." + name);
    if (warped) {
      if (!j["warp_a"].contains(name) || !j.contains("warp_b") || !j["warp_b"].contains(name))
        throw DoeError("hyperparameters.warp_a/warp_b: no value for '" + name + "'");
      h.warp_a(k) = number(j["warp_a"][name], "hyperparameters.warp_a." + name);
      h.warp_b(k) = number(j["warp_b"][name], "hyperparameters.warp_b." + name);
    }
  }
  h.signal_variance = number(j.value("signal_variance", json()), "hyperparameters.signal_variance");
  h.noise_variance = number(j.value("noise_variance", json()), "hyperparameters.noise_variance");
  return h;
}

// csv_fields{line = "...", where = "file line N"} → the fields of one CSV line (csv.hpp: quoted
// fields may hold commas and doubled quotes; an unterminated quote is an error naming `where`).
json csvFields(const json& o) {
  if (!o.contains("line") || !o["line"].is_string()) throw DoeError("line = text is required");
  return splitCsvLine(o["line"].get<std::string>(), o.value("where", std::string("<csv>")));
}

// gaussian_process{factors = {{name =, low =, high =}, ...}, data = {rows}, response = name,
//                  warp_inputs = false, seed = 1, hyperparameters = (as returned: fixed, not fitted),
//                  points = {rows}} → {hyperparameters =, log_likelihood =,
//                  predictions = {{mean =, sd =}, ...}} (sd of the latent function, noise excluded)
json gaussianProcess(const json& o) {
  const auto f = boxFactors(o);
  const std::string response = o.value("response", "");
  if (response.empty()) throw DoeError("response = name is required");
  if (!o.contains("data")) throw DoeError("data must be an array of rows");
  const Eigen::MatrixXd X = unitPoints(o["data"], f, "data");
  const Eigen::VectorXd y = responseColumns(o["data"], {response}).col(0);
  GaussianProcess gp;
  if (o.contains("hyperparameters") && !o["hyperparameters"].is_null()) {
    gp.fitFixed(X, y, hyperFromJson(o["hyperparameters"], f));
  } else {
    GpFitOptions fo;
    fo.seed = o.value("seed", 1ULL);
    fo.warp_inputs = o.value("warp_inputs", false);
    gp.fit(X, y, fo);
  }
  json out{{"hyperparameters", hyperJson(gp.hyperparameters(), f)}, {"log_likelihood", gp.logMarginalLikelihood()}};
  out["predictions"] = json::array();
  if (o.contains("points")) {
    const Eigen::MatrixXd P = unitPoints(o["points"], f, "points");
    for (Eigen::Index i = 0; i < P.rows(); ++i) {
      const auto p = gp.predict(P.row(i).transpose());
      out["predictions"].push_back({{"mean", p.mean}, {"sd", p.sd()}});
    }
  }
  return out;
}

// surrogate_suggest{factors = {{name =, low =, high =}, ...}, data = {rows}, responses = {...},
//                   targets = {resp = value}, batch =, seed =, samples =, candidates =,
//                   warp_inputs = false}
json surrogate(const json& o) {
  const auto f = boxFactors(o);
  const auto responses = strings(o.value("responses", json::array()), "responses");
  if (responses.empty()) throw DoeError("responses = {...} is required");
  if (!o.contains("targets") || !o["targets"].is_object()) throw DoeError("targets = {response = value} is required");
  Eigen::VectorXd targets(static_cast<Eigen::Index>(responses.size()));
  for (std::size_t r = 0; r < responses.size(); ++r) {
    if (!o["targets"].contains(responses[r])) throw DoeError("targets: no value for response '" + responses[r] + "'");
    targets(static_cast<Eigen::Index>(r)) = number(o["targets"][responses[r]], "targets." + responses[r]);
  }
  if (!o.contains("data") || !o["data"].is_array()) throw DoeError("data must be an array of rows");
  const auto& data = o["data"];
  const Eigen::MatrixXd X = unitPoints(data, f, "data");
  const Eigen::MatrixXd Y = responseColumns(data, responses);
  SurrogateOptions so;
  so.batch = o.value("batch", 1);
  so.samples = o.value("samples", so.samples);
  so.candidates = o.value("candidates", so.candidates);
  so.seed = o.value("seed", 1ULL);
  so.gp.seed = so.seed;
  so.gp.warp_inputs = o.value("warp_inputs", false);
  const SurrogateStep step = suggestCalibrationPoints(X, Y, targets, so);
  json out;
  out["incumbent_error"] = step.incumbent_error;
  out["incumbent_index"] = step.incumbent_index + 1;
  out["suggestions"] = json::array();
  for (const auto& s : step.suggestions) {
    json js;
    for (std::size_t j = 0; j < f.size(); ++j) {
      const double u = s.x(static_cast<Eigen::Index>(j));
      js["factors"][f[j].name] = f[j].low + u * (f[j].high - f[j].low);
      js["unit"][f[j].name] = u;
    }
    for (std::size_t r = 0; r < responses.size(); ++r)
      js["predicted"][responses[r]] = {{"mean", s.predicted[r].mean}, {"sd", s.predicted[r].sd()}};
    js["expected_improvement"] = s.expected_improvement;
    js["predicted_error"] = s.predicted_error;
    out["suggestions"].push_back(js);
  }
  for (std::size_t r = 0; r < responses.size(); ++r) out["hyperparameters"][responses[r]] = hyperJson(step.hyperparameters[r], f);
  return out;
}

json steepest(const json& o) {
  std::vector<Factor> f;
  for (const auto& x : o.value("factors", json::array()))
    f.push_back({x.value("name", ""), x.value("low", -1.0), x.value("high", 1.0)});
  const auto& c = o.value("coefficients", json::array());
  if (f.empty() || c.size() != f.size()) throw DoeError("need factors and one coefficient per factor");
  Eigen::VectorXd b(f.size());
  for (std::size_t j = 0; j < f.size(); ++j) b(static_cast<Eigen::Index>(j)) = number(c[j], "coefficients");
  PathOptions p;
  p.ascent = !o.value("descent", false);
  p.steps = o.value("steps", 5);
  if (o.contains("key")) {
    const std::string key = o["key"].get<std::string>();
    for (std::size_t j = 0; j < f.size(); ++j)
      if (f[j].name == key) p.keyFactor = static_cast<int>(j);
    if (!p.keyFactor) throw DoeError("key factor '" + key + "' is not among the factors");
  }
  p.keyStep = o.value("step", 1.0);
  p.keyStepReal = o.value("real", false);
  for (const auto& s : o.value("real_steps", json::array())) p.realSteps.push_back(number(s, "real_steps"));
  if (o.contains("origin")) {
    Eigen::VectorXd org(f.size());
    if (o["origin"].size() != f.size()) throw DoeError("origin needs one value per factor");
    for (std::size_t j = 0; j < f.size(); ++j) org(static_cast<Eigen::Index>(j)) = number(o["origin"][j], "origin");
    p.originReal = org;
  }
  return pathToJson(f, steepestPath(f, b, p));
}

template <json (*F)(const json&)>
int wrap(lua_State* L, const char* name) {
  {
    std::string msg;
    try {
      const json result = F(options(L));
      push(L, result);
      return 1;
    } catch (const std::exception& e) {
      msg = e.what();
    }
    lua_pushfstring(L, "paddy.doe.%s: %s", name, msg.c_str());
  }
  return lua_error(L);
}

int lDesign(lua_State* L) { return wrap<design>(L, "design"); }
int lAnalyze(lua_State* L) { return wrap<analyze>(L, "analyze"); }
int lOptimize(lua_State* L) { return wrap<optimize>(L, "optimize"); }
int lSteepest(lua_State* L) { return wrap<steepest>(L, "steepest_ascent"); }
int lSurrogate(lua_State* L) { return wrap<surrogate>(L, "surrogate_suggest"); }
int lGaussianProcess(lua_State* L) { return wrap<gaussianProcess>(L, "gaussian_process"); }
int lCsvFields(lua_State* L) { return wrap<csvFields>(L, "csv_fields"); }
// Naming a missing effect (discovery_json.hpp).
int lNoiseCovariance(lua_State* L) { return wrap<noiseCovarianceJson>(L, "noise_covariance"); }
int lDiagnose(lua_State* L) { return wrap<diagnoseJson>(L, "diagnose"); }
int lGaussNewton(lua_State* L) { return wrap<gaussNewtonJson>(L, "gauss_newton"); }
int lResponseSurface(lua_State* L) { return wrap<responseSurfaceJson>(L, "response_surface"); }
int lCompareFits(lua_State* L) { return wrap<compareFitsJson>(L, "compare_fits"); }
int lCompareNonNested(lua_State* L) { return wrap<compareNonNestedJson>(L, "compare_non_nested"); }
int lNullThresholds(lua_State* L) { return wrap<nullThresholdsJson>(L, "null_thresholds"); }
int lBootstrapThresholds(lua_State* L) { return wrap<bootstrapThresholdsJson>(L, "bootstrap_thresholds"); }

}  // namespace
}  // namespace paddy::doe

extern "C" int luaopen_paddy_doe(lua_State* L) {
  static const luaL_Reg fns[] = {{"design", paddy::doe::lDesign},
                                 {"analyze", paddy::doe::lAnalyze},
                                 {"optimize", paddy::doe::lOptimize},
                                 {"steepest_ascent", paddy::doe::lSteepest},
                                 {"surrogate_suggest", paddy::doe::lSurrogate},
                                 {"gaussian_process", paddy::doe::lGaussianProcess},
                                 {"csv_fields", paddy::doe::lCsvFields},
                                 {"noise_covariance", paddy::doe::lNoiseCovariance},
                                 {"diagnose", paddy::doe::lDiagnose},
                                 {"gauss_newton", paddy::doe::lGaussNewton},
                                 {"response_surface", paddy::doe::lResponseSurface},
                                 {"compare_fits", paddy::doe::lCompareFits},
                                 {"compare_non_nested", paddy::doe::lCompareNonNested},
                                 {"null_thresholds", paddy::doe::lNullThresholds},
                                 {"bootstrap_thresholds", paddy::doe::lBootstrapThresholds},
                                 {nullptr, nullptr}};
  luaL_newlib(L, fns);
  return 1;
}
