// EDEM's type A rolling friction applied explicitly ("constant_torque_explicit", the edem
// conventions) against the same law integrated implicitly ("constant_torque", paddy), for a
// sphere on an incline (docs/physics.md "EDEM conventions"):
//  * above the static limit (tan θ > μ_r) both roll down at the closed-form rate
//    a = g (sin θ − μ_r cos θ) / (1 + I/(m r_c²));
//  * below it (tan θ = μ_r / 2) the implicit torque holds the sphere exactly, while the explicit
//    one reverses ω every step and the sphere creeps down the slope, faster at the larger step.
#include "physics_fixture.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

using namespace paddy;

TEST_CASE("explicit type A rolling torque: closed-form roll above the limit like the implicit one",
          "[physics][rolling][edem]") {
  const double R = 1e-3, mu_r = 0.1, g = 9.81, t = 0.1;
  const double tan_theta = 2.0 * mu_r, c = 1.0 / std::sqrt(1.0 + tan_theta * tan_theta);
  const double a = g * (tan_theta * c - mu_r * c) / 1.4;
  for (double frac : {0.2, 0.05}) {
    Vec3 w;
    const double dist = test::rollDownIncline("constant_torque_explicit", tan_theta, mu_r, frac, t, &w);
    INFO("dt = " << frac << " T_R: rolled " << dist << " m, closed form " << 0.5 * a * t * t);
    std::printf("[physics] explicit type A, tan = 2 mu_r, dt = %.2f T_R: %.6e m in %.1f s, closed form %.6e m (%+.2e)\n",
                frac, dist, t, 0.5 * a * t * t, dist / (0.5 * a * t * t) - 1.0);
    REQUIRE(dist == Approx(0.5 * a * t * t).epsilon(0.01));
    REQUIRE(w.y() * R == Approx(a * t).epsilon(0.01));
  }
}

TEST_CASE("explicit type A rolling torque: a sphere below the limit creeps (dt-dependent), the implicit one holds",
          "[physics][rolling][edem]") {
  const double R = 1e-3, mu_r = 0.1, duration = 0.5, tan_theta = 0.5 * mu_r;
  double creep[2] = {0.0, 0.0};
  int k = 0;
  for (double frac : {0.2, 0.05}) {
    Vec3 w_exp, w_imp;
    double half_exp = 0.0, half_imp = 0.0;
    const double d_exp = test::rollDownIncline("constant_torque_explicit", tan_theta, mu_r, frac, duration, &w_exp, &half_exp);
    const double d_imp = test::rollDownIncline("constant_torque", tan_theta, mu_r, frac, duration, &w_imp, &half_imp);
    std::printf("[physics] tan = mu_r/2, dt = %.2f T_R: explicit moved %.4e m by 0.25 s, %.4e m by 0.5 s (|w| %.3g); "
                "implicit %.4e m (|w| %g)\n", frac, half_exp, d_exp, w_exp.norm(), d_imp, w_imp.norm());
    INFO("dt = " << frac << " T_R: explicit " << half_exp << " / " << d_exp << " m, implicit " << d_imp << " m");
    // Implicit: only the elastic shift of the tangential spring (~1e-8 m), then nothing.
    REQUIRE(std::abs(d_imp) < 1e-4 * R);
    REQUIRE(w_imp.norm() == 0.0);
    // Explicit: a steady creep down the slope, well beyond the elastic shift, still rotating.
    REQUIRE(d_exp > 100.0 * std::abs(d_imp));
    REQUIRE(d_exp - half_exp > 0.25 * d_exp);  // still creeping in the second half
    REQUIRE(w_exp.norm() > 0.0);
    creep[k++] = d_exp;
  }
  // The creep is an artefact of the step: it grows with dt.
  REQUIRE(creep[0] > 1.5 * creep[1]);
}
