#include "paddy/doe/bootstrap_null.hpp"

#include "paddy/doe/covariance.hpp"
#include "paddy/doe/error.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace paddy::doe {

namespace {

// A square root S of a symmetric positive semi-definite matrix (S S^T = A), by eigen-decomposition
// so that a singular Sigma_seed (an observable without seed scatter) is allowed.
Eigen::MatrixXd psdRoot(const Eigen::MatrixXd& A, const char* what) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A);
  if (es.info() != Eigen::Success) throw DoeError(std::string(what) + ": eigen-decomposition failed");
  const double scale = std::max(1.0, es.eigenvalues().cwiseAbs().maxCoeff());
  if (es.eigenvalues().minCoeff() < -1e-9 * scale)
    throw DoeError(std::string(what) + ": not positive semi-definite (smallest eigenvalue " +
                   std::to_string(es.eigenvalues().minCoeff()) + ")");
  return es.eigenvectors() * es.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
}

Eigen::VectorXd draw(std::mt19937_64& rng, const Eigen::MatrixXd& root) {
  std::normal_distribution<double> N(0.0, 1.0);
  Eigen::VectorXd u(root.cols());
  for (Eigen::Index i = 0; i < u.size(); ++i) u(i) = N(rng);
  return root * u;
}

}  // namespace

NullThresholds bootstrapNullThresholds(const BootstrapNullInput& in) {
  const Eigen::Index m = in.seedCovariance.rows();
  if (m == 0 || in.seedCovariance.cols() != m) throw DoeError("seed_covariance: must be a square m x m matrix");
  if (!in.seedCovariance.allFinite()) throw DoeError("seed_covariance: has a non-finite entry");
  if ((in.seedCovariance - in.seedCovariance.transpose()).cwiseAbs().maxCoeff() >
      1e-9 * std::max(1.0, in.seedCovariance.cwiseAbs().maxCoeff()))
    throw DoeError("seed_covariance: not symmetric");
  if (in.jacobian.rows() != m && !(in.jacobian.size() == 0))
    throw DoeError("jacobian: " + std::to_string(in.jacobian.rows()) + " rows but seed_covariance is " + std::to_string(m) + " x " +
                   std::to_string(m));
  if (in.sigma.size() != 0 && in.sigma.size() != m)
    throw DoeError("sigma: " + std::to_string(in.sigma.size()) + " entries, expected " + std::to_string(m));
  checkSharedMeasurement(in.sharedMeasurement, m);
  if (in.replicates < 2) throw DoeError("replicates: must be >= 2 (the number of seeds Sigma_seed was estimated from)");
  if (!(in.nAvg > 0.0) || !std::isfinite(in.nAvg)) throw DoeError("n_avg: must be > 0");
  if (in.trials < 20) throw DoeError("trials: must be >= 20");
  for (const auto& c : in.candidates)
    if (c.signature.size() != m) throw DoeError("candidates (" + c.name + ").signature: needs " + std::to_string(m) + " entries");

  const Eigen::VectorXd sigma = in.sigma.size() ? in.sigma : Eigen::VectorXd::Zero(m);
  Eigen::MatrixXd total = in.seedCovariance / in.nAvg;
  total.diagonal() += sigma.cwiseAbs2();
  if (in.sharedMeasurement.size()) total += in.sharedMeasurement;
  const Eigen::MatrixXd rootTotal = psdRoot(total, "covariance (sigma^2 + measurement_covariance + seed_covariance / n_avg)");
  const Eigen::MatrixXd rootSeed = psdRoot(in.seedCovariance, "seed_covariance");

  DiagnoseInput d;
  d.jacobian = in.jacobian.size() ? in.jacobian : Eigen::MatrixXd(m, 0);
  d.candidates = in.candidates;
  // Only z and Q0 of each null trial are used: the detection limits, which the per-seed
  // signatures are for, would be computed 2000 times for nothing.
  for (auto& c : d.candidates) c.signatureSeeds.clear();
  d.options = in.options;
  d.options.zThreshold.reset();
  d.options.q0Threshold.reset();
  d.options.qAfterThreshold.reset();

  std::mt19937_64 rng(in.seed);
  std::vector<double> zMax, q0, qAfter;
  zMax.reserve(static_cast<std::size_t>(in.trials));
  q0.reserve(static_cast<std::size_t>(in.trials));
  Eigen::MatrixXd X(in.replicates, m);
  for (int t = 0; t < in.trials; ++t) {
    d.residual = draw(rng, rootTotal);
    for (int r = 0; r < in.replicates; ++r) X.row(r) = draw(rng, rootSeed).transpose();
    d.covariance = noiseCovariance(X, sigma, in.nAvg, in.sharedMeasurement).covariance;
    const Diagnosis out = diagnose(d);
    double z = -std::numeric_limits<double>::infinity();
    for (const auto& c : out.candidates)
      if (c.identifiable) {
        z = std::max(z, c.score.z);
        qAfter.push_back(out.q0 - c.score.z * c.score.z);
      }
    // No identifiable candidate: the z threshold is never used; keep the list pairable.
    zMax.push_back(std::isfinite(z) ? z : 0.0);
    q0.push_back(out.q0);
  }
  return nullThresholds(zMax, q0, in.options.alpha, qAfter);
}

}  // namespace paddy::doe
