#include "paddy/doe/report_json.hpp"

#include "paddy/doe/error.hpp"

#include <cmath>

namespace paddy::doe {

using nlohmann::json;

namespace {
json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json factorsJson(const std::vector<Factor>& f) {
  json a = json::array();
  for (const auto& x : f) a.push_back({{"name", x.name}, {"low", x.low}, {"high", x.high}});
  return a;
}

std::string termName(const Model& m, const Term& t) {
  Model one{m.factorNames, {t}};
  return one.termName(0);
}
}  // namespace

json analysisToJson(const Analysis& a) {
  json j;
  j["factors"] = factorsJson(a.factors);
  for (std::size_t i = 0; i < a.factors.size(); ++i) {
    j["factors"][i]["data_min"] = a.real.col(static_cast<Eigen::Index>(i)).minCoeff();
    j["factors"][i]["data_max"] = a.real.col(static_cast<Eigen::Index>(i)).maxCoeff();
  }
  j["coding"] = "coded = (x - (low + high) / 2) / ((high - low) / 2)";
  j["model"] = a.modelName;
  j["terms"] = a.model.termNames();
  j["curvature"] = a.curvature;
  j["runs"] = a.real.rows();
  json responses = json::object();
  Eigen::VectorXd c(a.factors.size()), h(a.factors.size());
  for (std::size_t i = 0; i < a.factors.size(); ++i) {
    c(i) = a.factors[i].center();
    h(i) = a.factors[i].halfRange();
  }
  for (const auto& r : a.responses) {
    json o;
    json coef = json::object(), actual = json::object(), table = json::array();
    for (int i = 0; i < r.model.p(); ++i) coef[r.model.termName(i)] = r.beta(i);
    for (const auto& t : actualCoefficients(r.model, r.beta, c, h)) actual[termName(r.model, t.term)] = t.coefficient;
    for (const auto& row : r.coefficients)
      table.push_back({{"term", row.term}, {"estimate", row.estimate}, {"se", num(row.se)}, {"ci_low", num(row.ciLow)},
                       {"ci_high", num(row.ciHigh)}, {"t", num(row.t)}, {"p", num(row.p)}, {"vif", num(row.vif)}});
    json anova = json::array();
    for (const auto& row : r.anova)
      anova.push_back({{"source", row.source}, {"ss", num(row.ss)}, {"df", row.df}, {"ms", num(row.ms)},
                       {"F", num(row.F)}, {"p", num(row.p)}});
    json diag = json::array();
    for (const auto& d : r.diagnostics)
      diag.push_back({{"run", d.run}, {"actual", d.actual}, {"predicted", d.predicted}, {"residual", d.residual},
                      {"leverage", num(d.leverage)}, {"studentized", num(d.studentized)},
                      {"externally_studentized", num(d.externallyStudentized)}, {"cooks_distance", num(d.cooksDistance)}});
    o["coefficients"] = coef;
    o["coefficients_actual"] = actual;
    if (r.curvature) o["curvature_coefficient"] = r.curvatureCoefficient;
    o["coefficient_table"] = table;
    o["anova"] = anova;
    o["r2"] = num(r.r2);
    o["adj_r2"] = num(r.adjR2);
    o["pred_r2"] = num(r.predR2);
    o["press"] = num(r.press);
    o["cv_percent"] = num(r.cvPercent);
    o["adeq_precision"] = num(r.adeqPrecision);
    o["mean"] = r.mean;
    o["std_dev"] = r.stdDev;
    o["t_critical"] = r.tCritical;
    o["min"] = r.yMin;
    o["max"] = r.yMax;
    o["diagnostics"] = diag;
    responses[r.response] = o;
  }
  j["responses"] = responses;
  return j;
}

const ResponseModel& FitModels::response(const std::string& name) const {
  std::string avail;
  for (const auto& r : responses) {
    if (r.name == name) return r;
    avail += (avail.empty() ? "" : ", ") + r.name;
  }
  throw DoeError("no response named '" + name + "' in the fit (available: " + avail + ")");
}

FitModels fitFromJson(const json& j) {
  try {
    FitModels fit;
    std::vector<std::string> names;
    for (const auto& f : j.at("factors")) {
      fit.factors.push_back({f.at("name").get<std::string>(), f.at("low").get<double>(), f.at("high").get<double>()});
      names.push_back(fit.factors.back().name);
      fit.dataMin.push_back(f.value("data_min", f.at("low").get<double>()));
      fit.dataMax.push_back(f.value("data_max", f.at("high").get<double>()));
      if (!(fit.factors.back().high != fit.factors.back().low))
        throw DoeError("factor " + names.back() + " has equal low and high levels");
    }
    std::string spec;
    for (const auto& t : j.at("terms")) spec += (spec.empty() ? "" : ",") + t.get<std::string>();
    const Model model = Model::parse(names, spec, false);
    for (const auto& [rname, r] : j.at("responses").items()) {
      ResponseModel rm;
      rm.name = rname;
      rm.model = model;
      rm.beta.resize(model.p());
      const auto& coef = r.at("coefficients");
      for (int i = 0; i < model.p(); ++i) {
        const auto tn = model.termName(i);
        if (!coef.contains(tn)) throw DoeError("response " + rname + ": missing coefficient for term " + tn);
        rm.beta(i) = coef.at(tn).get<double>();
      }
      rm.yMin = r.at("min").get<double>();
      rm.yMax = r.at("max").get<double>();
      fit.responses.push_back(rm);
    }
    if (fit.responses.empty()) throw DoeError("the fit contains no responses");
    return fit;
  } catch (const json::exception& e) {
    throw DoeError(std::string("fit JSON is not a paddy doe analysis: ") + e.what());
  }
}

json solutionsToJson(const FitModels& fit, const std::vector<GoalSpec>& goals, const std::vector<Solution>& sols) {
  json j;
  json g = json::array();
  for (const auto& x : goals)
    g.push_back({{"response", x.response}, {"goal", goalName(x.goal)}, {"lower", x.lower}, {"upper", x.upper},
                 {"target", x.goal == Goal::Target ? json(x.target) : json(nullptr)}, {"weight1", x.weight1},
                 {"weight2", x.weight2}, {"importance", x.importance}});
  j["goals"] = g;
  j["factors"] = factorsJson(fit.factors);
  json s = json::array();
  for (const auto& sol : sols) {
    json f = json::object(), fc = json::object(), p = json::object(), d = json::object();
    for (std::size_t i = 0; i < fit.factors.size(); ++i) {
      f[fit.factors[i].name] = sol.real(static_cast<Eigen::Index>(i));
      fc[fit.factors[i].name] = sol.coded(static_cast<Eigen::Index>(i));
    }
    for (std::size_t i = 0; i < fit.responses.size(); ++i) p[fit.responses[i].name] = sol.predicted[i];
    for (std::size_t i = 0; i < goals.size(); ++i) d[goals[i].response] = sol.desirability[i];
    s.push_back({{"factors", f}, {"factors_coded", fc}, {"predicted", p}, {"desirability", sol.overall},
                 {"individual_desirability", d}});
  }
  j["solutions"] = s;
  return j;
}

json designToJson(const Design& d) {
  json rows = json::array();
  const Eigen::MatrixXd real = d.real();
  for (int i = 0; i < d.runs(); ++i) {
    json c = json::object(), r = json::object();
    for (int j = 0; j < d.k(); ++j) {
      c[d.factors[j].name] = d.coded(i, j);
      r[d.factors[j].name] = real(i, j);
    }
    rows.push_back({{"run", i + 1}, {"std", d.stdOrder[i]}, {"type", pointTypeName(d.type[i])}, {"coded", c}, {"real", r}});
  }
  return {{"factors", factorsJson(d.factors)}, {"runs", rows}};
}

json pathToJson(const std::vector<Factor>& f, const std::vector<PathPoint>& path) {
  json rows = json::array();
  for (const auto& p : path) {
    json c = json::object(), r = json::object();
    for (std::size_t j = 0; j < f.size(); ++j) {
      c[f[j].name] = p.coded(static_cast<Eigen::Index>(j));
      r[f[j].name] = p.real(static_cast<Eigen::Index>(j));
    }
    rows.push_back({{"step", p.step}, {"coded", c}, {"real", r}});
  }
  return rows;
}

}  // namespace paddy::doe
