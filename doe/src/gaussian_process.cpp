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

// θ = (log ℓ_1..d, log σ_f², log σ_n²) ↔ hyperparameters.
GpHyperparameters fromTheta(const std::vector<double>& t, int d) {
  GpHyperparameters h;
  h.length_scales.resize(d);
  for (int j = 0; j < d; ++j) h.length_scales(j) = std::exp(t[j]);
  h.signal_variance = std::exp(t[d]);
  h.noise_variance = std::exp(t[d + 1]);
  return h;
}

struct LikelihoodProblem {
  GaussianProcess* gp;
  const Eigen::MatrixXd* X;
  const Eigen::VectorXd* y;
};

double negLogLikelihood(unsigned n, const double* t, double*, void* data) {
  auto* p = static_cast<LikelihoodProblem*>(data);
  const int d = static_cast<int>(n) - 2;
  try {
    p->gp->fitFixed(*p->X, *p->y, fromTheta(std::vector<double>(t, t + n), d));
  } catch (const DoeError&) {
    return 1e30;  // not positive definite at these hyperparameters
  }
  return -p->gp->logMarginalLikelihood();
}

}  // namespace

double GpPrediction::sd() const { return std::sqrt(std::max(variance, 0.0)); }

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
  X_ = X;
  y_mean_ = y.mean();
  const double var = (y.array() - y_mean_).square().sum() / static_cast<double>(y.size());
  y_scale_ = var > 0 ? std::sqrt(var) : 1.0;
  z_ = (y.array() - y_mean_) / y_scale_;
  hyper_ = h;
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
  const unsigned n = static_cast<unsigned>(d + 2);
  std::vector<double> lo(n), hi(n);
  for (int j = 0; j < d; ++j) lo[j] = std::log(o.min_length), hi[j] = std::log(o.max_length);
  lo[d] = std::log(o.min_signal), hi[d] = std::log(o.max_signal);
  lo[d + 1] = std::log(o.min_noise), hi[d + 1] = std::log(o.max_noise);

  LikelihoodProblem prob{this, &X, &y};
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> best;
  double bestValue = std::numeric_limits<double>::infinity();
  for (int s = 0; s < std::max(1, o.starts); ++s) {
    std::vector<double> t(n);
    for (unsigned j = 0; j < n; ++j) {
      // First start: length 0.5, signal 1, noise 1e-3 (clamped to the box); then seeded draws.
      const double centre = j < static_cast<unsigned>(d) ? std::log(0.5) : (j == static_cast<unsigned>(d) ? 0.0 : std::log(1e-3));
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
  Eigen::VectorXd k(X_.rows());
  for (Eigen::Index i = 0; i < X_.rows(); ++i) k(i) = kernel(X_.row(i).transpose(), x);
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
