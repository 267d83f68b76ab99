// The contact-level differences between Paddy's and EDEM's conventions (docs/physics.md "EDEM
// conventions"), each against its closed form:
//  * type A rolling friction applied explicitly ("constant_torque_explicit"): the torque
//    −μ_r F_n R_i ω̂_i on each body from its own angular velocity, nothing at rest, no resist_i;
//  * JKR stiffnesses for damping and the tangential spring: 2E*a, 8G*a from the JKR contact
//    radius (Paddy) or 2E*sqrt(R*δ), 8G*sqrt(R*δ) from the overlap, zero in a gap (EDEM), so a
//    cohesive contact across a gap is damped in one and not in the other;
//  * the JKR sliding limit uses the repulsive part 4E*a³/(3R*), not the net force (both modes).
#include "contact_test_util.hpp"

#include <hertz_mindlin/hertz.hpp>
#include <hertz_mindlin/hertz_mindlin_damping.hpp>
#include <hertz_mindlin/mindlin.hpp>
#include <jkr/jkr.hpp>
#include <rolling_friction/constant_torque_explicit.hpp>

#include <catch2/catch.hpp>

using namespace ctest;
using paddy::contact::ConstantTorqueExplicitRolling;
using paddy::contact::HertzMindlinDamping;
using paddy::contact::HertzNormal;
using paddy::contact::JkrNormal;
using paddy::contact::MindlinTangential;

namespace {
// JKR at contact radius a, written out from the EDEM form independently of jkr.hpp:
// δ(a) = a²/R* − sqrt(4πγa/E*), F(a) = −4 sqrt(πγE*) a^{3/2} + 4E*a³/(3R*).
struct JkrPoint {
  double delta, repulsive, net;
};
JkrPoint jkrAt(double a, double e, double gamma, double r) {
  const double rep = 4.0 * e * a * a * a / (3.0 * r);
  return {a * a / r - std::sqrt(4.0 * kPi * gamma * a / e), rep, rep - 4.0 * std::sqrt(kPi * gamma * e) * std::pow(a, 1.5)};
}
}  // namespace

TEST_CASE("contact constant_torque_explicit: torque -mu_r F_n R_i w_i/|w_i| on each body from its own w",
          "[contact][rolling][edem]") {
  const MaterialPair p = MaterialPair::of(mud(), mud());
  const double mu_r = 0.125, d = 2e-6;
  Chain c;
  c.add(std::make_unique<HertzNormal>(p.e_star, p.g_star)).add(std::make_unique<ConstantTorqueExplicitRolling>(mu_r));
  ContactBatch& b = c.setup(4);
  setPair(b, 0, d, 1e-3, 2e-3, 1e-5, 8e-5);  // particle pair, different radii
  b.omega_i[0] = Vec3(3.0, -4.0, 0.0);
  b.omega_j[0] = Vec3(0.0, 0.0, 2.0);
  setPair(b, 1, d, 1e-3, kInf, 1e-5, kInf);  // wall: only i
  b.omega_i[1] = Vec3(0.0, 7.0, 0.0);
  b.omega_j[1] = Vec3(1.0, 0.0, 0.0);
  setPair(b, 2, d, 1e-3, 1e-3, 1e-5, 1e-5);  // not rotating: no torque (nothing holds it)
  setPair(b, 3, -d, 1e-3, 1e-3, 1e-5, 1e-5);  // no contact
  b.omega_i[3] = Vec3(1.0, 0.0, 0.0);
  c.run();
  const double f0 = b.fn_friction[0];
  REQUIRE(f0 == Approx(4.0 / 3.0 * p.e_star * std::sqrt(b.r_eff[0]) * std::pow(d, 1.5)).epsilon(1e-12));
  const Vec3 ti = -mu_r * f0 * (1e-3 - d / 2) * Vec3(0.6, -0.8, 0.0);
  const Vec3 tj = -mu_r * f0 * (2e-3 - d / 2) * Vec3(0.0, 0.0, 1.0);
  CHECK((b.torque_i[0] - ti).norm() <= 1e-14 * ti.norm());
  CHECK((b.torque_j[0] - tj).norm() <= 1e-14 * tj.norm());
  const Vec3 tw = -mu_r * b.fn_friction[1] * (1e-3 - d / 2) * Vec3::UnitY();
  CHECK((b.torque_i[1] - tw).norm() <= 1e-14 * tw.norm());
  CHECK(b.torque_j[1].norm() == 0.0);
  CHECK(b.torque_i[2].norm() == 0.0);
  CHECK(b.torque_i[3].norm() == 0.0);
  for (int k = 0; k < 4; ++k) {  // all explicit: nothing for the implicit resistance
    CHECK(b.resist_i[k] == 0.0);
    CHECK(b.resist_j[k] == 0.0);
  }
}

TEST_CASE("contact jkr stiffness conventions: 2E*a / 8G*a (paddy) or 2E* sqrt(R* d) / 8G* sqrt(R* d), zero in a gap (edem)",
          "[contact][jkr][edem]") {
  const MaterialPair p = MaterialPair::of(mud(), mud());
  const double r = 0.5 * 5e-3, gamma = 0.48;  // 10 mm spheres, the reference gamma coarse grained (alpha 5)
  JkrNormal paddy_jkr(p.e_star, p.g_star, gamma, false, false), edem_jkr(p.e_star, p.g_star, gamma, false, true);
  const double L = paddy_jkr.lengthScale(r);
  for (double t : {0.9, 1.0, 1.3, 2.0, 4.0}) {  // a = L t²: from the gap (δ < 0) to well inside
    const double a = L * t * t;
    const JkrPoint j = jkrAt(a, p.e_star, gamma, r);
    for (int mode = 0; mode < 2; ++mode) {
      Chain c;
      c.add(std::make_unique<JkrNormal>(p.e_star, p.g_star, gamma, false, mode == 1));
      ContactBatch& b = c.setup(1);
      setPair(b, 0, j.delta, 2 * r, 2 * r, 1e-3, 1e-3);
      c.run();
      INFO("t = " << t << ", delta = " << j.delta << " m, mode " << (mode ? "edem" : "paddy"));
      REQUIRE(b.active[0] == 1);
      CHECK(b.contact_radius[0] == Approx(a).epsilon(1e-9));
      CHECK(b.fn[0] == Approx(j.net).epsilon(1e-8));          // the force is the same in both
      CHECK(b.fn_friction[0] == Approx(j.repulsive).epsilon(1e-8));
      const double s = mode == 0 ? a : (j.delta > 0.0 ? std::sqrt(r * j.delta) : 0.0);
      CHECK(b.stiffness_n[0] == Approx(2.0 * p.e_star * s).epsilon(1e-8).margin(1e-12));
      CHECK(b.stiffness_t[0] == Approx(8.0 * p.g_star * s).epsilon(1e-8).margin(1e-12));
      if (mode == 1 && j.delta > 0.0) CHECK(b.stiffness_n[0] < 2.0 * p.e_star * a);  // sqrt(R*δ) < a under cohesion
    }
  }
  // A cohesive contact across a gap, separating at 0.1 m/s: damped under paddy, not under edem.
  const JkrPoint gap = jkrAt(0.9 * 0.9 * L, p.e_star, gamma, r);
  REQUIRE(gap.delta < 0.0);
  const double e = 0.13, m = 1e-3, v = 0.1;
  for (int mode = 0; mode < 2; ++mode) {
    Chain c;
    c.add(std::make_unique<JkrNormal>(p.e_star, p.g_star, gamma, false, mode == 1))
        .add(std::make_unique<HertzMindlinDamping>(e));
    ContactBatch& b = c.setup(1);
    setPair(b, 0, gap.delta, 2 * r, 2 * r, m, m);
    b.vn[0] = v;
    c.run();
    const double l = std::log(e), beta = l / std::sqrt(l * l + kPi * kPi);
    const double damping = mode == 0 ? 2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(2.0 * p.e_star * 0.81 * L * 0.5 * m) * v : 0.0;
    INFO("mode " << (mode ? "edem" : "paddy"));
    CHECK(b.fn[0] == Approx(gap.net + damping).epsilon(1e-8));
    if (mode == 0) CHECK(damping < -0.01 * std::abs(gap.net));
  }
}

TEST_CASE("contact jkr friction limit: mu_s times the repulsive part 4E*a^3/(3R*), not the net force; "
          "edem: none across a gap",
          "[contact][jkr][edem]") {
  const MaterialPair p = MaterialPair::of(mud(), mud());
  const double r = 2.5e-3, gamma = 0.48, mu = 0.15;
  const double L = JkrNormal(p.e_star, p.g_star, gamma, false).lengthScale(r);
  for (int mode = 0; mode < 2; ++mode) {
    for (double t : {1.1, 1.5, 3.0}) {
      const double a = L * t * t;
      const JkrPoint j = jkrAt(a, p.e_star, gamma, r);
      Chain c;
      c.add(std::make_unique<JkrNormal>(p.e_star, p.g_star, gamma, false, mode == 1))
          .add(std::make_unique<MindlinTangential>(mu, 1.0));
      ContactBatch& b = c.setup(1, 1e-5);
      setPair(b, 0, j.delta, 2 * r, 2 * r, 1e-3, 1e-3);
      b.vt[0] = Vec3(1.0, 0.0, 0.0);  // 10 μm per step: far beyond the elastic range
      for (int s = 0; s < 50; ++s) c.run();
      INFO("t = " << t << ", net " << j.net << " N, repulsive " << j.repulsive << " N");
      const double limit = mu * j.repulsive;
      if (mode == 1 && j.delta <= 0.0) {  // edem: no tangential spring across a gap (S_t = 0)
        CHECK(b.ft[0].norm() == 0.0);
        continue;
      }
      CHECK(b.ft[0].norm() == Approx(limit).epsilon(1e-8));
      // The net force (attractive for t³ < 3) would give a different limit: |μ F_net| ≠ μ F_rep.
      CHECK(std::abs(b.ft[0].norm() - mu * std::abs(j.net)) > 0.05 * limit);
    }
  }
}
