// Empirical thresholds for the decision rule from null trials, and Clopper–Pearson bounds.
//
// The chi^2 and normal tables of discovery.hpp assume a linear model and Gaussian noise; seed
// scatter of granular simulations is neither. Given N null trials (nothing missing) with, per
// trial, z_max = the largest score over identifiable candidates and Q0, nullThresholds picks the
// thresholds (t_z, t_q) at the (j+1)-th largest z_max and Q0 with the largest j such that at most
// alpha N trials raise any alarm (z_max > t_z or Q0 > t_q); this uses the pairing of the two
// statistics (they are positively correlated), so it is less conservative than splitting alpha.
// If the lists differ in length they cannot be paired and each threshold is the upper alpha/2
// empirical quantile (Bonferroni). q_after, if given (values Q0 - z_k^2 of null trials: under
// "k is the missing effect" Q_k has exactly this distribution in a linear model), gives
// q_after_threshold at its upper alpha quantile.
//
// Clopper–Pearson (C. J. Clopper and E. S. Pearson, Biometrika 26, 404–413, 1934): for x
// successes in n trials, lower = Beta^-1(1 - c; x, n - x + 1), upper = Beta^-1(c; x + 1, n - x),
// each a one-sided bound at confidence c (Boost.Math beta quantile). 0/20 gives upper 0.139.
#pragma once
#include <optional>
#include <vector>

namespace paddy::doe {

struct NullThresholds {
  double zThreshold = 0, q0Threshold = 0;
  std::optional<double> qAfterThreshold;
  int trials = 0, alarms = 0;      ///< null trials and how many exceed a threshold
  double alarmRate = 0, alarmRateUpper = 0;  ///< and its one-sided 95 % Clopper–Pearson bound
  bool paired = true;
};

/// Throws DoeError if a list is empty, has a non-finite value, or alpha is not in (0, 1).
NullThresholds nullThresholds(const std::vector<double>& zMax, const std::vector<double>& q0,
                              double alpha = 0.05, const std::vector<double>& qAfter = {});

struct BinomialBounds {
  double rate = 0, lower = 0, upper = 1;
};
/// Each bound one-sided at `confidence` (0.95: the design note's figures).
BinomialBounds clopperPearson(int successes, int trials, double confidence = 0.95);

}  // namespace paddy::doe
