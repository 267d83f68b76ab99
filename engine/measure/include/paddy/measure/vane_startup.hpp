// Yield stress from a vane start-up (stress-growth) test: the vane turns at a low constant speed
// from rest; the torque T(θ) rises through the elastic start-up to a peak T_m and falls or levels
// off as the material yields and flows (Nguyen & Boger 1983, J. Rheol. 27:321; Nguyen & Boger 1992,
// Annu. Rev. Fluid Mech. 24:47).
//
// Peak: the torque is smoothed by a centred moving mean over `smoothing_angle` (the DEM torque is
// noisy, and the maximum of raw samples is biased upwards by the noise); T_m is the largest
// smoothed value, θ_m its angle. The peak counts as reached (`peak_reached`) when, after θ_m, the
// smoothed torque has fallen by at least `drop_fraction`·T_m or the vane turned at least
// `plateau_angle` beyond θ_m; otherwise the torque was still rising when the test ended and T_m
// is only a lower bound.
//
// Yield stress: the vane relation of Nguyen & Boger (1983), T_m = (π D³/2)(H/D + m/6) τ_y
// (vaneTorqueFactor in vane.hpp; m = 2 sheared ends for a vane immersed below the surface). Its
// assumptions: at the peak the material yields on the cylinder swept by the blade tips (diameter
// D, height H) — the material between the blades turns as a rigid body — and the stress equals τ_y
// uniformly on that cylinder's side *and* on its two end discs, all at the same moment. With a
// non-uniform stress on the ends (rising towards the edge, Nguyen & Boger 1983's power-law
// distribution) the end term is smaller and τ_y from this relation is too low by a few per cent
// for H/D = 1.2 (the end discs carry 1/(3·1.2 + 1) = 22 % of the torque here).
#pragma once

#include <paddy/measure/vane.hpp>

#include <numbers>
#include <vector>

namespace paddy::measure {

struct VaneStartupOptions {
  double smoothing_angle = std::numbers::pi / 90.0;  // moving-mean width [rad] (2°); 0 = none
  double drop_fraction = 0.05;                       // peak reached after a drop of this fraction ...
  double plateau_angle = std::numbers::pi / 18.0;    // ... or this far beyond the peak [rad] (10°)
};

struct VaneStartupResult {
  double peak_torque = 0.0;   // T_m [N m] (smoothed)
  double peak_angle = 0.0;    // θ_m [rad]
  bool peak_reached = false;  // see the header comment
  double final_torque = 0.0;  // smoothed torque at the last sample [N m]
  double yield_stress = 0.0;  // τ_y = T_m / vaneTorqueFactor [Pa]
  std::vector<double> smoothed;  // smoothed torque at each sample [N m]
};

// angle [rad] non-decreasing from 0, torque [N m], same length ≥ 3. InputError naming the problem
// on bad options, sizes, non-finite values or decreasing angles.
VaneStartupResult vaneStartup(const std::vector<double>& angle, const std::vector<double>& torque,
                              const VaneGeometry& vane, const VaneStartupOptions& options = {});

}  // namespace paddy::measure
