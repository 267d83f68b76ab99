// Thresholds for the decision rule from the workflow's own noise model: a parametric bootstrap of
// null trials.
//
// The chi^2 and normal tables of discovery.hpp take Sigma as known. The workflow estimates it from
// n replicate seeds (covariance.hpp), and with few replicates and many observables the statistics
// then run far above their tables (docs/discovery.md: 29 % false alarms at 8 replicates of a
// 30-vector). nullThresholds (null_calibration.hpp) corrects this from null trials; this file makes
// those null trials from the fitted noise model itself, so one diagnosis needs no extra
// simulations:
//
//   Sigma_seed^  = the shrunk seed covariance of the replicates (taken as the truth),
//   Sigma^       = diag(sigma^2) + C + Sigma_seed^ / n_avg   (C: errors the measurements share),
//   per trial t: e_t ~ N(0, Sigma^)                  (a residual with nothing missing),
//                X_t = n rows ~ N(0, Sigma_seed^)     (replicates, as the workflow draws them),
//                Sigma_t = noiseCovariance(X_t, sigma, n_avg, C),
//                diagnose(e_t, Sigma_t, J, candidates) -> z_max, Q0, Q0 - z_k^2,
//   thresholds   = nullThresholds(z_max, Q0, alpha, Q0 - z_k^2).
//
// This is the parametric bootstrap (B. Efron and R. J. Tibshirani, An Introduction to the
// Bootstrap, Chapman & Hall 1993, ch. 6) of the decision statistics under "nothing missing", with
// the estimation of Sigma repeated inside each trial, as simulation-based calibration repeats the
// whole inference (S. Talts et al., "Validating Bayesian inference algorithms with
// simulation-based calibration", arXiv:1804.06788, 2018). It assumes Gaussian seed scatter and the
// linearised model; the candidates' signatures are taken as exact. Its false-alarm rate on data
// with a known answer is measured by paddy_discovery_error_rates (docs/discovery.md).
#pragma once
#include "paddy/doe/discovery.hpp"
#include "paddy/doe/null_calibration.hpp"

#include <cstdint>

namespace paddy::doe {

struct BootstrapNullInput {
  Eigen::MatrixXd jacobian;          ///< m x p, raw units (as diagnose)
  std::vector<Candidate> candidates;
  Eigen::VectorXd sigma;             ///< m measurement standard deviations (empty: all 0)
  Eigen::MatrixXd sharedMeasurement; ///< C of noiseCovariance: m x m, or empty (none)
  Eigen::MatrixXd seedCovariance;    ///< m x m, Sigma_seed of one replicate (NoiseCovariance::seedCovariance)
  int replicates = 0;                ///< n replicate seeds the workflow used to estimate it (>= 2)
  double nAvg = 1.0;                 ///< effective seeds behind a residual (> 0; see noiseCovariance)
  int trials = 2000;                 ///< bootstrap null trials (>= 20)
  std::uint64_t seed = 1;
  DecisionOptions options;           ///< alpha and the rule's other settings (thresholds ignored)
};

/// Throws DoeError naming the field on inconsistent sizes, replicates < 2, trials < 20, or a seed
/// covariance that is not symmetric positive semi-definite.
NullThresholds bootstrapNullThresholds(const BootstrapNullInput& in);

}  // namespace paddy::doe
