// Error rates of the discovery decision rule by Monte Carlo (discovery_trials.hpp), written as the
// tables of docs/discovery.md, "The statistics":
//   paddy_discovery_error_rates [--trials N] [--calibration N] [--seed S] --out DIR
// For each noise kind (Gaussian, t5, skewed, Gaussian with Sigma estimated from 8 or 30 replicates) and
// each threshold mode (chi^2 / normal tables with Holm; empirical thresholds from N null trials of
// that noise kind, null_calibration.hpp), runs N trials of every scenario (null; truth A, B, C and
// outside at standardised sizes 1..8) and writes DIR/discovery_error_rates.csv and .json with the
// counts and one-sided 95 % Clopper–Pearson bounds. Deterministic for a given seed.
//   paddy_discovery_error_rates --bootstrap B [--trials N] [--seed S] --out DIR
// instead measures the thresholds the workflow uses (bootstrap_null.hpp): Sigma estimated from 8
// replicates in every trial and the trial's thresholds from B bootstrap null trials of that
// estimate; null, truth A at sizes 4, 6, 8, truth C at 6 and outside at 8 →
// DIR/discovery_bootstrap_rates.csv and .json.
//   --strong-margin M  runs the rule with that strong margin (discovery.hpp; default infinite: a
// confusable rival always makes the answer ambiguous) and writes ..._strong<M>.csv and .json.
//   --relevant D  gives every candidate a smallest relevant strength of standardised size D
// (Candidate::relevant = D / sqrt(a_k)), adds the truths A at D/2 and at D (expected: not named) to
// the bootstrap scenarios and writes ..._relevant<D>.csv and .json.
#include "paddy/doe/csv.hpp"
#include "paddy/doe/discovery_trials.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/null_calibration.hpp"

#include <fmt/format.h>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>

using namespace paddy::doe;

namespace {

struct NoiseSetting {
  std::string name;
  NoiseKind kind;
  int replicates;
};

int intArg(const std::string& s, const std::string& what) {
  std::size_t pos = 0;
  int v = 0;
  try {
    v = std::stoi(s, &pos);
  } catch (...) {
    pos = 0;
  }
  if (pos != s.size() || v < 1) throw DoeError(what + ": '" + s + "' is not a positive integer");
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    int trials = 2000, calibration = 2000, bootstrap = 0;
    std::uint64_t seed = 1;
    std::string out;
    DecisionOptions base;  // the rule's options of every trial (thresholds added per mode)
    double relevant = 0.0;  // standardised smallest relevant strength of every candidate
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto next = [&]() -> std::string {
        if (i + 1 >= argc) throw DoeError(a + ": needs a value");
        return argv[++i];
      };
      if (a == "--trials") trials = intArg(next(), a);
      else if (a == "--calibration") calibration = intArg(next(), a);
      else if (a == "--bootstrap") bootstrap = intArg(next(), a);
      else if (a == "--seed") seed = static_cast<std::uint64_t>(intArg(next(), a));
      else if (a == "--out") out = next();
      else if (a == "--strong-margin") base.strongMargin = std::stod(next());
      else if (a == "--relevant") {
        const std::string v = next();
        std::size_t pos = 0;
        try { relevant = std::stod(v, &pos); } catch (...) { pos = 0; }
        if (pos != v.size() || !(relevant > 0 && relevant < 10)) throw DoeError("--relevant: '" + v + "' must be a number in (0, 10) (standardised size)");
      }
      else throw DoeError("unknown argument '" + a + "' (use --trials N --calibration N --bootstrap B --seed S --strong-margin M --relevant D --out DIR)");
    }
    if (out.empty()) throw DoeError("--out DIR is required");
    if (!(base.strongMargin >= base.bayesMargin)) throw DoeError("--strong-margin: must be >= " + fmt::format("{:g}", base.bayesMargin));
    const std::string suffix = (std::isfinite(base.strongMargin) ? fmt::format("_strong{:g}", base.strongMargin) : "") +
                               (relevant > 0 ? fmt::format("_relevant{:g}", relevant) : "");
    TrialModel model = syntheticTrialModel();
    for (std::size_t k = 0; k < model.candidates.size(); ++k) model.candidates[k].relevant = relevant / model.projectedNorm(static_cast<Eigen::Index>(k));
    const std::vector<NoiseSetting> noises{{"gaussian", NoiseKind::Gaussian, 0},
                                           {"t5", NoiseKind::StudentT5, 0},
                                           {"skewed", NoiseKind::Skewed, 0},
                                           {"gaussian_sigma_from_8_replicates", NoiseKind::Gaussian, 8},
                                           {"gaussian_sigma_from_30_replicates", NoiseKind::Gaussian, 30}};
    const std::vector<double> sizes{1, 2, 3, 4, 5, 6, 8};
    const std::vector<std::string> truths{"A", "B", "C", "outside"};
    nlohmann::json doc;
    doc["trials"] = trials;
    doc["calibration_trials"] = calibration;
    doc["seed"] = seed;
    if (std::isfinite(base.strongMargin)) doc["strong_margin"] = base.strongMargin;
    if (relevant > 0) doc["relevant_standardised"] = relevant;
    doc["model"] = {{"observables", model.jacobian.rows()}, {"parameters", model.jacobian.cols()}, {"candidates", {"A", "B", "C", "D"}}};
    {
      DiagnoseInput probe;
      probe.residual = Eigen::VectorXd::Zero(model.jacobian.rows());
      probe.covariance = Eigen::MatrixXd::Identity(model.jacobian.rows(), model.jacobian.rows());
      probe.jacobian = model.jacobian;
      probe.candidates = model.candidates;
      const Diagnosis d = diagnose(probe);
      nlohmann::json c = nlohmann::json::array();
      for (Eigen::Index k = 0; k < d.confusability.rows(); ++k) {
        nlohmann::json row = nlohmann::json::array();
        for (Eigen::Index l = 0; l < d.confusability.cols(); ++l) row.push_back(d.confusability(k, l));
        c.push_back(row);
      }
      doc["model"]["confusability"] = c;
    }
    doc["rows"] = nlohmann::json::array();
    std::vector<std::string> header{"noise", "thresholds", "truth", "size", "trials", "expected", "expected_rate",
                                    "expected_lower95", "expected_upper95", "wrong_name", "wrong_name_rate",
                                    "wrong_name_upper95", "correct", "ambiguous_with_truth", "ambiguous_other",
                                    "unknown", "none"};
    std::vector<std::vector<std::string>> rows;
    std::uint64_t scenarioSeed = seed * 1000003ULL;
    auto record = [&](const std::string& noise, const std::string& mode, const TrialScenario& sc, const TrialCounts& c) {
      const auto ok = clopperPearson(c.expected, c.trials);
      const auto wrong = clopperPearson(c.wrongName, c.trials);
      rows.push_back({noise, mode, sc.truth, fmt::format("{:g}", sc.size), std::to_string(c.trials),
                      std::to_string(c.expected), fmt::format("{:.4f}", ok.rate), fmt::format("{:.4f}", ok.lower),
                      fmt::format("{:.4f}", ok.upper), std::to_string(c.wrongName), fmt::format("{:.4f}", wrong.rate),
                      fmt::format("{:.4f}", wrong.upper), std::to_string(c.correct), std::to_string(c.ambiguousWithTruth),
                      std::to_string(c.ambiguousOther), std::to_string(c.unknown), std::to_string(c.none)});
      doc["rows"].push_back({{"noise", noise}, {"thresholds", mode}, {"truth", sc.truth}, {"size", sc.size},
                             {"trials", c.trials}, {"expected", c.expected}, {"expected_rate", ok.rate},
                             {"expected_lower95", ok.lower}, {"expected_upper95", ok.upper},
                             {"wrong_name", c.wrongName}, {"wrong_name_upper95", wrong.upper}, {"correct", c.correct},
                             {"ambiguous_with_truth", c.ambiguousWithTruth}, {"ambiguous_other", c.ambiguousOther},
                             {"unknown", c.unknown}, {"none", c.none}});
    };
    if (bootstrap > 0) {
      doc["bootstrap_trials"] = bootstrap;
      std::vector<TrialScenario> scenarios{{"none", 0.0, NoiseKind::Gaussian, 8, bootstrap},
                                                 {"A", 4.0, NoiseKind::Gaussian, 8, bootstrap},
                                                 {"A", 6.0, NoiseKind::Gaussian, 8, bootstrap},
                                                 {"A", 8.0, NoiseKind::Gaussian, 8, bootstrap},
                                                 {"C", 6.0, NoiseKind::Gaussian, 8, bootstrap},
                                                 {"outside", 8.0, NoiseKind::Gaussian, 8, bootstrap}};
      if (relevant > 0) {
        scenarios.insert(scenarios.begin() + 1, {"A", relevant, NoiseKind::Gaussian, 8, bootstrap});
        scenarios.insert(scenarios.begin() + 1, {"A", relevant / 2, NoiseKind::Gaussian, 8, bootstrap});
      }
      for (const auto& sc : scenarios) {
        record("gaussian_sigma_from_8_replicates", "bootstrap", sc, runTrials(model, sc, trials, ++scenarioSeed, base));
        std::cerr << "done bootstrap " << sc.truth << " " << sc.size << "\n";
      }
      writeFileAtomic(out + "/discovery_bootstrap_rates" + suffix + ".csv", toCsv(header, rows));
      writeFileAtomic(out + "/discovery_bootstrap_rates" + suffix + ".json", doc.dump(1) + "\n");
      std::cout << "wrote " << out << "/discovery_bootstrap_rates" << suffix << ".csv and .json (" << rows.size() << " rows)\n";
      return 0;
    }
    for (const auto& n : noises) {
      NullStatistics ns;
      runTrials(model, {"none", 0.0, n.kind, n.replicates}, calibration, seed * 7919ULL + 17, base, &ns);
      const NullThresholds thr = nullThresholds(ns.zMax, ns.q0, 0.05, ns.qAfter);
      doc["thresholds"][n.name] = {{"z_threshold", thr.zThreshold}, {"q0_threshold", thr.q0Threshold},
                                   {"q_after_threshold", *thr.qAfterThreshold}, {"calibration_alarm_rate", thr.alarmRate}};
      for (const std::string mode : {"chi2_holm", "empirical"}) {
        DecisionOptions opt = base;
        if (mode == "empirical") {
          opt.zThreshold = thr.zThreshold;
          opt.q0Threshold = thr.q0Threshold;
          opt.qAfterThreshold = thr.qAfterThreshold;
        }
        std::vector<TrialScenario> scenarios{{"none", 0.0, n.kind, n.replicates}};
        for (const auto& t : truths)
          for (double s : sizes) scenarios.push_back({t, s, n.kind, n.replicates});
        for (const auto& sc : scenarios) {
          record(n.name, mode, sc, runTrials(model, sc, trials, ++scenarioSeed, opt));
        }
        std::cerr << "done " << n.name << " " << mode << "\n";
      }
    }
    writeFileAtomic(out + "/discovery_error_rates" + suffix + ".csv", toCsv(header, rows));
    writeFileAtomic(out + "/discovery_error_rates" + suffix + ".json", doc.dump(1) + "\n");
    std::cout << "wrote " << out << "/discovery_error_rates" << suffix << ".csv and .json (" << rows.size() << " rows)\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "paddy_discovery_error_rates: error: " << e.what() << "\n";
    return 2;
  }
}
