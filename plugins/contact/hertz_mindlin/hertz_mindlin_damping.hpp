// Damping sub-model "hertz_mindlin": the normal viscous damping of EDEM's Hertz-Mindlin (no slip)
// model (EDEM theory reference guide; Tsuji, Tanaka & Ishida 1992):
//
//   F_n^d = −2 sqrt(5/6) β sqrt(S_n m*) v_n,   β = ln e / sqrt(ln²e + π²)
//
// With Paddy's sign convention (v_n > 0 separating, fn > 0 repulsive on i) this is
// fn += −c_n v_n with c_n = 2 sqrt(5/6) |β| sqrt(S_n m*) ≥ 0: it resists approach and separation.
// Applied to active contacts only; S_n comes from the normal model.
//
// Design choice: this sub-model handles the NORMAL direction only. The tangential damping
// −2 sqrt(5/6) β sqrt(S_t m*) v_t belongs to the "mindlin" tangential sub-model, which reads the
// same "restitution" parameter, so that the Coulomb limit caps spring + damping together
// (as EDEM does). Parameter: restitution e ∈ (0, 1] (e = 1: no damping).
#pragma once

#include "../common/contact_math.hpp"

#include <cmath>

namespace paddy::contact {

class HertzMindlinDamping final : public SubModel {
 public:
  explicit HertzMindlinDamping(double restitution)
      : factor_(2.0 * std::sqrt(5.0 / 6.0) * std::abs(restitutionBeta(restitution))) {}

  void compute(ContactBatch& b, std::size_t) const override {
    if (factor_ == 0.0) return;
    // Branch-free (an inactive contact keeps its fn) so that the loop vectorises, with
    // -fno-math-errno for this plugin (plugins/contact/CMakeLists.txt).
    const std::size_t n = b.n;
    const double factor = factor_;  // a local: the stores to fn cannot change it
    for (std::size_t k = 0; k < n; ++k) {
      const double on = static_cast<double>(b.active[k] != 0);
      const double c = factor * std::sqrt(b.stiffness_n[k] * b.m_eff[k]);
      b.fn[k] -= on * c * b.vn[k];
    }
  }

 private:
  double factor_;  // 2 sqrt(5/6) |β|
};

}  // namespace paddy::contact
