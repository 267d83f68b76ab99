// Vane-in-cup rheometer conversions (Couette analogy).
//
// Stress from torque (Dzuy & Boger 1983, J. Rheol. 27:321): the vane shears the material on the
// cylinder it sweeps (diameter D, height H) with a uniform stress τ on the side and on the sheared
// ends:  T = (π D³/2)(H/D + m/6) τ, m = number of sheared ends (2 for a vane immersed below the
// surface: (H/D + 1/3); 1 if the top is flush with the surface; 0 ignores the ends).
//
// Shear rate at the vane: the swept cylinder acts as the inner cylinder of a Couette cell of gap
// ratio κ = D/D_cup (Barnes & Carnali 1990, J. Rheol. 34:841). For a power-law fluid of index n
// the stress falls as 1/r² and the exact rate at the inner cylinder is
//   γ̇_v = 2Ω / (n (1 − κ^{2/n}))            (Macosko 1994, Rheology, §5.3; Krieger 1968, Trans. Soc. Rheol. 12:5)
// which is 2Ω/(1 − κ²) for a Newtonian fluid and 2Ω/n in an infinite cup. For a general fluid
// n is the local index n = d ln T / d ln Ω of the torque–speed data (Krieger 1968): in an infinite
// cup γ̇_v = 2Ω/n is then exact for any fluid; in a finite cup it is the power-law approximation.
// vaneFlowCurve takes n_i as the slope at ln Ω_i of a least-squares quadratic in (ln Ω, ln T)
// through the 5 nearest points, computes γ̇_i, then fits Herschel–Bulkley to (γ̇_i, τ_i).
// Bias: with a yield stress the material beyond the yield radius does not flow; the power-law
// formula then approximates the localised shear (Estellé, Lanos & Perrot 2008).
#pragma once

#include <paddy/measure/herschel_bulkley.hpp>

#include <limits>
#include <vector>

namespace paddy::measure {

struct VaneGeometry {
  double diameter = 0.0;  // vane (swept) diameter D [m]
  double height = 0.0;    // blade height H [m]
  double cup_diameter = std::numeric_limits<double>::infinity();  // [m]; inf = infinite cup
  int sheared_ends = 2;   // 0, 1 or 2
};

// T/τ = (π D³/2)(H/D + m/6) [m³]. Throws InputError on bad geometry.
double vaneTorqueFactor(const VaneGeometry& vane);
double vaneShearStress(double torque, const VaneGeometry& vane);  // τ = T / factor [Pa]
double vaneTorque(double shear_stress, const VaneGeometry& vane);  // T = factor · τ [N·m]
// γ̇ at the vane for angular speed omega [rad/s] and local flow index n (default Newtonian).
double vaneShearRate(double omega, const VaneGeometry& vane, double n = 1.0);
double rpmToRadPerSecond(double rpm);  // Ω = 2π·rpm/60

struct VaneFlowCurve {
  std::vector<double> shear_rate;    // [1/s]
  std::vector<double> shear_stress;  // [Pa]
  std::vector<double> n_local;       // local flow index d ln T / d ln Ω used for each point
  HerschelBulkleyFit fit;            // Herschel–Bulkley fit of the flow curve (γ̇, τ)
};

// (Ω [rad/s], T [N·m]) data → flow curve. InputError naming the problem: fewer than 3 points,
// sizes differ, a speed or torque not finite and > 0, speeds not strictly increasing.
VaneFlowCurve vaneFlowCurve(const std::vector<double>& omega, const std::vector<double>& torque,
                            const VaneGeometry& vane);

// Forward model for tests and predictions: the torque a Herschel–Bulkley material exerts on the
// vane at speed omega in the Couette analogy. The stress at the vane τ_v solves
//   Ω = ½ ∫_{κ²τ_v}^{τ_v} γ̇(τ)/τ dτ,  γ̇(τ) = ((τ − τ0)/K)^{1/n} for τ > τ0, else 0
// (Krieger & Maron 1952 integral), then T = factor · τ_v.
double vaneTorqueHerschelBulkley(double omega, const HerschelBulkley& model, const VaneGeometry& vane);

}  // namespace paddy::measure
