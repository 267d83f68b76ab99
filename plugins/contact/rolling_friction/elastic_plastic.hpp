// Rolling sub-model "elastic_plastic": elastic-plastic spring-dashpot rolling resistance, EDEM
// "type C" (Ai, Chen, Rotter & Ooi 2011, model C; rolling stiffness after Iwashita & Oda 1998):
//
//   ω_r  = (ω_i − ω_j) − ((ω_i − ω_j)·n) n          relative rolling angular velocity
//   M_k ← rotate(M_k, n) − k_r ω_r dt,  k_r = 2.25 S_n μ_r² R*²   spring torque (history)
//   |M_k| ≤ M_m = μ_r R* fn_friction                 full mobilisation: M_k ← M_m M_k/|M_k|
//   M_d  = −η_r ω_r,  η_r = 2 ζ sqrt(I_r k_r)        viscous torque, ζ = rolling_damping,
//                                                    switched off at full mobilisation (Ai f = 0)
//   τ_i += M_k + M_d,   τ_j −= M_k + M_d   (also for walls: the reaction on the wall)
//
// I_r = [1/(I_i + m_i R_i²) + 1/(I_j + m_j R_j²)]^{-1} (Ai et al.), with I = 2/5 m R² (solid
// spheres). ContactBatch carries only m* and the radii, so m_i, m_j are recovered assuming equal
// densities: m_i = m* (1 + R_i³/R_j³), m_j = m* (1 + R_j³/R_i³). This is exact for a wall
// (I_r = 1.4 m* R*²) and for same-material pairs; for mixed-density particle pairs it is an
// approximation (see docs/physics.md). S_n and fn_friction come from the normal model.
// History: M_k (3 doubles), cleared when !active.
// Parameters: rolling_friction μ_r ∈ [0, 10]; rolling_damping ζ ∈ [0, 10] (default 0.3).
#pragma once

#include "../common/contact_math.hpp"

#include <cmath>

namespace paddy::contact {

class ElasticPlasticRolling final : public SubModel {
 public:
  ElasticPlasticRolling(double rolling_friction, double rolling_damping)
      : mu_r_(rolling_friction), zeta_(rolling_damping) {}

  std::size_t historySize() const override { return 3; }

  // Ai et al.'s rolling inertia about the contact point (equal-density recovery of m_i, m_j).
  static double rollingInertia(double m_eff, double ri, double rj) {
    const double q = ri / rj;  // 0 for a wall
    const double mi = m_eff * (1.0 + q * q * q);
    const double inv_j = std::isinf(rj) ? 0.0 : 1.0 / (1.4 * m_eff * (1.0 + 1.0 / (q * q * q)) * rj * rj);
    return 1.0 / (1.0 / (1.4 * mi * ri * ri) + inv_j);
  }

  void compute(ContactBatch& b, std::size_t offset) const override {
    for (std::size_t k = 0; k < b.n; ++k) {
      double* h = b.historyOf(k, offset);
      if (!b.active[k] || mu_r_ == 0.0) {
        h[0] = h[1] = h[2] = 0.0;
        continue;
      }
      const Vec3& n = b.normal[k];
      const double r = b.r_eff[k];
      const double kr = 2.25 * b.stiffness_n[k] * mu_r_ * mu_r_ * r * r;
      const double limit = mu_r_ * r * b.fn_friction[k];
      Vec3 w = b.omega_i[k] - b.omega_j[k];
      w -= w.dot(n) * n;
      Vec3 m = loadVec(h);
      rotateIntoPlane(m, n);
      m -= (kr * b.dt) * w;
      Vec3 total = m;
      const double mag = m.norm();
      if (mag >= limit) {
        m *= (mag > 0.0 ? limit / mag : 0.0);
        total = m;
      } else {
        const double eta = 2.0 * zeta_ * std::sqrt(rollingInertia(b.m_eff[k], b.radius_i[k], b.radius_j[k]) * kr);
        total -= eta * w;
      }
      b.torque_i[k] += total;
      b.torque_j[k] -= total;
      storeVec(h, m);
    }
  }

 private:
  double mu_r_, zeta_;
};

}  // namespace paddy::contact
