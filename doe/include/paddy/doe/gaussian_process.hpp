// Gaussian-process regression (kriging) for sequential, surrogate-based calibration.
//
// Model (Rasmussen & Williams, "Gaussian Processes for Machine Learning", MIT Press 2006,
// ch. 2 and 5): y = f(x) + ε, f ~ GP(m, k), ε ~ N(0, σ_n²), on inputs scaled to the unit cube
// and outputs standardised (m = mean of y, unit variance).
//   Kernel, Matérn ν = 5/2 with one length scale per input (ARD), eq. 4.17:
//     k(x, x') = σ_f² (1 + √5 r + 5 r²/3) exp(−√5 r),   r² = Σ_d (x_d − x'_d)² / ℓ_d²
//   Posterior at x* (Algorithm 2.1, Cholesky K + σ_n² I = L Lᵀ, α = Lᵀ\(L\y)):
//     μ(x*) = k*ᵀ α,   var f(x*) = k(x*, x*) − vᵀv,  v = L \ k*
//   Log marginal likelihood (eq. 2.30):
//     log p(y|X,θ) = −½ yᵀα − Σ_i log L_ii − (n/2) log 2π
// Hyperparameters θ = (log ℓ_1..ℓ_d, log σ_f², log σ_n²) maximise the log marginal likelihood
// (type-II maximum likelihood) with NLopt LN_BOBYQA from the centre of the box and a seeded set
// of further starts; the box keeps the problem well posed with few points.
//
// Input warping (optional; Snoek, Swersky, Zemel & Adams 2014, "Input warping for Bayesian
// optimization of non-stationary functions", ICML, PMLR 32:1674): each input passes through the
// Kumaraswamy CDF before the kernel,
//     w_d(x) = 1 − (1 − x^{a_d})^{b_d},   x in [0, 1],  a_d, b_d > 0,
// which stretches the part of a range where the response changes fast (a response that is steep
// near x = 0, like a pile's spread at vanishing cohesion, gets a < 1). a_d, b_d join θ as
// log a_d, log b_d with the paper's log-normal prior N(0, 0.75²) on each, so they are maximum a
// posteriori estimates: −log p(y|X,θ) + Σ_d [(log a_d)² + (log b_d)²] / (2 · 0.75²) is minimised.
// a = b = 1 is the identity.
#pragma once

#include <Eigen/Dense>
#include <cstdint>

namespace paddy::doe {

struct GpHyperparameters {
  Eigen::VectorXd length_scales;  ///< ℓ_d, in unit-cube coordinates
  double signal_variance = 1.0;   ///< σ_f², standardised units
  double noise_variance = 1e-4;   ///< σ_n², standardised units
  Eigen::VectorXd warp_a, warp_b; ///< Kumaraswamy warping per input; empty: none
};

struct GpFitOptions {
  double min_length = 0.03, max_length = 10.0;
  double min_signal = 0.05, max_signal = 20.0;
  double min_noise = 1e-6, max_noise = 1.0;
  int starts = 8;                 ///< restarts of the likelihood search (the first at the centre)
  bool warp_inputs = false;       ///< fit a Kumaraswamy warping of each input (see above)
  double warp_prior_sd = 0.75;    ///< sd of the log-normal prior on a_d, b_d
  double warp_log_bound = 2.0;    ///< |log a_d|, |log b_d| at most this
  std::uint64_t seed = 1;
};

struct GpPrediction {
  double mean = 0;      ///< in the units of y
  double variance = 0;  ///< of the latent f (noise excluded), in the units of y squared
  double sd() const;
};

class GaussianProcess {
 public:
  // X: n × d inputs in the unit cube, y: n outputs. fit() chooses the hyperparameters by maximum
  // likelihood; fitFixed() uses the given ones. Both throw DoeError on bad input (n < 2, NaN,
  // size mismatch, a covariance matrix that is not positive definite).
  void fit(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const GpFitOptions& options = {});
  void fitFixed(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const GpHyperparameters& h);

  GpPrediction predict(const Eigen::VectorXd& x) const;
  double logMarginalLikelihood() const { return log_likelihood_; }  ///< of the standardised y
  const GpHyperparameters& hyperparameters() const { return hyper_; }
  int dimension() const { return static_cast<int>(X_.cols()); }
  int size() const { return static_cast<int>(X_.rows()); }

  double kernel(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;  ///< standardised units, warped inputs
  Eigen::VectorXd warp(const Eigen::VectorXd& x) const;  ///< the inputs as the kernel sees them

 private:
  void factorize();
  Eigen::MatrixXd X_;            ///< warped inputs
  Eigen::VectorXd z_;            ///< standardised y
  double y_mean_ = 0, y_scale_ = 1;
  GpHyperparameters hyper_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::VectorXd alpha_;
  double log_likelihood_ = 0;
};

// Expected improvement below the incumbent `best` of a normal prediction N(mu, sigma²)
// (Jones, Schonlau & Welch 1998, J. Global Optim. 13:455, eq. 15), for minimisation:
//   EI = (best − μ) Φ(u) + σ φ(u),  u = (best − μ)/σ;   EI = max(best − μ, 0) when σ = 0.
double expectedImprovement(double mu, double sigma, double best);

}  // namespace paddy::doe
