// Rolling sub-model "constant_torque": directional constant torque, EDEM rolling friction
// "type A" (Ai, Chen, Rotter & Ooi 2011, model A; Zhou et al. 1999; EDEM theory reference guide):
//
//   τ_i = −μ_r F_n R_i ω̂_i,   τ_j = −μ_r F_n R_j ω̂_j   (each body's own angular velocity)
//
// F_n = fn_friction (elastic normal force: Hertz F_n, or the repulsive part of JKR);
// R_i = R_i − δ/2, the distance from the centre to the contact point the engine uses.
// ω̂ = ω/|ω|; no torque when |ω| < 1e-9 rad/s. Wall contacts (radius_j = inf): only i gets a
// torque. Known limitation of model A: the torque does not vanish at rest, so ω chatters around 0
// with amplitude ~ τ dt / I. Parameter: rolling_friction μ_r ∈ [0, 10]. No history.
#pragma once

#include "../common/contact_math.hpp"

#include <cmath>

namespace paddy::contact {

class ConstantTorqueRolling final : public SubModel {
 public:
  static constexpr double kOmegaRest = 1e-9;  // [rad/s] below this a body counts as not rotating

  explicit ConstantTorqueRolling(double rolling_friction) : mu_r_(rolling_friction) {}

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
