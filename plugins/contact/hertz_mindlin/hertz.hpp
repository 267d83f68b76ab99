// Normal sub-model "hertz": elastic Hertz contact of two spheres (Hertz 1882), as in the
// Hertz-Mindlin (no slip) model of the EDEM theory reference guide, with the tangential
// stiffness of Mindlin (1949) / Mindlin & Deresiewicz (1953):
//
//   F_n = 4/3 E* sqrt(R*) δ^{3/2}     for δ > 0 (no force otherwise)
//   a   = sqrt(R* δ)                  contact radius
//   S_n = 2 E* a,   S_t = 8 G* a      normal / tangential stiffness
//   fn_friction = F_n,   active = (δ > 0)
//
// E*, G* come from the material pair (MaterialPair::of). No parameters, no history.
#pragma once

#include <paddy/contact_model.hpp>

#include <cmath>

namespace paddy::contact {

class HertzNormal final : public SubModel {
 public:
  HertzNormal(double e_star, double g_star) : e_star_(e_star), g_star_(g_star) {}

  // One contact; also used by "jkr" with γ = 0 so that it reduces to Hertz bit for bit.
  static void contact(ContactBatch& b, std::size_t k, double e_star, double g_star) {
    const double d = b.overlap[k];
    if (!(d > 0.0)) return;  // outputs already cleared by resetOutputs()
    const double a = std::sqrt(b.r_eff[k] * d);
    const double f = (4.0 / 3.0) * e_star * a * d;  // = 4/3 E* sqrt(R*) δ^{3/2}
    b.active[k] = 1;
    b.contact_radius[k] = a;
    b.fn[k] += f;
    b.fn_friction[k] = f;
    b.stiffness_n[k] = 2.0 * e_star * a;
    b.stiffness_t[k] = 8.0 * g_star * a;
  }

  void compute(ContactBatch& b, std::size_t) const override {
    for (std::size_t k = 0; k < b.n; ++k) contact(b, k, e_star_, g_star_);
  }

 private:
  double e_star_, g_star_;
};

}  // namespace paddy::contact
