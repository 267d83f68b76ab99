// One bounded Gauss–Newton / Levenberg–Marquardt step of a calibration, the parameter covariance,
// and the comparison of the fits before and after adding an effect.
//
// Whitened r = L^-1 (y_measured - f(theta)), J = L^-1 df/dtheta. The step d minimises
//   |r - J d|^2 + mu |D d|^2,  D^2 = diag(J^T J)  (Marquardt's scaling; mu = damping >= 0)
// subject to lower - theta <= d <= upper - theta. This box-constrained linear least-squares
// problem is solved exactly by a primal active-set method (bounded-variable least squares,
// P. B. Stark and R. L. Parker, Comput. Statist. 10, 129–141, 1995): free variables solved by a
// complete orthogonal decomposition of [J_F; sqrt(mu) D_F] (minimum-norm for a rank-deficient J),
// a blocked step stops at the first bound, and a bound is released when its Lagrange multiplier
// has the wrong sign (KKT: gradient of the objective >= 0 at a lower bound, <= 0 at an upper).
//   covariance of theta^ = (J^T J)^+ (pseudo-inverse; rank < p is reported),  se = sqrt(diag)
//   misfit_predicted = sqrt(|r - J d|^2 / m)
// (D. W. Marquardt, J. SIAM 11, 431–441, 1963.)
//
// Fits compared on the whitened misfits Q = r^T r (-2 log L up to a constant for Gaussian noise
// of known Sigma):
//   LR = Q_before - Q_after ~ chi^2(df) under "the added effect is absent" (Wilks),
//   Delta BIC = (Q_after + k_after ln n) - (Q_before + k_before ln n)   (negative favours the
//   effect; Kass & Raftery 1995: |Delta BIC| 2–6 positive, 6–10 strong, > 10 very strong),
//   BF approx exp(-Delta BIC / 2).
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace paddy::doe {

struct BoundedStep {
  Eigen::VectorXd theta, step;
  Eigen::MatrixXd covariance;   ///< (J^T J)^+ of the whitened Jacobian
  Eigen::VectorXd se;
  int rank = 0;
  double misfitPredicted = 0;
  std::vector<int> atBound;     ///< -1 at lower, +1 at upper, 0 free
  int iterations = 0;
};

/// theta within [lower, upper] (empty bounds = unbounded), r (m) and J (m x p) whitened.
/// Throws DoeError naming the field for dimension mismatch, non-finite values, theta outside its
/// bounds, lower > upper or damping < 0.
BoundedStep boundedGaussNewtonStep(const Eigen::VectorXd& theta, const Eigen::VectorXd& r,
                                   const Eigen::MatrixXd& J, const Eigen::VectorXd& lower,
                                   const Eigen::VectorXd& upper, double damping = 0.0);

struct FitComparison {
  double lr = 0, p = 1, deltaBic = 0, bayesFactor = 1;
  std::string evidence;  ///< Kass–Raftery category of Delta BIC
};
/// Throws DoeError for df < 1, n < 1, negative or non-finite Q.
FitComparison compareFits(double qBefore, double qAfter, int df, int n, int kBefore, int kAfter);

}  // namespace paddy::doe
