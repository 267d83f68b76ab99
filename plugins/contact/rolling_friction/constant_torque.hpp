// Rolling sub-model "constant_torque": directional constant torque, EDEM rolling friction
// "type A" (Ai, Chen, Rotter & Ooi 2011, model A; Zhou et al. 1999; EDEM theory reference guide):
//
//   τ_i = −μ_r F_n R_i ω̂_i,   τ_j = −μ_r F_n R_j ω̂_j   (each body's own angular velocity)
//
// F_n = fn_friction (elastic normal force: Hertz F_n, or the repulsive part of JKR);
// R_i = R_i − δ/2, the distance from the centre to the contact point the engine uses.
// The model writes the magnitudes μ_r F_n R_i and μ_r F_n R_j into resist_i / resist_j; the
// integrator applies the sum over a body's contacts implicitly (engine/core/src/integrator.cpp):
// the torque opposes the rotation, can stop it within a step and then holds the body at rest
// against any other torque up to that sum (the static limit of the law), but never reverses it.
// Written explicitly (τ from ω̂ of the current step), the torque reverses ω every step near rest
// and the slump test then depends on dt (docs/physics.md §2.5). Wall contacts (radius_j = inf):
// only i is resisted; the wall receives no rolling torque (as in EDEM's type A).
// Parameter: rolling_friction μ_r ∈ [0, 10]. No history.
#pragma once

#include "../common/contact_math.hpp"

#include <cmath>

namespace paddy::contact {

class ConstantTorqueRolling final : public SubModel {
 public:
  explicit ConstantTorqueRolling(double rolling_friction) : mu_r_(rolling_friction) {}

  void compute(ContactBatch& b, std::size_t) const override {
    if (mu_r_ == 0.0) return;
    for (std::size_t k = 0; k < b.n; ++k) {
      if (!b.active[k]) continue;
      const double m = mu_r_ * b.fn_friction[k];
      b.resist_i[k] += m * contactLever(b.radius_i[k], b.overlap[k]);
      if (!std::isinf(b.radius_j[k])) b.resist_j[k] += m * contactLever(b.radius_j[k], b.overlap[k]);
    }
  }

 private:
  double mu_r_;
};

}  // namespace paddy::contact
