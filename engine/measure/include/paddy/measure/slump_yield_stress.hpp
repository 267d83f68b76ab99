// Yield stress from a slump test: the static slump model of Murata (1984) in the form of Pashias,
// Boger, Summers & Glenister (1996, J. Rheol. 40:1179) for a cylinder and of Schowalter &
// Christensen (1998, J. Rheol. 42:865) for a truncated cone (the Abrams / GB/T 50080 cone:
// top diameter 100 mm, bottom 200 mm, height 300 mm).
//
// The mould, of height H and radius r(z) = r_top + (r_bottom − r_top) z/H at depth z below the
// top, is filled with a material of bulk density ρ and yield stress τ_y and lifted. With V(z) the
// volume above depth z and A(z) = π r(z)² the cross-section, the vertical stress at depth z is the
// weight above over the area, σ(z) = ρ g V(z)/A(z); the material yields where σ/2 > τ_y (Tresca,
// the shear stress at 45° is half the axial stress).
//   - Unyielded top plug: depth h0 with ρ g V(h0)/A(h0) = 2τ_y (h0 ≥ H: nothing yields, no slump).
//   - Yielded part (depth h0 … H) slumps, each horizontal slice keeping its volume, until it too
//     carries 2τ_y: A'(z) = ρ g V(z)/(2τ_y), so its final height is
//       h1 = ∫_{h0}^{H} A(z)/A'(z) dz = (2τ_y/(ρ g)) ln(V(H)/V(h0))   (dV/dz = A).
//   - Slump s = H − h0 − h1.
// Cylinder (r_top = r_bottom): h0 = 2τ_y/(ρg) and s/H = 1 − 2τ'(1 − ln 2τ'), τ' = τ_y/(ρ g H)
// (Pashias et al. 1996, eq. 9). Cone: with the apex a = r_top H/(r_bottom − r_top) above the top,
// V(z)/A(z) = ((z + a)³ − a³)/(3 (z + a)²); for the Abrams cone a = H and Schowalter &
// Christensen's s' = 1 − h0' − 2τ' ln(7/((1 + h0')³ − 1)), with 2τ' = ((1 + h0')³ − 1)/(3 (1 + h0')²).
// Assumptions (not those of a coarse-grained DEM pile, docs/validation.md): a continuum with a
// sharp yield stress; slices stay horizontal and deform without friction on the plate; no inertia
// (the material stops where it first carries τ_y, it does not overshoot); the slump is small
// against the spread's size effects (no edge, no surface tension); ρ is the bulk density of the
// material in the mould (for spheres: particle density × solid fraction).
#pragma once

namespace paddy::measure {

struct SlumpMould {
  double height = 0.3;           // H [m]
  double top_diameter = 0.1;     // [m]
  double bottom_diameter = 0.2;  // [m] (= top_diameter: a cylinder)
};

// Slump s [m] of a material of yield stress tau_y [Pa] (≥ 0) and bulk density [kg/m³] (> 0) under
// gravity g [m/s²] (> 0). InputError naming the parameter on bad input.
double slumpFromYieldStress(double tau_y, double density, double gravity, const SlumpMould& mould);

// The inverse: τ_y [Pa] from a slump 0 < s < H (TOMS 748 on the monotonic s(τ_y)). InputError
// naming the value and the allowed range when s is outside (0, H).
double yieldStressFromSlump(double slump, double density, double gravity, const SlumpMould& mould);

// Largest yield stress that still slumps: ρ g V(H)/(2 A(H)) [Pa].
double slumpYieldLimit(double density, double gravity, const SlumpMould& mould);

}  // namespace paddy::measure
