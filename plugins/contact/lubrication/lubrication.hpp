// Extra sub-model "lubrication": the viscous force of the interstitial fluid squeezed out of, or
// sucked into, the narrow gap between two spheres (or a sphere and a wall).
//
//   normal:      F_n = −6π μ R*² v_n / h                    (Reynolds lubrication; for equal spheres
//                                                            3/2 π μ R² v_n / h, sphere–plate 6π μ R² v_n / h)
//   tangential:  F_t = −6π μ R* (8/15) ln(R*/h) v_t          (Goldman, Cox & Brenner 1967, the
//                                                            log term of the sliding sphere near a plane)
//   h = max(gap, h_min),   gap = −overlap;   acting while gap < h_cut.
//
// v_n > 0 is separating, so F_n resists approach (repulsive) and separation (attractive) alike.
// h_min = lubrication_min_gap · R* regularises the 1/h singularity (surface roughness; in contact
// the film is h_min thick); h_cut = lubrication_cutoff · R* ends the force where the lubrication
// approximation (h ≪ R*) stops holding. The log is taken ≥ 0.
// Time step: each coefficient is capped, c ← min(c, m*/(z dt)) with z = 12 (the kissing number:
// the most equal spheres that can touch one). Explicit integration of dashpots is stable when
// dt λ_max < 2, λ_max the largest eigenvalue of M⁻¹C; by Gershgorin λ_max ≤ Σ_contacts c/m* ≤ z c/m*
// for a sphere among equal ones (the tensor c_n nn + c_t(I − nn) has norm max(c_n, c_t)), so with
// the cap dt λ_max ≤ 1: velocities are at most stopped within a step, never reversed, however
// many films a sphere has. The cap keeps h → h_min stable for any step; where it binds the film
// is stiffer than the step can resolve and the force is the most the step allows (docs/physics.md
// says for which μ). With dt = 0 (a force evaluation outside a step) no cap applies.
// Chain role: a normal-force extra; fn −= c_n v_n, ft −= c_t v_t. It leaves active, fn_friction
// and the Coulomb cap alone (a viscous force is not a contact load, and not limited by friction).
// maxSeparation(R*) = h_cut (grows with R*, as the contract requires).
// Strength 0 (μ = 0): maxSeparation 0, compute does nothing — bit for bit the chain without it.
// Parameters: lubrication_viscosity μ [Pa s]; lubrication_min_gap, lubrication_cutoff [R*].
#pragma once

#include "../common/contact_math.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace paddy::contact {

class Lubrication final : public SubModel {
 public:
  static constexpr double kMaxNeighbours = 12.0;  // z of the cap m*/(z dt)

  Lubrication(double viscosity, double min_gap_ratio, double cutoff_ratio)
      : mu_(viscosity), min_gap_(min_gap_ratio), cutoff_(cutoff_ratio) {}

  // Uncapped coefficients at gap h (h ≥ h_min assumed).
  double normalCoefficient(double r_eff, double h) const { return 6.0 * std::numbers::pi * mu_ * r_eff * r_eff / h; }
  double tangentialCoefficient(double r_eff, double h) const {
    return 6.0 * std::numbers::pi * mu_ * r_eff * (8.0 / 15.0) * std::max(0.0, std::log(r_eff / h));
  }

  double maxSeparation(double r_eff) const override { return mu_ > 0.0 ? cutoff_ * r_eff : 0.0; }

  void compute(ContactBatch& b, std::size_t) const override {
    if (mu_ == 0.0) return;
    for (std::size_t k = 0; k < b.n; ++k) {
      const double r = b.r_eff[k], gap = -b.overlap[k];
      if (gap >= cutoff_ * r) continue;
      const double h = std::max(gap, min_gap_ * r);
      double cn = normalCoefficient(r, h), ct = tangentialCoefficient(r, h);
      if (b.dt > 0.0) {
        const double cap = b.m_eff[k] / (kMaxNeighbours * b.dt);
        cn = std::min(cn, cap);
        ct = std::min(ct, cap);
      }
      b.fn[k] -= cn * b.vn[k];
      b.ft[k] -= ct * b.vt[k];
    }
  }

 private:
  double mu_, min_gap_, cutoff_;
};

}  // namespace paddy::contact
