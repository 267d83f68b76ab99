#include "paddy/doe/response_surface.hpp"

#include "paddy/doe/covariance.hpp"
#include "paddy/doe/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace paddy::doe {

Eigen::VectorXd quadraticTerms(const Eigen::VectorXd& u) {
  const auto d = u.size();
  Eigen::VectorXd t(1 + d + d * (d + 1) / 2);
  Eigen::Index k = 0;
  t(k++) = 1.0;
  for (Eigen::Index j = 0; j < d; ++j) t(k++) = u(j);
  for (Eigen::Index j = 0; j < d; ++j)
    for (Eigen::Index l = j; l < d; ++l) t(k++) = u(j) * u(l);
  return t;
}

namespace {

void check(const ResponseSurfaceInput& in) {
  const auto n = in.points.rows(), d = in.points.cols(), m = in.values.cols();
  if (d < 1) throw DoeError("points: no parameters (columns)");
  if (m < 1) throw DoeError("values: no observables (columns)");
  if (in.values.rows() != n)
    throw DoeError("values: must have one row per point (" + std::to_string(n) + "), got " + std::to_string(in.values.rows()));
  if (in.measured.size() != m)
    throw DoeError("measured: must have " + std::to_string(m) + " entries (the values' columns), got " + std::to_string(in.measured.size()));
  if (in.covariance.rows() != m || in.covariance.cols() != m) throw DoeError("covariance: must be " + std::to_string(m) + " x " + std::to_string(m));
  if (in.lower.size() != d || in.upper.size() != d) throw DoeError("lower, upper: must have " + std::to_string(d) + " entries (the points' columns)");
  const auto q = 1 + d + d * (d + 1) / 2;
  if (n < q)
    throw DoeError("points: a quadratic surface in " + std::to_string(d) + " parameter(s) needs at least " + std::to_string(q) + " points, got " +
                   std::to_string(n));
  if (!in.points.allFinite()) throw DoeError("points: non-finite value");
  if (!in.values.allFinite()) throw DoeError("values: non-finite value");
  if (!in.measured.allFinite()) throw DoeError("measured: non-finite value");
  if (in.specimenRuns.rows() > 0) {
    if (in.specimenRuns.rows() < 2) throw DoeError("specimen_runs: at least two runs are needed for a spread, got 1");
    if (in.specimenRuns.cols() != m)
      throw DoeError("specimen_runs: each run must have " + std::to_string(m) + " entries (the values' columns), got " +
                     std::to_string(in.specimenRuns.cols()));
    if (!in.specimenRuns.allFinite()) throw DoeError("specimen_runs: non-finite value");
  }
  for (Eigen::Index j = 0; j < d; ++j) {
    if (!std::isfinite(in.lower(j)) || !std::isfinite(in.upper(j)) || !(in.lower(j) < in.upper(j)))
      throw DoeError("lower, upper: entry " + std::to_string(j + 1) + " must be finite with lower < upper");
    for (Eigen::Index i = 0; i < n; ++i) {
      const double span = in.upper(j) - in.lower(j);
      if (in.points(i, j) < in.lower(j) - 1e-12 * span || in.points(i, j) > in.upper(j) + 1e-12 * span)
        throw DoeError("points: point " + std::to_string(i + 1) + ", parameter " + std::to_string(j + 1) + " lies outside [lower, upper]");
    }
  }
}

}  // namespace

ResponseSurfaceFit fitResponseSurface(const ResponseSurfaceInput& in) {
  check(in);
  const auto n = in.points.rows(), d = in.points.cols(), m = in.values.cols();
  const Eigen::VectorXd c = 0.5 * (in.lower + in.upper), h = 0.5 * (in.upper - in.lower);
  auto coded = [&](const Eigen::VectorXd& x) { return Eigen::VectorXd((x - c).cwiseQuotient(h)); };
  const auto q = 1 + d + d * (d + 1) / 2;

  Eigen::MatrixXd X(n, q);
  for (Eigen::Index i = 0; i < n; ++i) X.row(i) = quadraticTerms(coded(in.points.row(i).transpose())).transpose();
  Eigen::VectorXd norms = X.colwise().norm().transpose();
  for (Eigen::Index k = 0; k < q; ++k)
    if (!(norms(k) > 0)) norms(k) = 1.0;
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> cod(X * norms.cwiseInverse().asDiagonal());
  cod.setThreshold(1e-10);
  if (cod.rank() < q)
    throw DoeError("points: the design does not determine a quadratic surface (rank " + std::to_string(cod.rank()) + " of " +
                   std::to_string(q) + " terms): spread the points over every parameter and pair of parameters");
  ResponseSurfaceFit out;
  out.terms = static_cast<int>(q);
  out.coefficients = norms.cwiseInverse().asDiagonal() * cod.solve(in.values);
  const Eigen::MatrixXd resid = in.values - X * out.coefficients;
  out.residualSd = Eigen::VectorXd::Constant(m, std::numeric_limits<double>::quiet_NaN());
  if (n > q) out.residualSd = (resid.colwise().squaredNorm().transpose() / static_cast<double>(n - q)).cwiseSqrt();

  const Whitening W(in.covariance, "covariance");
  auto predict = [&](const Eigen::VectorXd& u) { return Eigen::VectorXd(out.coefficients.transpose() * quadraticTerms(u)); };

  // The minimiser of the misfit to y in coded units: a grid search over [lo, hi]^d, then zoom
  // around the best node. Returns the best node and its misfit.
  const int g = std::max(3, static_cast<int>(std::floor(std::pow(20000.0, 1.0 / static_cast<double>(d)))));
  auto minimise = [&](const Eigen::VectorXd& y, double& bestQ) {
    auto misfit = [&](const Eigen::VectorXd& u) { return W.apply(Eigen::VectorXd(y - predict(u))).squaredNorm(); };
    Eigen::VectorXd lo = Eigen::VectorXd::Constant(d, -1.0), hi = Eigen::VectorXd::Constant(d, 1.0);
    Eigen::VectorXd best = Eigen::VectorXd::Zero(d);
    bestQ = std::numeric_limits<double>::infinity();
    for (int round = 0; round < 7; ++round) {
      std::vector<int> idx(static_cast<std::size_t>(d), 0);
      Eigen::VectorXd u(d);
      while (true) {
        for (Eigen::Index j = 0; j < d; ++j) u(j) = lo(j) + (hi(j) - lo(j)) * idx[static_cast<std::size_t>(j)] / (g - 1);
        const double Q = misfit(u);
        if (Q < bestQ) bestQ = Q, best = u;
        Eigen::Index j = 0;
        while (j < d && ++idx[static_cast<std::size_t>(j)] == g) idx[static_cast<std::size_t>(j++)] = 0;
        if (j == d) break;
      }
      for (Eigen::Index j = 0; j < d; ++j) {
        const double cell = (hi(j) - lo(j)) / (g - 1);
        lo(j) = std::max(-1.0, best(j) - 2 * cell);
        hi(j) = std::min(1.0, best(j) + 2 * cell);
      }
    }
    return best;
  };
  double bestQ = 0.0;
  const Eigen::VectorXd best = minimise(in.measured, bestQ);
  out.x = c + best.cwiseProduct(h);
  out.predicted = predict(best);
  out.misfitPredicted = std::sqrt(bestQ / static_cast<double>(m));
  // Gradient of the terms in u, then chain rule du/dx = 1/h.
  Eigen::MatrixXd dT = Eigen::MatrixXd::Zero(q, d);
  {
    Eigen::Index k = 1 + d;
    for (Eigen::Index j = 0; j < d; ++j) dT(1 + j, j) = 1.0;
    for (Eigen::Index j = 0; j < d; ++j)
      for (Eigen::Index l = j; l < d; ++l, ++k) {
        dT(k, j) += best(l);
        dT(k, l) += best(j);
      }
  }
  out.jacobian = out.coefficients.transpose() * dT * h.cwiseInverse().asDiagonal();
  const Eigen::MatrixXd Jw = W.apply(out.jacobian);
  out.covariance = Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(Jw.transpose() * Jw).pseudoInverse();
  out.se = out.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
  out.atBound.assign(static_cast<std::size_t>(d), 0);
  for (Eigen::Index j = 0; j < d; ++j) out.atBound[static_cast<std::size_t>(j)] = best(j) <= -1.0 ? -1 : best(j) >= 1.0 ? 1 : 0;

  // Spread over specimens (header comment): the minimiser again for y +- each run's deviation.
  const auto K = in.specimenRuns.rows();
  if (K >= 2) {
    const Eigen::VectorXd mean = in.specimenRuns.colwise().mean().transpose();
    Eigen::MatrixXd xs(2 * K, d);
    for (Eigen::Index k = 0; k < K; ++k) {
      const Eigen::VectorXd dev = in.specimenRuns.row(k).transpose() - mean;
      double q = 0.0;
      xs.row(2 * k) = (c + minimise(Eigen::VectorXd(in.measured + dev), q).cwiseProduct(h)).transpose();
      xs.row(2 * k + 1) = (c + minimise(Eigen::VectorXd(in.measured - dev), q).cwiseProduct(h)).transpose();
    }
    const Eigen::RowVectorXd xm = xs.colwise().mean();
    const double scale = static_cast<double>(K) / static_cast<double>(K - 1) / static_cast<double>(2 * K);
    out.specimenSe = ((xs.rowwise() - xm).colwise().squaredNorm().transpose() * scale).cwiseSqrt();
  }
  return out;
}

}  // namespace paddy::doe
