// Naming a missing effect: score tests of candidate effects on the whitened residual of a
// calibration that does not fit, and the decision effect / none / ambiguous / unknown.
//
// Inputs in raw units: residual y_measured - y_simulated(theta^) (m), noise covariance Sigma
// (m x m, covariance.hpp), Jacobian dy/dtheta (m x p), candidates k with signature dy/dlambda_k at
// lambda_k = 0 and physical range [low, high]. Everything is whitened with Sigma = L L^T and
// passed to scoreTests (score_test.hpp).
//
// Decision (level alpha, defaults below):
//  1. A candidate is *not identifiable* when recalibration absorbs its signature
//     (|P g| < absorbed_tolerance |g|) or when even its largest physical strength moves the
//     projected data by less than min_range_z noise standard deviations (high sqrt(a) < min_range_z);
//     it is reported as such and never named, and never counts as evidence of absence.
//  2. One family of hypotheses: the global misfit Q0 (chi^2(m - rank J)) and the score of every
//     identifiable candidate, z_k, or z_k - relevant_k sqrt(a_k) when the candidate has a smallest
//     relevant strength (a one-sided test of lambda_k <= relevant_k: at its boundary this statistic
//     has the null distribution of z_k, so the tables and the bootstrap thresholds apply unchanged); Holm's step-down adjustment over these K+1 p-values (S. Holm, "A
//     simple sequentially rejective multiple test procedure", Scand. J. Statist. 6, 65–70, 1979)
//     keeps the probability of any alarm on data with nothing missing at most alpha. (Testing Q0
//     at alpha and the z's by Holm at alpha separately would allow up to 2 alpha.)
//     With empirical thresholds (null_calibration.hpp) a candidate passes when z_k > z_threshold
//     and Q0 is significant when Q0 > q0_threshold instead.
//  3. A passing candidate is *plausible* when its interval lambda^ +- z_{1-alpha/2} se meets
//     [low, high]. The best plausible candidate k* is the one with the largest log Bayes factor
//     (score_test.hpp; z^2/2 where no prior scale is known).
//  4. `ambiguous` if another plausible candidate has a Bayes factor within a factor bayes_margin
//     of k*'s, or is confusable with it (c(k*, l) >= confusable) and its Bayes factor is within a
//     factor strong_margin of k*'s (default infinite: a confusable rival always makes the answer
//     ambiguous; e.g. 20, Kass & Raftery's "strong" evidence, names k* when the data single it
//     out, at a measured cost in wrong names). ambiguous_with lists them (k* first) and
//     separating_block names the block (experiment) that best tells k* from its first rival.
//     `unknown` if Q0 is significant but no candidate passes, if no passing candidate is
//     plausible, or if Q_k* is still significant (chi^2(m - rank J - 1) at alpha_after).
//     `none` if nothing passes and Q0 is not significant. Otherwise `effect`, named k*.
//
// Separating block (T-optimal discrimination, A. C. Atkinson and V. V. Fedorov, "The design of
// experiments for discriminating between two rival models", Biometrika 62, 57–70, 1975): with
// u = P g_k*, v = P g_l restricted to the rows of block B, the noncentrality with which B alone
// separates k* at strength lambda^ from the best fit of l is
//   T_B = lambda^2 |u_B|^2 (1 - c_B^2),  c_B = cos(u_B, v_B);
// the block with the largest T_B is named. 1 - c_B^2 alone (also reported) would favour blocks
// where neither candidate has any signal.
#pragma once
#include "paddy/doe/detection.hpp"
#include "paddy/doe/score_test.hpp"

#include <Eigen/Dense>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace paddy::doe {

struct Candidate {
  std::string name;
  Eigen::VectorXd signature;  ///< raw units, m entries
  double low = 0.0;
  double high = std::numeric_limits<double>::infinity();
  std::optional<double> priorSd;  ///< tau; default high - low when finite
  /// Smallest strength that matters (default 0). The candidate's test is then of lambda <= relevant
  /// against lambda > relevant: z_relevant = (lambda^ - relevant) / se = z - relevant sqrt(a). An
  /// effect the data show to be present but too weak to matter is not named; a small systematic
  /// bias of the model (e.g. of its resolution) along the candidate's signature does not raise an
  /// alarm. 0 gives the test of lambda = 0 exactly. Must lie in [low, high).
  double relevant = 0.0;
  /// The per-seed secants whose mean is `signature` (optional; at least 2, m entries each): their
  /// spread is the signature's own noise (detection.hpp).
  std::vector<Eigen::VectorXd> signatureSeeds;
};

struct DecisionOptions {
  double alpha = 0.05;            ///< family-wise level of the K+1 tests
  double alphaAfter = 0.05;       ///< level of the misfit left after the named effect
  double confusable = 0.9;        ///< |cos| of projected signatures above which two are confusable
  double bayesMargin = 3.0;       ///< BF(k*) / BF(rival) needed to name k* (Kass–Raftery "positive")
  /// BF(k*) / BF(rival) needed over a confusable rival; infinite (the default): a confusable rival
  /// always makes the answer ambiguous. 20 is Kass–Raftery's "strong" (docs/discovery.md: its cost).
  double strongMargin = std::numeric_limits<double>::infinity();
  double absorbedTolerance = 0.05;  ///< |P g| / |g| below this: absorbed by recalibration
  double minRangeZ = 1.0;         ///< high sqrt(a) below this: no sensitivity in the physical range
  double detectionPower = 0.9;    ///< power at which detection limits are stated (detection.hpp)
  std::optional<double> zThreshold, q0Threshold, qAfterThreshold;  ///< empirical thresholds
};

struct DiagnoseInput {
  Eigen::VectorXd residual;       ///< y_measured - y_simulated, raw units
  Eigen::MatrixXd covariance;     ///< m x m
  Eigen::MatrixXd jacobian;       ///< m x p (p may be 0)
  std::vector<Candidate> candidates;
  std::vector<std::string> labels, blocks;  ///< optional, m entries each
  DecisionOptions options;
};

struct CandidateReport {
  std::string name;
  CandidateScore score;
  double zRelevant = 0;     ///< (lambda^ - relevant) / se = z - relevant sqrt(a); = z when relevant = 0
  double pRelevant = 1;     ///< 1 - Phi(z_relevant), one-sided: the p-value of the candidate's test
  double pHolm = 1;         ///< Holm-adjusted pRelevant (1 when not identifiable or in empirical mode)
  bool identifiable = true;
  std::string notIdentifiableReason;  ///< "absorbed by recalibration" / "no sensitivity in [low, high]"
  bool passes = false, plausible = false;
  /// Its strength's 95 % interval meets [low, high]. A candidate in range can be a rival of the
  /// best one (close evidence) even when its own test does not pass: it explains the data alike.
  bool inRange = false;
  double score_rank = 0;    ///< log BF or z^2/2, the ranking score
  /// What the score can see, the signature's seed noise allowed for (detection.hpp); `detectable`:
  /// the detection limit lies within [low, high].
  Detectability detection;
  bool detectable = false;
};

struct BlockSeparation {
  std::string block;
  double separation = 0;    ///< 1 - c_B^2
  double tCriterion = 0;    ///< lambda^2 |u_B|^2 (1 - c_B^2)
};

struct ResidualRow {
  std::string label, block;
  double raw = 0;            ///< residual in raw units
  double standardised = 0;   ///< raw / sqrt(Sigma_ii)
  double standardisedAfter = 0;  ///< after recalibrating theta and adding the best plausible effect (if any), linearised
  double whitened = 0, projected = 0;
};

struct Diagnosis {
  std::string decision;      ///< effect, none, ambiguous, unknown
  std::string named;         ///< set for `effect`
  std::string best;          ///< best plausible candidate (any decision), may be empty
  std::string reason;        ///< one sentence saying why
  std::vector<std::string> ambiguousWith;
  std::string separatingBlock;
  std::vector<BlockSeparation> blockSeparations;
  double q0 = 0, q0P = 1, q0PHolm = 1;
  int q0Df = 0, rank = 0;
  bool q0Significant = false;
  double misfit = 0, misfitProjected = 0, misfitAfter = 0;  ///< sqrt(.../m)
  std::vector<CandidateReport> candidates;
  double detectionThreshold = 0;  ///< z* of the detection limits (detection.hpp)
  Eigen::MatrixXd confusability;
  Eigen::VectorXd whitenedResidual, projectedResidual;
  std::vector<ResidualRow> residualMap;
};

/// Throws DoeError naming the field for dimension mismatches, non-finite values, a covariance that
/// is not positive definite, an empty or duplicate candidate name, or low > high.
Diagnosis diagnose(const DiagnoseInput& in);

/// Holm step-down adjusted p-values, same order as p.
std::vector<double> holmAdjust(const std::vector<double>& p);

/// T_B and 1 - c_B^2 per distinct block name (in order of first appearance) for u = P g_k,
/// v = P g_l (whitened rows), strength = lambda^ of k.
std::vector<BlockSeparation> blockSeparations(const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                              double strength, const std::vector<std::string>& blocks);

}  // namespace paddy::doe
