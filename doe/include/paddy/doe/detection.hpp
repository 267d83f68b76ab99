// What the score test of a candidate can see when its signature is itself estimated from seeds.
//
// A candidate's signature g is the mean of K secants g_s (one per seed) of the simulation, so it
// carries seed noise. Whitened and projected off the free parameters (score_test.hpp): u = P L^-1 g,
// a = |u|^2, b = u^T P r. Noise in g inflates a: E a = |P L^-1 g_true|^2 + tr(P S_g), S_g the
// whitened covariance of the mean signature. Its unbiased estimate from the seeds' spread is
//   a_noise = sum_s |P L^-1 (g_s - g)|^2 / (K (K - 1)),     a_signal = a - a_noise,
// a_signal estimates |P L^-1 g_true|^2 and may be <= 0 (the signature is within its own noise).
// The residual r is independent of g (its own seeds), so z = b / sqrt(a) stays N(0, 1) under
// lambda = 0; at strength lambda, E b = lambda a_signal. Hence, for the one-sided threshold z* of
// the decision (the bootstrap z_threshold, or the first Holm step z_{1 - alpha/(K+1)}) and a
// smallest relevant strength lambda_rel (z_relevant = z - lambda_rel sqrt(a)):
//   detection limit  lambda_det = (z* + z_power + lambda_rel sqrt(a)) sqrt(a) / a_signal
//                    (the strength whose score passes with probability `power`; infinite when
//                     a_signal <= 0: these experiments cannot show the candidate)
//   strength         lambda_c = b / a_signal,  se_c = sqrt(a) / a_signal
//                    (b / a is attenuated by the factor a_signal / a: the dilution of a regression
//                     slope by noise in its regressor; W. A. Fuller, "Measurement Error Models",
//                     Wiley 1987, §1.1)
//   upper limit      max(lambda_c, 0) + z_{0.95} se_c   (one-sided 95 %; infinite when a_signal <= 0)
// Without seeds (K < 2) a_noise = 0 and these are the plain linear formulas. The detection limit
// concerns the candidate's score alone: naming also needs no rival and no misfit left
// (discovery.hpp), and a signature far from linear over the range (one that recalibration absorbs
// more of at larger strengths) is seen later than the limit says (docs/discovery.md measures both).
#pragma once
#include <Eigen/Dense>
#include <limits>
#include <vector>

namespace paddy::doe {

struct Detectability {
  double aNoise = 0, aSignal = 0;
  double detectionLimit = std::numeric_limits<double>::infinity();
  double strength = 0;                                        ///< lambda_c
  double strengthSe = std::numeric_limits<double>::infinity();  ///< se_c
  double upperLimit = std::numeric_limits<double>::infinity();
};

/// a_noise of the formula above from the seeds' deviations g_s - g, each already whitened and
/// projected (P L^-1 (g_s - g)); 0 for fewer than two.
double signatureNoise(const std::vector<Eigen::VectorXd>& projectedDeviations);

/// a, b of the candidate's score, a_noise, the threshold z*, the power (in (0, 1)) and lambda_rel.
Detectability detectability(double a, double b, double aNoise, double zStar, double power, double relevant);

}  // namespace paddy::doe
