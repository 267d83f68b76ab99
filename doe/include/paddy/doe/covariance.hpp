// Noise covariance of a stacked observable vector and the whitening it defines.
//
//   Sigma = Sigma_meas + Sigma_seed / n_avg
//
// Sigma_meas = diag(sigma_i^2) + C from the measurement uncertainties: sigma_i is each entry's own
// (independent) error, C an optional m x m covariance of errors the entries share — e.g. one
// specimen read at several speeds, every torque multiplied by the same 1 + eps, eps ~ N(0, c^2):
// C_ij = c^2 y_i y_j (in the standardised units of the workflow, y_i = value_i / sigma_i).
// Sigma_seed from n >= 2 replicate
// simulations at the calibrated parameters (rows = replicates, columns = observables), shrunk
// toward its diagonal with the Schäfer–Strimmer estimator ("target D": variances kept, the
// correlations r_ij shrunk toward 0):
//   x~_ki = (x_ki - mean_i) / sd_i,  w_kij = x~_ki x~_kj,  w_ij = mean_k w_kij,
//   r_ij = n/(n-1) w_ij,  Var(r_ij) = n / (n-1)^3 * sum_k (w_kij - w_ij)^2,
//   lambda* = clamp( sum_{i!=j} Var(r_ij) / sum_{i!=j} r_ij^2 , 0, 1 ),
//   R* = (1 - lambda*) R + lambda* I,  Sigma_seed = D^1/2 R* D^1/2,  D = diag(sample variances)
// (J. Schäfer and K. Strimmer, "A shrinkage approach to large-scale covariance matrix estimation
// and implications for functional genomics", Stat. Appl. Genet. Mol. Biol. 4(1), art. 32, 2005,
// Table 1 target D and appendix). Since R* is a convex combination of a correlation matrix and I
// with lambda* > 0 unless the data fix every correlation, Sigma_seed is positive definite even
// with fewer replicates than observables; Sigma_meas > 0 makes Sigma positive definite in any case.
// Observables with zero seed variance keep zero correlation.
//
// Whitening: Sigma = L L^T (Cholesky); W = L^-1, so W Sigma W^T = I. L keeps the zero pattern of
// a block-diagonal Sigma (independent experiments), so whitened rows stay within their block.
#pragma once
#include <Eigen/Dense>

namespace paddy::doe {

struct NoiseCovariance {
  Eigen::MatrixXd covariance;      ///< Sigma = diag(sigma^2) + C + Sigma_seed / n_avg
  Eigen::MatrixXd seedCovariance;  ///< shrunk Sigma_seed of one replicate
  Eigen::VectorXd seedSd;          ///< sample standard deviation of each observable over replicates
  double shrinkage = 0.0;          ///< lambda*, 0 = sample correlations kept, 1 = diagonal
};

/// replicates: n x m (n >= 2, finite); sigma: m measurement standard deviations (>= 0, may be
/// empty = all 0); nAvg > 0 (the effective number of seeds: below 1 when the measurement
/// carries seed-like scatter of its own, 1/n_avg = 1/replicates + 1/measured_repeats);
/// sharedMeasurement: C, m x m symmetric positive semi-definite, or empty (none). Throws DoeError
/// naming the field when an input is invalid or when an observable has neither seed scatter nor
/// measurement error (Sigma would be singular).
NoiseCovariance noiseCovariance(const Eigen::MatrixXd& replicates, const Eigen::VectorXd& sigma,
                                double nAvg = 1.0, const Eigen::MatrixXd& sharedMeasurement = Eigen::MatrixXd());

/// Checks C of noiseCovariance (square m x m, finite, symmetric, no eigenvalue below -1e-10 of
/// its scale); an empty matrix passes. Throws DoeError("<what>: ...").
void checkSharedMeasurement(const Eigen::MatrixXd& C, Eigen::Index m, const char* what = "measurement_covariance");

/// Schäfer–Strimmer shrinkage of the sample correlation toward I (formulas above); returns lambda*.
double correlationShrinkage(const Eigen::MatrixXd& replicates);

/// Cholesky whitening of a symmetric positive-definite covariance.
class Whitening {
public:
  /// Throws DoeError("<what> ...") if Sigma is not square, not finite, not symmetric or not
  /// positive definite (the message gives the smallest eigenvalue).
  explicit Whitening(const Eigen::MatrixXd& sigma, const char* what = "covariance");
  Eigen::VectorXd apply(const Eigen::VectorXd& v) const;  ///< L^-1 v
  Eigen::MatrixXd apply(const Eigen::MatrixXd& M) const;  ///< L^-1 M
  const Eigen::VectorXd& sd() const { return sd_; }       ///< sqrt(diag Sigma)
  int size() const { return static_cast<int>(sd_.size()); }

private:
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::VectorXd sd_;
};

}  // namespace paddy::doe
