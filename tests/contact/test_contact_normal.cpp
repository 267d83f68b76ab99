// Normal-direction contact sub-models against closed-form results: Hertz force law, the
// Hertz-Mindlin damping (coefficient of restitution), JKR cohesion (quartic solution, the
// characteristic points of the force curve, cut-off, hysteresis and energy per cycle).
#include "contact_test_util.hpp"

#include <hertz_mindlin/hertz.hpp>
#include <hertz_mindlin/hertz_mindlin_damping.hpp>
#include <jkr/jkr.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace ctest;
using paddy::contact::HertzMindlinDamping;
using paddy::contact::HertzNormal;
using paddy::contact::JkrNormal;

namespace {

struct PairCase {
  const char* name;
  MaterialPair pair;
  double r_eff;
};
std::vector<PairCase> pairCases() {
  return {{"mud-mud", MaterialPair::of(mud(), mud()), 0.5e-3},
          {"mud-steel wall", MaterialPair::of(mud(), steel()), 1.0e-3},
          {"steel-steel", MaterialPair::of(steel(), steel()), 2.0e-3}};
}

// Reference JKR relations, written out independently of jkr.hpp.
struct JkrRef {
  double e, gamma, r;
  double force(double a) const {
    return -4.0 * std::sqrt(kPi * gamma * e) * std::pow(a, 1.5) + 4.0 * e / (3.0 * r) * a * a * a;
  }
  double overlap(double a) const { return a * a / r - std::sqrt(4.0 * kPi * gamma * a / e); }
  double termScale(double a) const { return a * a / r + std::sqrt(4.0 * kPi * gamma * a / e); }
  double L() const { return std::cbrt(kPi * gamma * r * r / e); }
  double ell() const { return L() * L() / r; }
  double ac() const { return std::cbrt(9.0 * kPi * gamma * r * r / (2.0 * e) * (0.75 - 1.0 / std::sqrt(2.0))); }
  double deltaC() const { return overlap(ac()); }
  // Stable-branch contact radius from Ferrari's closed form of t⁴ − 2t − d = 0 (a = L t²):
  // resolvent m³ + d m − 1/2 = 0 (Cardano, one real root for d > −1.1906), t = (s + sqrt(4/s − s²))/2,
  // s = sqrt(2m). Valid for moderate |d|.
  double ferrariRadius(double delta) const {
    const double d = delta / ell();
    const double disc = 1.0 / 16.0 + d * d * d / 27.0;
    const double m = std::cbrt(0.25 + std::sqrt(disc)) + std::cbrt(0.25 - std::sqrt(disc));
    const double s = std::sqrt(2.0 * m);
    const double t = 0.5 * (s + std::sqrt(4.0 / s - s * s));
    return L() * t * t;
  }
};

double runNormal(Chain& c, double overlap, double r_eff) {
  ContactBatch& b = c.setup(1);
  setPair(b, 0, overlap, 2.0 * r_eff, 2.0 * r_eff, 1.0, 1.0);
  c.run();
  return b.fn[0];
}

}  // namespace

TEST_CASE("contact hertz: effective moduli of the reference materials", "[contact][hertz]") {
  const MaterialPair mm = MaterialPair::of(mud(), mud());
  CHECK(mm.e_star == Approx(2.0e6).epsilon(1e-14));    // E = 3 MPa, (1−ν²)/E = 2.5e-7 per body
  CHECK(mm.g_star == Approx(1.0e6 / 3.0).epsilon(1e-14));  // (2−ν)/G = 1.5e-6 per body
  const MaterialPair ms = MaterialPair::of(mud(), steel());
  CHECK(ms.e_star == Approx(1.0 / (0.75 / 3.0e6 + 0.91 / 1.82e10)).epsilon(1e-14));
}

TEST_CASE("contact hertz: F_n = 4/3 E* sqrt(R*) d^1.5, a, S_n, S_t over decades", "[contact][hertz]") {
  for (const auto& pc : pairCases()) {
    Chain c;
    c.add(std::make_unique<HertzNormal>(pc.pair.e_star, pc.pair.g_star));
    const int n = 33;  // δ = 1e-12 ... 1e-4 m, four per decade
    ContactBatch& b = c.setup(n);
    for (int k = 0; k < n; ++k)
      setPair(b, k, std::pow(10.0, -12.0 + 0.25 * k), 2.0 * pc.r_eff, 2.0 * pc.r_eff, 1.0, 1.0);
    c.run();
    for (int k = 0; k < n; ++k) {
      INFO(pc.name << " overlap " << b.overlap[k]);
      const double d = b.overlap[k], a = std::sqrt(pc.r_eff * d);
      const double f = 4.0 / 3.0 * pc.pair.e_star * std::sqrt(pc.r_eff) * std::pow(d, 1.5);
      CHECK(b.fn[k] == Approx(f).epsilon(1e-13));
      CHECK(b.fn_friction[k] == b.fn[k]);
      CHECK(b.contact_radius[k] == Approx(a).epsilon(1e-14));
      CHECK(b.stiffness_n[k] == Approx(2.0 * pc.pair.e_star * a).epsilon(1e-14));
      CHECK(b.stiffness_t[k] == Approx(8.0 * pc.pair.g_star * a).epsilon(1e-14));
      CHECK(b.active[k] == 1);
    }
    // S_n is the derivative dF_n/dδ.
    const double d0 = 1e-6, h = 1e-12;
    const double slope = (runNormal(c, d0 + h, pc.r_eff) - runNormal(c, d0 - h, pc.r_eff)) / (2 * h);
    runNormal(c, d0, pc.r_eff);
    CHECK(slope == Approx(c.batch->stiffness_n[0]).epsilon(1e-6));
  }
  // No force and inactive at zero overlap or a gap.
  Chain c;
  c.add(std::make_unique<HertzNormal>(2e6, 1e6));
  for (double d : {0.0, -1e-9, -1e-3}) {
    CHECK(runNormal(c, d, 1e-3) == 0.0);
    CHECK(c.batch->active[0] == 0);
    CHECK(c.batch->stiffness_t[0] == 0.0);
  }
}

TEST_CASE("contact hertz_mindlin damping: normal force -2 sqrt(5/6) beta sqrt(S_n m*) v_n", "[contact][damping]") {
  const MaterialPair p = MaterialPair::of(mud(), mud());
  for (double e : {0.1, 0.5, 0.9, 1.0}) {
    Chain c;
    c.add(std::make_unique<HertzNormal>(p.e_star, p.g_star)).add(std::make_unique<HertzMindlinDamping>(e));
    ContactBatch& b = c.setup(2);
    setPair(b, 0, 1e-6, 1e-3, 1e-3, 7e-6, 7e-6);
    setPair(b, 1, -1e-6, 1e-3, 1e-3, 7e-6, 7e-6);  // gap: no damping
    b.vn[0] = b.vn[1] = -0.3;                          // approaching
    c.run();
    const double beta = std::log(e) / std::sqrt(std::log(e) * std::log(e) + kPi * kPi);
    const double sn = 2.0 * p.e_star * std::sqrt(0.5e-3 * 1e-6);
    const double elastic = 4.0 / 3.0 * p.e_star * std::sqrt(0.5e-3) * std::pow(1e-6, 1.5);
    // EDEM's coefficient −2 sqrt(5/6) β sqrt(S_n m*) ≥ 0 multiplies the approach speed: with
    // v_n > 0 separating and fn > 0 repulsive the damping force is −c_n v_n.
    const double cn = -2.0 * std::sqrt(5.0 / 6.0) * beta * std::sqrt(sn * 3.5e-6);
    const double damp = -cn * -0.3;
    CHECK(cn >= 0.0);
    CHECK(damp >= 0.0);  // resists approach: adds repulsion
    CHECK(b.fn[0] == Approx(elastic + damp).epsilon(1e-13));
    CHECK(b.fn_friction[0] == Approx(elastic).epsilon(1e-14));  // limits use the elastic force
    CHECK(b.fn[1] == 0.0);
  }
}

// Velocity Verlet with the half-step velocity in the damping (the engine's scheme) has an O(dt)
// error in e: at dt = t_c/100 e = 0.1 comes out 1.7 % low (0.098325), halving with dt. That is
// the integrator, not the formula; the bound is therefore checked at t_c/1000 (1 %) and, for the
// formula itself, at t_c/10000 (0.1 %). The t_c/100 figures are printed for the record.
TEST_CASE("contact hertz_mindlin: restitution of a binary collision within 1 %", "[contact][damping]") {
  const Material m = mud();
  const MaterialPair p = MaterialPair::of(m, m);
  const double r = 1e-3, mass = sphereMass(m, r);
  for (double e : {0.1, 0.5, 0.9}) {
    for (double v0 : {0.1, 1.0}) {
      for (double div : {100.0, 1000.0, 10000.0}) {
        Chain c;
        c.add(std::make_unique<HertzNormal>(p.e_star, p.g_star)).add(std::make_unique<HertzMindlinDamping>(e));
        const double tc = hertzContactTime(0.5 * mass, 0.5 * r, p.e_star, v0);
        const double dt = tc / div;
        const CollisionResult res = collide(c, r, mass, v0, dt, -2.0 * v0 * dt, 0.0);
        const double measured = res.v_rebound / v0;
        std::printf("[contact] restitution e=%.2f v0=%.1f m/s dt=t_c/%g: measured %.6f (rel. error %+.3e), %ld steps\n",
                    e, v0, div, measured, measured / e - 1.0, res.steps);
        if (div == 1000.0) CHECK(std::abs(measured / e - 1.0) < 0.01);
        if (div == 10000.0) CHECK(std::abs(measured / e - 1.0) < 0.001);
      }
    }
  }
}

TEST_CASE("contact jkr: gamma = 0 reduces to hertz exactly", "[contact][jkr]") {
  for (const auto& pc : pairCases()) {
    for (bool hyst : {false, true}) {
      Chain h, j;
      h.add(std::make_unique<HertzNormal>(pc.pair.e_star, pc.pair.g_star));
      j.add(std::make_unique<JkrNormal>(pc.pair.e_star, pc.pair.g_star, 0.0, hyst));
      CHECK(j.models[0]->maxSeparation(pc.r_eff) == 0.0);
      const int n = 40;
      ContactBatch& bh = h.setup(n);
      ContactBatch& bj = j.setup(n);
      for (int k = 0; k < n; ++k) {
        const double d = (k % 2 ? 1.0 : -1.0) * std::pow(10.0, -12.0 + 0.2 * k);
        setPair(bh, k, d, 2.0 * pc.r_eff, 2.0 * pc.r_eff, 1.0, 1.0);
        setPair(bj, k, d, 2.0 * pc.r_eff, 2.0 * pc.r_eff, 1.0, 1.0);
      }
      h.run();
      j.run();
      for (int k = 0; k < n; ++k) {
        CHECK(bj.fn[k] == bh.fn[k]);
        CHECK(bj.active[k] == bh.active[k]);
        CHECK(bj.contact_radius[k] == bh.contact_radius[k]);
        CHECK(bj.fn_friction[k] == bh.fn_friction[k]);
        CHECK(bj.stiffness_n[k] == bh.stiffness_n[k]);
        CHECK(bj.stiffness_t[k] == bh.stiffness_t[k]);
      }
    }
  }
}

TEST_CASE("contact jkr: a(delta) satisfies delta(a) to 1e-10 from delta_c to large overlaps", "[contact][jkr]") {
  double worst = 0.0;
  for (const auto& pc : pairCases()) {
    for (double gamma : {1e-6, 0.096, 1.0, 100.0}) {
      const JkrRef ref{pc.pair.e_star, gamma, pc.r_eff};
      const JkrNormal jkr(pc.pair.e_star, pc.pair.g_star, gamma, false);
      const double dc = ref.deltaC();
      CHECK(jkr.criticalOverlap(pc.r_eff) == Approx(dc).epsilon(1e-12));
      std::vector<double> deltas{dc, 0.0};
      for (int k = 0; k <= 200; ++k) deltas.push_back(dc * (1.0 - k / 200.0));  // δ_c … 0
      for (int k = 0; k <= 120; ++k) deltas.push_back(std::abs(dc) * std::pow(10.0, -6.0 + 0.1 * k));  // … 1e6|δ_c|
      for (double d : deltas) {
        const double a = jkr.contactRadius(d, pc.r_eff);
        const double err = std::abs(ref.overlap(a) - d) / std::max(std::abs(d), ref.termScale(a));
        worst = std::max(worst, err);
        INFO(pc.name << " gamma " << gamma << " delta " << d << " a " << a);
        CHECK(err < 1e-10);
        if (std::abs(d) > 1e-3 * std::abs(dc)) CHECK(std::abs(ref.overlap(a) - d) < 1e-10 * std::abs(d));
        CHECK(a >= std::cbrt(kPi * gamma * pc.r_eff * pc.r_eff / (4.0 * pc.pair.e_star)) * (1 - 1e-12));  // stable branch
      }
    }
  }
  std::printf("[contact] jkr a(delta): worst residual |delta(a) - delta| / scale = %.2e\n", worst);
}

TEST_CASE("contact jkr: solveScaled is the root of t^4 - 2t = d to rounding over the whole range", "[contact][jkr]") {
  // Reference: bisection in long double on [t_min, max(2, 2 |d|^(1/4))], where t⁴ − 2t − d is increasing.
  const long double t_min_l = 1.0L / std::cbrt(2.0L);
  auto reference = [&](double d) {
    const long double dl = d;
    long double lo = t_min_l, hi = std::max(2.0L, 2.0L * std::sqrt(std::sqrt(std::fabs(dl))));
    for (int i = 0; i < 200; ++i) {
      const long double mid = 0.5L * (lo + hi);
      if (mid == lo || mid == hi) break;
      (mid * mid * mid * mid - 2.0L * mid - dl > 0.0L ? hi : lo) = mid;
    }
    return 0.5L * (lo + hi);
  };
  const double d_min = JkrNormal::minimumOverlapScaled();
  std::vector<double> ds;
  for (int k = 1; k <= 16; ++k) ds.push_back(d_min + std::pow(10.0, -k));  // approach to the branch point
  for (int i = 0; i <= 200000; ++i) ds.push_back(d_min + (10.0 - d_min) * i / 200000.0);  // dense where contacts live
  for (double e = 1.0; e <= 150.0; e += 0.01) ds.push_back(std::pow(10.0, e));        // large d, up to 1e150
  // The batch solver (the one the force loop uses) on the same values, in batches of every length
  // from 1 to kCapacity in turn (a vector loop's tail is handled apart from its body).
  std::vector<double> tb(ds.size());
  for (std::size_t i = 0, len = 1; i < ds.size(); i += len, len = len % ContactBatch::kCapacity + 1)
    JkrNormal::solveScaledBatch(ds.data() + i, tb.data() + i, std::min(len, ds.size() - i));
  double worst_root = 0.0, worst_old = 0.0, worst_res = 0.0, worst_batch = 0.0;
  for (std::size_t n = 0; n < ds.size(); ++n) {
    const double d = ds[n];
    const double t = JkrNormal::solveScaled(d);
    const long double r = reference(d);
    const double x = d - d_min;
    // Allow for the conditioning of the root: a relative rounding error of ε in the terms of
    // t⁴ − 2t − d (the residual bound asserted below) moves the root by ε (t⁴ + 2t + |d|) / (t (4t³ − 2))
    // relative, which grows without bound at the branch point t_min (a backward-stable solver, FMA
    // or not, meets this; the rounding of d alone, |d| / (t (4t³ − 2)), is smaller by up to 3×).
    const long double terms = r * r * r * r + 2.0L * r + std::fabs(static_cast<long double>(d));
    const long double tol_rel = 4e-16L * (1.0L + terms / (r * (4.0L * r * r * r - 2.0L) + 1e-300L));
    const long double err = std::fabs(t - r) / r;
    worst_root = std::max(worst_root, double(err / tol_rel));
    INFO("d = " << d << " t = " << t << " ref = " << double(r) << " err " << double(err) << " tol " << double(tol_rel));
    REQUIRE(err <= tol_rel);
    const long double err_batch = std::fabs(tb[n] - r) / r;
    worst_batch = std::max(worst_batch, double(err_batch / tol_rel));
    INFO("batch: t = " << tb[n] << " err " << double(err_batch));
    REQUIRE(err_batch <= tol_rel);
    // Residual, relative to the size of its terms.
    const long double tl = t;
    const long double res = std::fabs(tl * tl * tl * tl - 2.0L * tl - d) / (tl * tl * tl * tl + 2.0L * tl + std::fabs(d));
    worst_res = std::max(worst_res, double(res));
    if (x > 1e-6) {
      REQUIRE(res <= 4e-16L);
      const double old = JkrNormal::solveScaledIterative(d);
      worst_old = std::max(worst_old, std::fabs(t - old) / old / double(tol_rel));
      INFO("d = " << d << " t = " << t << " old = " << old << " ref = " << double(r));
      REQUIRE(std::fabs(t - old) <= 2.0 * double(tol_rel) * old);  // both within the conditioning
    }
  }
  CHECK(JkrNormal::solveScaled(d_min) == Approx(double(t_min_l)).epsilon(1e-15));
  CHECK(JkrNormal::solveScaled(d_min - 1.0) == Approx(double(t_min_l)).epsilon(1e-15));
  const double below[3] = {d_min, d_min - 1.0, -1e300};
  double t_below[3];
  JkrNormal::solveScaledBatch(below, t_below, 3);
  for (const double t : t_below) CHECK(t == Approx(double(t_min_l)).epsilon(1e-15));
  std::printf("jkr solveScaled over %zu values of d: worst |t - t_ref| / tol %.3g (batch %.3g), worst relative residual %.3g, "
              "worst |t - t_old| / t / tol %.3g\n", ds.size(), worst_root, worst_batch, worst_res, worst_old);
}

TEST_CASE("contact jkr: characteristic points of the force curve", "[contact][jkr]") {
  const MaterialPair p = MaterialPair::of(mud(), mud());
  const double r = 0.5e-3, gamma = 0.096;
  const JkrRef ref{p.e_star, gamma, r};
  const double fc = kPi * gamma * r;  // πγR*
  Chain c;
  c.add(std::make_unique<JkrNormal>(p.e_star, p.g_star, gamma, false));
  ContactBatch& b = *c.batch;

  SECTION("zero force at a_0 = (9 pi gamma R*^2 / E*)^(1/3)") {
    const double a0 = std::cbrt(9.0 * kPi * gamma * r * r / p.e_star);
    const double f = runNormal(c, ref.overlap(a0), r);
    CHECK(std::abs(f) < 1e-10 * fc);
    CHECK(b.contact_radius[0] == Approx(a0).epsilon(1e-10));
    CHECK(b.fn_friction[0] == Approx(4.0 * p.e_star * a0 * a0 * a0 / (3.0 * r)).epsilon(1e-10));
    CHECK(b.stiffness_n[0] == Approx(2.0 * p.e_star * a0).epsilon(1e-10));
    CHECK(b.stiffness_t[0] == Approx(8.0 * p.g_star * a0).epsilon(1e-10));
  }
  SECTION("peak attraction 3 pi gamma R* at a^3 = 9 pi gamma R*^2 / (4 E*)") {
    const double ap = std::cbrt(9.0 * kPi * gamma * r * r / (4.0 * p.e_star));
    CHECK(runNormal(c, ref.overlap(ap), r) == Approx(-3.0 * fc).epsilon(1e-10));
    // ... and it is the minimum along the whole curve (fine scan from δ_c to 3|δ_c|).
    const double dc = ref.deltaC();
    double fmin = 0.0;
    for (int k = 0; k <= 200000; ++k) fmin = std::min(fmin, runNormal(c, dc + k * 4.0 * std::abs(dc) / 200000, r));
    CHECK(fmin == Approx(-3.0 * fc).epsilon(1e-8));
    CHECK(fmin >= -3.0 * fc * (1 + 1e-12));
  }
  SECTION("force at touch (delta = 0) is -8/3 pi gamma R*") {
    CHECK(runNormal(c, 0.0, r) == Approx(-8.0 / 3.0 * fc).epsilon(1e-12));
    CHECK(b.contact_radius[0] == Approx(std::cbrt(4.0 * kPi * gamma * r * r / p.e_star)).epsilon(1e-12));
  }
  SECTION("critical separation: EDEM a_c, the true fixed-grip pull-off point, cut-off") {
    // EDEM's a_c is the small-a (unstable-branch) point where F = -1.5 pi gamma R*.
    CHECK(ref.force(ref.ac()) == Approx(-1.5 * fc).epsilon(1e-12));
    // δ(a) is minimal at a_m^3 = pi gamma R*^2/(4E*) (fixed-grip JKR pull-off): F = -(5/9) 3 pi gamma R*.
    const double am = std::cbrt(kPi * gamma * r * r / (4.0 * p.e_star));
    CHECK(ref.force(am) == Approx(-5.0 / 9.0 * 3.0 * fc).epsilon(1e-12));
    CHECK(ref.ac() < am);
    const double dc = ref.deltaC();
    CHECK(dc > ref.overlap(am));  // δ_c lies just above the minimum of δ(a): one stable root
    CHECK(dc / ref.ell() == Approx(JkrNormal::criticalOverlapScaled()).epsilon(1e-12));
    CHECK(ref.overlap(am) / ref.ell() == Approx(-1.5 / std::cbrt(2.0)).epsilon(1e-12));
    CHECK(c.models[0]->maxSeparation(r) == Approx(-dc).epsilon(1e-12));
    // Just inside the cut-off: the stable-branch force (Ferrari closed form), about -1.832 pi gamma R*.
    const double in = dc * (1.0 - 1e-12);
    const double f_in = runNormal(c, in, r);
    CHECK(b.active[0] == 1);
    CHECK(f_in == Approx(ref.force(ref.ferrariRadius(dc))).epsilon(1e-8));
    CHECK(b.contact_radius[0] == Approx(ref.ferrariRadius(dc)).epsilon(1e-8));
    std::printf("[contact] jkr: delta_c = %.6f l, F(delta_c+) = %.6f pi gamma R*, a_c/a_m = %.6f\n",
                dc / ref.ell(), f_in / fc, ref.ac() / am);
    // Just outside: nothing.
    CHECK(runNormal(c, dc * (1.0 + 1e-12), r) == 0.0);
    CHECK(b.active[0] == 0);
    CHECK(b.fn_friction[0] == 0.0);
  }
}

namespace {
// Quasi-static cycle δ: lo → hi → lo with nodes at δ_c and 0, so the midpoint rule never samples
// a jump. The contact does work −F dδ on the relative motion, so the energy lost over the closed
// path is ∮ F dδ, returned as Σ F Δδ.
double cycleLoss(Chain& c, double r, double dc, double hi, int n) {
  ContactBatch& b = c.setup(1);
  setPair(b, 0, 0.0, 2.0 * r, 2.0 * r, 1.0, 1.0);
  const double lo = 1.5 * dc;
  const std::vector<double> nodes{lo, dc, 0.0, hi};
  double loss = 0.0;
  auto leg = [&](double from, double to) {
    const double h = (to - from) / n;
    for (int k = 0; k < n; ++k) {
      b.overlap[0] = from + (k + 0.5) * h;
      c.run();
      loss += b.fn[0] * h;  // work done BY the contact on the relative motion is −F dδ
    }
  };
  for (std::size_t s = 0; s + 1 < nodes.size(); ++s) leg(nodes[s], nodes[s + 1]);
  for (std::size_t s = nodes.size() - 1; s > 0; --s) leg(nodes[s], nodes[s - 1]);
  return loss;
}
}  // namespace

TEST_CASE("contact jkr: hysteretic variant snaps in at touch and releases at delta_c", "[contact][jkr]") {
  const MaterialPair p = MaterialPair::of(mud(), mud());
  const double r = 0.5e-3, gamma = 0.096, fc = kPi * gamma * r;
  const JkrRef ref{p.e_star, gamma, r};
  const double dc = ref.deltaC();
  Chain hy, ed;
  hy.add(std::make_unique<JkrNormal>(p.e_star, p.g_star, gamma, true));
  ed.add(std::make_unique<JkrNormal>(p.e_star, p.g_star, gamma, false));
  CHECK(hy.models[0]->historySize() == 1);
  CHECK(ed.models[0]->historySize() == 0);
  CHECK(hy.models[0]->maxSeparation(r) == Approx(-dc).epsilon(1e-12));
  ContactBatch& b = hy.setup(1);
  setPair(b, 0, 0.0, 2.0 * r, 2.0 * r, 1.0, 1.0);
  auto at = [&](double d) {
    b.overlap[0] = d;
    hy.run();
    return b.fn[0];
  };
  auto edem = [&](double d) { return runNormal(ed, d, r); };
  // Approach: nothing until touch, although the EDEM variant attracts there.
  CHECK(at(1.2 * dc) == 0.0);
  for (double d : {0.99 * dc, 0.5 * dc, 1e-6 * dc}) {
    CHECK(at(d) == 0.0);
    CHECK(b.active[0] == 0);
    CHECK(edem(d) < 0.0);
  }
  CHECK(at(0.0) == Approx(-8.0 / 3.0 * fc).epsilon(1e-12));  // snap-in
  // Loading and unloading follow the EDEM curve down to δ_c.
  for (double d : {0.5 * std::abs(dc), 5.0 * std::abs(dc), 0.3 * dc, 0.9 * dc, dc * (1 - 1e-12)}) {
    CHECK(at(d) == edem(d));
    CHECK(b.active[0] == 1);
  }
  CHECK(at(dc * (1 + 1e-12)) == 0.0);  // released
  CHECK(at(0.5 * dc) == 0.0);          // and stays released until the next touch
  CHECK(at(1e-9 * std::abs(dc)) < 0.0);
}

TEST_CASE("contact jkr: energy lost per quasi-static approach-separation cycle", "[contact][jkr]") {
  const MaterialPair p = MaterialPair::of(mud(), mud());
  const double r = 0.5e-3, gamma = 0.096;
  const JkrRef ref{p.e_star, gamma, r};
  const double dc = ref.deltaC();
  // Closed form: with a = L t², δ = ℓ(t⁴ − 2t), F = πγR*(4/3 t⁶ − 4t³),
  //   −∫_{δ_c}^{0} F dδ = πγL² [P(t_c) − P(t_0)],  P(t) = 8/15 t¹⁰ − 8/3 t⁷ + 2 t⁴,
  // t_0 = 2^{1/3} (δ = 0, P(t_0) = −12/5 · 2^{1/3}), t_c the stable root at δ_c (Ferrari).
  const double tc = std::sqrt(ref.ferrariRadius(dc) / ref.L());
  auto P = [](double t) { return 8.0 / 15.0 * std::pow(t, 10) - 8.0 / 3.0 * std::pow(t, 7) + 2.0 * std::pow(t, 4); };
  const double coef = P(tc) - (-12.0 / 5.0 * std::cbrt(2.0));
  const double w_closed = kPi * gamma * ref.L() * ref.L() * coef;
  Chain hy, ed;
  hy.add(std::make_unique<JkrNormal>(p.e_star, p.g_star, gamma, true));
  ed.add(std::make_unique<JkrNormal>(p.e_star, p.g_star, gamma, false));
  const double w_hyst = cycleLoss(hy, r, dc, 3.0 * std::abs(dc), 20000);
  const double w_edem = cycleLoss(ed, r, dc, 3.0 * std::abs(dc), 20000);
  std::printf("[contact] jkr cycle loss (mud-mud, R*=0.5 mm, gamma=0.096): closed form %.6e J (= %.5f pi gamma L^2), "
              "hysteretic %.6e J, EDEM %.3e J\n", w_closed, coef, w_hyst, w_edem);
  CHECK(coef == Approx(3.33397).epsilon(1e-5));
  CHECK(w_hyst == Approx(w_closed).epsilon(1e-8));
  CHECK(std::abs(w_edem) < 1e-10 * w_closed);
}

TEST_CASE("contact jkr: collision without damping conserves energy (EDEM variant)", "[contact][jkr]") {
  const Material m = mud();
  const MaterialPair p = MaterialPair::of(m, m);
  const double r = 1e-3, mass = sphereMass(m, r), gamma = 0.096, v0 = 1.0;
  const JkrRef ref{p.e_star, gamma, 0.5 * r};
  const double dc = ref.deltaC();
  const double tc = hertzContactTime(0.5 * mass, 0.5 * r, p.e_star, v0);
  const double dt = tc / 100000.0;
  Chain c;
  c.add(std::make_unique<JkrNormal>(p.e_star, p.g_star, gamma, false)).add(std::make_unique<HertzMindlinDamping>(1.0));
  const CollisionResult res = collide(c, r, mass, v0, dt, dc - 3.7 * v0 * dt, dc);
  const double rel = std::abs(res.ke_out - res.ke_in) / res.ke_in;
  std::printf("[contact] jkr EDEM collision, e=1, v0=%.1f m/s, dt=t_c/1e5: |dKE|/KE = %.2e (%ld steps)\n", v0, rel,
              res.steps);
  CHECK(rel < 1e-6);

  // The hysteretic variant loses the adhesion work of the cycle (a dynamic check of the closed form).
  Chain h;
  h.add(std::make_unique<JkrNormal>(p.e_star, p.g_star, gamma, true)).add(std::make_unique<HertzMindlinDamping>(1.0));
  const CollisionResult rh = collide(h, r, mass, v0, dt, dc - 3.7 * v0 * dt, dc);
  const double tcr = std::sqrt(ref.ferrariRadius(dc) / ref.L());
  const double coef = 8.0 / 15.0 * std::pow(tcr, 10) - 8.0 / 3.0 * std::pow(tcr, 7) + 2.0 * std::pow(tcr, 4) +
                      12.0 / 5.0 * std::cbrt(2.0);
  const double w_closed = kPi * gamma * ref.L() * ref.L() * coef;
  const double lost = rh.ke_in - rh.ke_out;
  std::printf("[contact] jkr hysteretic collision: KE lost %.6e J vs closed form %.6e J (%.2e of KE)\n", lost, w_closed,
              w_closed / res.ke_in);
  CHECK(lost == Approx(w_closed).epsilon(1e-3));
}
