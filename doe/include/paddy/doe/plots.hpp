// Diagnostic and response-surface plots rendered with gnuplot (PNG via pngcairo, plus SVG).
//
// For every plot a data file (.dat) and a script (.gp) are written into the output directory and
// `gnuplot` is run there, so the plots can be restyled by editing the scripts. Plots:
//   pareto_<resp>     standardised effects |t_j| = |b_j / se_j|, bars sorted, with the
//                     t(1 - alpha/2, df_res) significance line (Montgomery ch. 6; Design-Expert)
//   pred_actual_<resp>, normal_<resp> (externally studentised residuals vs normal quantiles of
//                     (i - 0.5)/n), surface_<resp>_<A>_<B> and contour_<resp>_<A>_<B> (other
//                     factors at their centre), desirability_<resp> (d(y) ramps).
// Throws DoeError with a clear message when gnuplot is not installed or fails.
#pragma once
#include "paddy/doe/analysis.hpp"
#include "paddy/doe/desirability.hpp"

#include <string>
#include <vector>

namespace paddy::doe {

bool gnuplotAvailable();
/// Returns the image files written.
std::vector<std::string> plotAnalysis(const std::string& dir, const Analysis& a);
std::vector<std::string> plotDesirabilityRamps(const std::string& dir, const std::vector<GoalSpec>& goals);

}  // namespace paddy::doe
