#include "paddy/doe/regression.hpp"

#include "paddy/doe/error.hpp"

#include <cmath>

namespace paddy::doe {

LeastSquares leastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                          const std::vector<std::string>& termNames) {
  const int n = static_cast<int>(X.rows()), p = static_cast<int>(X.cols());
  if (y.size() != n) throw DoeError("least squares: response length does not match the design");
  if (p > n)
    throw DoeError("the model has " + std::to_string(p) + " terms but only " + std::to_string(n) +
                   " runs; choose a smaller model or add runs");
  if (!X.allFinite() || !y.allFinite()) throw DoeError("least squares: non-finite values in the data");
  Eigen::VectorXd norms = X.colwise().norm().transpose();
  for (int j = 0; j < p; ++j)
    if (norms(j) == 0.0) {
      const std::string name = j < static_cast<int>(termNames.size()) ? termNames[j] : std::to_string(j);
      throw DoeError("the design is singular: term " + name + " is zero in every run");
    }
  const Eigen::MatrixXd Xs = X * norms.cwiseInverse().asDiagonal();
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Xs);
  qr.setThreshold(1e-10);
  if (qr.rank() < p) {
    std::string aliased;
    const auto& perm = qr.colsPermutation().indices();
    for (int i = static_cast<int>(qr.rank()); i < p; ++i) {
      const int j = perm(i);
      aliased += (aliased.empty() ? "" : ", ") +
                 (j < static_cast<int>(termNames.size()) ? termNames[j] : std::to_string(j));
    }
    throw DoeError("the design is singular (rank " + std::to_string(qr.rank()) + " < " +
                   std::to_string(p) + " model terms); aliased or inestimable terms: " + aliased);
  }
  LeastSquares r;
  r.n = n;
  r.p = p;
  r.beta = qr.solve(y).cwiseQuotient(norms);
  // (Xs^T Xs)^-1 = P R^-1 R^-T P^T ; then unscale: (X^T X)^-1 = D^-1 (Xs^T Xs)^-1 D^-1
  const Eigen::MatrixXd R = qr.matrixR().topLeftCorner(p, p).template triangularView<Eigen::Upper>();
  const Eigen::MatrixXd Rinv = R.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(p, p));
  Eigen::MatrixXd PRinv = qr.colsPermutation() * Rinv;  // P R^-1
  Eigen::MatrixXd inv = PRinv * PRinv.transpose();
  r.xtxInv = norms.cwiseInverse().asDiagonal() * inv * norms.cwiseInverse().asDiagonal();
  r.fitted = X * r.beta;
  r.residuals = y - r.fitted;
  r.sse = r.residuals.squaredNorm();
  const Eigen::MatrixXd XR = Xs * PRinv;  // = Q1
  r.leverage = XR.rowwise().squaredNorm();
  return r;
}

}  // namespace paddy::doe
