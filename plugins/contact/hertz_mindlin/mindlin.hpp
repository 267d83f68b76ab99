// Tangential sub-model "mindlin": no-slip Mindlin tangential spring with Coulomb limit, as in
// EDEM's Hertz-Mindlin (no slip) model (Mindlin 1949; Mindlin & Deresiewicz 1953; EDEM theory
// reference guide; damping after Tsuji, Tanaka & Ishida 1992):
//
//   ξ ← rotate(ξ, n) + v_t dt                 spring displacement, kept in the tangent plane
//   F_t = −S_t ξ − c_t v_t,   c_t = 2 sqrt(5/6) |β| sqrt(S_t m*),  β = ln e / sqrt(ln²e + π²)
//   if |F_t| > μ_s fn_friction:  F_t ← μ_s fn_friction F_t / |F_t|   (cap on the TOTAL force)
//                                ξ   ← −F_t / S_t     (the spring alone carries the capped force)
//
// S_t (= 8 G* a for Hertz and JKR) and fn_friction come from the normal model. rotate() turns the
// previous step's ξ into the current tangent plane keeping its length. The cap applies to the
// TOTAL tangential force (spring + damping), as in EDEM. Spring rescaling: the spring alone holds
// the capped force (−S_t ξ = F_t), rather than LAMMPS' ξ = −(F_t + c_t v_t)/S_t, which lets the
// spring store up to ½(c_t|v_t| − μ_s F_n)²/S_t when damping dominates and flips F_t towards the
// former sliding direction when sliding stops (see docs/physics.md). History: ξ (3 doubles), cleared when !active.
// Parameters: friction μ_s ∈ [0, 10]; restitution e ∈ (0, 1] (shared with "hertz_mindlin").
#pragma once

#include "../common/contact_math.hpp"

#include <cmath>

namespace paddy::contact {

class MindlinTangential final : public SubModel {
 public:
  MindlinTangential(double friction, double restitution)
      : mu_(friction), factor_(2.0 * std::sqrt(5.0 / 6.0) * std::abs(restitutionBeta(restitution))) {}

  std::size_t historySize() const override { return 3; }

  void compute(ContactBatch& b, std::size_t offset) const override {
    for (std::size_t k = 0; k < b.n; ++k) {
      double* h = b.historyOf(k, offset);
      if (!b.active[k]) {
        h[0] = h[1] = h[2] = 0.0;
        continue;
      }
      Vec3 xi = loadVec(h);
      rotateIntoPlane(xi, b.normal[k]);
      xi += b.vt[k] * b.dt;
      const double st = b.stiffness_t[k];
      const Vec3 damp = -(factor_ * std::sqrt(st * b.m_eff[k])) * b.vt[k];
      Vec3 f = -st * xi + damp;
      const double limit = mu_ * b.fn_friction[k];
      const double mag = f.norm();
      if (mag > limit) {
        f *= (mag > 0.0 ? limit / mag : 0.0);
        xi = st > 0.0 ? Vec3(-f / st) : Vec3::Zero();
      }
      b.ft[k] += f;
      storeVec(h, xi);
    }
  }

 private:
  double mu_;
  double factor_;  // 2 sqrt(5/6) |β|
};

}  // namespace paddy::contact
