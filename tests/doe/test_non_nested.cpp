// Vuong's test of two non-nested fits (non_nested.hpp): a hand-worked example, and its error
// rates by Monte Carlo on data with a known answer: when one model is right it is preferred with
// high power and the other almost never; when both are equally wrong either is preferred at about
// the level alpha.
#include "paddy/doe/discovery_json.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/non_nested.hpp"

#include "doe_test_util.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace paddy::doe;

using doe_test::gaussian;

TEST_CASE("non-nested: Vuong's statistic worked by hand", "[doe][discovery]") {
  // d = ((4-1)/2, (1-0)/2, 0, (0-1)/2) = (1.5, 0.5, 0, -0.5): LR = 1.5, mean 0.375,
  // omega^2 = (1.125^2 + 0.125^2 + 0.375^2 + 0.875^2)/4 = 0.546875, z = 1.5 / (2 sqrt(0.546875)).
  Eigen::Vector4d a(1, 0, 2, 1), b(2, 1, 2, 0);
  const auto c = vuongTest(a, b, Eigen::Matrix4d::Identity(), 1, 1);
  CHECK(c.lr == Approx(1.5).epsilon(1e-14));
  CHECK(c.omega == Approx(std::sqrt(0.546875)).epsilon(1e-14));
  CHECK(c.z == Approx(1.5 / (2.0 * std::sqrt(0.546875))).epsilon(1e-14));
  CHECK(c.p == Approx(0.310494).margin(5e-6));  // 2 (1 - Phi(1.014185))
  CHECK(c.preferred == "neither");
  // a covariance of 4 I scales every d_i by 1/4: z unchanged
  const auto c4 = vuongTest(a, b, 4.0 * Eigen::Matrix4d::Identity(), 1, 1);
  CHECK(c4.lr == Approx(0.375).epsilon(1e-14));
  CHECK(c4.z == Approx(c.z).epsilon(1e-12));
  // the Schwarz correction: one parameter more in A costs ln(m)/2
  CHECK(vuongTest(a, b, Eigen::Matrix4d::Identity(), 2, 1).lr == Approx(1.5 - 0.5 * std::log(4.0)).epsilon(1e-14));
  // swapping the models flips the sign
  CHECK(vuongTest(b, a, Eigen::Matrix4d::Identity(), 1, 1).z == Approx(-c.z).epsilon(1e-14));
  // identical fits: omega = 0, neither preferred
  const auto same = vuongTest(a, a, Eigen::Matrix4d::Identity(), 1, 1);
  CHECK(same.z == 0.0);
  CHECK(same.preferred == "neither");
}

TEST_CASE("non-nested: the right model is preferred, the wrong one almost never", "[doe][discovery][montecarlo]") {
  const int m = 20, trials = 2000;
  std::mt19937_64 rng(11);
  // B misses the data by a fixed vector delta spread over every observable, |delta| = 6 (whitened):
  // LR has mean |delta|^2/2 = 18 and z about |delta|/2 = 3. (A miss concentrated in a few
  // observables is judged less surely: omega grows with it, z tends to sqrt(m/2).)
  Eigen::VectorXd delta(m);
  for (int i = 0; i < m; ++i) delta(i) = (i % 3 == 0 ? -1.0 : 1.0) * 6.0 / std::sqrt(static_cast<double>(m));
  // A correlated noise: Sigma = L L^T with a common factor.
  Eigen::MatrixXd Sigma = Eigen::MatrixXd::Identity(m, m) + 0.5 * Eigen::MatrixXd::Ones(m, m);
  const Eigen::MatrixXd L = Sigma.llt().matrixL();
  int a = 0, b = 0;
  for (int t = 0; t < trials; ++t) {
    const Eigen::VectorXd e = L * gaussian(rng, m);
    const auto c = vuongTest(e, e - L * delta, Sigma, 1, 1);
    if (c.preferred == "a") ++a;
    if (c.preferred == "b") ++b;
  }
  CAPTURE(a, b);
  CHECK(a >= 0.8 * trials);
  CHECK(b <= 0.01 * trials);
}

TEST_CASE("non-nested: two equally wrong models are told apart at about the level alpha", "[doe][discovery][montecarlo]") {
  const int m = 20, trials = 4000;
  std::mt19937_64 rng(12);
  int picked = 0;
  for (int t = 0; t < trials; ++t) {
    // each misses by its own random vector of the same length (2 noise sd)
    Eigen::VectorXd dA = gaussian(rng, m), dB = gaussian(rng, m);
    dA *= 2.0 / dA.norm();
    dB *= 2.0 / dB.norm();
    const Eigen::VectorXd e = gaussian(rng, m);
    const auto c = vuongTest(e - dA, e - dB, Eigen::MatrixXd::Identity(m, m), 1, 1, 0.05);
    if (c.preferred != "neither") ++picked;
  }
  CAPTURE(picked);
  // alpha = 0.05: 200 of 4000 expected; the normal approximation with m = 20 is a little liberal.
  CHECK(picked <= 0.075 * trials);
  CHECK(picked >= 0.02 * trials);
}

TEST_CASE("non-nested: bad input is refused naming the field, and the JSON entry point", "[doe][discovery]") {
  const Eigen::Vector3d a(1, 2, 3);
  CHECK_THROWS_WITH(vuongTest(a, Eigen::Vector2d(1, 2), Eigen::Matrix3d::Identity(), 1, 1), Catch::Contains("residual_b: 2 entries"));
  CHECK_THROWS_WITH(vuongTest(a, a, Eigen::Matrix2d::Identity(), 1, 1), Catch::Contains("covariance: must be 3 x 3"));
  CHECK_THROWS_WITH(vuongTest(a, a, Eigen::Matrix3d::Identity(), -1, 1), Catch::Contains("k_a, k_b"));
  CHECK_THROWS_WITH(vuongTest(a, a, Eigen::Matrix3d::Identity(), 1, 1, 1.5), Catch::Contains("alpha"));
  CHECK_THROWS_WITH(vuongTest(a, a, -Eigen::Matrix3d::Identity(), 1, 1), Catch::Contains("not positive definite"));
  const nlohmann::json out = compareNonNestedJson({{"residual_a", {1, 0, 2, 1}}, {"residual_b", {2, 1, 2, 0}},
                                                   {"covariance", {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}},
                                                   {"k_a", 1}, {"k_b", 1}});
  CHECK(out["lr"].get<double>() == Approx(1.5));
  CHECK(out["preferred"] == "neither");
  CHECK_THROWS_WITH(compareNonNestedJson({{"residual_a", {1, 2}}}), Catch::Contains("residual_b"));
}
