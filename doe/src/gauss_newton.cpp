#include "paddy/doe/gauss_newton.hpp"

#include "paddy/doe/error.hpp"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <limits>

namespace paddy::doe {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// min |rhs - J_F d_F|^2 + mu |D_F d_F|^2 over the free entries, fixed entries held at d.
Eigen::VectorXd solveFree(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, const Eigen::VectorXd& D, double mu,
                          const std::vector<int>& state, const Eigen::VectorXd& d) {
  const auto m = J.rows(), p = J.cols();
  std::vector<Eigen::Index> freeIdx;
  Eigen::VectorXd rhs = r;
  for (Eigen::Index j = 0; j < p; ++j) {
    if (state[static_cast<std::size_t>(j)] == 0) freeIdx.push_back(j);
    else rhs -= J.col(j) * d(j);
  }
  Eigen::VectorXd s = d;
  if (freeIdx.empty()) return s;
  const auto nf = static_cast<Eigen::Index>(freeIdx.size());
  const bool damped = mu > 0;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(m + (damped ? nf : 0), nf);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(A.rows());
  b.head(m) = rhs;
  for (Eigen::Index i = 0; i < nf; ++i) {
    A.col(i).head(m) = J.col(freeIdx[static_cast<std::size_t>(i)]);
    if (damped) A(m + i, i) = std::sqrt(mu) * D(freeIdx[static_cast<std::size_t>(i)]);
  }
  // scale columns to unit norm so that the rank decision does not depend on parameter units
  Eigen::VectorXd norms = A.colwise().norm().transpose();
  for (Eigen::Index i = 0; i < nf; ++i)
    if (!(norms(i) > 0)) norms(i) = 1.0;
  const Eigen::MatrixXd As = A * norms.cwiseInverse().asDiagonal();
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(As);
  cod.setThreshold(1e-12);
  const Eigen::VectorXd x = cod.solve(b).cwiseQuotient(norms);
  for (Eigen::Index i = 0; i < nf; ++i) s(freeIdx[static_cast<std::size_t>(i)]) = x(i);
  return s;
}

}  // namespace

BoundedStep boundedGaussNewtonStep(const Eigen::VectorXd& theta, const Eigen::VectorXd& r, const Eigen::MatrixXd& J,
                                   const Eigen::VectorXd& lowerIn, const Eigen::VectorXd& upperIn, double damping) {
  const auto p = theta.size(), m = r.size();
  if (p < 1) throw DoeError("theta: no parameters");
  if (m < 1) throw DoeError("residual: empty");
  if (J.rows() != m || J.cols() != p)
    throw DoeError("jacobian: must be " + std::to_string(m) + " x " + std::to_string(p) + " (residual entries x parameters), got " +
                   std::to_string(J.rows()) + " x " + std::to_string(J.cols()));
  if (!theta.allFinite()) throw DoeError("theta: non-finite value");
  if (!r.allFinite()) throw DoeError("residual: non-finite value");
  if (!J.allFinite()) throw DoeError("jacobian: non-finite value");
  if (!(damping >= 0) || !std::isfinite(damping)) throw DoeError("damping: must be finite and >= 0");
  const Eigen::VectorXd lower = lowerIn.size() ? lowerIn : Eigen::VectorXd::Constant(p, -kInf);
  const Eigen::VectorXd upper = upperIn.size() ? upperIn : Eigen::VectorXd::Constant(p, kInf);
  if (lower.size() != p) throw DoeError("lower: " + std::to_string(lower.size()) + " entries for " + std::to_string(p) + " parameters");
  if (upper.size() != p) throw DoeError("upper: " + std::to_string(upper.size()) + " entries for " + std::to_string(p) + " parameters");
  for (Eigen::Index j = 0; j < p; ++j) {
    const std::string which = "parameter " + std::to_string(j + 1);
    if (std::isnan(lower(j)) || std::isnan(upper(j)) || lower(j) > upper(j))
      throw DoeError("lower/upper: " + which + " needs lower <= upper");
    if (theta(j) < lower(j) || theta(j) > upper(j))
      throw DoeError("theta: " + which + " = " + std::to_string(theta(j)) + " is outside [" + std::to_string(lower(j)) + ", " +
                     std::to_string(upper(j)) + "]");
  }
  const Eigen::VectorXd lo = lower - theta, hi = upper - theta;  // bounds on the step
  const Eigen::VectorXd D = J.colwise().norm().transpose();      // D^2 = diag(J^T J)
  const Eigen::VectorXd g = J.transpose() * r;
  const double gradTol = 1e-10 * std::max(1.0, g.cwiseAbs().maxCoeff());
  auto gradient = [&](const Eigen::VectorXd& d) -> Eigen::VectorXd {
    return -(J.transpose() * (r - J * d)) + damping * D.cwiseProduct(D).cwiseProduct(d);
  };

  std::vector<int> state(static_cast<std::size_t>(p), 0);
  Eigen::VectorXd d = Eigen::VectorXd::Zero(p);
  BoundedStep out;
  const int maxIter = 20 * static_cast<int>(p + 1);
  bool converged = false;
  for (int it = 0; it < maxIter; ++it) {
    out.iterations = it + 1;
    const Eigen::VectorXd s = solveFree(J, r, D, damping, state, d);
    double alpha = 1.0;
    Eigen::Index blocking = -1;
    for (Eigen::Index j = 0; j < p; ++j) {
      if (state[static_cast<std::size_t>(j)] != 0) continue;
      const double delta = s(j) - d(j);
      if (s(j) > hi(j) && delta > 0) {
        const double a = (hi(j) - d(j)) / delta;
        if (a < alpha) alpha = a, blocking = j;
      } else if (s(j) < lo(j) && delta < 0) {
        const double a = (lo(j) - d(j)) / delta;
        if (a < alpha) alpha = a, blocking = j;
      }
    }
    if (blocking < 0) {
      d = s;
      const Eigen::VectorXd grad = gradient(d);
      Eigen::Index release = -1;
      double worst = gradTol;
      for (Eigen::Index j = 0; j < p; ++j) {
        const int st = state[static_cast<std::size_t>(j)];
        const double violation = st < 0 ? -grad(j) : st > 0 ? grad(j) : 0.0;
        if (violation > worst) worst = violation, release = j;
      }
      if (release < 0) {
        converged = true;
        break;
      }
      state[static_cast<std::size_t>(release)] = 0;
      continue;
    }
    d += std::max(alpha, 0.0) * (s - d);
    for (Eigen::Index j = 0; j < p; ++j) {  // fix every free variable that reached a bound
      if (state[static_cast<std::size_t>(j)] != 0) continue;
      const double tol = 1e-12 * std::max(1.0, std::abs(d(j)));
      if (j == blocking || d(j) >= hi(j) - tol || d(j) <= lo(j) + tol) {
        const bool up = j == blocking ? s(j) > hi(j) : d(j) >= hi(j) - tol;
        state[static_cast<std::size_t>(j)] = up ? 1 : -1;
        d(j) = up ? hi(j) : lo(j);
      }
    }
  }
  if (!converged) throw DoeError("bounded Gauss-Newton step: the active-set iteration did not converge");
  out.step = d;
  out.theta = (theta + d).cwiseMax(lower).cwiseMin(upper);
  out.atBound = state;
  out.misfitPredicted = std::sqrt((r - J * d).squaredNorm() / static_cast<double>(m));

  // parameter covariance (J^T J)^+ with unit-norm columns for the rank decision
  Eigen::VectorXd norms = D;
  for (Eigen::Index j = 0; j < p; ++j)
    if (!(norms(j) > 0)) norms(j) = 1.0;
  const Eigen::MatrixXd Js = J * norms.cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeFullV);
  const Eigen::VectorXd sv = svd.singularValues();
  const double cut = 1e-10 * (sv.size() ? sv(0) : 0.0);
  Eigen::VectorXd inv2 = Eigen::VectorXd::Zero(p);
  Eigen::VectorXd nullWeight = Eigen::VectorXd::Zero(p);
  out.rank = 0;
  for (Eigen::Index k = 0; k < p; ++k) {
    const double s = k < sv.size() ? sv(k) : 0.0;
    if (s > cut && s > 0) {
      inv2(k) = 1.0 / (s * s);
      ++out.rank;
    } else {
      nullWeight += svd.matrixV().col(k).cwiseAbs2();
    }
  }
  const Eigen::MatrixXd& V = svd.matrixV();
  out.covariance = norms.cwiseInverse().asDiagonal() * (V * inv2.asDiagonal() * V.transpose()) * norms.cwiseInverse().asDiagonal();
  out.se = out.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
  for (Eigen::Index j = 0; j < p; ++j)
    if (nullWeight(j) > 1e-8) out.se(j) = kInf;  // not identified: moves along a direction the data cannot see
  return out;
}

FitComparison compareFits(double qBefore, double qAfter, int df, int n, int kBefore, int kAfter) {
  if (!(std::isfinite(qBefore) && qBefore >= 0)) throw DoeError("q_before: must be finite and >= 0");
  if (!(std::isfinite(qAfter) && qAfter >= 0)) throw DoeError("q_after: must be finite and >= 0");
  if (df < 1) throw DoeError("df: must be >= 1 (parameters added), got " + std::to_string(df));
  if (n < 1) throw DoeError("n: must be >= 1 (observables), got " + std::to_string(n));
  if (kBefore < 0 || kAfter < 0) throw DoeError("k_before/k_after: must be >= 0");
  FitComparison c;
  c.lr = qBefore - qAfter;
  c.p = boost::math::cdf(boost::math::complement(boost::math::chi_squared(df), std::max(c.lr, 0.0)));
  c.deltaBic = (qAfter + kAfter * std::log(static_cast<double>(n))) - (qBefore + kBefore * std::log(static_cast<double>(n)));
  c.bayesFactor = std::exp(-0.5 * c.deltaBic);
  const double e = -c.deltaBic;  // evidence for the fit after
  c.evidence = e > 10 ? "very strong" : e > 6 ? "strong" : e > 2 ? "positive" : e > -2 ? "not worth more than a bare mention"
             : "against the added effect";
  return c;
}

}  // namespace paddy::doe
