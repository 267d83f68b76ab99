// Tangential (Mindlin) and rolling-resistance sub-models against closed-form results: spring
// stiffness, Coulomb cap, sliding deceleration μg and the 5/7 rolling speed, rolling stopping
// distances of EDEM type A and type C rolling friction.
#include "contact_test_util.hpp"

#include <hertz_mindlin/hertz.hpp>
#include <hertz_mindlin/hertz_mindlin_damping.hpp>
#include <hertz_mindlin/mindlin.hpp>
#include <rolling_friction/constant_torque.hpp>
#include <rolling_friction/elastic_plastic.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

using namespace ctest;
using paddy::contact::ConstantTorqueRolling;
using paddy::contact::ElasticPlasticRolling;
using paddy::contact::HertzMindlinDamping;
using paddy::contact::HertzNormal;
using paddy::contact::MindlinTangential;

namespace {
double kBeta(double e) { return std::log(e) / std::sqrt(std::log(e) * std::log(e) + kPi * kPi); }
}  // namespace

TEST_CASE("contact mindlin: spring stiffness 8 G* a, rotation, cap, damping, reset", "[contact][mindlin]") {
  const MaterialPair p = MaterialPair::of(mud(), steel());
  const double r = 1e-3, m = sphereMass(mud(), r), d = 1e-6, dt = 1e-6;
  const double a = std::sqrt(r * d), st = 8.0 * p.g_star * a;
  const double fn = 4.0 / 3.0 * p.e_star * a * d;

  SECTION("small displacement: F_t = -8 G* a xi, xi accumulates v_t dt") {
    Chain c;
    c.add(std::make_unique<HertzNormal>(p.e_star, p.g_star)).add(std::make_unique<MindlinTangential>(10.0, 1.0));
    ContactBatch& b = c.setup(1, dt);
    setPair(b, 0, d, r, kInf, m, kInf);
    b.vt[0] = Vec3(1e-4, -2e-4, 0.0);
    c.run();
    CHECK((b.ft[0] + st * b.vt[0] * dt).norm() < 1e-13 * b.ft[0].norm());
    CHECK(b.ft[0].norm() == Approx(8.0 * p.g_star * a * b.vt[0].norm() * dt).epsilon(1e-13));
    c.run();  // second step: displacement doubles
    CHECK((b.ft[0] + 2.0 * st * b.vt[0] * dt).norm() < 1e-13 * b.ft[0].norm());
    // Rotate the normal by 30°: the spring turns into the new tangent plane with its length.
    const double f_before = b.ft[0].norm();
    b.vt[0].setZero();
    b.normal[0] = Vec3(std::sin(kPi / 6), 0.0, std::cos(kPi / 6));
    c.run();
    CHECK(b.ft[0].norm() == Approx(f_before).epsilon(1e-13));
    CHECK(std::abs(b.ft[0].dot(b.normal[0])) < 1e-13 * f_before);
    // Losing contact clears the spring.
    b.overlap[0] = -1e-9;
    c.run();
    CHECK(b.ft[0].norm() == 0.0);
    b.overlap[0] = d;
    b.normal[0] = Vec3::UnitZ();
    c.run();
    CHECK(b.ft[0].norm() == 0.0);
  }
  SECTION("Coulomb cap on the total force; spring rescaled consistently") {
    const double mu = 0.3, e = 0.5;
    Chain c;
    c.add(std::make_unique<HertzNormal>(p.e_star, p.g_star)).add(std::make_unique<MindlinTangential>(mu, e));
    ContactBatch& b = c.setup(1, dt);
    setPair(b, 0, d, r, kInf, m, kInf);
    const double ct = 2.0 * std::sqrt(5.0 / 6.0) * std::abs(kBeta(e)) * std::sqrt(st * m);
    b.vt[0] = Vec3(1e-5, 0.0, 0.0);  // first step below the cap: spring + damping
    c.run();
    CHECK(b.ft[0].x() == Approx(-(st * 1e-5 * dt + ct * 1e-5)).epsilon(1e-13));
    b.vt[0] = Vec3(0.5, 0.0, 0.0);  // large step: capped
    c.run();
    CHECK(b.ft[0].norm() == Approx(mu * fn).epsilon(1e-13));
    CHECK(b.ft[0].x() < 0.0);
    // The spring alone holds the capped force: when sliding stops (v_t = 0) the force stays at
    // the cap against the former sliding direction (no reversal although c_t v_t >> mu F_n here).
    CHECK(ct * 0.5 > 10.0 * mu * fn);
    b.vt[0].setZero();
    c.run();
    CHECK(b.ft[0].x() == Approx(-mu * fn).epsilon(1e-12));
    // ... and unloads elastically: moving back by v dt takes S_t v dt off.
    b.vt[0] = Vec3(-1e-6, 0.0, 0.0);
    c.run();
    CHECK(b.ft[0].x() == Approx(-mu * fn + st * 1e-6 * dt + ct * 1e-6).epsilon(1e-10));
  }
}

namespace {
// One contact of the Mindlin law, written as the formula reads (Vec3 operations, branches, the
// shared rotateIntoPlane): the reference the batch loop of MindlinTangential must reproduce to rounding.
struct MindlinStep {
  Vec3 force = Vec3::Zero(), spring = Vec3::Zero();
  bool slides = false;
};
MindlinStep mindlinReference(Vec3 xi, const Vec3& n, const Vec3& vt, double st, double m_eff, double limit,
                             double factor, double dt) {
  paddy::contact::rotateIntoPlane(xi, n);
  xi += vt * dt;
  MindlinStep out;
  out.force = -st * xi - factor * std::sqrt(st * m_eff) * vt;
  out.spring = xi;
  if (out.force.norm() > limit) {
    out.slides = true;
    out.force *= limit / out.force.norm();
    out.spring = st > 0.0 ? Vec3(-out.force / st) : Vec3::Zero();
  }
  return out;
}
}  // namespace

TEST_CASE("contact mindlin: the batch loop is the law of each contact, for every batch length", "[contact][mindlin]") {
  // Batches of every length 1..128 (a vectorised loop's body and its scalar tail are separate
  // code) of random contacts in every regime: inactive (spring cleared, no force), sticking,
  // sliding (force at the cap, spring rescaled), no spring yet, a spring along the new normal
  // (cleared by the rotation), zero stiffness (no force; the spring still accumulates).
  const double mu = 0.4, e = 0.3, dt = 2e-6;
  const double factor = 2.0 * std::sqrt(5.0 / 6.0) * std::abs(kBeta(e));
  const MindlinTangential law(mu, e);
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto unit = [&] {
    Vec3 v;
    do v = Vec3(u(rng), u(rng), u(rng)); while (v.norm() < 0.1);
    return Vec3(v.normalized());
  };
  const Vec3 kBefore(0.25e-6, -0.5e-6, 1e-6);
  auto b = std::make_unique<ContactBatch>();
  std::vector<double> hist(3 * ContactBatch::kCapacity), before;
  int regimes[6] = {0, 0, 0, 0, 0, 0};  // inactive, sticks, slides, empty spring, parallel spring, S_t = 0
  double worst = 0.0;
  for (std::size_t len = 1; len <= ContactBatch::kCapacity; ++len) {
    b->n = len;
    b->dt = dt;
    b->setContiguousHistory(hist.data(), 3, len);
    for (std::size_t k = 0; k < len; ++k) {
      const int kind = static_cast<int>((k * 7 + len) % 6);
      b->normal[k] = unit();
      const double st = kind == 5 ? 0.0 : 1e4 * (1.5 + u(rng));
      Vec3 xi = 1e-6 * (1.2 + u(rng)) * unit();
      if (kind == 3) xi.setZero();
      if (kind == 4) {  // exactly along the new normal: the rotation cannot keep it
        b->normal[k] = (k % 2 ? 1.0 : -1.0) * Vec3::UnitZ();
        xi = Vec3(0.0, 0.0, 2e-7);
      }
      b->vt[k] = (kind == 2 ? 1.0 : 1e-3) * (1.1 + u(rng)) * unit();
      b->vt[k] -= b->vt[k].dot(b->normal[k]) * b->normal[k];
      b->active[k] = kind == 0 ? 0 : 1;
      b->stiffness_t[k] = st;
      b->m_eff[k] = 1e-5 * (1.5 + u(rng));
      b->fn_friction[k] = (kind == 2 ? 1e-4 : 1.0) * (1.5 + u(rng));
      b->ft[k] = kBefore;  // the law adds to the force of the sub-models before it
      hist[3 * k] = xi.x(), hist[3 * k + 1] = xi.y(), hist[3 * k + 2] = xi.z();
    }
    before = hist;
    law.compute(*b, 0);
    for (std::size_t k = 0; k < len; ++k) {
      const Vec3 xi0(before[3 * k], before[3 * k + 1], before[3 * k + 2]);
      const Vec3 spring(hist[3 * k], hist[3 * k + 1], hist[3 * k + 2]);
      const Vec3 added = b->ft[k] - kBefore;
      if (!b->active[k]) {
        ++regimes[0];
        CHECK(spring == Vec3::Zero());
        CHECK(added == Vec3::Zero());
        continue;
      }
      const double limit = mu * b->fn_friction[k];
      const MindlinStep ref = mindlinReference(xi0, b->normal[k], b->vt[k], b->stiffness_t[k], b->m_eff[k], limit, factor, dt);
      if (xi0 == Vec3::Zero()) ++regimes[3];
      if (xi0.cross(b->normal[k]).norm() == 0.0 && xi0 != Vec3::Zero()) ++regimes[4];
      if (b->stiffness_t[k] == 0.0) ++regimes[5];
      ++regimes[ref.slides ? 2 : 1];
      // Rounding: a few ulps of the force's scale (the sum ft + f adds the ulp of |kBefore|).
      const double scale_f = ref.force.norm() + kBefore.norm(), scale_x = ref.spring.norm() + 1e-300;
      const double err_f = (added - ref.force).norm() / scale_f, err_x = (spring - ref.spring).norm() / scale_x;
      worst = std::max({worst, err_f, err_x});
      CHECK(err_f < 1e-14);
      CHECK(err_x < 1e-13);
      if (ref.slides) CHECK(std::abs(added.norm() - limit) < 1e-14 * scale_f);
    }
  }
  std::printf("[contact] mindlin batch: worst relative difference to the per-contact law %.2e; inactive %d, "
              "sticking %d, sliding %d, empty spring %d, parallel spring %d, S_t = 0 %d\n", worst, regimes[0], regimes[1],
              regimes[2], regimes[3], regimes[4], regimes[5]);
  for (int r : regimes) CHECK(r > 100);
}

TEST_CASE("contact mindlin: sliding sphere decelerates at mu g and rolls at 5/7 v0", "[contact][mindlin]") {
  const Material mat = mud();
  const MaterialPair p = MaterialPair::of(mat, steel());
  const double r = 1e-3, m = sphereMass(mat, r), mu = 0.3, v0 = 0.5, dt = 1e-6;
  Chain c;
  c.add(std::make_unique<HertzNormal>(p.e_star, p.g_star))
      .add(std::make_unique<HertzMindlinDamping>(0.5))
      .add(std::make_unique<MindlinTangential>(mu, 0.5));
  const double d0 = hertzRestingOverlap(p.e_star, r, m);
  SphereOnWall s(c, r, m, d0);
  s.v = Vec3(v0, 0.0, 0.0);
  const double lever = r - 0.5 * d0;
  const double q = s.inertia / (m * lever * lever);  // I / (m r_c²)
  const double t_slide = v0 / (mu * kG * (1.0 + 1.0 / q));
  const double t1 = 0.2 * t_slide, t2 = 0.8 * t_slide;
  double v1 = 0.0, v2 = 0.0;
  const long n = static_cast<long>(3.0 * t_slide / dt);
  for (long k = 1; k <= n; ++k) {
    s.step(dt);
    if (k == static_cast<long>(t1 / dt)) v1 = s.v.x();
    if (k == static_cast<long>(t2 / dt)) v2 = s.v.x();
  }
  const double decel = (v1 - v2) / ((static_cast<long>(t2 / dt) - static_cast<long>(t1 / dt)) * dt);
  const double v_final = v0 / (1.0 + q);  // angular momentum about the contact point is conserved
  std::printf("[contact] sliding sphere: deceleration %.6f m/s^2 (mu g = %.6f, rel %+.2e); final speed %.6f v0 "
              "(5/7 = %.6f; with lever R-d/2: %.6f)\n", decel, mu * kG, decel / (mu * kG) - 1.0, s.v.x() / v0,
              5.0 / 7.0, v_final / v0);
  CHECK(decel == Approx(mu * kG).epsilon(1e-4));
  CHECK(s.v.x() == Approx(v_final).epsilon(1e-4));
  CHECK(s.v.x() / v0 == Approx(5.0 / 7.0).epsilon(1e-3));
  CHECK(s.w.y() * lever == Approx(s.v.x()).epsilon(1e-4));  // rolling without slip
}

TEST_CASE("contact constant_torque: resisting torques mu_r F_n R_i and mu_r F_n R_j", "[contact][rolling]") {
  const MaterialPair p = MaterialPair::of(mud(), mud());
  Chain c;
  c.add(std::make_unique<HertzNormal>(p.e_star, p.g_star)).add(std::make_unique<ConstantTorqueRolling>(0.125));
  ContactBatch& b = c.setup(4);
  const double d = 2e-6;
  setPair(b, 0, d, 1e-3, 2e-3, 1e-5, 8e-5);  // particle pair, different radii
  b.omega_i[0] = Vec3(3.0, -4.0, 0.0);
  b.omega_j[0] = Vec3(0.0, 0.0, 2.0);
  setPair(b, 1, d, 1e-3, kInf, 1e-5, kInf);  // wall: j gets nothing
  b.omega_i[1] = Vec3(0.0, 7.0, 0.0);
  setPair(b, 2, d, 1e-3, 1e-3, 1e-5, 1e-5);  // not rotating: the same (the limit holds a body at rest)
  setPair(b, 3, -d, 1e-3, 1e-3, 1e-5, 1e-5);  // no contact
  b.omega_i[3] = Vec3(1.0, 0.0, 0.0);
  c.run();
  const double f0 = b.fn_friction[0];
  REQUIRE(f0 > 0.0);
  CHECK(b.resist_i[0] == Approx(0.125 * f0 * (1e-3 - d / 2)).epsilon(1e-14));
  CHECK(b.resist_j[0] == Approx(0.125 * f0 * (2e-3 - d / 2)).epsilon(1e-14));
  CHECK(b.resist_i[1] == Approx(0.125 * b.fn_friction[1] * (1e-3 - d / 2)).epsilon(1e-14));
  CHECK(b.resist_j[1] == 0.0);
  CHECK(b.resist_i[2] == Approx(0.125 * b.fn_friction[2] * (1e-3 - d / 2)).epsilon(1e-14));
  CHECK(b.resist_i[3] == 0.0);
  CHECK(b.resist_j[3] == 0.0);
  for (int k = 0; k < 4; ++k) {  // nothing explicit: the engine applies the resistance
    CHECK(b.torque_i[k].norm() == 0.0);
    CHECK(b.torque_j[k].norm() == 0.0);
  }
}

TEST_CASE("contact elastic_plastic: rolling spring, damping, limit, inertia", "[contact][rolling]") {
  const MaterialPair p = MaterialPair::of(mud(), mud());
  const double r = 1e-3, m = 7e-6, d = 2e-6, dt = 1e-6, mu_r = 0.125, zeta = 0.3;
  // Ai et al. I_r: wall 1.4 m R², equal spheres [2/(1.4 m R²)]^-1 = 0.7 m R² (m* = m/2).
  CHECK(ElasticPlasticRolling::rollingInertia(m, r, kInf) == Approx(1.4 * m * r * r).epsilon(1e-14));
  CHECK(ElasticPlasticRolling::rollingInertia(0.5 * m, r, r) == Approx(0.7 * m * r * r).epsilon(1e-14));
  const double m2 = 8.0 * m;  // radius 2r, same density
  CHECK(ElasticPlasticRolling::rollingInertia(m * m2 / (m + m2), r, 2 * r) ==
        Approx(1.0 / (1.0 / (1.4 * m * r * r) + 1.0 / (1.4 * m2 * 4 * r * r))).epsilon(1e-13));

  Chain c;
  c.add(std::make_unique<HertzNormal>(p.e_star, p.g_star)).add(std::make_unique<ElasticPlasticRolling>(mu_r, zeta));
  ContactBatch& b = c.setup(1, dt);
  setPair(b, 0, d, r, r, m, m);
  b.omega_i[0] = Vec3(2.0, 0.0, 5.0);  // z (twisting) part is not rolling
  b.omega_j[0] = Vec3(-1.0, 0.0, 0.0);
  c.run();
  const double re = 0.5 * r, sn = 2.0 * p.e_star * std::sqrt(re * d);
  const double kr = 2.25 * sn * mu_r * mu_r * re * re;
  const double eta = 2.0 * zeta * std::sqrt(0.7 * m * r * r * kr);
  const Vec3 wr(3.0, 0.0, 0.0);
  const Vec3 expect = -kr * wr * dt - eta * wr;
  CHECK((b.torque_i[0] - expect).norm() < 1e-12 * expect.norm());
  CHECK((b.torque_j[0] + b.torque_i[0]).norm() == 0.0);
  // Drive to full mobilisation: |M| = mu_r R* F_n, no damping.
  b.omega_i[0] = Vec3(2000.0, 0.0, 0.0);
  for (int k = 0; k < 50; ++k) c.run();
  const double limit = mu_r * re * b.fn_friction[0];
  CHECK(b.torque_i[0].norm() == Approx(limit).epsilon(1e-13));
  CHECK(b.torque_i[0].x() < 0.0);
  // Unloading from the limit is elastic: reversing the rotation for one step takes k_r ω dt off.
  b.omega_i[0] = Vec3(-1.0, 0.0, 0.0);
  b.omega_j[0].setZero();
  c.run();
  CHECK(b.torque_i[0].x() == Approx(-limit + kr * 1.0 * dt + eta * 1.0).epsilon(1e-12));
  b.overlap[0] = -1e-9;  // contact lost: history cleared
  c.run();
  b.overlap[0] = d;
  b.omega_i[0].setZero();
  c.run();
  CHECK(b.torque_i[0].norm() == 0.0);
}

namespace {
// A sphere rolling on a steel plate with initial speed v0 (and ω0 = v0/r_c); returns the distance
// travelled until v first reaches zero.
double stoppingDistance(std::unique_ptr<paddy::SubModel> rolling, double v0, double dt, double* lever_out,
                        double* fn_out) {
  const Material mat = mud();
  const MaterialPair p = MaterialPair::of(mat, steel());
  const double r = 1e-3, m = sphereMass(mat, r);
  Chain c;
  c.add(std::make_unique<HertzNormal>(p.e_star, p.g_star))
      .add(std::make_unique<HertzMindlinDamping>(0.3))
      .add(std::make_unique<MindlinTangential>(0.5, 0.3))
      .add(std::move(rolling));
  const double d0 = hertzRestingOverlap(p.e_star, r, m);
  SphereOnWall s(c, r, m, d0);
  const double lever = r - 0.5 * d0;
  s.v = Vec3(v0, 0.0, 0.0);
  s.w = Vec3(0.0, v0 / lever, 0.0);
  for (long k = 0; k < 100000000 && s.v.x() > 0.0; ++k) s.step(dt);
  *lever_out = lever;
  *fn_out = c.batch->fn_friction[0];
  return s.x.x();
}
}  // namespace

TEST_CASE("contact rolling: stopping distance of a rolling sphere, type A and type C", "[contact][rolling]") {
  const Material mat = mud();
  const double r = 1e-3, m = sphereMass(mat, r), inertia = 0.4 * m * r * r;
  const double mu_r = 0.1, v0 = 0.1, dt = 1e-6;
  double lever = 0.0, fn = 0.0;

  // Type A: torque μ_r F_n r_c about the rolling axis; rolling without slip gives
  //   a = μ_r m g r_c² / (I + m r_c²)  (= 5/7 μ_r g for r_c = R).
  const double dist_a = stoppingDistance(std::make_unique<ConstantTorqueRolling>(mu_r), v0, dt, &lever, &fn);
  const double acc_a = mu_r * m * kG * lever * lever / (inertia + m * lever * lever);
  const double exp_a = v0 * v0 / (2.0 * acc_a);
  std::printf("[contact] rolling type A: distance %.7e m, closed form %.7e m (rel %+.2e); 5/7 mu_r g form %.7e m\n",
              dist_a, exp_a, dist_a / exp_a - 1.0, v0 * v0 / (2.0 * 5.0 / 7.0 * mu_r * kG));
  CHECK(dist_a == Approx(exp_a).epsilon(2e-4));
  CHECK(dist_a == Approx(v0 * v0 / (2.0 * 5.0 / 7.0 * mu_r * kG)).epsilon(2e-3));

  // Type C at full mobilisation: torque μ_r R* F_n (R* = R for a wall):
  //   a = μ_r m g R r_c / (I + m r_c²).
  // Elastic phase: the spring loads from 0 to M_m = μ_r R F_n over the rotation θ_e = M_m / k_r.
  // Its viscous torque −η_r ω_r (not capped, Ai et al.) gives the angular impulse
  // ∫η_r ω_r dt = η_r θ_e exactly, i.e. a speed loss Δv = η_r θ_e r_c / (I + m r_c²); the
  // softer start adds at most the rolling distance r_c θ_e. With time steps the damping acts on
  // every step of the elastic phase but the last (the one that reaches the limit), so the
  // damped rotation lies in [θ_e − ω0 dt, θ_e]. Hence, with Δv± from these two rotations,
  //   (v0 − Δv+)² / (2a) ≤ distance ≤ (v0 − Δv−)² / (2a) + r_c θ_e   (± 2e-4 time-step error).
  const MaterialPair ps = MaterialPair::of(mat, steel());
  for (double zeta : {0.0, 0.3}) {
    const double dist_c = stoppingDistance(std::make_unique<ElasticPlasticRolling>(mu_r, zeta), v0, dt, &lever, &fn);
    const double acc_c = mu_r * m * kG * r * lever / (inertia + m * lever * lever);
    const double d0 = 2.0 * (r - lever);
    const double kr = 2.25 * 2.0 * ps.e_star * std::sqrt(r * d0) * mu_r * mu_r * r * r;
    const double theta_e = mu_r * r * m * kG / kr;
    const double eta = 2.0 * zeta * std::sqrt(1.4 * m * r * r * kr);
    const double dv = eta * theta_e * lever / (inertia + m * lever * lever);
    const double dv_min = eta * (theta_e - v0 / lever * dt) * lever / (inertia + m * lever * lever);
    const double exp_c = (v0 - dv) * (v0 - dv) / (2.0 * acc_c);
    const double exp_c_max = (v0 - dv_min) * (v0 - dv_min) / (2.0 * acc_c);
    std::printf("[contact] rolling type C (zeta=%.1f): distance %.7e m, closed form %.7e m (rel %+.2e), "
                "elastic allowance %.2e m, damping speed loss %.3e v0\n",
                zeta, dist_c, exp_c, dist_c / exp_c - 1.0, lever * theta_e, dv / v0);
    CHECK(dist_c >= exp_c * (1.0 - 2e-4));
    CHECK(dist_c <= exp_c_max * (1.0 + 2e-4) + lever * theta_e);
    if (zeta == 0.0) CHECK(dist_c == Approx(v0 * v0 / (2.0 * 5.0 / 7.0 * mu_r * kG)).epsilon(2e-3));
  }
}
