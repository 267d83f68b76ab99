// Rolling sub-model "constant_torque_explicit": EDEM's standard rolling friction (type A) as EDEM
// documents and integrates it (Altair EDEM help, "Standard Rolling Friction Model"; Sakaguchi,
// Ozaki & Igarashi 1993; Ai, Chen, Rotter & Ooi 2011, model A):
//
//   τ_i = −μ_r F_n R_i ω̂_i,   τ_j = −μ_r F_n R_j ω̂_j,   ω̂ = ω/|ω| of THIS step (explicit)
//
// F_n = fn_friction (elastic normal force: Hertz F_n, or the repulsive part of JKR);
// R_i = R_i − δ/2, the distance from the centre to the contact point (contactLever).
// The torque is written into torque_i / torque_j like any other torque, so the integrator treats
// it explicitly: near rest it reverses ω every step (chatter of amplitude ~ τ dt / I) and a body
// loaded below the static limit creeps at a mean rate that grows with dt. That is the behaviour
// of a code that applies the law as written; "constant_torque" is the same law integrated
// implicitly (no reversal, holds at rest). docs/physics.md "EDEM conventions".
// No torque when |ω| < kOmegaRest. Wall contacts (radius_j = inf): only i gets a torque (EDEM
// applies none to the geometry by default). Parameter: rolling_friction μ_r ∈ [0, 10]. No history.
#pragma once

#include "../common/contact_math.hpp"

#include <cmath>

namespace paddy::contact {

class ConstantTorqueExplicitRolling final : public SubModel {
 public:
  static constexpr double kOmegaRest = 1e-9;   // [rad/s] below this a body counts as not rotating

  explicit ConstantTorqueExplicitRolling(double rolling_friction) : mu_r_(rolling_friction) {}

  void compute(ContactBatch& b, std::size_t) const override {
    if (mu_r_ == 0.0) return;
    for (std::size_t k = 0; k < b.n; ++k) {
      if (!b.active[k]) continue;
      const double m = mu_r_ * b.fn_friction[k];
      const double wi = b.omega_i[k].norm();
      if (wi > kOmegaRest) b.torque_i[k] -= (m * contactLever(b.radius_i[k], b.overlap[k]) / wi) * b.omega_i[k];
      if (std::isinf(b.radius_j[k])) continue;
      const double wj = b.omega_j[k].norm();
      if (wj > kOmegaRest) b.torque_j[k] -= (m * contactLever(b.radius_j[k], b.overlap[k]) / wj) * b.omega_j[k];
    }
  }

 private:
  double mu_r_;
};

}  // namespace paddy::contact
