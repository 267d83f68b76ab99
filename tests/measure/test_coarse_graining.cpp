// Coarse-graining scaling laws: identity at α = 1, each law checked through the physics it keeps.
#include <paddy/errors.hpp>
#include <paddy/measure/coarse_graining.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace paddy::measure;
using paddy::InputError;
using paddy::ParamValues;
using Catch::Matchers::Contains;

namespace {
// The reference study's optimum (mud–mud) plus material and numerics.
ParamValues reference() {
  return {{"surface_energy", 0.096}, {"restitution", 0.13}, {"friction", 0.15}, {"rolling_friction", 0.125},
          {"rolling_damping", 0.3},  {"density", 1680.0},   {"shear_modulus", 1e6}, {"poisson", 0.5},
          {"radius", 1e-3},          {"time_step", 2e-6},   {"particle_count", 9e5}};
}

// JKR (reference README): δ(a) = a²/R* − sqrt(4πγa/E*), F(a) = −4 sqrt(πγE*) a^1.5 + 4E* a³/(3R*).
double jkrOverlap(double a, double gamma, double E, double R) { return a * a / R - std::sqrt(4 * std::numbers::pi * gamma * a / E); }
double jkrForce(double a, double gamma, double E, double R) {
  return -4 * std::sqrt(std::numbers::pi * gamma * E) * std::pow(a, 1.5) + 4 * E * a * a * a / (3 * R);
}
}  // namespace

TEST_CASE("measure: coarse graining with alpha = 1 is the identity", "[measure][cg]") {
  const auto p = reference();
  const auto s = scaleParameters(p, 1.0);
  CHECK(s.values == p);
  for (const auto& row : s.table) CHECK(row.factor == 1.0);
  CHECK(s.text().find(" yes ") == std::string::npos);  // nothing marked as changed
}

TEST_CASE("measure: coarse-graining laws", "[measure][cg]") {
  const double alpha = 2.5;
  const auto p = reference();
  const auto s = scaleParameters(p, alpha);
  const auto& v = s.values;
  // Unchanged: material, restitution, friction, rolling friction, damping.
  for (const char* name : {"restitution", "friction", "rolling_friction", "rolling_damping", "density",
                           "shear_modulus", "poisson"})
    CHECK(v.at(name) == p.at(name));
  CHECK(v.at("radius") == Approx(alpha * 1e-3));
  CHECK(v.at("surface_energy") == Approx(alpha * 0.096));
  CHECK(v.at("time_step") == Approx(alpha * 2e-6));
  CHECK(v.at("particle_count") == Approx(9e5 / (alpha * alpha * alpha)));
  CHECK(s.text().find(" yes ") != std::string::npos);

  const double R = p.at("radius"), Rc = v.at("radius");
  // Time step follows the Rayleigh time ∝ R.
  const double tr = CoarseGraining::rayleighTime(R, 1680, 1e6, 0.5);
  const double tr_cg = CoarseGraining::rayleighTime(Rc, v.at("density"), v.at("shear_modulus"), v.at("poisson"));
  CHECK(tr_cg / tr == Approx(alpha));
  CHECK(v.at("time_step") / tr_cg == Approx(p.at("time_step") / tr));
  // Pull-off force ∝ α²; cohesive stress F_po/d² invariant.
  const double f = CoarseGraining::jkrPullOffForce(0.096, R / 2);
  const double f_cg = CoarseGraining::jkrPullOffForce(v.at("surface_energy"), Rc / 2);
  CHECK(f_cg / f == Approx(alpha * alpha));
  CHECK(f_cg / (4 * Rc * Rc) == Approx(f / (4 * R * R)));
  // The whole JKR force–overlap curve is self-similar: δ → αδ, F → α²F (E* unchanged).
  const double E = 2 * 1e6 * 1.5 / (2 * (1 - 0.25));  // E* of two equal spheres, E = 2G(1+ν)
  for (double a : {2e-6, 1e-5, 4e-5}) {
    CHECK(jkrOverlap(alpha * a, v.at("surface_energy"), E, Rc / 2) ==
          Approx(alpha * jkrOverlap(a, 0.096, E, R / 2)));
    CHECK(jkrForce(alpha * a, v.at("surface_energy"), E, Rc / 2) == Approx(alpha * alpha * jkrForce(a, 0.096, E, R / 2)));
  }
  // Hertz: F = 4/3 E* sqrt(R*) δ^1.5 → α² at δ' = αδ; rolling torque μ_r F R → α³.
  auto hertz = [&](double delta, double Re) { return 4.0 / 3.0 * E * std::sqrt(Re) * std::pow(delta, 1.5); };
  CHECK(hertz(alpha * 1e-5, Rc / 2) == Approx(alpha * alpha * hertz(1e-5, R / 2)));
  CHECK(v.at("rolling_friction") * hertz(alpha * 1e-5, Rc / 2) * Rc ==
        Approx(std::pow(alpha, 3) * p.at("rolling_friction") * hertz(1e-5, R / 2) * R));
  // Not invariant (documented): the particle Bond number F_po / (m g) falls as 1/α.
  auto weight = [&](double radius) { return 1680 * 4.0 / 3.0 * std::numbers::pi * std::pow(radius, 3) * 9.81; };
  CHECK((f_cg / weight(Rc)) / (f / weight(R)) == Approx(1 / alpha));
}

TEST_CASE("measure: coarse graining rejects unknown parameters and bad alpha", "[measure][cg]") {
  CHECK_THROWS_WITH(scaleParameters({{"bridge_volume", 1e-12}}, 2.0), Contains("known: radius"));
  const auto s = scaleParameters({{"bridge_volume", 1e-12}}, 2.0, {{"bridge_volume", 3.0, "liquid volume ~ R^3"}});
  CHECK(s.values.at("bridge_volume") == Approx(8e-12));
  CHECK_THROWS_WITH(CoarseGraining(0.0), Contains("alpha"));
  CHECK_THROWS_AS(scaleParameters(reference(), -1.0), InputError);
  CHECK(CoarseGraining(2.0).factor("surface_energy") == Approx(2.0));
  CHECK(CoarseGraining(2.0).particleCount(800.0) == Approx(100.0));
}
