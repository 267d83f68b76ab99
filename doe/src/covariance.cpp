#include "paddy/doe/covariance.hpp"

#include "paddy/doe/error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace paddy::doe {

namespace {

// Columns of the replicates standardised to mean 0, sd 1 (zero-variance columns stay 0).
Eigen::MatrixXd standardised(const Eigen::MatrixXd& X, Eigen::VectorXd& sd) {
  const auto n = X.rows();
  const Eigen::RowVectorXd mean = X.colwise().mean();
  Eigen::MatrixXd C = X.rowwise() - mean;
  sd = (C.colwise().squaredNorm() / static_cast<double>(n - 1)).cwiseSqrt().transpose();
  for (Eigen::Index j = 0; j < C.cols(); ++j) C.col(j) = sd(j) > 0 ? Eigen::VectorXd(C.col(j) / sd(j)) : Eigen::VectorXd::Zero(n);
  return C;
}

void checkReplicates(const Eigen::MatrixXd& X) {
  if (X.rows() < 2)
    throw DoeError("replicates: need at least 2 replicate runs (rows), got " + std::to_string(X.rows()));
  if (X.cols() < 1) throw DoeError("replicates: no observables (columns)");
  if (!X.allFinite()) throw DoeError("replicates: non-finite value");
}

}  // namespace

double correlationShrinkage(const Eigen::MatrixXd& X) {
  checkReplicates(X);
  const auto n = static_cast<double>(X.rows());
  const auto m = X.cols();
  Eigen::VectorXd sd;
  const Eigen::MatrixXd Z = standardised(X, sd);
  double num = 0.0, den = 0.0;
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = i + 1; j < m; ++j) {
      if (sd(i) == 0 || sd(j) == 0) continue;
      const Eigen::ArrayXd w = Z.col(i).array() * Z.col(j).array();
      const double wbar = w.mean();
      const double r = n / (n - 1.0) * wbar;
      const double varR = n / std::pow(n - 1.0, 3) * (w - wbar).square().sum();
      num += varR;
      den += r * r;
    }
  if (den <= 0.0) return 1.0;
  return std::clamp(num / den, 0.0, 1.0);
}

void checkSharedMeasurement(const Eigen::MatrixXd& C, Eigen::Index m, const char* what) {
  if (C.size() == 0) return;
  const std::string w = what;
  if (C.rows() != m || C.cols() != m)
    throw DoeError(w + ": must be " + std::to_string(m) + " x " + std::to_string(m) + " (one row and column per observable), got " +
                   std::to_string(C.rows()) + " x " + std::to_string(C.cols()));
  if (!C.allFinite()) throw DoeError(w + ": has a non-finite entry");
  const double scale = std::max(1e-300, C.cwiseAbs().maxCoeff());
  if ((C - C.transpose()).cwiseAbs().maxCoeff() > 1e-10 * scale) throw DoeError(w + ": not symmetric");
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(C, Eigen::EigenvaluesOnly);
  if (es.eigenvalues()(0) < -1e-10 * scale)
    throw DoeError(w + ": not positive semi-definite (smallest eigenvalue " + std::to_string(es.eigenvalues()(0)) + ")");
}

NoiseCovariance noiseCovariance(const Eigen::MatrixXd& X, const Eigen::VectorXd& sigma, double nAvg,
                                const Eigen::MatrixXd& shared) {
  checkReplicates(X);
  const auto m = X.cols();
  checkSharedMeasurement(shared, m);
  if (sigma.size() != 0 && sigma.size() != m)
    throw DoeError("sigma: " + std::to_string(sigma.size()) + " entries but the replicates have " +
                   std::to_string(m) + " observables (columns)");
  if (sigma.size() && (!sigma.allFinite() || (sigma.array() < 0).any()))
    throw DoeError("sigma: every measurement standard deviation must be finite and >= 0");
  if (!(nAvg > 0.0) || !std::isfinite(nAvg))
    throw DoeError("n_avg: must be > 0 (effective number of seeds averaged), got " + std::to_string(nAvg));
  NoiseCovariance out;
  Eigen::VectorXd sd;
  const Eigen::MatrixXd Z = standardised(X, sd);
  out.seedSd = sd;
  out.shrinkage = correlationShrinkage(X);
  const double n = static_cast<double>(X.rows());
  Eigen::MatrixXd R = Z.transpose() * Z / (n - 1.0);  // sample correlation (0 rows/cols for sd = 0)
  R *= (1.0 - out.shrinkage);
  for (Eigen::Index i = 0; i < m; ++i) R(i, i) = 1.0;
  out.seedCovariance = sd.asDiagonal() * R * sd.asDiagonal();
  out.covariance = out.seedCovariance / nAvg;
  if (shared.size()) out.covariance += shared;
  for (Eigen::Index i = 0; i < m; ++i) {
    if (sigma.size()) out.covariance(i, i) += sigma(i) * sigma(i);
    if (!(out.covariance(i, i) > 0))
      throw DoeError("observable " + std::to_string(i + 1) +
                     " has zero variance: no seed scatter over the replicates and no measurement error");
  }
  return out;
}

Whitening::Whitening(const Eigen::MatrixXd& sigma, const char* what) {
  const std::string w = what;
  if (sigma.rows() != sigma.cols() || sigma.rows() == 0)
    throw DoeError(w + ": must be a non-empty square matrix, got " + std::to_string(sigma.rows()) + " x " +
                   std::to_string(sigma.cols()));
  if (!sigma.allFinite()) throw DoeError(w + ": non-finite value");
  const double scale = sigma.diagonal().cwiseAbs().maxCoeff();
  if (!((sigma - sigma.transpose()).cwiseAbs().maxCoeff() <= 1e-10 * scale))
    throw DoeError(w + ": not symmetric");
  llt_.compute(sigma);
  const bool ok = llt_.info() == Eigen::Success && (llt_.matrixL().toDenseMatrix().diagonal().array() > 0).all();
  if (!ok) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(sigma, Eigen::EigenvaluesOnly);
    throw DoeError(w + ": not positive definite (smallest eigenvalue " + std::to_string(es.eigenvalues()(0)) + ")");
  }
  sd_ = sigma.diagonal().cwiseSqrt();
}

Eigen::VectorXd Whitening::apply(const Eigen::VectorXd& v) const { return llt_.matrixL().solve(v); }
Eigen::MatrixXd Whitening::apply(const Eigen::MatrixXd& M) const {
  if (M.cols() == 0) return M;
  return llt_.matrixL().solve(M);
}

}  // namespace paddy::doe
