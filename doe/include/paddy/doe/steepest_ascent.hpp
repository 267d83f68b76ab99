// Path of steepest ascent / descent from a first-order model (Montgomery, Design and Analysis of
// Experiments, section 11.2; Design-Expert "point prediction along a path").
//
// For y = b0 + sum b_j x_j in coded units the path moves proportionally to (b_1, ..., b_k)
// (ascent) or to its negative (descent). Montgomery's procedure: choose a key factor i and its
// step dx_i (coded, or real units converted with h_i), then dx_j = b_j / (b_i / dx_i) for all j.
// Alternatively fixed real step sizes can be given per factor (the reference study's Table 6
// uses 0.03 / 0.1 / 0.03), moving each factor in the direction of the sign of its coefficient.
// Relative error of a simulated response against a measurement: delta = |Y_meas - Y_sim| / Y_meas
// (this is what reproduces the reference Table 6 numbers).
#pragma once
#include "paddy/doe/design.hpp"

#include <optional>
#include <vector>

namespace paddy::doe {

struct PathOptions {
  bool ascent = true;                      ///< false: steepest descent
  int steps = 5;                           ///< points after the origin
  std::optional<int> keyFactor;            ///< default: largest |b_j|
  double keyStep = 1.0;                    ///< step of the key factor (magnitude)
  bool keyStepReal = false;                ///< keyStep given in real units
  std::vector<double> realSteps;           ///< if non-empty: fixed real step magnitude per factor
  std::optional<Eigen::VectorXd> originReal;  ///< default: design centre
};

struct PathPoint {
  int step = 0;
  Eigen::VectorXd coded, real;
};

/// coefficients: first-order coefficients b_1..b_k in coded units (no intercept).
std::vector<PathPoint> steepestPath(const std::vector<Factor>& factors,
                                    const Eigen::VectorXd& coefficients, const PathOptions& opt);

double relativeError(double measured, double simulated);

}  // namespace paddy::doe
