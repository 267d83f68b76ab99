// Rao score test of each candidate missing effect, linearised at the calibrated parameters.
//
// Whitened data (see covariance.hpp): residual r (m), Jacobian J (m x p) of the free parameters,
// signatures g_k = d y / d lambda_k at lambda_k = 0 (m each). The model is
//   r = J dtheta + g_k lambda_k + e,  e ~ N(0, I),  lambda_k >= 0.
// Recalibration absorbs span(J): P = I - Q1 Q1^T with Q1 an orthonormal basis of span(J) from a
// column-pivoting Householder QR of J with unit-norm columns (rank = pivots above 1e-10 of the
// largest, so a rank-deficient J is handled: P projects off the span that is estimable).
//   Q0 = r^T P r                           ~ chi^2(m - rank J) if nothing is missing
//   a_k = g_k^T P g_k,  b_k = g_k^T P r,  z_k = b_k / sqrt(a_k)   (score statistic, N(0,1) under
//                                                                   lambda_k = 0; one-sided)
//   lambda_k^ = b_k / a_k,  se = a_k^-1/2   (the profile least-squares estimate of lambda_k)
//   Q_k = Q0 - max(z_k, 0)^2                (misfit left after adding k, exact for linear models)
//   c_kl = (P g_k)^T (P g_l) / (|P g_k| |P g_l|)          (confusability)
// (C. R. Rao, "Large sample tests of statistical hypotheses concerning several parameters with
// applications to problems of estimation", Proc. Camb. Phil. Soc. 44, 50–57, 1948: the score test
// needs only the fit under the null, i.e. today's model.)
//
// Linearised Bayes factor of "lambda_k > 0" against "nothing missing", with a half-normal prior
// lambda_k ~ 2 N(0, tau^2) on lambda >= 0 (the one-sided version of the normal prior in the design
// note), theta integrated with a flat prior (which the projection does):
//   BF_k = 2 (1 + tau^2 a)^-1/2 exp(z^2 tau^2 a / (2 (1 + tau^2 a))) Phi(z sqrt(tau^2 a / (1 + tau^2 a)))
// (derivation: complete the square in lambda; Kass & Raftery, "Bayes factors", JASA 90, 773–795,
// 1995). The normal-prior version lacks the factor 2 Phi(.) and gives a negative z the same
// evidence as a positive one, which lambda >= 0 rules out.
#pragma once
#include <Eigen/Dense>
#include <optional>
#include <vector>

namespace paddy::doe {

/// Orthogonal projection off span(J).
class Projection {
public:
  explicit Projection(const Eigen::MatrixXd& J, double rankTolerance = 1e-10);
  Eigen::VectorXd apply(const Eigen::VectorXd& v) const;  ///< P v
  Eigen::MatrixXd apply(const Eigen::MatrixXd& M) const;  ///< P M
  int rank() const { return static_cast<int>(basis_.cols()); }
  int rows() const { return static_cast<int>(basis_.rows()); }

private:
  Eigen::MatrixXd basis_;  ///< m x rank orthonormal basis of span(J)
};

struct CandidateScore {
  double a = 0, b = 0, z = 0, p = 1;  ///< p = 1 - Phi(z), one-sided
  double strength = 0, strengthSe = 0;
  double qAfter = 0;             ///< Q0 - max(z,0)^2
  double qAfterP = 1;            ///< chi^2(df - 1) upper tail of qAfter (1 when df - 1 < 1)
  double absorbedFraction = 1;   ///< 1 - |P g| / |g| : share of the signature recalibration absorbs
  std::optional<double> logBayesFactor;  ///< when a prior scale tau is given
};

struct ScoreTests {
  double q0 = 0;
  int df = 0, rank = 0;
  double q0P = 1;                 ///< chi^2(df) upper tail of q0
  Eigen::VectorXd projectedResidual;  ///< P r
  Eigen::MatrixXd projectedSignatures;  ///< P G (m x K)
  std::vector<CandidateScore> candidates;
  Eigen::MatrixXd confusability;  ///< K x K, 0 where a signature has no projected part
};

/// r (m), J (m x p, p may be 0), G (m x K); priorSd[k] = tau_k (empty optional: no Bayes factor).
/// Throws DoeError if dimensions disagree or m - rank J < 1.
ScoreTests scoreTests(const Eigen::VectorXd& r, const Eigen::MatrixXd& J, const Eigen::MatrixXd& G,
                      const std::vector<std::optional<double>>& priorSd = {});

/// log BF of the formula above.
double logBayesFactorHalfNormal(double a, double b, double tau);

}  // namespace paddy::doe
