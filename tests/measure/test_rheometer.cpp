// Vane rheometer conversions, Herschel–Bulkley fit and relative errors.
#include <paddy/errors.hpp>
#include <paddy/measure/herschel_bulkley.hpp>
#include <paddy/measure/relative_error.hpp>
#include <paddy/measure/vane.hpp>

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace paddy::measure;
using paddy::InputError;
using Catch::Matchers::Contains;

namespace {
std::vector<double> logspace(double a, double b, int n) {
  std::vector<double> v;
  for (int k = 0; k < n; ++k) v.push_back(a * std::pow(b / a, k / double(n - 1)));
  return v;
}
}  // namespace

TEST_CASE("measure: vane equation against a hand calculation", "[measure][vane]") {
  // D = 20 mm, H = 40 mm, both ends sheared. By hand:
  //   side  π D² H / 2 = π·4e-4·0.04/2 = 2.51327e-5 m³
  //   ends  π D³ / 6   = π·8e-6/6     = 4.18879e-6 m³
  //   T/τ = 2.93215e-5 m³  →  T = 0.01 N·m gives τ = 341.05 Pa.
  VaneGeometry v{0.02, 0.04};
  CHECK(vaneTorqueFactor(v) == Approx(2.93215e-5).epsilon(1e-5));
  CHECK(vaneShearStress(0.01, v) == Approx(341.047).epsilon(1e-5));
  CHECK(vaneTorque(vaneShearStress(0.01, v), v) == Approx(0.01));
  v.sheared_ends = 1;  // top flush with the surface: only the bottom end shears
  CHECK(vaneTorqueFactor(v) == Approx(2.51327e-5 + 4.18879e-6 / 2).epsilon(1e-5));
  v.sheared_ends = 0;
  CHECK(vaneTorqueFactor(v) == Approx(2.51327e-5).epsilon(1e-5));
}

TEST_CASE("measure: shear rate at the vane (Couette analogy)", "[measure][vane]") {
  const VaneGeometry v{0.02, 0.04, 0.04};  // κ = 0.5
  CHECK(vaneShearRate(1.0, v) == Approx(2.0 / 0.75));                       // Newtonian
  CHECK(vaneShearRate(1.0, v, 0.5) == Approx(2.0 / (0.5 * (1 - 0.0625))));  // κ^(2/n) = 0.5^4
  const VaneGeometry inf{0.02, 0.04};
  CHECK(vaneShearRate(3.0, inf) == Approx(6.0));
  CHECK(vaneShearRate(3.0, inf, 0.4) == Approx(15.0));
  CHECK(rpmToRadPerSecond(60.0) == Approx(2 * 3.14159265358979));
  CHECK_THROWS_WITH(vaneShearRate(1.0, v, 0.0), Contains("flow index"));
  CHECK_THROWS_WITH(vaneShearRate(1.0, VaneGeometry{0.02, 0.04, 0.01}), Contains("cup diameter"));
}

TEST_CASE("measure: Herschel-Bulkley fit recovers exact parameters", "[measure][hb]") {
  const HerschelBulkley truth{25.0, 6.0, 0.55};
  const auto D = logspace(0.1, 100.0, 12);
  std::vector<double> tau;
  for (double x : D) tau.push_back(truth.stress(x));
  const auto fit = fitHerschelBulkley(D, tau);
  INFO("tau0 = " << fit.model.tau0 << " K = " << fit.model.K << " n = " << fit.model.n << " evals " << fit.evaluations);
  CHECK(fit.model.tau0 == Approx(25.0).epsilon(1e-4));
  CHECK(fit.model.K == Approx(6.0).epsilon(1e-4));
  CHECK(fit.model.n == Approx(0.55).epsilon(1e-4));
  CHECK(fit.r2 > 1.0 - 1e-10);
  CHECK(fit.rmse < 1e-4);
  // A power law (τ0 = 0) and a Newtonian fluid stay at the bound τ0 = 0.
  std::vector<double> newton;
  for (double x : D) newton.push_back(0.8 * x);
  const auto nf = fitHerschelBulkley(D, newton);
  CHECK(nf.model.tau0 == Approx(0.0).margin(1e-4));
  CHECK(nf.model.n == Approx(1.0).epsilon(1e-5));
  CHECK(nf.model.K == Approx(0.8).epsilon(1e-5));
}

TEST_CASE("measure: Herschel-Bulkley fit from noisy data (seeded)", "[measure][hb]") {
  const HerschelBulkley truth{40.0, 12.0, 0.45};
  const auto D = logspace(0.05, 200.0, 20);
  std::mt19937 rng(2016);
  std::normal_distribution<double> noise(0.0, 0.02);  // 2 % relative
  std::vector<double> tau;
  for (double x : D) tau.push_back(truth.stress(x) * (1.0 + noise(rng)));
  const auto fit = fitHerschelBulkley(D, tau);
  INFO("tau0 = " << fit.model.tau0 << " K = " << fit.model.K << " n = " << fit.model.n << " R2 " << fit.r2
                 << " rmse " << fit.rmse);
  CHECK(fit.model.tau0 == Approx(40.0).epsilon(0.10));
  CHECK(fit.model.K == Approx(12.0).epsilon(0.10));
  CHECK(fit.model.n == Approx(0.45).margin(0.03));
  CHECK(fit.r2 > 0.99);
  CHECK(fit.rmse < 0.03 * truth.stress(200.0));
}

TEST_CASE("measure: Herschel-Bulkley fit rejects bad input", "[measure][hb]") {
  CHECK_THROWS_WITH(fitHerschelBulkley({1, 2}, {3, 4}), Contains("at least 3"));
  CHECK_THROWS_WITH(fitHerschelBulkley({1, 2, 3}, {3, 4}), Contains("3 shear rates but 2"));
  CHECK_THROWS_WITH(fitHerschelBulkley({1, 0, 3}, {3, 4, 5}), Contains("not positive"));
  CHECK_THROWS_WITH(fitHerschelBulkley({1, -2, 3}, {3, 4, 5}), Contains("not positive"));
  CHECK_THROWS_WITH(fitHerschelBulkley({1, std::nan(""), 3}, {3, 4, 5}), Contains("not a number"));
  CHECK_THROWS_WITH(fitHerschelBulkley({1, 2, 3}, {3, std::numeric_limits<double>::infinity(), 5}),
                    Contains("not a number"));
  CHECK_THROWS_WITH(fitHerschelBulkley({1, 2, 3}, {3, -4, 5}), Contains("negative"));
  CHECK_THROWS_WITH(fitHerschelBulkley({1, 1, 2, 2}, {3, 3, 4, 4}), Contains("distinct"));
}

TEST_CASE("measure: vane flow curve inverts the Couette forward model", "[measure][vane]") {
  const VaneGeometry v{0.02, 0.04, 0.04};
  const auto omega = logspace(0.05, 20.0, 12);
  SECTION("Newtonian: exact") {
    const HerschelBulkley mu{0.0, 1.5, 1.0};
    std::vector<double> T;
    for (double w : omega) T.push_back(vaneTorqueHerschelBulkley(w, mu, v));
    CHECK(T[3] == Approx(vaneTorque(1.5 * 2 * omega[3] / 0.75, v)).epsilon(1e-8));  // τ = μ·2Ω/(1−κ²)
    const auto c = vaneFlowCurve(omega, T, v);
    CHECK(c.fit.model.K == Approx(1.5).epsilon(1e-5));
    CHECK(c.fit.model.n == Approx(1.0).epsilon(1e-5));
    CHECK(c.fit.model.tau0 == Approx(0.0).margin(1e-4));
  }
  SECTION("power law: exact with the n correction") {
    const HerschelBulkley pl{0.0, 10.0, 0.4};
    std::vector<double> T;
    for (double w : omega) T.push_back(vaneTorqueHerschelBulkley(w, pl, v));
    const auto c = vaneFlowCurve(omega, T, v);
    INFO("K = " << c.fit.model.K << " n = " << c.fit.model.n << " tau0 = " << c.fit.model.tau0);
    CHECK(c.fit.model.n == Approx(0.4).epsilon(1e-4));
    CHECK(c.fit.model.K == Approx(10.0).epsilon(1e-3));
    CHECK(c.fit.model.tau0 == Approx(0.0).margin(1e-2));
  }
  SECTION("Herschel-Bulkley: shear rates within a few percent, parameters recovered") {
    const HerschelBulkley hb{30.0, 8.0, 0.5};
    for (double cup : {0.04, 0.025, std::numeric_limits<double>::infinity()}) {
      const VaneGeometry vc{0.02, 0.04, cup};
      std::vector<double> T;
      for (double w : omega) T.push_back(vaneTorqueHerschelBulkley(w, hb, vc));
      const auto c = vaneFlowCurve(omega, T, vc);
      INFO("cup " << cup << ": tau0 = " << c.fit.model.tau0 << " K = " << c.fit.model.K << " n = " << c.fit.model.n);
      double worst = 0.0;
      for (std::size_t i = 0; i < omega.size(); ++i) {
        const double exact = std::pow((c.shear_stress[i] - hb.tau0) / hb.K, 1.0 / hb.n);  // γ̇ at the vane
        worst = std::max(worst, std::abs(c.shear_rate[i] / exact - 1.0));
      }
      INFO("worst shear-rate error " << worst);
      CHECK(worst < 0.05);
      CHECK(c.fit.model.tau0 == Approx(30.0).epsilon(0.05));
      CHECK(c.fit.model.K == Approx(8.0).epsilon(0.10));
      CHECK(c.fit.model.n == Approx(0.5).margin(0.03));
    }
  }
  SECTION("bad input names the problem") {
    CHECK_THROWS_WITH(vaneFlowCurve({1, 2}, {1, 2}, v), Contains("at least 3"));
    CHECK_THROWS_WITH(vaneFlowCurve({0, 1, 2}, {1, 2, 3}, v), Contains("must be finite and > 0"));
    CHECK_THROWS_WITH(vaneFlowCurve({1, 3, 2}, {1, 2, 3}, v), Contains("increase"));
    CHECK_THROWS_WITH(vaneFlowCurve({1, 2, 3}, {1, 2}, v), Contains("3 speeds but 2 torques"));
  }
}

TEST_CASE("measure: relative errors as the reference defines them", "[measure][errors]") {
  // δ = |Ym − Ys| / Ys: slump 231 vs 235, flow 480 vs 478.
  const auto e = relativeErrors({231.0, 480.0}, {235.0, 478.0});
  REQUIRE(e.per_point.size() == 2);
  CHECK(e.per_point[0] == Approx(4.0 / 231.0));
  CHECK(e.per_point[1] == Approx(2.0 / 480.0));
  CHECK(e.mean == Approx((4.0 / 231.0 + 2.0 / 480.0) / 2));
  CHECK(e.max == Approx(4.0 / 231.0));
  CHECK(relativeError(100.0, 80.0) == Approx(0.20));  // the measured value is the denominator
  CHECK_THROWS_WITH(relativeErrors({0.0}, {1.0}), Contains("measured value is 0"));
  CHECK_THROWS_WITH(relativeErrors({1.0, 2.0}, {1.0}), Contains("2 measured values but 1"));
  CHECK_THROWS_WITH(relativeErrors({}, {}), Contains("no values"));
  CHECK_THROWS_AS(relativeError(std::nan(""), 1.0), InputError);
}

TEST_CASE("measure: relative errors reproduce the reference's Table 6", "[measure]") {
  const char* src = std::getenv("PADDY_SOURCE_DIR");
  REQUIRE(src != nullptr);
  std::ifstream in(std::string(src) + "/../shared/reference/table6_steepest_ascent.csv");
  REQUIRE(in.good());
  std::string line;
  std::getline(in, line);  // header
  int rows = 0;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
    REQUIRE(v.size() == 8);
    // columns: run, A, B, C, slump, slump error %, flow, flow error %
    CHECK(100.0 * relativeError(231.0, v[4]) == Approx(v[5]).margin(0.005));
    CHECK(100.0 * relativeError(480.0, v[6]) == Approx(v[7]).margin(0.005));
    ++rows;
  }
  REQUIRE(rows == 4);
}
