// A quadratic response surface of a vector of simulated observables over a few parameters, and
// the point of the parameter box where it matches the measurements best: the refit of the
// discovery workflow (docs/discovery.md, step 4). One seed's simulated response of a coarse pile
// is rough in the parameters (a change of 0.4 % of a range moved the misfit by 1.3 noise sd in
// the blind benchmark), so forward differences at one seed point anywhere; a surface fitted by
// least squares through points spread over the box averages that roughness out (response surface
// methodology: G. E. P. Box and K. B. Wilson, J. R. Stat. Soc. B 13, 1–45, 1951; R. H. Myers,
// D. C. Montgomery and C. M. Anderson-Cook, Response Surface Methodology, 4th ed., Wiley 2016,
// ch. 2–3 and 6).
//
// Coded coordinates u_j = (x_j - c_j) / h_j, c and h the box's centre and half-width. Per
// observable i, by least squares over the n points (n >= q = 1 + d + d(d+1)/2):
//   f_i(u) = b_i0 + sum_j b_ij u_j + sum_{j<=k} b_ijk u_j u_k
// (the same terms as a Box–Behnken model; complete orthogonal decomposition of the n x q model
// matrix, its columns scaled to unit norm; rank < q is an error naming the points). The surface's
// residual sd per observable is sqrt(RSS_i / (n - q)) when n > q.
// Misfit Q(x) = (y - f(x))^T Sigma^-1 (y - f(x)), minimised over the box: every node of a grid of
// g^d nodes (g = max(3, floor(20000^(1/d))), at most 20 000), then the box around the best node
// (two cells each side) gridded again, 6 times. At x*:
//   J = df/dx (the surface's gradient, natural units), covariance of x* = (J^T Sigma^-1 J)^+,
//   se = sqrt(diag), misfit_predicted = sqrt(Q(x*) / m)
// (the covariance ignores the surface's own coefficient error: with n - q residual degrees of
// freedom it is the linearised Gauss–Newton covariance at x*).
// Spread over specimens (optional specimen runs f_1..f_K, K >= 2, simulated at x* at other seeds):
// the measurements are one specimen whose seed scatter moves whole curves together, which a
// covariance shrunk toward its diagonal counts as independent readings, so se above is too small
// (docs/discovery.md, "The tack test at two pull speeds"). Each run's deviation d_k = f_k - mean
// stands for another specimen: the minimiser is found again for y + d_k and y - d_k, and
//   specimen_se_j = sqrt( sum over the 2K minimisers of (x_j - mean_j)^2 / (2K) * K / (K - 1) ),
// for a linear response exactly the sample sd of x_j's change g_j . d_k over the K runs (a
// parametric bootstrap over specimens: B. Efron and R. J. Tibshirani, An Introduction to the
// Bootstrap, Chapman & Hall 1993, ch. 6; the antithetic pairs keep the draws' mean at y).
#pragma once
#include <Eigen/Dense>
#include <vector>

namespace paddy::doe {

struct ResponseSurfaceInput {
  Eigen::MatrixXd points;      ///< n x d parameter values, inside [lower, upper]
  Eigen::MatrixXd values;      ///< n x m simulated observables
  Eigen::VectorXd measured;    ///< m
  Eigen::MatrixXd covariance;  ///< m x m, symmetric positive definite (the misfit's weights)
  Eigen::VectorXd lower, upper;  ///< d, lower < upper
  Eigen::MatrixXd specimenRuns;  ///< K x m, optional (0 rows: none; else K >= 2): runs at x* at other seeds
};

struct ResponseSurfaceFit {
  Eigen::VectorXd x;              ///< d, the minimiser of the predicted misfit in the box
  Eigen::VectorXd predicted;      ///< m, f(x)
  Eigen::MatrixXd jacobian;       ///< m x d at x, natural units
  Eigen::MatrixXd covariance;     ///< d x d, (J^T Sigma^-1 J)^+
  Eigen::VectorXd se;             ///< d
  Eigen::MatrixXd coefficients;   ///< q x m in coded units (terms: 1, u_j, then u_j u_k for j <= k)
  Eigen::VectorXd residualSd;     ///< m, NaN when n == q
  double misfitPredicted = 0;     ///< sqrt(Q(x) / m)
  int terms = 0;                  ///< q
  std::vector<int> atBound;       ///< d: -1 at lower, +1 at upper, 0 inside
  Eigen::VectorXd specimenSe;     ///< d, the spread of x over specimens; empty without specimen runs
};

/// Evaluates the quadratic terms of coded coordinates u (1, u_j, u_j u_k for j <= k).
Eigen::VectorXd quadraticTerms(const Eigen::VectorXd& u);

/// Throws DoeError naming the field: dimension mismatch, non-finite values, too few points,
/// points outside the box, lower >= upper, a rank-deficient design, a covariance that is not
/// positive definite, a single specimen run or specimen runs of another width than the values.
ResponseSurfaceFit fitResponseSurface(const ResponseSurfaceInput& in);

}  // namespace paddy::doe
