// Ordinary least squares by column-pivoting Householder QR (never the normal equations).
//
// X P = Q R with columns first scaled to unit norm so that the rank test is scale free. The rank
// is declared deficient when |R_ii| < 1e-10 |R_00|; the error names the aliased terms.
// Quantities (Montgomery, Design and Analysis of Experiments, ch. 10):
//   beta = P R^-1 Q^T y, (X^T X)^-1 = P R^-1 R^-T P^T, fitted = X beta, e = y - fitted,
//   leverage h_ii = diag(X (X^T X)^-1 X^T), SSE = e^T e.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace paddy::doe {

struct LeastSquares {
  Eigen::VectorXd beta;
  Eigen::MatrixXd xtxInv;   ///< (X^T X)^-1
  Eigen::VectorXd fitted, residuals, leverage;
  double sse = 0.0;
  int n = 0, p = 0;
};

/// Throws DoeError if p > n or if X is rank deficient (message lists termNames of aliased columns).
LeastSquares leastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y,
                          const std::vector<std::string>& termNames);

}  // namespace paddy::doe
