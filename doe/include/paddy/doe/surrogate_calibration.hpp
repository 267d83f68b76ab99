// Sequential surrogate-based calibration: which simulations to run next so that the simulated
// responses reach measured targets with as few simulations as possible.
//
// One Gaussian process per response (gaussian_process.hpp) on the inputs scaled to the unit
// cube; the quantity to minimise is the composite relative error (Astudillo & Frazier 2019,
// "Bayesian optimization of composite functions", ICML, PMLR 97:354):
//   J(y) = max_r |y_r − t_r| / |t_r|          (worst response; J ≤ 0.02: all within 2 %)
//   EI(x) = E[ max(0, J* − J(Y(x))) ],  Y_r(x) ~ N(μ_r(x), σ_r²(x)) independent,
// estimated with M fixed standard-normal draws z_{m,r} (common random numbers: EI is then a
// deterministic, continuous function of x):  EI ≈ (1/M) Σ_m max(0, J* − J(μ + σ ∘ z_m)).
// J* is the smallest J(μ(x_i)) over the points already run (posterior means: robust to the
// run-to-run scatter of a stochastic simulation).
// EI is maximised over seeded uniform candidates in the box plus candidates around the incumbent,
// the best refined by NLopt LN_COBYLA. A batch of q points (for q simulations in parallel) is
// chosen by the kriging believer (Ginsbourger, Le Riche & Carraro 2010): after each choice the
// models are conditioned on their own predicted mean there, hyperparameters kept.
#pragma once

#include "paddy/doe/gaussian_process.hpp"

#include <Eigen/Dense>
#include <cstdint>
#include <vector>

namespace paddy::doe {

struct SurrogateOptions {
  int batch = 1;          ///< points to suggest (run in parallel)
  int samples = 256;      ///< M, draws for the expected improvement
  int candidates = 4000;  ///< random candidates per point
  std::uint64_t seed = 1;
  GpFitOptions gp;
};

struct SurrogateSuggestion {
  Eigen::VectorXd x;                   ///< unit-cube coordinates
  std::vector<GpPrediction> predicted; ///< per response
  double expected_improvement = 0;
  double predicted_error = 0;          ///< J(μ(x))
};

struct SurrogateStep {
  std::vector<SurrogateSuggestion> suggestions;
  std::vector<GpHyperparameters> hyperparameters;  ///< per response
  double incumbent_error = 0;          ///< J*
  int incumbent_index = -1;            ///< row of X with J(μ) = J*
};

// Composite relative error of the worst response.
double compositeError(const Eigen::VectorXd& y, const Eigen::VectorXd& targets);

// X: n × d points run so far (unit cube), Y: n × R responses, targets: R measured values (≠ 0).
SurrogateStep suggestCalibrationPoints(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y,
                                       const Eigen::VectorXd& targets, const SurrogateOptions& options = {});

// The Monte Carlo expected improvement of J at x for fitted models (exposed for tests).
double compositeExpectedImprovement(const std::vector<GaussianProcess>& models, const Eigen::VectorXd& x,
                                    const Eigen::VectorXd& targets, double incumbent,
                                    const Eigen::MatrixXd& draws /* M × R standard normal */);

}  // namespace paddy::doe
