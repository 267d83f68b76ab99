// Normal sub-model "jkr": Hertz-Mindlin with JKR cohesion (Johnson, Kendall & Roberts 1971), in the
// form of the EDEM 2018 theory reference guide (γ = surface energy; work of adhesion = 2γ):
//
//   F_JKR = −4 sqrt(π γ E*) a^{3/2} + 4E*/(3R*) a³
//   δ     = a²/R* − sqrt(4 π γ a / E*)
//
// a(δ) is the root on the stable branch (the larger root, a ≥ a_m, a_m³ = πγR*²/(4E*) being the
// minimum of δ(a)). With L³ = πγR*²/E*, ℓ = L²/R* and a = L t², the relation is the quartic
// t⁴ − 2t = δ/ℓ, solved from a start within 8 % of the root by two Halley steps and one Newton step
// (residual ~1e-16 relative), for a whole batch of contacts at once (solveScaledBatch).
// The force is F = πγR* (4/3 t⁶ − 4 t³).
//
// Cut-off (EDEM): a_c = [9πγR*²/(2E*) (3/4 − 1/√2)]^{1/3}, δ_c = a_c²/R* − sqrt(4πγ a_c/E*) < 0
// (δ_c = −1.18643 ℓ). Note F(a_c) = −1.5 πγR*, i.e. a_c is where the force is half the peak
// attraction on the small-a (unstable) branch; the stable-branch force at δ_c is −1.83218 πγR*.
//   jkr_hysteretic = 0 (EDEM): force on the stable branch whenever δ ≥ δ_c, approach and
//                    separation alike (conservative: no net work over a cycle).
//   jkr_hysteretic = 1: no force before first touch (δ ≥ 0 forms the contact, history flag), then
//                    the JKR branch holds in tension until δ < δ_c (release). Contact formation
//                    as in LAMMPS' "jkr" (which, unlike here, releases at the force-controlled
//                    pull-off δ_f = −0.5724 ℓ). Loses the adhesion work
//                    W = −∫_{δ_c}^{0} F dδ = 3.33397 πγL² per approach–separation cycle.
// Shared state: active = 1 inside the cut-off, a, fn_friction = 4E*a³/(3R*) (the repulsive,
// Hertzian part of F_JKR: the load of the sliding limit and of the rolling torque, as EDEM's JKR
// page prescribes), and the stiffnesses read by damping and the tangential spring:
//   jkr_overlap_stiffness = 0 (Paddy): S_n = 2E*a, S_t = 8G*a from the JKR contact radius a,
//                    so a contact is damped and has a tangential spring across the whole
//                    cohesive range, in a gap (δ < 0) too;
//   jkr_overlap_stiffness = 1 (EDEM): S_n = 2E* sqrt(R*δ), S_t = 8G* sqrt(R*δ) from the geometric
//                    overlap, as in Hertz-Mindlin (no slip) (EDEM's JKR page: tangential elastic
//                    force and both dissipation forces "as Hertz-Mindlin"); zero for δ ≤ 0, so a
//                    contact held by cohesion across a gap is undamped and transmits no
//                    tangential force. docs/physics.md "EDEM conventions".
// maxSeparation(R*) = −δ_c. With γ = 0 the model is "hertz" exactly (same code path).
// Parameters: surface_energy γ [J/m²] ∈ [0, 100]; jkr_hysteretic ∈ {0, 1};
// jkr_overlap_stiffness ∈ {0, 1}.
#pragma once

#include "../common/contact_math.hpp"
#include "../hertz_mindlin/hertz.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace paddy::contact {

class JkrNormal final : public SubModel {
 public:
  JkrNormal(double e_star, double g_star, double gamma, bool hysteretic, bool overlap_stiffness = false)
      : e_star_(e_star), g_star_(g_star), gamma_(gamma), hysteretic_(hysteretic), overlap_stiffness_(overlap_stiffness) {}

  // Dimensionless constants of the quartic t⁴ − 2t = δ/ℓ.
  static double criticalOverlapScaled() {  // δ_c / ℓ from the EDEM a_c
    const double ac = std::cbrt(4.5 * (0.75 - 1.0 / std::numbers::sqrt2));  // a_c / L
    return ac * ac - 2.0 * std::sqrt(ac);
  }
  static double minimumOverlapScaled() { return -1.5 / std::cbrt(2.0); }  // min δ/ℓ, at t³ = 1/2

  // Largest root t of t⁴ − 2t = d (stable branch), for d ≥ minimumOverlapScaled().
  // A start within 8 % of the root, two Halley steps (cubic convergence: error below 2e-9) and one
  // Newton step (below 1e-16): a fixed chain of three divisions, no convergence test. Near the
  // branch point t_min the root itself is ill-conditioned (dt/dd ~ (d − d_min)^(−1/2)); there the
  // result is as good as the rounding of the quartic's terms t⁴, 2t, d allows. Valid up to d ~ 1e150
  // (g g1 overflows far beyond).
  static double solveScaled(double d) {
    double t;
    solveScaledBatch(&d, &t, 1);
    return t;
  }

  // solveScaled for n values at once. The starts: for d < 0 the branch-point expansion
  // t⁴ − 2t − d ≈ 6 t_min² (t − t_min)² − (d − d_min); otherwise one fixed-point step
  // t ← (d + 2t)^{1/4} from an upper bound (t0³ ≥ 4, t0⁴ ≥ 2d). Written branch-free (both starts
  // computed, one selected) so that the compiler vectorises the
  // loop (-O3, and -fno-math-errno for this plugin, plugins/contact/CMakeLists.txt: std::sqrt may
  // then become one vector instruction): the scalar chain of square roots and divisions is
  // latency-bound, the vector unit's lanes are not. A batch's vector body and its scalar tail may
  // differ in the last bit (other contraction of products and sums); both are tested.
  static void solveScaledBatch(const double* __restrict d_in, double* __restrict t_out, std::size_t n) {
    constexpr double t_min = 0.79370052598409973738;  // 2^(−1/3)
    constexpr double cbrt4 = 1.5874010519681994;
    const double d_min = minimumOverlapScaled();
    constexpr double inv6t2 = 1.0 / (6.0 * t_min * t_min);
    for (std::size_t k = 0; k < n; ++k) {
      const double d = std::max(d_in[k], d_min);
      const double branch = t_min + std::sqrt((d - d_min) * inv6t2);
      const double t0 = std::max(cbrt4, std::sqrt(std::sqrt(std::max(2.0 * d, 0.0))));
      const double fixed = std::sqrt(std::sqrt(d + 2.0 * t0));
      double t = d < 0.0 ? branch : fixed;
      for (int it = 0; it < 2; ++it) {  // Halley
        const double t2 = t * t, t3 = t2 * t;
        const double g = t3 * t - 2.0 * t - d, g1 = 4.0 * t3 - 2.0, g2 = 12.0 * t2;
        t -= g * g1 / (g1 * g1 - 0.5 * g * g2);
      }
      const double t3 = t * t * t;  // Newton
      t -= (t3 * t - 2.0 * t - d) / (4.0 * t3 - 2.0);
      t_out[k] = d <= d_min ? t_min : std::max(t, t_min);
    }
  }

  // The former iterative solver (Newton to convergence), kept as a reference for tests.
  static double solveScaledIterative(double d) {
    const double t_min = 1.0 / std::cbrt(2.0);
    if (d <= minimumOverlapScaled()) return t_min;
    double t = std::max(1.5874010519681994, d > 0.0 ? std::sqrt(std::sqrt(2.0 * d)) : 0.0);  // cbrt(4)
    if (d > 0.0) t = std::sqrt(std::sqrt(d + 2.0 * t));
    for (int it = 0; it < 60; ++it) {  // convex, increasing for t > t_min: monotone from above
      const double t3 = t * t * t;
      const double g = t3 * t - 2.0 * t - d;
      if (!(g > 0.0)) break;
      const double step = g / (4.0 * t3 - 2.0);
      t -= step;
      if (step <= 1e-12 * t) break;
    }
    return std::max(t, t_min);
  }

  double lengthScale(double r) const { return std::cbrt(std::numbers::pi * gamma_ * r * r / e_star_); }  // L
  double overlapScale(double r) const { const double l = lengthScale(r); return l * l / r; }            // ℓ
  double criticalOverlap(double r) const { return criticalOverlapScaled() * overlapScale(r); }           // δ_c
  double contactRadius(double overlap, double r) const {
    const double t = solveScaled(overlap / overlapScale(r));
    return lengthScale(r) * t * t;
  }

  std::size_t historySize() const override { return hysteretic_ ? 1 : 0; }
  double maxSeparation(double r_eff) const override { return gamma_ > 0.0 ? -criticalOverlap(r_eff) : 0.0; }

  void compute(ContactBatch& b, std::size_t offset) const override {
    if (gamma_ == 0.0) {
      for (std::size_t k = 0; k < b.n; ++k) {
        HertzNormal::contact(b, k, e_star_, g_star_);
        if (hysteretic_) b.historyOf(k, offset)[0] = b.active[k];
      }
      return;
    }
    const double dc_scaled = criticalOverlapScaled();
    // 1. Scaled overlaps and which contacts are on (length scales recomputed only when R* changes).
    double ds[ContactBatch::kCapacity], len_of[ContactBatch::kCapacity], t_of[ContactBatch::kCapacity];
    bool on_of[ContactBatch::kCapacity];
    double r_last = -1.0, len = 0.0, ell = 0.0;
    for (std::size_t k = 0; k < b.n; ++k) {
      const double r = b.r_eff[k], d = b.overlap[k];
      if (r != r_last) {
        r_last = r;
        len = lengthScale(r);
        ell = len * len / r;
      }
      ds[k] = d / ell;
      len_of[k] = len;
      bool on = ds[k] >= dc_scaled;
      if (hysteretic_) {
        double& touched = b.historyOf(k, offset)[0];
        if (d >= 0.0) touched = 1.0;
        if (!on) touched = 0.0;
        on = on && touched != 0.0;
      }
      on_of[k] = on;
    }
    // 2. Contact radii of the whole batch at once (vectorised).
    solveScaledBatch(ds, t_of, b.n);
    // 3. Forces and stiffnesses of the contacts that are on.
    for (std::size_t k = 0; k < b.n; ++k) {
      if (!on_of[k]) continue;
      const double r = b.r_eff[k], d = b.overlap[k];
      const double t = t_of[k];
      const double t3 = t * t * t;
      const double a = len_of[k] * t * t;
      const double fscale = std::numbers::pi * gamma_ * r;  // πγR*
      const double repulsive = fscale * (4.0 / 3.0) * t3 * t3;  // 4E*a³/(3R*)
      b.active[k] = 1;
      b.contact_radius[k] = a;
      b.fn[k] += repulsive - fscale * 4.0 * t3;
      b.fn_friction[k] = repulsive;
      const double a_stiff = overlap_stiffness_ ? (d > 0.0 ? std::sqrt(r * d) : 0.0) : a;
      b.stiffness_n[k] = 2.0 * e_star_ * a_stiff;
      b.stiffness_t[k] = 8.0 * g_star_ * a_stiff;
    }
  }

 private:
  double e_star_, g_star_, gamma_;
  bool hysteretic_;
  bool overlap_stiffness_;  // S_n, S_t from sqrt(R* δ) (EDEM) instead of a (Paddy)
};

}  // namespace paddy::contact
