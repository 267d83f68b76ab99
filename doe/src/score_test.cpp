#include "paddy/doe/score_test.hpp"

#include "paddy/doe/error.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <limits>
#include <string>

namespace paddy::doe {

namespace {

double chi2Upper(double q, int df) {
  if (df < 1) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::chi_squared(df), std::max(q, 0.0)));
}

// log Phi(x), accurate far into the lower tail.
double logNormalCdf(double x) {
  if (x > -30.0) return std::log(0.5 * boost::math::erfc(-x / std::sqrt(2.0)));
  // Mills ratio asymptotics: Phi(x) ~ phi(x) / |x| (1 - 1/x^2)
  return -0.5 * x * x - std::log(-x) - 0.5 * std::log(2.0 * M_PI) + std::log1p(-1.0 / (x * x));
}

}  // namespace

Projection::Projection(const Eigen::MatrixXd& J, double tol) {
  const auto m = J.rows();
  // keep the columns with any sensitivity, scaled to unit norm (scale-free rank test)
  std::vector<Eigen::Index> keep;
  for (Eigen::Index j = 0; j < J.cols(); ++j)
    if (J.col(j).norm() > 0) keep.push_back(j);
  if (keep.empty()) {
    basis_ = Eigen::MatrixXd::Zero(m, 0);
    return;
  }
  Eigen::MatrixXd Js(m, static_cast<Eigen::Index>(keep.size()));
  for (std::size_t i = 0; i < keep.size(); ++i) Js.col(static_cast<Eigen::Index>(i)) = J.col(keep[i]).normalized();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Js);
  qr.setThreshold(tol);
  const auto rank = qr.rank();
  basis_ = Eigen::MatrixXd(qr.householderQ()) .leftCols(rank);
}

Eigen::VectorXd Projection::apply(const Eigen::VectorXd& v) const {
  return v - basis_ * (basis_.transpose() * v);
}

Eigen::MatrixXd Projection::apply(const Eigen::MatrixXd& M) const {
  return M - basis_ * (basis_.transpose() * M);
}

double logBayesFactorHalfNormal(double a, double b, double tau) {
  if (!(a > 0) || !(tau > 0)) return 0.0;
  const double t2a = tau * tau * a;
  const double z = b / std::sqrt(a);
  const double shrink = t2a / (1.0 + t2a);
  return std::log(2.0) - 0.5 * std::log1p(t2a) + 0.5 * z * z * shrink + logNormalCdf(z * std::sqrt(shrink));
}

ScoreTests scoreTests(const Eigen::VectorXd& r, const Eigen::MatrixXd& J, const Eigen::MatrixXd& G,
                      const std::vector<std::optional<double>>& priorSd) {
  const auto m = r.size();
  if (J.cols() > 0 && J.rows() != m)
    throw DoeError("jacobian: " + std::to_string(J.rows()) + " rows but the residual has " + std::to_string(m) + " entries");
  if (G.cols() > 0 && G.rows() != m)
    throw DoeError("candidates: signatures have " + std::to_string(G.rows()) + " entries but the residual has " +
                   std::to_string(m));
  if (!priorSd.empty() && static_cast<Eigen::Index>(priorSd.size()) != G.cols())
    throw DoeError("scoreTests: one prior scale per candidate");
  const Projection P(J.cols() > 0 ? J : Eigen::MatrixXd::Zero(m, 0));
  ScoreTests out;
  out.rank = P.rank();
  out.df = static_cast<int>(m) - out.rank;
  if (out.df < 1)
    throw DoeError("no degrees of freedom left: " + std::to_string(m) + " observables and a Jacobian of rank " +
                   std::to_string(out.rank) + " (need more observables than identifiable parameters)");
  out.projectedResidual = P.apply(r);
  out.q0 = out.projectedResidual.squaredNorm();
  out.q0P = chi2Upper(out.q0, out.df);
  out.projectedSignatures = P.apply(G);
  const auto K = G.cols();
  const boost::math::normal stdNormal;
  for (Eigen::Index k = 0; k < K; ++k) {
    CandidateScore s;
    const Eigen::VectorXd pg = out.projectedSignatures.col(k);
    s.a = pg.squaredNorm();
    s.b = pg.dot(out.projectedResidual);
    const double gNorm = G.col(k).norm();
    s.absorbedFraction = gNorm > 0 ? 1.0 - std::sqrt(s.a) / gNorm : 1.0;
    if (s.a > 0) {
      s.z = s.b / std::sqrt(s.a);
      s.p = boost::math::cdf(boost::math::complement(stdNormal, s.z));
      s.strength = s.b / s.a;
      s.strengthSe = 1.0 / std::sqrt(s.a);
    } else {
      s.strengthSe = std::numeric_limits<double>::infinity();
    }
    s.qAfter = out.q0 - std::pow(std::max(s.z, 0.0), 2);
    s.qAfterP = chi2Upper(s.qAfter, out.df - 1);
    if (!priorSd.empty() && priorSd[static_cast<std::size_t>(k)])
      s.logBayesFactor = logBayesFactorHalfNormal(s.a, s.b, *priorSd[static_cast<std::size_t>(k)]);
    out.candidates.push_back(s);
  }
  out.confusability = Eigen::MatrixXd::Zero(K, K);
  for (Eigen::Index k = 0; k < K; ++k)
    for (Eigen::Index l = 0; l < K; ++l) {
      const double nk = out.projectedSignatures.col(k).norm(), nl = out.projectedSignatures.col(l).norm();
      if (nk > 0 && nl > 0)
        out.confusability(k, l) = out.projectedSignatures.col(k).dot(out.projectedSignatures.col(l)) / (nk * nl);
    }
  return out;
}

}  // namespace paddy::doe
