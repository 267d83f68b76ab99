// Is the vane torque of a constant-speed step steady yet? A batch-means criterion in the rotation
// angle θ (from the start of the step), applied to the torque samples (θ_i, T_i):
//
//   1. Windows: the turned angle is cut into windows of `window_angle` Δθ, window j = [jΔθ, (j+1)Δθ);
//      the mean torque of each complete window is one batch mean m_j (batch means average out the
//      correlated DEM torque noise; Law & Carson 1979, Oper. Res. 27:1011).
//   2. The last k = `windows` complete windows are compared. Least-squares line m_j = a + b θ_j
//      through their centres θ_j: slope b (the trend, N m/rad), its standard error
//      s_b = sqrt(Σ r_j² / (k − 2) / Σ (θ_j − θ̄)²) and the two-sided p value of t = b / s_b with
//      k − 2 degrees of freedom (Student t, Boost.Math).
//   3. Steady when all of:
//        (a) the step has turned at least `min_angle` (the elastic start-up is over), and at least
//            k windows are complete;
//        (b) no significant trend: p ≥ `alpha` (the window means agree within their scatter about
//            a constant);
//        (c) the fitted change over the compared windows is small: |b| · kΔθ ≤ drift_tolerance · |m̄|
//            (a drift hidden in the scatter but large against the mean is not steady either).
//      A linear ramp (no scatter, b ≠ 0) fails (b) and (c) at any angle; a slow drift fails (b)
//      once the windows resolve it, or (c).
//   Reported: mean m̄ of the k window means, its standard error s/√k (s the std of the window
//   means, n − 1), the trend and its standard error, p, the relative drift, the verdict and why.
#pragma once

#include <numbers>
#include <string>
#include <vector>

namespace paddy::measure {

struct SteadyTorqueOptions {
  double window_angle = std::numbers::pi / 18.0;  // Δθ [rad] (10°)
  int windows = 6;                                // k ≥ 3 windows compared
  double min_angle = std::numbers::pi / 3.0;      // [rad] (60°)
  double alpha = 0.05;                            // level of the trend test, 0 < alpha < 1
  double drift_tolerance = 0.05;                  // largest |b|·kΔθ / |m̄|, > 0
};

struct SteadyTorqueResult {
  bool steady = false;
  std::string reason;              // why not steady ("" when steady)
  double angle = 0.0;              // angle turned in the step (last sample) [rad]
  int complete_windows = 0;        // complete windows so far
  int compared_windows = 0;        // windows the statistics below are over (≤ k)
  double mean = 0.0;               // m̄ [N m]
  double standard_error = 0.0;     // s/√k [N m]
  double trend = 0.0;              // b [N m/rad]
  double trend_standard_error = 0.0;
  double trend_p_value = 1.0;      // two-sided
  double drift = 0.0;              // |b|·kΔθ / |m̄|
  std::vector<double> window_means;  // the compared windows', oldest first
};

// angle [rad] from the step start, non-decreasing, ≥ 0; torque [N m], same length. With fewer
// than k complete windows the statistics are over those there are (mean over all samples when
// none is complete) and the step is not steady. InputError naming the problem on bad options,
// sizes that differ, non-finite values, decreasing angles, or a complete window without samples
// (sampling too coarse for the window).
SteadyTorqueResult steadyTorque(const std::vector<double>& angle, const std::vector<double>& torque,
                                const SteadyTorqueOptions& options = {});

}  // namespace paddy::measure
