// Extra sub-model "liquid_bridge": the capillary force of a pendular liquid bridge between two
// spheres (or a sphere and a wall), acting in contact and across a gap up to the bridge's rupture.
//
//   F(s) = 2π R γ_s cos θ / (1 + 1.05 ŝ + 2.5 ŝ²),   ŝ = s sqrt(R / V),   R = 2 R*
//
// Willett, Adams, Johnson & Seville (2000), Langmuir 16, 9396: the closed-form fit of the
// capillary force of a bridge of volume V and contact angle θ between equal spheres of radius R at
// separation s (their "simple expression", written with the full separation s; the bracket is
// 1 + 2.1 (s/2) sqrt(R/V) + 10 ((s/2) sqrt(R/V))²). Unequal spheres use Willett's harmonic mean
// radius R = 2 R_i R_j / (R_i + R_j) = 2 R*; a wall (R_j → ∞) gives R = 2 R_i and the
// sphere–plate force 4π R_i γ_s cos θ at touch. In contact (overlap ≥ 0) the force is F(0).
// Rupture (Lian, Thornton & Adams 1993): s_c = (1 + θ/2) V^{1/3}, θ in radians.
// Life of a bridge: it forms when the surfaces touch (overlap ≥ 0) and holds, attracting, until
// the gap exceeds s_c (history: 1 double, the bridge flag). Two bodies approaching without ever
// having touched feel nothing.
//
// Chain role: a normal-force extra (runs right after the normal model). fn −= F. It leaves
// fn_friction (the Coulomb/rolling load) to the normal model: the bridge's pull is carried by the
// elastic repulsion it causes (a bigger Hertz overlap), and counting it again would count it
// twice. It does not mark gap contacts active: across a gap only the capillary force acts.
// maxSeparation(R*) = s_c (independent of R*: V is one volume per pair).
// Time step: the bridge's largest stiffness |dF/ds| = 1.05 F(0) sqrt(R/V) (at s = 0); for the
// mud (2 mm, V = 0.05 of a sphere, γ_s = 0.072 N/m) ≈ 1 N/m, four orders below the Hertz
// stiffness the step resolves (docs/physics.md). stiffnessBound() gives it for a set-up check.
// Strength 0 (V = 0 or γ_s = 0): no history, maxSeparation 0, compute does nothing — bit for bit
// the chain without it.
// Parameters: bridge_volume V [m³]; surface_tension γ_s [N/m]; contact_angle θ [deg].
#pragma once

#include "../common/contact_math.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace paddy::contact {

class LiquidBridge final : public SubModel {
 public:
  LiquidBridge(double volume, double surface_tension, double contact_angle_deg)
      : volume_(volume), tension_(surface_tension), theta_(contact_angle_deg * std::numbers::pi / 180.0) {}

  bool on() const { return volume_ > 0.0 && tension_ > 0.0; }
  double ruptureDistance() const { return (1.0 + 0.5 * theta_) * std::cbrt(volume_); }
  // Willett's force for effective radius r_eff at gap s ≥ 0 (s < 0 counts as 0).
  double force(double r_eff, double s) const {
    const double r = 2.0 * r_eff;
    const double sh = std::max(s, 0.0) * std::sqrt(r / volume_);
    return 2.0 * std::numbers::pi * r * tension_ * std::cos(theta_) / (1.0 + 1.05 * sh + 2.5 * sh * sh);
  }
  // Largest |dF/ds| (at s = 0).
  double stiffnessBound(double r_eff) const { return 1.05 * force(r_eff, 0.0) * std::sqrt(2.0 * r_eff / volume_); }

  std::size_t historySize() const override { return on() ? 1 : 0; }
  double maxSeparation(double) const override { return on() ? ruptureDistance() : 0.0; }

  void compute(ContactBatch& b, std::size_t offset) const override {
    if (!on()) return;
    const double s_c = ruptureDistance();
    for (std::size_t k = 0; k < b.n; ++k) {
      double& bridge = b.historyOf(k, offset)[0];
      const double gap = -b.overlap[k];
      if (gap <= 0.0) bridge = 1.0;
      if (gap > s_c) bridge = 0.0;
      if (bridge == 0.0) continue;
      b.fn[k] -= force(b.r_eff[k], gap);
    }
  }

 private:
  double volume_, tension_, theta_;
};

}  // namespace paddy::contact
