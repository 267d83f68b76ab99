// Vuong's test of two non-nested fits (see non_nested.hpp for the formulas and source).
#include "paddy/doe/non_nested.hpp"

#include "paddy/doe/covariance.hpp"
#include "paddy/doe/error.hpp"

#include <boost/math/distributions/normal.hpp>
#include <cmath>

namespace paddy::doe {

NonNestedComparison vuongTest(const Eigen::VectorXd& rA, const Eigen::VectorXd& rB, const Eigen::MatrixXd& covariance,
                              int kA, int kB, double alpha) {
  const Eigen::Index m = rA.size();
  if (m < 2) throw DoeError("residual_a: needs at least 2 entries");
  if (rB.size() != m)
    throw DoeError("residual_b: " + std::to_string(rB.size()) + " entries but residual_a has " + std::to_string(m));
  if (covariance.rows() != m || covariance.cols() != m)
    throw DoeError("covariance: must be " + std::to_string(m) + " x " + std::to_string(m));
  if (!rA.allFinite() || !rB.allFinite()) throw DoeError("residual_a, residual_b: every entry must be finite");
  if (kA < 0 || kB < 0) throw DoeError("k_a, k_b: the numbers of fitted parameters must be >= 0");
  if (!(alpha > 0 && alpha < 1)) throw DoeError("alpha: must be in (0, 1)");
  const Whitening W(covariance, "covariance");
  const Eigen::VectorXd eA = W.apply(rA), eB = W.apply(rB);
  const Eigen::ArrayXd d = (eB.array().square() - eA.array().square()) / 2.0;
  const double md = static_cast<double>(m);
  NonNestedComparison out;
  out.lr = d.sum() - 0.5 * (kA - kB) * std::log(md);
  out.omega = std::sqrt((d - d.mean()).square().sum() / md);
  const boost::math::normal N;
  if (out.omega > 1e-12 * std::max(1.0, d.abs().maxCoeff())) {
    out.z = out.lr / (std::sqrt(md) * out.omega);
    out.p = 2.0 * boost::math::cdf(boost::math::complement(N, std::abs(out.z)));
  }
  const double crit = boost::math::quantile(boost::math::complement(N, alpha / 2.0));
  out.preferred = out.z > crit ? "a" : out.z < -crit ? "b" : "neither";
  return out;
}

}  // namespace paddy::doe
