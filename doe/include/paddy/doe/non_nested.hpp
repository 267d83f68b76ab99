// Which of two non-nested models fits the same data better: Vuong's test.
//
// Two refits, A and B (e.g. two confusable candidate effects each added to the model and
// recalibrated), leave residuals r_A = y - f_A and r_B = y - f_B at the same seeds. With Gaussian
// noise of covariance Sigma = L L^T, whiten them (e = L^-1 r) and take per observable the
// log-likelihood difference
//   d_i = (e_B,i^2 - e_A,i^2) / 2,        LR = sum_i d_i - (k_A - k_B)/2 ln m   (Schwarz correction)
//   omega^2 = (1/m) sum_i (d_i - dbar)^2,  z = LR / (sqrt(m) omega)
// Under "both fit equally well" z is asymptotically N(0, 1) (Vuong 1989, Theorem 5.1, strictly
// non-nested case); z > z_{1-alpha/2} prefers A, z < -z_{1-alpha/2} prefers B, otherwise the data
// cannot tell them apart. When omega = 0 the two models fit every observable alike (overlapping)
// and neither is preferred.
// Q. H. Vuong, "Likelihood ratio tests for model selection and non-nested hypotheses",
// Econometrica 57(2), 307-333, 1989 (eqs. 5.6 and 5.11). Its error rates on data with a known
// answer: tests/doe/test_non_nested.cpp.
#pragma once
#include <Eigen/Dense>
#include <string>

namespace paddy::doe {

struct NonNestedComparison {
  double lr = 0;         ///< sum of d_i with the Schwarz correction (> 0 favours A)
  double omega = 0;      ///< sd of the d_i
  double z = 0;          ///< LR / (sqrt(m) omega); 0 when omega = 0
  double p = 1;          ///< two-sided p-value of "equally good"
  std::string preferred; ///< "a", "b" or "neither" at the level alpha
};

/// residualA, residualB: m entries each (raw units); covariance: m x m symmetric positive
/// definite; kA, kB: the models' numbers of fitted parameters (>= 0); alpha in (0, 1).
/// Throws DoeError naming the field on inconsistent sizes or values.
NonNestedComparison vuongTest(const Eigen::VectorXd& residualA, const Eigen::VectorXd& residualB,
                              const Eigen::MatrixXd& covariance, int kA, int kB, double alpha = 0.05);

}  // namespace paddy::doe
