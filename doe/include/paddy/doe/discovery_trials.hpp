// Monte Carlo error rates of the discovery decision rule (discovery.hpp) on synthetic linear
// models with a known missing term: y = J theta + lambda g_truth + e, whitened noise e of unit
// variance that is Gaussian, Student t with 5 degrees of freedom (scaled to unit variance: heavy
// tails, kurtosis 9) or skewed ((chi^2_4 - 4) / sqrt 8, skewness 1.41). Optionally Sigma is not
// known but estimated in every trial from `replicates` replicate noise vectors (covariance.hpp),
// as the workflow does from replicate seeds.
//
// The synthetic model (seeded): m = 30 observables in 3 blocks of 10, p = 3 free parameters with
// a Gaussian random Jacobian, 4 candidates: "A" and "B" random, "C" random and "D" built so that
// cos(P g_C, P g_D) = 0.95 (a confusable pair), and an effect "outside" the list orthogonal to
// span(J, G). Each candidate's physical range is [0, 10 / sqrt(a_k)] (standardised size up to
// 10), its prior scale the width of that range.
//
// The standardised size of the effect is delta = lambda sqrt(a_truth) = the mean of z_truth (for
// "outside": sqrt of the noncentrality of Q0). The expected decision is `none` on null data,
// `effect` naming the truth for A or B, `ambiguous` listing the truth for C or D, `unknown` for
// "outside"; an error is any `effect` that names a candidate other than the truth. A candidate with a
// smallest relevant strength (Candidate::relevant; set it on the model's candidates) whose truth lies
// at or below it is expected not to be named (any decision but `effect`).
#pragma once
#include "paddy/doe/discovery.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace paddy::doe {

enum class NoiseKind { Gaussian, StudentT5, Skewed };
std::string noiseKindName(NoiseKind k);  ///< "gaussian", "t5", "skewed"

struct TrialModel {
  Eigen::MatrixXd jacobian;          ///< m x p
  std::vector<Candidate> candidates; ///< signatures, ranges, prior scales
  Eigen::VectorXd outside;           ///< unit vector orthogonal to span(J, G)
  std::vector<std::string> blocks;
  Eigen::VectorXd projectedNorm;     ///< sqrt(a_k) per candidate
};

TrialModel syntheticTrialModel(std::uint64_t seed = 20260101);

struct TrialScenario {
  std::string truth;   ///< candidate name, "none" or "outside"
  double size = 0.0;   ///< delta (ignored for "none")
  NoiseKind noise = NoiseKind::Gaussian;
  int replicates = 0;  ///< 0: Sigma = I known; >= 2: Sigma estimated from this many replicates per trial
  int bootstrap = 0;   ///< > 0 (with replicates >= 2): thresholds of each trial from this many bootstrap
                       ///< null trials of its own Sigma estimate (bootstrap_null.hpp), as the workflow sets them
};

struct TrialCounts {
  int trials = 0;
  int correct = 0;             ///< effect naming the truth
  int wrongName = 0;           ///< effect naming another candidate (the error to avoid)
  int ambiguousWithTruth = 0, ambiguousOther = 0, unknown = 0, none = 0;
  int expected = 0;            ///< the scenario's expected decision (see above)
};

/// Null-trial statistics for nullThresholds (null_calibration.hpp).
struct NullStatistics {
  std::vector<double> zMax, q0, qAfter;
};

/// `trials` independent trials of `scenario`; `collect` (optional) receives z_max, Q0 and the
/// pooled Q0 - z_k^2 of every trial.
TrialCounts runTrials(const TrialModel& model, const TrialScenario& scenario, int trials, std::uint64_t seed,
                      const DecisionOptions& options = {}, NullStatistics* collect = nullptr);

}  // namespace paddy::doe
