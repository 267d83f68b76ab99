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
    constexpr std::size_t K = ContactBatch::kCapacity;
    const std::size_t n = b.n;
    // 1. Gather each contact's spring (its history block lies elsewhere in memory) and the
    //    vectors the law reads into one array per component.
    alignas(64) double xx[K], xy[K], xz[K], nx[K], ny[K], nz[K], vx[K], vy[K], vz[K], st[K], limit[K], m_eff[K];
    for (std::size_t k = 0; k < n; ++k) {
      const double* h = b.historyOf(k, offset);
      xx[k] = h[0], xy[k] = h[1], xz[k] = h[2];
      nx[k] = b.normal[k].x(), ny[k] = b.normal[k].y(), nz[k] = b.normal[k].z();
      vx[k] = b.vt[k].x(), vy[k] = b.vt[k].y(), vz[k] = b.vt[k].z();
      st[k] = b.stiffness_t[k];
      limit[k] = mu_ * b.fn_friction[k];
      m_eff[k] = b.m_eff[k];
    }
    // 2. The law (formula above) for the whole batch, branch-free so that it vectorises: every
    //    alternative is computed and one selected (-fno-math-errno for this plugin lets std::sqrt be
    //    one vector instruction; the scalar chain of square roots and divisions is latency-bound).
    double fx[K], fy[K], fz[K];
    batchLaw(n, b.dt, xx, xy, xz, nx, ny, nz, vx, vy, vz, st, limit, m_eff, fx, fy, fz);
    // 3. Scatter: the force of an active contact, its new spring; an inactive one's spring is cleared.
    for (std::size_t k = 0; k < n; ++k) {
      double* h = b.historyOf(k, offset);
      if (!b.active[k]) {
        h[0] = h[1] = h[2] = 0.0;
        continue;
      }
      b.ft[k] += Vec3(fx[k], fy[k], fz[k]);
      h[0] = xx[k], h[1] = xy[k], h[2] = xz[k];
    }
  }

  // The law for n contacts in component arrays. In: spring x (from the last step), normal n,
  // tangential velocity v, stiffness S_t, Coulomb limit μ_s fn_friction and m*.
  // Out: force f; x becomes the new spring. Per contact:
  //   rotateIntoPlane: p = x − (x·n) n, x ← p |x|/|p| (0 when |p| = 0), then x += v dt;
  //   f = −S_t x − factor sqrt(S_t m*) v; if |f| > limit: f ← f limit/|f|, x ← −f/S_t (0 if S_t = 0).
  void batchLaw(std::size_t n, double dt, double* __restrict xx, double* __restrict xy, double* __restrict xz,
                const double* __restrict nx, const double* __restrict ny, const double* __restrict nz,
                const double* __restrict vx, const double* __restrict vy, const double* __restrict vz,
                const double* __restrict st, const double* __restrict limit, const double* __restrict m_eff,
                double* __restrict fx, double* __restrict fy, double* __restrict fz) const {
    for (std::size_t k = 0; k < n; ++k) {
      const double len2 = xx[k] * xx[k] + xy[k] * xy[k] + xz[k] * xz[k];
      const double along = xx[k] * nx[k] + xy[k] * ny[k] + xz[k] * nz[k];
      const double px = xx[k] - along * nx[k], py = xy[k] - along * ny[k], pz = xz[k] - along * nz[k];
      const double p2 = px * px + py * py + pz * pz;
      const double stretch = std::sqrt(len2 / p2);
      const double keep = p2 > 0.0 ? stretch : 0.0;
      const double sx = px * keep + vx[k] * dt, sy = py * keep + vy[k] * dt, sz = pz * keep + vz[k] * dt;
      const double c = factor_ * std::sqrt(st[k] * m_eff[k]);
      const double gx = -st[k] * sx - c * vx[k], gy = -st[k] * sy - c * vy[k], gz = -st[k] * sz - c * vz[k];
      const double mag = std::sqrt(gx * gx + gy * gy + gz * gz);
      const bool slides = mag > limit[k];
      const double scale = slides ? limit[k] / mag : 1.0;
      const double hx = gx * scale, hy = gy * scale, hz = gz * scale;
      const bool stiff = st[k] > 0.0;
      const double qx = -hx / st[k], qy = -hy / st[k], qz = -hz / st[k];
      fx[k] = hx, fy[k] = hy, fz[k] = hz;
      xx[k] = slides ? (stiff ? qx : 0.0) : sx;
      xy[k] = slides ? (stiff ? qy : 0.0) : sy;
      xz[k] = slides ? (stiff ? qz : 0.0) : sz;
    }
  }

 private:
  double mu_;
  double factor_;  // 2 sqrt(5/6) |β|
};

}  // namespace paddy::contact
