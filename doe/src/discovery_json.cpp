#include "paddy/doe/discovery_json.hpp"

#include "paddy/doe/bootstrap_null.hpp"
#include "paddy/doe/non_nested.hpp"
#include "paddy/doe/covariance.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/gauss_newton.hpp"
#include "paddy/doe/null_calibration.hpp"
#include "paddy/doe/response_surface.hpp"

#include <cmath>
#include <fmt/format.h>

namespace paddy::doe {

namespace {

using nlohmann::json;

double number(const json& j, const std::string& what) {
  if (!j.is_number()) throw DoeError(what + ": must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw DoeError(what + ": not finite");
  return v;
}

// Bound: a number, or null / absent for "unbounded" (JSON has no infinity).
double bound(const json& o, const char* key, double fallback, const std::string& where) {
  if (!o.contains(key) || o[key].is_null()) return fallback;
  return number(o[key], where + "." + key);
}

// An empty Lua table arrives as an empty JSON object.
bool emptyTable(const json& j) { return j.is_object() && j.empty(); }

Eigen::VectorXd vector(const json& j, const std::string& what) {
  if (emptyTable(j)) return Eigen::VectorXd(0);
  if (!j.is_array()) throw DoeError(what + ": must be a list of numbers");
  Eigen::VectorXd v(static_cast<Eigen::Index>(j.size()));
  for (std::size_t i = 0; i < j.size(); ++i) v(static_cast<Eigen::Index>(i)) = number(j[i], what + "[" + std::to_string(i + 1) + "]");
  return v;
}

Eigen::MatrixXd matrix(const json& j, const std::string& what, Eigen::Index cols = -1) {
  if (emptyTable(j)) return Eigen::MatrixXd(0, std::max<Eigen::Index>(cols, 0));
  if (!j.is_array()) throw DoeError(what + ": must be a list of rows");
  if (j.empty()) return Eigen::MatrixXd(0, std::max<Eigen::Index>(cols, 0));
  const std::size_t c = j[0].is_array() ? j[0].size() : 0;
  Eigen::MatrixXd M(static_cast<Eigen::Index>(j.size()), static_cast<Eigen::Index>(c));
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string row = what + " row " + std::to_string(i + 1);
    if (!j[i].is_array() && !(c == 0 && emptyTable(j[i]))) throw DoeError(row + ": must be a list of numbers");
    if (j[i].size() != c)
      throw DoeError(row + ": " + std::to_string(j[i].size()) + " entries, row 1 has " + std::to_string(c));
    for (std::size_t k = 0; k < c; ++k)
      M(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) = number(j[i][k], row + "[" + std::to_string(k + 1) + "]");
  }
  return M;
}

std::vector<std::string> names(const json& j, const std::string& what) {
  if (emptyTable(j)) return {};
  if (!j.is_array()) throw DoeError(what + ": must be a list of names");
  std::vector<std::string> v;
  for (std::size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_string()) throw DoeError(what + "[" + std::to_string(i + 1) + "]: must be a string");
    v.push_back(j[i].get<std::string>());
  }
  return v;
}

std::vector<double> list(const json& j, const std::string& what) {
  const Eigen::VectorXd v = vector(j, what);
  return {v.data(), v.data() + v.size()};
}

const json& required(const json& o, const char* key) {
  if (!o.contains(key) || o[key].is_null()) throw DoeError(std::string(key) + ": required");
  return o[key];
}

void requireObject(const json& o) {
  if (!o.is_object()) throw DoeError("expected an object (table) of named fields");
}

// Covariance from "covariance" (m x m) or "sigma" (m standard deviations); identity if neither.
Eigen::MatrixXd covarianceOf(const json& o, Eigen::Index m, bool identityIfMissing) {
  const bool hasCov = o.contains("covariance") && !o["covariance"].is_null();
  const bool hasSigma = o.contains("sigma") && !o["sigma"].is_null();
  if (hasCov && hasSigma) throw DoeError("covariance and sigma: give one of them, not both");
  if (hasCov) {
    Eigen::MatrixXd C = matrix(o["covariance"], "covariance");
    if (C.rows() != m || C.cols() != m)
      throw DoeError("covariance: " + std::to_string(C.rows()) + " x " + std::to_string(C.cols()) + " but the residual has " +
                     std::to_string(m) + " entries");
    return C;
  }
  if (hasSigma) {
    const Eigen::VectorXd s = vector(o["sigma"], "sigma");
    if (s.size() != m)
      throw DoeError("sigma: " + std::to_string(s.size()) + " entries but the residual has " + std::to_string(m));
    for (Eigen::Index i = 0; i < m; ++i)
      if (!(s(i) > 0)) throw DoeError("sigma[" + std::to_string(i + 1) + "]: must be > 0, got " + std::to_string(s(i)));
    return s.cwiseAbs2().asDiagonal();
  }
  if (identityIfMissing) return Eigen::MatrixXd::Identity(m, m);
  throw DoeError("covariance or sigma: required");
}

json toJson(const Eigen::VectorXd& v) {
  json a = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) a.push_back(std::isfinite(v(i)) ? json(v(i)) : json(nullptr));
  return a;
}

json toJson(const Eigen::MatrixXd& M) {
  json a = json::array();
  for (Eigen::Index i = 0; i < M.rows(); ++i) a.push_back(toJson(Eigen::VectorXd(M.row(i).transpose())));
  return a;
}

json finiteOrNull(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// measurement_covariance: the errors the measurements share (noiseCovariance's C); absent, null
// or an empty table = none.
Eigen::MatrixXd sharedMeasurementOf(const json& o) {
  if (!o.contains("measurement_covariance") || o["measurement_covariance"].is_null() || emptyTable(o["measurement_covariance"]))
    return Eigen::MatrixXd();
  return matrix(o["measurement_covariance"], "measurement_covariance");
}

}  // namespace

json noiseCovarianceJson(const json& o) {
  requireObject(o);
  const Eigen::MatrixXd X = matrix(required(o, "replicates"), "replicates");
  const Eigen::VectorXd sigma = o.contains("sigma") && !o["sigma"].is_null() ? vector(o["sigma"], "sigma") : Eigen::VectorXd();
  const double nAvg = o.contains("n_avg") ? number(o["n_avg"], "n_avg") : 1.0;
  const Eigen::MatrixXd shared = sharedMeasurementOf(o);
  const NoiseCovariance c = noiseCovariance(X, sigma, nAvg, shared);
  return {{"covariance", toJson(c.covariance)}, {"seed_covariance", toJson(c.seedCovariance)},
          {"shrinkage", c.shrinkage}, {"seed_sd", toJson(c.seedSd)}, {"replicates", X.rows()}, {"n_avg", nAvg}};
}

DiagnoseInput diagnoseInputFromJson(const json& o) {
  requireObject(o);
  DiagnoseInput in;
  in.residual = vector(required(o, "residual"), "residual");
  const auto m = in.residual.size();
  in.covariance = covarianceOf(o, m, false);
  if (o.contains("jacobian") && !o["jacobian"].is_null()) {
    in.jacobian = matrix(o["jacobian"], "jacobian");
    if (in.jacobian.rows() == 0) in.jacobian = Eigen::MatrixXd(m, 0);
    else if (in.jacobian.rows() != m)
      throw DoeError("jacobian: " + std::to_string(in.jacobian.rows()) + " rows but the residual has " + std::to_string(m) +
                     " entries (rows = observables, columns = parameters)");
  } else {
    in.jacobian = Eigen::MatrixXd(m, 0);
  }
  const json cands = o.contains("candidates") && !emptyTable(o["candidates"]) ? o["candidates"] : json::array();
  if (!cands.is_array()) throw DoeError("candidates: must be a list of {name, signature, low, high}");
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const std::string where = "candidates[" + std::to_string(k + 1) + "]";
    const json& c = cands[k];
    if (!c.is_object()) throw DoeError(where + ": must be {name =, signature =, low =, high =}");
    Candidate cand;
    if (!c.contains("name") || !c["name"].is_string()) throw DoeError(where + ".name: required string");
    cand.name = c["name"].get<std::string>();
    if (!c.contains("signature")) throw DoeError(where + " (" + cand.name + ").signature: required");
    cand.signature = vector(c["signature"], where + " (" + cand.name + ").signature");
    cand.low = bound(c, "low", 0.0, where);
    cand.high = bound(c, "high", std::numeric_limits<double>::infinity(), where);
    if (c.contains("prior_sd") && !c["prior_sd"].is_null()) cand.priorSd = number(c["prior_sd"], where + ".prior_sd");
    if (c.contains("relevant") && !c["relevant"].is_null()) cand.relevant = number(c["relevant"], where + ".relevant");
    if (c.contains("signature_seeds") && !emptyTable(c["signature_seeds"])) {
      const json& seeds = c["signature_seeds"];
      if (!seeds.is_array()) throw DoeError(where + " (" + cand.name + ").signature_seeds: must be a list of signatures, one per seed");
      for (std::size_t s = 0; s < seeds.size(); ++s)
        cand.signatureSeeds.push_back(vector(seeds[s], where + " (" + cand.name + ").signature_seeds[" + std::to_string(s + 1) + "]"));
    }
    in.candidates.push_back(cand);
  }
  if (o.contains("labels") && !o["labels"].is_null()) in.labels = names(o["labels"], "labels");
  if (o.contains("blocks") && !o["blocks"].is_null()) in.blocks = names(o["blocks"], "blocks");
  auto& opt = in.options;
  auto num = [&](const char* key, double& field) {
    if (o.contains(key) && !o[key].is_null()) field = number(o[key], key);
  };
  num("alpha", opt.alpha);
  opt.alphaAfter = opt.alpha;
  num("alpha_after", opt.alphaAfter);
  num("confusable", opt.confusable);
  num("bayes_margin", opt.bayesMargin);
  num("strong_margin", opt.strongMargin);
  num("absorbed_tolerance", opt.absorbedTolerance);
  num("min_range_z", opt.minRangeZ);
  num("detection_power", opt.detectionPower);
  auto opt_num = [&](const char* key, std::optional<double>& field) {
    if (o.contains(key) && !o[key].is_null()) field = number(o[key], key);
  };
  opt_num("z_threshold", opt.zThreshold);
  opt_num("q0_threshold", opt.q0Threshold);
  opt_num("q_after_threshold", opt.qAfterThreshold);
  return in;
}

json diagnosisToJson(const Diagnosis& d) {
  json j;
  j["decision"] = d.decision;
  j["named"] = d.named.empty() ? json(nullptr) : json(d.named);
  j["best"] = d.best.empty() ? json(nullptr) : json(d.best);
  j["reason"] = d.reason;
  j["ambiguous_with"] = d.ambiguousWith;
  j["separating_block"] = d.separatingBlock.empty() ? json(nullptr) : json(d.separatingBlock);
  j["block_separation"] = json::array();
  for (const auto& b : d.blockSeparations)
    j["block_separation"].push_back({{"block", b.block}, {"separation", b.separation}, {"t_criterion", b.tCriterion}});
  j["q0"] = d.q0;
  j["q0_df"] = d.q0Df;
  j["q0_p"] = d.q0P;
  j["q0_p_holm"] = d.q0PHolm;
  j["q0_significant"] = d.q0Significant;
  j["rank"] = d.rank;
  j["misfit"] = d.misfit;
  j["misfit_projected"] = d.misfitProjected;
  j["misfit_after"] = d.misfitAfter;
  j["candidates"] = json::array();
  for (const auto& c : d.candidates) {
    const auto& s = c.score;
    json jc{{"name", c.name}, {"a", s.a}, {"b", s.b}, {"z", s.z}, {"p", s.p}, {"z_relevant", c.zRelevant}, {"p_relevant", c.pRelevant}, {"p_holm", c.pHolm},
            {"strength", s.strength}, {"strength_se", finiteOrNull(s.strengthSe)}, {"q_after", s.qAfter},
            {"q_after_p", s.qAfterP}, {"absorbed_fraction", s.absorbedFraction}, {"identifiable", c.identifiable},
            {"passes", c.passes}, {"plausible", c.plausible}};
    jc["bayes_factor"] = s.logBayesFactor ? finiteOrNull(std::exp(*s.logBayesFactor)) : json(nullptr);
    jc["log_bayes_factor"] = s.logBayesFactor ? json(*s.logBayesFactor) : json(nullptr);
    jc["not_identifiable_reason"] = c.identifiable ? json(nullptr) : json(c.notIdentifiableReason);
    const auto& det = c.detection;
    jc["a_noise"] = det.aNoise;
    jc["a_signal"] = det.aSignal;
    jc["detection_limit"] = finiteOrNull(det.detectionLimit);
    jc["detectable"] = c.detectable;
    jc["strength_corrected"] = det.aSignal > 0 ? json(det.strength) : json(nullptr);
    jc["strength_corrected_se"] = finiteOrNull(det.strengthSe);
    jc["upper_limit"] = finiteOrNull(det.upperLimit);
    j["candidates"].push_back(jc);
  }
  j["detection_threshold"] = d.detectionThreshold;
  j["confusability"] = toJson(d.confusability);
  j["whitened_residual"] = toJson(d.whitenedResidual);
  j["projected_residual"] = toJson(d.projectedResidual);
  j["residual_map"] = json::array();
  for (const auto& r : d.residualMap)
    j["residual_map"].push_back({{"label", r.label}, {"block", r.block}, {"raw", r.raw}, {"standardised", r.standardised},
                                 {"standardised_after", r.standardisedAfter}, {"whitened", r.whitened},
                                 {"projected", r.projected}});
  return j;
}

json diagnoseJson(const json& o) { return diagnosisToJson(diagnose(diagnoseInputFromJson(o))); }

json gaussNewtonJson(const json& o) {
  requireObject(o);
  const Eigen::VectorXd theta = vector(required(o, "theta"), "theta");
  const Eigen::VectorXd res = vector(required(o, "residual"), "residual");
  const Eigen::MatrixXd Jraw = matrix(required(o, "jacobian"), "jacobian");
  const auto m = res.size(), p = theta.size();
  if (Jraw.rows() != m || Jraw.cols() != p)
    throw DoeError("jacobian: must be " + std::to_string(m) + " x " + std::to_string(p) + " (residual entries x theta entries), got " +
                   std::to_string(Jraw.rows()) + " x " + std::to_string(Jraw.cols()));
  const Whitening W(covarianceOf(o, m, true), "covariance");
  auto bounds = [&](const char* key, double fallback) {
    Eigen::VectorXd v = Eigen::VectorXd::Constant(p, fallback);
    if (!o.contains(key) || o[key].is_null()) return v;
    const json& a = o[key];
    if (!a.is_array() || static_cast<Eigen::Index>(a.size()) != p)
      throw DoeError(std::string(key) + ": must list one bound per theta entry (" + std::to_string(p) + ")");
    for (Eigen::Index i = 0; i < p; ++i)
      if (!a[static_cast<std::size_t>(i)].is_null()) v(i) = number(a[static_cast<std::size_t>(i)], std::string(key) + "[" + std::to_string(i + 1) + "]");
    return v;
  };
  const double damping = o.contains("damping") ? number(o["damping"], "damping") : 0.0;
  const BoundedStep s = boundedGaussNewtonStep(theta, W.apply(res), W.apply(Jraw), bounds("lower", -std::numeric_limits<double>::infinity()),
                                               bounds("upper", std::numeric_limits<double>::infinity()), damping);
  json j{{"theta", toJson(s.theta)}, {"step", toJson(s.step)}, {"covariance", toJson(s.covariance)}, {"se", toJson(s.se)},
         {"rank", s.rank}, {"misfit_predicted", s.misfitPredicted}, {"iterations", s.iterations}};
  j["at_bound"] = json::array();
  for (int b : s.atBound) j["at_bound"].push_back(b < 0 ? "lower" : b > 0 ? "upper" : "");
  return j;
}

json responseSurfaceJson(const json& o) {
  requireObject(o);
  ResponseSurfaceInput in;
  in.points = matrix(required(o, "points"), "points");
  in.values = matrix(required(o, "values"), "values");
  in.measured = vector(required(o, "measured"), "measured");
  in.covariance = covarianceOf(o, in.measured.size(), true);
  in.lower = vector(required(o, "lower"), "lower");
  in.upper = vector(required(o, "upper"), "upper");
  if (o.contains("specimen_runs") && !o["specimen_runs"].is_null()) in.specimenRuns = matrix(o["specimen_runs"], "specimen_runs");
  const ResponseSurfaceFit f = fitResponseSurface(in);
  json j{{"x", toJson(f.x)}, {"predicted", toJson(f.predicted)}, {"jacobian", toJson(f.jacobian)}, {"covariance", toJson(f.covariance)},
         {"se", toJson(f.se)}, {"residual_sd", toJson(f.residualSd)}, {"misfit_predicted", f.misfitPredicted}, {"terms", f.terms},
         {"coefficients", toJson(f.coefficients)}};
  j["at_bound"] = json::array();
  for (int b : f.atBound) j["at_bound"].push_back(b < 0 ? "lower" : b > 0 ? "upper" : "");
  j["specimen_se"] = f.specimenSe.size() > 0 ? toJson(f.specimenSe) : json(nullptr);
  return j;
}

json compareFitsJson(const json& o) {
  requireObject(o);
  auto integer = [&](const char* key, int fallback) {
    if (!o.contains(key) || o[key].is_null()) return fallback;
    const double v = number(o[key], key);
    if (v != std::floor(v)) throw DoeError(std::string(key) + ": must be an integer");
    return static_cast<int>(v);
  };
  const int n = integer("n", -1);
  if (n < 0) throw DoeError("n: required (number of observables)");
  const int kBefore = integer("k_before", 0);
  const FitComparison c = compareFits(number(required(o, "q_before"), "q_before"), number(required(o, "q_after"), "q_after"),
                                      integer("df", 1), n, kBefore, integer("k_after", kBefore + integer("df", 1)));
  return {{"lr", c.lr}, {"p", c.p}, {"delta_bic", c.deltaBic}, {"bayes_factor", finiteOrNull(c.bayesFactor)}, {"evidence", c.evidence}};
}

namespace {
json thresholdsToJson(const NullThresholds& t, const char* method) {
  json j{{"z_threshold", t.zThreshold}, {"q0_threshold", t.q0Threshold}, {"trials", t.trials}, {"alarms", t.alarms},
         {"alarm_rate", t.alarmRate}, {"alarm_rate_upper", t.alarmRateUpper}, {"paired", t.paired}, {"method", method}};
  j["q_after_threshold"] = t.qAfterThreshold ? json(*t.qAfterThreshold) : json(nullptr);
  return j;
}
}  // namespace

json nullThresholdsJson(const json& o) {
  requireObject(o);
  const auto z = list(required(o, "z_max"), "z_max");
  const auto q = list(required(o, "q0"), "q0");
  const auto qa = o.contains("q_after") && !o["q_after"].is_null() ? list(o["q_after"], "q_after") : std::vector<double>{};
  return thresholdsToJson(nullThresholds(z, q, o.contains("alpha") ? number(o["alpha"], "alpha") : 0.05, qa), "null_trials");
}

json compareNonNestedJson(const json& o) {
  requireObject(o);
  const Eigen::VectorXd a = vector(required(o, "residual_a"), "residual_a");
  const Eigen::VectorXd b = vector(required(o, "residual_b"), "residual_b");
  const Eigen::MatrixXd cov = matrix(required(o, "covariance"), "covariance");
  auto integer = [&](const char* key) {
    if (!o.contains(key) || o[key].is_null()) return 0;
    const double v = number(o[key], key);
    if (v != std::floor(v)) throw DoeError(std::string(key) + ": must be an integer");
    return static_cast<int>(v);
  };
  const double alpha = o.contains("alpha") && !o["alpha"].is_null() ? number(o["alpha"], "alpha") : 0.05;
  const NonNestedComparison c = vuongTest(a, b, cov, integer("k_a"), integer("k_b"), alpha);
  return {{"lr", c.lr}, {"omega", c.omega}, {"z", c.z}, {"p", c.p}, {"preferred", c.preferred}, {"alpha", alpha}};
}

json bootstrapThresholdsJson(const json& o) {
  requireObject(o);
  const Eigen::MatrixXd seedCov = matrix(required(o, "seed_covariance"), "seed_covariance");
  // Jacobian, candidates and the rule's options are read as diagnose reads them; the residual and
  // covariance are the bootstrap's own (a zero residual and the identity stand in for the parse).
  json d = o;
  const auto m = seedCov.rows();
  if (!d.contains("residual") || d["residual"].is_null()) d["residual"] = std::vector<double>(static_cast<std::size_t>(m), 0.0);
  d.erase("covariance");
  d["sigma"] = std::vector<double>(static_cast<std::size_t>(m), 1.0);
  const DiagnoseInput parsed = diagnoseInputFromJson(d);
  BootstrapNullInput in;
  in.jacobian = parsed.jacobian;
  in.candidates = parsed.candidates;
  in.options = parsed.options;
  in.seedCovariance = seedCov;
  in.sigma = o.contains("sigma") && !o["sigma"].is_null() ? vector(o["sigma"], "sigma") : Eigen::VectorXd();
  in.sharedMeasurement = sharedMeasurementOf(o);
  in.replicates = static_cast<int>(number(required(o, "replicates"), "replicates"));
  in.nAvg = o.contains("n_avg") ? number(o["n_avg"], "n_avg") : 1.0;
  if (o.contains("trials")) in.trials = static_cast<int>(number(o["trials"], "trials"));
  if (o.contains("seed")) in.seed = static_cast<std::uint64_t>(number(o["seed"], "seed"));
  return thresholdsToJson(bootstrapNullThresholds(in), "bootstrap");
}

void printDiagnosis(std::ostream& out, const Diagnosis& d) {
  out << fmt::format("decision: {}{}\n", d.decision, d.named.empty() ? "" : " (" + d.named + ")");
  out << "reason:   " << d.reason << "\n";
  if (!d.ambiguousWith.empty()) {
    out << "confusable:";
    for (const auto& n : d.ambiguousWith) out << " " << n;
    out << "\n";
  }
  if (!d.separatingBlock.empty()) out << "separating block: " << d.separatingBlock << "\n";
  out << fmt::format("Q0 = {:.4g} on {} df (p = {:.4g}, Holm {:.4g}); misfit {:.4g}, after recalibration {:.4g}, after {} {:.4g}\n",
                     d.q0, d.q0Df, d.q0P, d.q0PHolm, d.misfit, d.misfitProjected, d.best.empty() ? "(none)" : d.best, d.misfitAfter);
  out << fmt::format("{:<24} {:>9} {:>8} {:>9} {:>9} {:>11} {:>10} {:>9} {:>11} {:>11}  {}\n", "candidate", "a", "z", "p_holm", "strength",
                     "strength_se", "Q_after", "BF", "detect_from", "upper_limit", "status");
  const auto limit = [](double v) { return std::isfinite(v) ? fmt::format("{:.4g}", v) : std::string("none"); };
  for (const auto& c : d.candidates) {
    const std::string status = !c.identifiable ? "not identifiable: " + c.notIdentifiableReason
                             : c.plausible ? "passes" : c.passes ? "passes, strength outside range" : "";
    out << fmt::format("{:<24} {:>9.4g} {:>8.3f} {:>9.4g} {:>9.4g} {:>11.4g} {:>10.4g} {:>9} {:>11} {:>11}  {}\n", c.name, c.score.a, c.score.z,
                       c.pHolm, c.score.strength, c.score.strengthSe, c.score.qAfter,
                       c.score.logBayesFactor ? fmt::format("{:.3g}", std::exp(*c.score.logBayesFactor)) : "-",
                       limit(c.detection.detectionLimit), limit(c.detection.upperLimit), status);
  }
  out << fmt::format("\n{:<24} {:<12} {:>12} {:>13} {:>13}\n", "observable", "block", "residual", "standardised", "after");
  for (const auto& r : d.residualMap)
    out << fmt::format("{:<24} {:<12} {:>12.5g} {:>13.3f} {:>13.3f}\n", r.label, r.block, r.raw, r.standardised, r.standardisedAfter);
}

}  // namespace paddy::doe
