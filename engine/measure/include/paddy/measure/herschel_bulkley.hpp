// Herschel–Bulkley fit of a flow curve: τ = τ0 + K·D^n (τ shear stress [Pa], D shear rate [1/s],
// τ0 yield stress [Pa], K consistency [Pa·s^n], n flow index [-]); Herschel & Bulkley 1926.
//
// Method: least squares in τ, SSE = Σ (τ_i − τ0 − K D_i^n)², bounds τ0 ≥ 0, K > 0,
// n_min ≤ n ≤ n_max (default 0.05 … 2). Start: for n on a grid of 40 values the model is linear in
// (τ0, K), solved exactly with the bounds (variable projection); the best grid point starts NLopt
// LN_BOBYQA (Powell 2009) on scaled variables (τ/τ_max, D/D_geo-mean). R² = 1 − SSE/SST,
// RMSE = sqrt(SSE/N).
#pragma once

#include <vector>

namespace paddy::measure {

struct HerschelBulkley {
  double tau0 = 0.0;  // [Pa]
  double K = 0.0;     // [Pa·s^n]
  double n = 1.0;     // [-]
  double stress(double shear_rate) const;
};

struct HerschelBulkleyFit {
  HerschelBulkley model;
  double r2 = 0.0;
  double rmse = 0.0;    // [Pa]
  int evaluations = 0;  // objective evaluations of the optimiser
};

struct HerschelBulkleyOptions {
  double n_min = 0.05;
  double n_max = 2.0;
  double xtol_rel = 1e-10;
  int max_evaluations = 20000;
};

// Throws paddy::InputError naming the problem: fewer than 3 points, sizes differ, a NaN/infinite
// value, a non-positive shear rate, a negative stress, fewer than 3 distinct shear rates, or
// bounds outside 0 < n_min < n_max.
HerschelBulkleyFit fitHerschelBulkley(const std::vector<double>& shear_rate,
                                      const std::vector<double>& shear_stress,
                                      const HerschelBulkleyOptions& options = {});

}  // namespace paddy::measure
