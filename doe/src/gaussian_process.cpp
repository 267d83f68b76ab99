#include "paddy/doe/gaussian_process.hpp"

#include "paddy/doe/error.hpp"

#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>
#include <nlopt.hpp>
#include <random>
#include <vector>

namespace paddy::doe {

namespace {

constexpr double kLog2Pi = 1.8378770664093454836;

void checkData(const Eigen::MatrixXd& X, const Eigen::VectorXd& y) {
  if (X.rows() != y.size()) throw DoeError("gaussian process: " + std::to_string(X.rows()) +
                                           " input rows but " + std::to_string(y.size()) + " outputs");
  if (X.rows() < 2) throw DoeError("gaussian process: needs at least 2 points, got " + std::to_string(X.rows()));
  if (X.cols() < 1) throw DoeError("gaussian process: inputs have no columns");
  if (!X.allFinite() || !y.allFinite()) throw DoeError("gaussian process: inputs or outputs are not finite");
}

// θ = (log ℓ_1..d, log σ_f², log σ_n² [, log a_1..d, log b_1..d]) ↔ hyperparameters.
GpHyperparameters fromTheta(const std::vector<double>& t, int d) {
  GpHyperparameters h;
  h.length_scales.resize(d);
  for (int j = 0; j < d; ++j) h.length_scales(j) = std::exp(t[j]);
  h.signal_variance = std::exp(t[d]);
  h.noise_variance = std::exp(t[d + 1]);
  if (t.size() == static_cast<std::size_t>(3 * d + 2)) {
    h.warp_a.resize(d), h.warp_b.resize(d);
    for (int j = 0; j < d; ++j) h.warp_a(j) = std::exp(t[d + 2 + j]), h.warp_b(j) = std::exp(t[2 * d + 2 + j]);
  }
  return h;
}

struct LikelihoodProblem {
  GaussianProcess* gp;
  const Eigen::MatrixXd* X;
  const Eigen::VectorXd* y;
  int d;
  double warp_prior_sd;
};

double negLogLikelihood(unsigned n, const double* t, double*, void* data) {
  auto* p = static_cast<LikelihoodProblem*>(data);
  const int d = p->d;
  try {
    p->gp->fitFixed(*p->X, *p->y, fromTheta(std::vector<double>(t, t + n), d));
  } catch (const DoeError&) {
    return 1e30;  // not positive definite at these hyperparameters
  }
  double prior = 0;  // log-normal prior on the warping's a_d, b_d (MAP)
  for (unsigned j = static_cast<unsigned>(d + 2); j < n; ++j) prior += t[j] * t[j];
  return -p->gp->logMarginalLikelihood() + prior / (2 * p->warp_prior_sd * p->warp_prior_sd);
}

}  // namespace

double GpPrediction::sd() const { return std::sqrt(std::max(variance, 0.0)); }

Eigen::VectorXd GaussianProcess::warp(const Eigen::VectorXd& x) const {
  if (hyper_.warp_a.size() == 0) return x;
  Eigen::VectorXd w(x.size());
  for (Eigen::Index j = 0; j < x.size(); ++j) {
    const double u = std::clamp(x(j), 0.0, 1.0);
    w(j) = 1.0 - std::pow(1.0 - std::pow(u, hyper_.warp_a(j)), hyper_.warp_b(j));
  }
  return w;
}

double GaussianProcess::kernel(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  const double r = ((a - b).array() / hyper_.length_scales.array()).matrix().norm();
  const double s5r = std::sqrt(5.0) * r;
  return hyper_.signal_variance * (1.0 + s5r + 5.0 * r * r / 3.0) * std::exp(-s5r);
}

void GaussianProcess::fitFixed(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const GpHyperparameters& h) {
  checkData(X, y);
  if (h.length_scales.size() != X.cols()) throw DoeError("gaussian process: one length scale per input column needed");
  if (!(h.length_scales.array() > 0).all() || !(h.signal_variance > 0) || !(h.noise_variance >= 0))
    throw DoeError("gaussian process: length scales and signal variance must be > 0, noise variance >= 0");
  const bool warped = h.warp_a.size() != 0 || h.warp_b.size() != 0;
  if (warped && (h.warp_a.size() != X.cols() || h.warp_b.size() != X.cols() || !(h.warp_a.array() > 0).all() ||
                 !(h.warp_b.array() > 0).all()))
    throw DoeError("gaussian process: warping needs one a > 0 and one b > 0 per input column");
  hyper_ = h;
  X_.resize(X.rows(), X.cols());
  for (Eigen::Index i = 0; i < X.rows(); ++i) X_.row(i) = warp(X.row(i).transpose()).transpose();
  y_mean_ = y.mean();
  const double var = (y.array() - y_mean_).square().sum() / static_cast<double>(y.size());
  y_scale_ = var > 0 ? std::sqrt(var) : 1.0;
  z_ = (y.array() - y_mean_) / y_scale_;
  factorize();
}

void GaussianProcess::factorize() {
  const Eigen::Index n = X_.rows();
  Eigen::MatrixXd K(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j <= i; ++j) K(i, j) = K(j, i) = kernel(X_.row(i).transpose(), X_.row(j).transpose());
    K(i, i) += hyper_.noise_variance;
  }
  llt_.compute(K);
  if (llt_.info() != Eigen::Success) throw DoeError("gaussian process: covariance matrix is not positive definite");
  alpha_ = llt_.solve(z_);
  const Eigen::MatrixXd L = llt_.matrixL();
  log_likelihood_ = -0.5 * z_.dot(alpha_) - L.diagonal().array().log().sum() - 0.5 * static_cast<double>(n) * kLog2Pi;
}

void GaussianProcess::fit(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const GpFitOptions& o) {
  checkData(X, y);
  const int d = static_cast<int>(X.cols());
  if (o.warp_inputs && !(o.warp_prior_sd > 0 && o.warp_log_bound > 0))
    throw DoeError("gaussian process: warp_prior_sd and warp_log_bound must be > 0");
  const unsigned n = static_cast<unsigned>(o.warp_inputs ? 3 * d + 2 : d + 2);
  std::vector<double> lo(n), hi(n);
  for (int j = 0; j < d; ++j) lo[j] = std::log(o.min_length), hi[j] = std::log(o.max_length);
  lo[d] = std::log(o.min_signal), hi[d] = std::log(o.max_signal);
  lo[d + 1] = std::log(o.min_noise), hi[d + 1] = std::log(o.max_noise);
  for (unsigned j = static_cast<unsigned>(d + 2); j < n; ++j) lo[j] = -o.warp_log_bound, hi[j] = o.warp_log_bound;

  LikelihoodProblem prob{this, &X, &y, d, o.warp_prior_sd};
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> best;
  double bestValue = std::numeric_limits<double>::infinity();
  for (int s = 0; s < std::max(1, o.starts); ++s) {
    std::vector<double> t(n);
    for (unsigned j = 0; j < n; ++j) {
      // First start: length 0.5, signal 1, noise 1e-3, no warping (clamped to the box); then
      // seeded draws.
      const auto du = static_cast<unsigned>(d);
      const double centre = j < du ? std::log(0.5) : (j == du ? 0.0 : (j == du + 1 ? std::log(1e-3) : 0.0));
      t[j] = s == 0 ? std::clamp(centre, lo[j], hi[j]) : lo[j] + u(rng) * (hi[j] - lo[j]);
    }
    nlopt::opt opt(nlopt::LN_BOBYQA, n);
    opt.set_lower_bounds(lo);
    opt.set_upper_bounds(hi);
    opt.set_min_objective(negLogLikelihood, &prob);
    opt.set_xtol_rel(1e-6);
    opt.set_maxeval(400);
    double value = 0;
    try {
      opt.optimize(t, value);
    } catch (const std::exception&) {
      value = negLogLikelihood(n, t.data(), nullptr, &prob);  // keep the point reached
    }
    if (value < bestValue) bestValue = value, best = t;
  }
  if (!(bestValue < 1e29)) throw DoeError("gaussian process: no hyperparameters give a positive-definite covariance");
  fitFixed(X, y, fromTheta(best, d));
}

GpPrediction GaussianProcess::predict(const Eigen::VectorXd& x) const {
  if (x.size() != X_.cols()) throw DoeError("gaussian process: point has " + std::to_string(x.size()) +
                                            " coordinates, the model " + std::to_string(X_.cols()));
  const Eigen::VectorXd xw = warp(x);
  Eigen::VectorXd k(X_.rows());
  for (Eigen::Index i = 0; i < X_.rows(); ++i) k(i) = kernel(X_.row(i).transpose(), xw);
  const Eigen::VectorXd v = llt_.matrixL().solve(k);
  GpPrediction p;
  p.mean = y_mean_ + y_scale_ * k.dot(alpha_);
  p.variance = std::max(0.0, hyper_.signal_variance - v.squaredNorm()) * y_scale_ * y_scale_;
  return p;
}

double expectedImprovement(double mu, double sigma, double best) {
  if (!(sigma > 0)) return std::max(best - mu, 0.0);
  const boost::math::normal_distribution<double> N;
  const double u = (best - mu) / sigma;
  return (best - mu) * boost::math::cdf(N, u) + sigma * boost::math::pdf(N, u);
}

}  // namespace paddy::doe
