// Extra sub-model "plastic_adhesion": adhesion that grows with the largest load a contact has
// carried, in the spirit of the elasto-plastic adhesive contacts of Luding (2008, "Cohesive,
// frictional powders: contact models for tension", Granular Matter 10, 235) and the EEPA model
// (Thakur, Morrissey, Sun, Chen & Ooi 2014, Granular Matter 16, 383): a wet, plastic contact that
// was pressed harder flattens more and sticks harder.
//
// History per contact: F_max (the largest normal load fn_friction the normal model gave it while
// bonded), δ_max (the largest overlap), the bond flag. A bond forms when the surfaces touch.
//   pull-off   A   = λ F_max                      λ = plastic_adhesion (dimensionless)
//   range      s_c = min(δ_max, κ R*)              κ = plastic_adhesion_range
//   F_ad(δ)    = A                 for δ ≥ 0       (in contact)
//              = A (1 + δ / s_c)   for −s_c < δ < 0 (bonded across a gap: linear softening, as
//                                                   Luding's tensile branch; the range is the
//                                                   plastic indentation, capped)
//   the bond breaks (history cleared) when δ ≤ −s_c.
// fn −= F_ad. Friction: fn_friction += F_ad — the adhesive pull loads the flattened contact, so
// the Coulomb and rolling limits grow with it and stay > 0 in tension (Luding 2008 lets friction
// act in tension with the limit μ (f_n + f_adh)); this is why it must run before the tangential
// and rolling sub-models. Across the bonded gap it marks the contact active with S_n = A / s_c
// (the softening slope), so the chain's damping acts there too.
// Time step: |dF_ad/dδ| = A / s_c ≤ λ F_max / δ_max ≤ λ (2/3) S_n(δ_max) for Hertz (F = 2/3 S_n δ),
// so for λ ≤ 1.5 the slope stays below the Hertz stiffness the step already resolves. The range
// of λ is [0, 0.9]: at λ = 1 an unloaded contact is pulled back to its largest overlap
// (F_H(δ) = F_max) and never recovers, so contacts ratchet to ever larger overlaps (the 20 mm
// slump with λ = 1 stopped with an overlap above 50 % of a radius during the pour); λ < 1 leaves
// an elastic recovery to λ^{2/3} δ_max.
// maxSeparation(R*) = κ R* when λ > 0.
// Strength 0 (λ = 0): no history, maxSeparation 0, compute does nothing — bit for bit the chain
// without it.
#pragma once

#include "../common/contact_math.hpp"

#include <algorithm>
#include <cmath>

namespace paddy::contact {

class PlasticAdhesion final : public SubModel {
 public:
  PlasticAdhesion(double lambda, double range) : lambda_(lambda), range_(range) {}

  // F_ad for a contact with history (F_max, δ_max) at overlap δ (0 beyond the range).
  double force(double f_max, double delta_max, double r_eff, double delta) const {
    const double a = lambda_ * f_max;
    if (delta >= 0.0) return a;
    const double s_c = std::min(delta_max, range_ * r_eff);
    return delta > -s_c ? a * (1.0 + delta / s_c) : 0.0;
  }

  std::size_t historySize() const override { return lambda_ > 0.0 ? 3 : 0; }
  double maxSeparation(double r_eff) const override { return lambda_ > 0.0 ? range_ * r_eff : 0.0; }

  void compute(ContactBatch& b, std::size_t offset) const override {
    if (lambda_ == 0.0) return;
    for (std::size_t k = 0; k < b.n; ++k) {
      double* h = b.historyOf(k, offset);  // F_max, δ_max, bonded
      const double d = b.overlap[k];
      if (d >= 0.0) {
        h[2] = 1.0;
        h[0] = std::max(h[0], b.fn_friction[k]);
        h[1] = std::max(h[1], d);
      }
      const double s_c = std::min(h[1], range_ * b.r_eff[k]);
      if (h[2] == 0.0 || (d < 0.0 && !(d > -s_c))) {
        h[0] = h[1] = h[2] = 0.0;
        continue;
      }
      const double f = force(h[0], h[1], b.r_eff[k], d);
      b.fn[k] -= f;
      b.fn_friction[k] += f;
      if (d < 0.0) {
        b.active[k] = 1;
        b.stiffness_n[k] = std::max(b.stiffness_n[k], lambda_ * h[0] / s_c);
      }
    }
  }

 private:
  double lambda_, range_;
};

}  // namespace paddy::contact
