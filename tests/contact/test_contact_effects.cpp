// The candidate physical effects (plugins/contact/{liquid_bridge,lubrication,plastic_adhesion})
// against their closed forms, their order in a contact law, and the capability refusals.
//   liquid bridge:    Willett et al. 2000, F = 2πRγ cosθ/(1 + 1.05ŝ + 2.5ŝ²), ŝ = s sqrt(R/V),
//                     R = 2R*; rupture (1 + θ/2) V^(1/3) (Lian et al. 1993)
//   lubrication:      F_n = −6πμR*² v_n/h, F_t = −6πμR* (8/15) ln(R*/h) v_t (Reynolds; Goldman,
//                     Cox & Brenner 1967), h = max(gap, h_min), coefficients ≤ m*/(12 dt)
//   plastic adhesion: A = λ F_max, F = A in contact, A (1 + δ/s_c) across the bonded gap
#include "contact_test_util.hpp"

#include "contact_law.hpp"

#include <hertz_mindlin/hertz.hpp>
#include <liquid_bridge/liquid_bridge.hpp>
#include <lubrication/lubrication.hpp>
#include <plastic_adhesion/plastic_adhesion.hpp>

#include <paddy/errors.hpp>
#include <paddy/measure/coarse_graining.hpp>
#include <paddy/plugin_manager.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

using namespace ctest;
using paddy::contact::HertzNormal;
using paddy::contact::LiquidBridge;
using paddy::contact::Lubrication;
using paddy::contact::PlasticAdhesion;

namespace {

const double kR = 1e-3;  // sphere radius [m]
const MaterialPair kMud = MaterialPair::of(mud(), mud());

std::shared_ptr<paddy::PluginManager> shipped() {
  static auto pm = [] {
    auto m = std::make_shared<paddy::PluginManager>();
    m->loadDefault();
    return m;
  }();
  return pm;
}

// Willett et al. (2000) written out for equal spheres of radius R at full separation s.
double willett(double R, double gamma, double theta, double V, double s) {
  const double x = (s / 2.0) * std::sqrt(R / V);
  return 2.0 * kPi * R * gamma * std::cos(theta) / (1.0 + 2.1 * x + 10.0 * x * x);
}

}  // namespace

TEST_CASE("contact/liquid_bridge: Willett force between equal spheres and a sphere and a plate, rupture at Lian's distance",
          "[contact][effects]") {
  const double V = 0.05 * 4.0 / 3.0 * kPi * kR * kR * kR, gamma = 0.072, theta_deg = 30.0;
  const double theta = theta_deg * kPi / 180.0;
  Chain chain;
  chain.add(std::make_unique<LiquidBridge>(V, gamma, theta_deg));
  ContactBatch& b = chain.setup(1);
  const double m = sphereMass(mud(), kR);
  const double s_c = (1.0 + theta / 2.0) * std::cbrt(V);
  REQUIRE(chain.models[0]->maxSeparation(kR / 2) == Approx(s_c).epsilon(1e-15));

  // Approaching from a gap without having touched: no bridge yet.
  setPair(b, 0, -0.5 * s_c, kR, kR, m, m);
  chain.run();
  CHECK(b.fn[0] == 0.0);
  // Touch: F(0) = 2πRγ cosθ (R = 2R* = R for equal spheres).
  setPair(b, 0, 1e-7, kR, kR, m, m);
  chain.run();
  CHECK(b.fn[0] == Approx(-2.0 * kPi * kR * gamma * std::cos(theta)).epsilon(1e-14));
  // Separating: Willett's force at each gap, until the rupture distance.
  for (double frac : {0.01, 0.1, 0.3, 0.6, 0.99}) {
    setPair(b, 0, -frac * s_c, kR, kR, m, m);
    chain.run();
    CHECK(b.fn[0] == Approx(-willett(kR, gamma, theta, V, frac * s_c)).epsilon(1e-13));
  }
  setPair(b, 0, -1.01 * s_c, kR, kR, m, m);
  chain.run();
  CHECK(b.fn[0] == 0.0);
  // Ruptured: coming back inside s_c does not re-form it.
  setPair(b, 0, -0.5 * s_c, kR, kR, m, m);
  chain.run();
  CHECK(b.fn[0] == 0.0);

  // Sphere–plate (R_j = ∞, R* = R): F(0) = 4πRγ cosθ.
  setPair(b, 0, 1e-7, kR, kInf, m, kInf);
  chain.run();
  CHECK(b.fn[0] == Approx(-4.0 * kPi * kR * gamma * std::cos(theta)).epsilon(1e-14));
  // Its largest stiffness, 1.05 F(0) sqrt(2R*/V), matches a finite difference at s = 0.
  const LiquidBridge lb(V, gamma, theta_deg);
  const double ds = 1e-12;
  CHECK(lb.stiffnessBound(kR / 2) == Approx((lb.force(kR / 2, 0.0) - lb.force(kR / 2, ds)) / ds).epsilon(1e-4));
}

TEST_CASE("contact/lubrication: Reynolds normal and log tangential force, regularised and capped at m*/(12 dt)",
          "[contact][effects]") {
  const double mu = 0.5, hmin = 0.01, hcut = 0.1;
  Chain chain;
  chain.add(std::make_unique<Lubrication>(mu, hmin, hcut));
  ContactBatch& b = chain.setup(1);
  const double m = sphereMass(mud(), kR), rs = kR / 2;
  CHECK(chain.models[0]->maxSeparation(rs) == Approx(hcut * rs));
  const double vn = -0.01;
  const Vec3 vt(0.02, 0.0, 0.0);
  for (double h : {0.02 * rs, 0.05 * rs, 0.09 * rs}) {
    setPair(b, 0, -h, kR, kR, m, m);
    b.vn[0] = vn;
    b.vt[0] = vt;
    chain.run();
    // Two equal spheres: 6πμ(R/2)² v/h = 3/2 πμR² v/h.
    CHECK(b.fn[0] == Approx(1.5 * kPi * mu * kR * kR * (-vn) / h).epsilon(1e-14));
    CHECK(b.ft[0].x() == Approx(-6.0 * kPi * mu * rs * (8.0 / 15.0) * std::log(rs / h) * vt.x()).epsilon(1e-14));
  }
  // Below the minimum gap, and in contact, the film is h_min thick.
  setPair(b, 0, 1e-6, kR, kR, m, m);
  b.vn[0] = vn;
  chain.run();
  CHECK(b.fn[0] == Approx(1.5 * kPi * mu * kR * kR * (-vn) / (hmin * rs)).epsilon(1e-14));
  // Beyond the cut-off nothing.
  setPair(b, 0, -1.01 * hcut * rs, kR, kR, m, m);
  b.vn[0] = vn;
  chain.run();
  CHECK(b.fn[0] == 0.0);
  // Separating pulls (resists separation); sphere–plate 6πμR² v/h.
  setPair(b, 0, -0.05 * kR, kR, kInf, m, kInf);
  b.vn[0] = 0.01;
  chain.run();
  CHECK(b.fn[0] == Approx(-6.0 * kPi * mu * kR * kR * 0.01 / (0.05 * kR)).epsilon(1e-14));
  // With a step, each coefficient is at most m*/(12 dt): a large step sees exactly that.
  const double dt = 1.0;
  chain.setup(1, dt);
  setPair(b, 0, 1e-6, kR, kR, m, m);
  b.vn[0] = vn;
  b.vt[0] = vt;
  chain.run();
  CHECK(b.fn[0] == Approx(-(0.5 * m / (12.0 * dt)) * vn).epsilon(1e-14));
  CHECK(b.ft[0].x() == Approx(-(0.5 * m / (12.0 * dt)) * vt.x()).epsilon(1e-14));
}

TEST_CASE("contact/plastic_adhesion: pull-off grows with the largest load, softens across the bonded gap, breaks at s_c",
          "[contact][effects]") {
  const double lambda = 0.4, kappa = 0.05;
  Chain chain;
  chain.add(std::make_unique<HertzNormal>(kMud.e_star, kMud.g_star));
  chain.add(std::make_unique<PlasticAdhesion>(lambda, kappa));
  ContactBatch& b = chain.setup(1);
  const double m = sphereMass(mud(), kR), rs = kR / 2;
  auto hertz = [&](double d) { return 4.0 / 3.0 * kMud.e_star * std::sqrt(rs) * std::pow(d, 1.5); };
  // Load to δ1, then to a smaller δ2: the pull-off stays λ F(δ1).
  const double d1 = 2e-6, d2 = 0.5e-6;
  setPair(b, 0, d1, kR, kR, m, m);
  chain.run();
  CHECK(b.fn[0] == Approx(hertz(d1) * (1.0 - lambda)).epsilon(1e-12));
  CHECK(b.fn_friction[0] == Approx(hertz(d1) * (1.0 + lambda)).epsilon(1e-12));
  setPair(b, 0, d2, kR, kR, m, m);
  chain.run();
  CHECK(b.fn[0] == Approx(hertz(d2) - lambda * hertz(d1)).epsilon(1e-12));
  // Across the gap (s_c = min(δ1, κR*) = δ1 here): linear softening, active with S_n = A/s_c.
  const double s_c = std::min(d1, kappa * rs);
  for (double frac : {0.1, 0.5, 0.9}) {
    setPair(b, 0, -frac * s_c, kR, kR, m, m);
    chain.run();
    CHECK(b.fn[0] == Approx(-lambda * hertz(d1) * (1.0 - frac)).epsilon(1e-12));
    CHECK(b.active[0] == 1);
    CHECK(b.stiffness_n[0] == Approx(lambda * hertz(d1) / s_c).epsilon(1e-12));
  }
  setPair(b, 0, -1.01 * s_c, kR, kR, m, m);
  chain.run();
  CHECK(b.fn[0] == 0.0);
  CHECK(b.active[0] == 0);
  // Broken: back inside the old range, nothing until the surfaces touch again.
  setPair(b, 0, -0.5 * s_c, kR, kR, m, m);
  chain.run();
  CHECK(b.fn[0] == 0.0);
}

TEST_CASE("contact/effects: at strength 0 an effect keeps no history, reaches no further and changes no bit",
          "[contact][effects]") {
  Chain with, without;
  with.add(std::make_unique<HertzNormal>(kMud.e_star, kMud.g_star));
  without.add(std::make_unique<HertzNormal>(kMud.e_star, kMud.g_star));
  with.add(std::make_unique<LiquidBridge>(0.0, 0.072, 0.0));
  with.add(std::make_unique<Lubrication>(0.0, 0.01, 0.1));
  with.add(std::make_unique<PlasticAdhesion>(0.0, 0.05));
  for (std::size_t s = 1; s < with.models.size(); ++s) {
    CHECK(with.models[s]->historySize() == 0);
    CHECK(with.models[s]->maxSeparation(kR) == 0.0);
  }
  const double m = sphereMass(mud(), kR);
  for (double d : {-1e-5, 0.0, 3e-7, 2e-6}) {
    for (Chain* c : {&with, &without}) {
      ContactBatch& b = c->setup(1, 1e-6);
      setPair(b, 0, d, kR, kR, m, m);
      b.vn[0] = -0.3;
      b.vt[0] = Vec3(0.1, 0.0, 0.0);
      c->run();
    }
    CHECK(std::memcmp(&with.batch->fn[0], &without.batch->fn[0], sizeof(double)) == 0);
    CHECK(with.batch->ft[0] == without.batch->ft[0]);
    CHECK(with.batch->fn_friction[0] == without.batch->fn_friction[0]);
  }
}

TEST_CASE("contact/law order: a normal-force extra runs before tangential, so it raises the Coulomb limit",
          "[contact][effects]") {
  paddy::InteractionSpec spec;
  spec.normal = "hertz";
  spec.damping = "hertz_mindlin";
  spec.tangential = "mindlin";
  spec.extras = {"plastic_adhesion"};
  const double mu = 0.3, lambda = 0.5;
  spec.params = {{"restitution", 0.5}, {"friction", mu}, {"plastic_adhesion", lambda}};
  const paddy::ContactLaw law(*shipped(), spec, kMud);
  CHECK(law.description() == "normal:hertz + extra:plastic_adhesion + damping:hertz_mindlin + tangential:mindlin");
  auto batch = std::make_unique<ContactBatch>();
  std::vector<double> history(law.historySize(), 0.0);
  ContactBatch& b = *batch;
  b.n = 1;
  b.dt = 1e-6;
  b.setContiguousHistory(history.data(), law.historySize(), 1);
  const double m = sphereMass(mud(), kR), d = 2e-6;
  setPair(b, 0, d, kR, kR, m, m);
  b.normal[0] = Vec3::UnitZ();
  b.vn[0] = 0.0;
  b.vt[0] = Vec3(1.0, 0.0, 0.0);  // a fast slip: the tangential force sits on the Coulomb limit
  b.omega_i[0].setZero();
  b.omega_j[0].setZero();
  law.compute(b);
  const double f_h = 4.0 / 3.0 * kMud.e_star * std::sqrt(kR / 2) * std::pow(d, 1.5);
  CHECK(b.fn[0] == Approx(f_h * (1.0 - lambda)).epsilon(1e-12));
  CHECK(b.ft[0].norm() == Approx(mu * f_h * (1.0 + lambda)).epsilon(1e-12));
}

TEST_CASE("contact/law capabilities: an incompatible chain is refused at set-up naming both sub-models",
          "[contact][effects]") {
  paddy::PluginManager pm;
  pm.loadDefault();
  // A second fluid model: lubrication refuses another viscous fluid force.
  paddy::SubModelInfo film{"test_film_drag", paddy::SubModelKind::Extra, "test double", {},
                           [](const paddy::ParamValues&, const MaterialPair&) -> std::unique_ptr<SubModel> {
                             return std::make_unique<Lubrication>(0.0, 0.01, 0.1);
                           },
                           paddy::kNormalForce | paddy::kViscousFluidForce};
  pm.addSubModel(film);
  // A normal model that sets no contact state or stiffness: damping and friction cannot work.
  paddy::SubModelInfo bare{"test_bare_normal", paddy::SubModelKind::Normal, "test double", {},
                           [](const paddy::ParamValues&, const MaterialPair& p) -> std::unique_ptr<SubModel> {
                             return std::make_unique<HertzNormal>(p.e_star, p.g_star);
                           },
                           paddy::kNormalForce};
  pm.addSubModel(bare);

  paddy::InteractionSpec spec;
  spec.params = {{"restitution", 0.5}, {"friction", 0.3}};
  spec.extras = {"lubrication", "test_film_drag"};
  CHECK_THROWS_WITH(paddy::ContactLaw(pm, spec, kMud),
                    Catch::Contains("extra 'lubrication' cannot be combined with extra 'test_film_drag'") &&
                        Catch::Contains("viscous fluid force"));
  spec.extras = {"lubrication", "lubrication"};
  CHECK_THROWS_WITH(paddy::ContactLaw(pm, spec, kMud), Catch::Contains("'lubrication' appears twice"));
  spec.extras = {};
  spec.normal = "test_bare_normal";
  CHECK_THROWS_WITH(paddy::ContactLaw(pm, spec, kMud),
                    Catch::Contains("damping 'hertz_mindlin' needs contact state") &&
                        Catch::Contains("normal 'test_bare_normal' provides normal force"));
  // The shipped effects combine with the shipped chain.
  spec.normal = "jkr";
  spec.params["surface_energy"] = 0.1;
  spec.extras = {"liquid_bridge", "lubrication", "plastic_adhesion"};
  spec.params["bridge_volume"] = 1e-10;
  spec.params["lubrication_viscosity"] = 0.1;
  spec.params["plastic_adhesion"] = 0.2;
  const paddy::ContactLaw law(pm, spec, kMud);
  CHECK(law.maxSeparation(kR / 2) == Approx(std::cbrt(1e-10)).epsilon(1e-14));  // the bridge reaches farthest
}

TEST_CASE("contact/coarse graining: the laws the sub-models declare agree with the built-in table",
          "[contact][effects][coarse_graining]") {
  const auto pm = shipped();
  int checked = 0;
  for (auto kind : {paddy::SubModelKind::Normal, paddy::SubModelKind::Damping, paddy::SubModelKind::Tangential,
                    paddy::SubModelKind::Rolling, paddy::SubModelKind::Extra})
    for (const auto* info : pm->subModels(kind))
      for (const auto& p : info->params) {
        CHECK_FALSE(p.coarse_graining_reason.empty());
        for (const auto& law : paddy::measure::CoarseGraining::laws())
          if (law.name == p.name) {
            CHECK(law.exponent == p.coarse_graining_exponent);
            ++checked;
          }
      }
  CHECK(checked >= 5);
}
