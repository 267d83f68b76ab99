// Score tests, decision rule and residual map of the discovery statistics (discovery.hpp) on
// models with a known answer.
#include "paddy/doe/discovery.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/score_test.hpp"

#include "doe_test_util.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace paddy::doe;
using doe_test::gaussian;

namespace {

Eigen::VectorXd vec(std::initializer_list<double> v) {
  Eigen::VectorXd x(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double d : v) x(i++) = d;
  return x;
}

const CandidateReport& report(const Diagnosis& d, const std::string& name) {
  for (const auto& c : d.candidates)
    if (c.name == name) return c;
  throw std::runtime_error("no candidate " + name);
}

// m = 30 observables in 3 blocks, p = 3 random parameters, residual = J dtheta + noise (+ effect)
struct LinearModel {
  std::mt19937_64 rng{12345};
  Eigen::Index m = 30;
  Eigen::MatrixXd J;
  std::vector<std::string> blocks;
  LinearModel() {
    J.resize(m, 3);
    for (int j = 0; j < 3; ++j) J.col(j) = gaussian(rng, m);
    for (Eigen::Index i = 0; i < m; ++i) blocks.push_back(i < 10 ? "slump" : i < 20 ? "rheometer" : "lift");
  }
  DiagnoseInput input(const Eigen::VectorXd& effect) {
    DiagnoseInput in;
    in.residual = effect + gaussian(rng, m) + J * gaussian(rng, 3);
    in.covariance = Eigen::MatrixXd::Identity(m, m);
    in.jacobian = J;
    in.blocks = blocks;
    return in;
  }
  Candidate candidate(const std::string& name, const Eigen::VectorXd& g, double high = 100.0) {
    Candidate c;
    c.name = name;
    c.signature = g;
    c.high = high;
    return c;
  }
};

}  // namespace

TEST_CASE("discovery: three observables worked by hand", "[doe][discovery]") {
  // J = (1,1,1): recalibration absorbs a common offset. P = I - 11^T/3.
  // r = (1,2,6): P r = (-2,-1,3), Q0 = 14 on 2 df, p = exp(-7).
  // g = (0,0,1): P g = (-1/3,-1/3,2/3), a = 2/3, b = 3, z = 3/sqrt(2/3), lambda^ = 4.5, se = sqrt(1.5),
  // Q_after = 14 - 13.5 = 0.5. g2 = (1,0,0): cos(P g, P g2) = -1/2.
  const Eigen::VectorXd r = vec({1, 2, 6});
  const Eigen::MatrixXd J = Eigen::MatrixXd::Ones(3, 1);
  Eigen::MatrixXd G(3, 2);
  G << 0, 1, 0, 0, 1, 0;
  const ScoreTests st = scoreTests(r, J, G);
  CHECK(st.rank == 1);
  CHECK(st.df == 2);
  CHECK(st.projectedResidual.isApprox(vec({-2, -1, 3}), 1e-12));
  CHECK(st.q0 == Approx(14.0).epsilon(1e-12));
  CHECK(st.q0P == Approx(std::exp(-7.0)).epsilon(1e-10));
  const auto& c = st.candidates[0];
  CHECK(c.a == Approx(2.0 / 3.0).epsilon(1e-12));
  CHECK(c.b == Approx(3.0).epsilon(1e-12));
  CHECK(c.z == Approx(3.0 / std::sqrt(2.0 / 3.0)).epsilon(1e-12));
  CHECK(c.strength == Approx(4.5).epsilon(1e-12));
  CHECK(c.strengthSe == Approx(std::sqrt(1.5)).epsilon(1e-12));
  CHECK(c.qAfter == Approx(0.5).epsilon(1e-10));
  CHECK(c.qAfterP == Approx(std::erfc(std::sqrt(0.25))).epsilon(1e-10));  // chi^2_1 tail of 0.5
  CHECK(c.p == Approx(0.5 * std::erfc(c.z / std::sqrt(2.0))).epsilon(1e-10));
  CHECK(st.confusability(0, 1) == Approx(-0.5).epsilon(1e-12));
  CHECK(st.confusability(0, 0) == Approx(1.0).epsilon(1e-12));

  // Same data with Sigma = 4 I: z and Q0 scale, lambda^ does not.
  DiagnoseInput in;
  in.residual = r;
  in.covariance = 4.0 * Eigen::MatrixXd::Identity(3, 3);
  in.jacobian = J;
  Candidate g;
  g.name = "g";
  g.signature = G.col(0);
  g.high = 10.0;
  in.candidates = {g};
  in.labels = {"slump", "flow", "torque"};
  const Diagnosis d = diagnose(in);
  CHECK(d.q0 == Approx(3.5).epsilon(1e-12));
  CHECK(d.misfit == Approx(std::sqrt((1.0 + 4.0 + 36.0) / 4.0 / 3.0)).epsilon(1e-12));
  CHECK(d.misfitProjected == Approx(std::sqrt(3.5 / 3.0)).epsilon(1e-12));
  CHECK(d.candidates[0].score.z == Approx(1.5 / std::sqrt(2.0 / 3.0)).epsilon(1e-12));
  CHECK(d.candidates[0].score.strength == Approx(4.5).epsilon(1e-12));
  CHECK(d.residualMap[2].label == "torque");
  CHECK(d.residualMap[2].standardised == Approx(3.0).epsilon(1e-12));
}

TEST_CASE("discovery: rank-deficient Jacobian projects off the estimable span", "[doe][discovery]") {
  // Two identical columns: rank 1, the same projection as one column.
  Eigen::MatrixXd J(3, 2);
  J << 1, 2, 1, 2, 1, 2;
  const Eigen::MatrixXd G = vec({0, 0, 1});
  const ScoreTests st = scoreTests(vec({1, 2, 6}), J, G);
  CHECK(st.rank == 1);
  CHECK(st.df == 2);
  CHECK(st.q0 == Approx(14.0).epsilon(1e-12));
  // p = 0 (nothing recalibrated): P = I
  const ScoreTests none = scoreTests(vec({1, 2, 6}), Eigen::MatrixXd(3, 0), G);
  CHECK(none.q0 == Approx(41.0).epsilon(1e-12));
  CHECK(none.candidates[0].strength == Approx(6.0).epsilon(1e-12));
  CHECK_THROWS_WITH(scoreTests(vec({1, 2}), Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd(2, 0)),
                    Catch::Contains("no degrees of freedom"));
}

TEST_CASE("discovery: half-normal Bayes factor against quadrature", "[doe][discovery]") {
  // BF = int_0^inf 2 N(l; 0, tau^2) exp(b l - a l^2 / 2) dl (likelihood ratio against lambda = 0)
  for (const auto& [a, b, tau] : {std::tuple{2.0, 3.0, 1.5}, std::tuple{0.5, -1.0, 2.0}, std::tuple{10.0, 12.0, 0.3}}) {
    const int n = 400000;
    const double upper = 12.0 * tau + 40.0 / std::sqrt(a);
    double sum = 0;
    for (int i = 0; i < n; ++i) {
      const double l = (i + 0.5) * upper / n;
      sum += 2.0 / (tau * std::sqrt(2.0 * M_PI)) * std::exp(-l * l / (2 * tau * tau) + b * l - 0.5 * a * l * l);
    }
    sum *= upper / n;
    CHECK(logBayesFactorHalfNormal(a, b, tau) == Approx(std::log(sum)).epsilon(1e-6));
  }
}

TEST_CASE("discovery: Holm step-down adjustment", "[doe][discovery]") {
  // sorted 0.005 (x4 = 0.02), 0.01 (x3 = 0.03), 0.03 (x2 = 0.06), 0.04 (x1, raised to 0.06)
  const auto adj = holmAdjust({0.01, 0.04, 0.03, 0.005});
  REQUIRE(adj.size() == 4);
  CHECK(adj[0] == Approx(0.03));
  CHECK(adj[1] == Approx(0.06));
  CHECK(adj[2] == Approx(0.06));
  CHECK(adj[3] == Approx(0.02));
  CHECK(holmAdjust({0.6, 0.9})[1] == Approx(1.0));  // capped at 1
}

TEST_CASE("discovery: a known missing term is named with its strength", "[doe][discovery]") {
  LinearModel lm;
  const Eigen::VectorXd gA = gaussian(lm.rng, lm.m), gB = gaussian(lm.rng, lm.m), gC = gaussian(lm.rng, lm.m);
  const double lambda = 1.7;  // projected size lambda |P gA| ~ 8 noise sd
  DiagnoseInput in = lm.input(lambda * gA);
  in.candidates = {lm.candidate("A", gA, 5.0), lm.candidate("B", gB, 5.0), lm.candidate("C", gC, 5.0)};
  const Diagnosis d = diagnose(in);
  CHECK(d.decision == "effect");
  CHECK(d.named == "A");
  const auto& a = report(d, "A");
  CHECK(std::abs(a.score.strength - lambda) < 3.0 * a.score.strengthSe);
  CHECK(a.score.strengthSe < 0.3);
  CHECK(a.pHolm < 1e-6);
  CHECK(d.q0Significant);
  CHECK(d.misfitAfter < d.misfitProjected);
  CHECK(d.misfitAfter < 1.2);  // the rest is noise: sqrt(chi^2_26 / 30) ~ 0.93
  // the standardised residual after adding A is small everywhere
  double worstAfter = 0;
  for (const auto& row : d.residualMap) worstAfter = std::max(worstAfter, std::abs(row.standardisedAfter));
  CHECK(worstAfter < 4.0);
}

TEST_CASE("discovery: a term inside the span of J is not identifiable", "[doe][discovery]") {
  LinearModel lm;
  const Eigen::VectorXd inSpan = lm.J * vec({1.0, -2.0, 0.5});
  const Eigen::VectorXd gB = gaussian(lm.rng, lm.m);
  DiagnoseInput in = lm.input(3.0 * inSpan);
  in.candidates = {lm.candidate("absorbed", inSpan), lm.candidate("B", gB),
                   lm.candidate("tiny", 1e-3 * gaussian(lm.rng, lm.m), 1.0)};
  const Diagnosis d = diagnose(in);
  const auto& ab = report(d, "absorbed");
  CHECK_FALSE(ab.identifiable);
  CHECK(ab.notIdentifiableReason == "absorbed by recalibration");
  CHECK_FALSE(ab.passes);
  const auto& tiny = report(d, "tiny");
  CHECK_FALSE(tiny.identifiable);
  CHECK(tiny.notIdentifiableReason == "no sensitivity in [low, high]");
  CHECK(report(d, "B").identifiable);
  CHECK(d.decision == "none");  // recalibration absorbs the term: nothing is left to name
  CHECK(d.named.empty());
}

TEST_CASE("discovery: nearly parallel candidates are ambiguous; the separating block is named", "[doe][discovery]") {
  LinearModel lm;
  // C and D agree in slump and rheometer and differ in lift
  const Eigen::VectorXd gC = gaussian(lm.rng, lm.m);
  Eigen::VectorXd gD = gC;
  gD.tail(10) += 0.35 * gaussian(lm.rng, 10);
  const Eigen::VectorXd gA = gaussian(lm.rng, lm.m);
  DiagnoseInput in = lm.input(1.5 * gC);
  in.candidates = {lm.candidate("A", gA), lm.candidate("C", gC), lm.candidate("D", gD)};
  const Diagnosis d = diagnose(in);
  CHECK(d.confusability(1, 2) > 0.9);
  CHECK(d.decision == "ambiguous");
  CHECK(d.named.empty());
  REQUIRE(d.ambiguousWith.size() == 2);
  CHECK(((d.ambiguousWith[0] == "C" && d.ambiguousWith[1] == "D") || (d.ambiguousWith[0] == "D" && d.ambiguousWith[1] == "C")));
  CHECK(d.separatingBlock == "lift");
  REQUIRE(d.blockSeparations.size() == 3);
  // the raw signatures agree in slump and rheometer; only recalibration (global) makes them differ there
  INFO("T: slump " << d.blockSeparations[0].tCriterion << ", rheometer " << d.blockSeparations[1].tCriterion << ", lift "
                   << d.blockSeparations[2].tCriterion);
  CHECK(d.blockSeparations[2].block == "lift");
  CHECK(d.blockSeparations[2].tCriterion > 3.0 * std::max(d.blockSeparations[0].tCriterion, d.blockSeparations[1].tCriterion));
}

TEST_CASE("discovery: a confusable rival is set aside only on strong evidence (strong_margin)", "[doe][discovery]") {
  LinearModel lm;
  const Eigen::VectorXd gC = gaussian(lm.rng, lm.m);
  Eigen::VectorXd gD = gC;
  gD.tail(10) += 0.35 * gaussian(lm.rng, 10);
  DiagnoseInput in = lm.input(8.0 * gC);  // a large C: z_C - z_D is many times its noise sd
  in.candidates = {lm.candidate("C", gC), lm.candidate("D", gD)};
  // The default: a confusable rival always makes the answer ambiguous.
  const Diagnosis by_default = diagnose(in);
  CHECK(by_default.decision == "ambiguous");
  in.options.strongMargin = 20.0;
  const Diagnosis strong = diagnose(in);
  REQUIRE(strong.confusability(0, 1) > 0.9);
  INFO(strong.reason);
  CHECK(strong.decision == "effect");
  CHECK(strong.named == "C");
  // The same data with a margin no evidence can reach: the pair stays ambiguous, C listed first.
  in.options.strongMargin = 1e300;
  const Diagnosis strict = diagnose(in);
  CHECK(strict.decision == "ambiguous");
  REQUIRE(strict.ambiguousWith.size() == 2);
  CHECK(strict.ambiguousWith[0] == "C");
  // A margin below the "positive" one is refused, naming the field.
  in.options.strongMargin = 2.0;
  CHECK_THROWS_WITH(diagnose(in), Catch::Contains("strong_margin"));
}

TEST_CASE("discovery: a rival that explains the misfit alike makes it ambiguous even when its own test fails", "[doe][discovery]") {
  LinearModel lm;
  // A and B share half their signature (not confusable); the missing term lies between them, so
  // they explain it about equally well. B's smallest relevant strength is large, so its own test
  // fails while A's passes: naming A would be a guess.
  const Eigen::VectorXd common = gaussian(lm.rng, lm.m);
  const Eigen::VectorXd gA = common + 0.8 * gaussian(lm.rng, lm.m), gB = common + 0.8 * gaussian(lm.rng, lm.m);
  const Eigen::VectorXd noise = gaussian(lm.rng, lm.m);
  auto run = [&](double highB) {
    DiagnoseInput in = lm.input(Eigen::VectorXd::Zero(lm.m));
    in.residual = 0.6 * (gA + gB) + noise;
    in.candidates = {lm.candidate("A", gA, 5.0), lm.candidate("B", gB, highB)};
    in.candidates[1].relevant = 0.6 * highB;
    return diagnose(in);
  };
  const Diagnosis d = run(5.0);
  const auto& a = report(d, "A");
  const auto& b = report(d, "B");
  INFO("z_A " << a.score.z << ", z_B " << b.score.z << ", z_rel_B " << b.zRelevant << ", c " << d.confusability(0, 1)
              << ", log BF ratio " << a.score_rank - b.score_rank);
  REQUIRE(a.passes);
  REQUIRE_FALSE(b.passes);  // B fails only its relevance test ...
  REQUIRE(b.score.z > 4.0);  // ... though its score is large
  REQUIRE(b.inRange);
  REQUIRE(d.confusability(0, 1) < 0.9);
  REQUIRE(std::abs(a.score_rank - b.score_rank) < std::log(3.0));
  CHECK(d.decision == "ambiguous");
  CHECK(d.named.empty());
  REQUIRE(d.ambiguousWith.size() == 2);
  CHECK(d.ambiguousWith[0] == "A");
  CHECK(d.ambiguousWith[1] == "B");
  // B allowed only strengths far below what the data need: it is no explanation, A is named.
  const Diagnosis outOfRange = run(0.05);
  REQUIRE_FALSE(report(outOfRange, "B").inRange);
  CHECK(outOfRange.decision == "effect");
  CHECK(outOfRange.named == "A");
}

TEST_CASE("discovery: a missing term orthogonal to every candidate is unknown", "[doe][discovery]") {
  LinearModel lm;
  Eigen::MatrixXd G(lm.m, 2);
  G.col(0) = gaussian(lm.rng, lm.m);
  G.col(1) = gaussian(lm.rng, lm.m);
  Eigen::MatrixXd JG(lm.m, 5);
  JG << lm.J, G;
  const Eigen::VectorXd outside = Projection(JG).apply(gaussian(lm.rng, lm.m)).normalized();
  DiagnoseInput in = lm.input(10.0 * outside);
  in.candidates = {lm.candidate("A", G.col(0)), lm.candidate("B", G.col(1))};
  const Diagnosis d = diagnose(in);
  CHECK(d.decision == "unknown");
  CHECK(d.named.empty());
  CHECK(d.q0Significant);
}

TEST_CASE("discovery: no missing term gives none", "[doe][discovery]") {
  LinearModel lm;
  DiagnoseInput in = lm.input(Eigen::VectorXd::Zero(lm.m));
  in.candidates = {lm.candidate("A", gaussian(lm.rng, lm.m)), lm.candidate("B", gaussian(lm.rng, lm.m))};
  const Diagnosis d = diagnose(in);
  CHECK(d.decision == "none");
  CHECK_FALSE(d.q0Significant);
}

TEST_CASE("discovery: a strength outside the physical range is not named", "[doe][discovery]") {
  LinearModel lm;
  const Eigen::VectorXd gA = gaussian(lm.rng, lm.m);
  DiagnoseInput in = lm.input(2.0 * gA);
  in.candidates = {lm.candidate("A", gA, 0.5)};  // the data need lambda ~ 2, physics allows 0.5
  const Diagnosis d = diagnose(in);
  CHECK(report(d, "A").passes);
  CHECK_FALSE(report(d, "A").plausible);
  CHECK(d.decision == "unknown");
}

TEST_CASE("discovery: a smallest relevant strength tests lambda <= relevant", "[doe][discovery]") {
  LinearModel lm;
  const Eigen::VectorXd gA = gaussian(lm.rng, lm.m), gB = gaussian(lm.rng, lm.m);
  const Eigen::VectorXd noise = gaussian(lm.rng, lm.m), shift = lm.J * gaussian(lm.rng, 3);
  auto run = [&](double lambda, double relevant) {
    DiagnoseInput in = lm.input(Eigen::VectorXd::Zero(lm.m));
    in.residual = lambda * gA + noise + shift;  // the same noise for every call
    in.candidates = {lm.candidate("A", gA, 5.0), lm.candidate("B", gB, 5.0)};
    in.candidates[0].relevant = relevant;
    return diagnose(in);
  };
  // A present but weak effect (projected size ~ 0.8 |P gA| ~ 4 noise sd) is named when any
  // strength counts, and not when strengths below 0.7 do not matter.
  const Diagnosis any = run(0.8, 0.0), relevant = run(0.8, 0.7);
  CHECK(any.decision == "effect");
  CHECK(any.named == "A");
  const auto& a0 = report(any, "A");
  const auto& a1 = report(relevant, "A");
  CHECK(a0.zRelevant == a0.score.z);  // relevant = 0: exactly today's test
  CHECK(a0.pRelevant == a0.score.p);
  CHECK(a1.score.z == a0.score.z);    // the score itself does not change
  CHECK(a1.zRelevant == Approx(a1.score.z - 0.7 * std::sqrt(a1.score.a)).epsilon(1e-12));
  CHECK(a1.zRelevant == Approx((a1.score.strength - 0.7) / a1.score.strengthSe).epsilon(1e-9));
  CHECK(a1.pRelevant == Approx(0.5 * std::erfc(a1.zRelevant / std::sqrt(2.0))).epsilon(1e-9));
  CHECK_FALSE(a1.passes);
  CHECK(relevant.decision != "effect");
  CHECK(relevant.named.empty());
  // B's test is unchanged by A's relevance
  CHECK(report(relevant, "B").pRelevant == report(any, "B").score.p);
  // A strong effect is still named, with the same strength estimate
  const Diagnosis strong = run(3.0, 0.7);
  CHECK(strong.decision == "effect");
  CHECK(strong.named == "A");
  CHECK(report(strong, "A").score.strength == report(run(3.0, 0.0), "A").score.strength);
  // relevant must lie in [low, high)
  DiagnoseInput bad = lm.input(Eigen::VectorXd::Zero(lm.m));
  bad.candidates = {lm.candidate("A", gA, 5.0)};
  bad.candidates[0].relevant = 5.0;
  CHECK_THROWS_WITH(diagnose(bad), Catch::Contains("candidates[1] (A): relevant = 5") && Catch::Contains("must lie in [low, high)"));
  bad.candidates[0].relevant = -0.1;
  CHECK_THROWS_WITH(diagnose(bad), Catch::Contains("relevant = -0.1"));
}

TEST_CASE("discovery: input errors name the field", "[doe][discovery]") {
  LinearModel lm;
  DiagnoseInput in = lm.input(Eigen::VectorXd::Zero(lm.m));
  in.candidates = {lm.candidate("A", gaussian(lm.rng, 29))};
  CHECK_THROWS_WITH(diagnose(in), Catch::Contains("candidates[1] (A): signature has 29 entries"));
  in.candidates = {lm.candidate("A", gaussian(lm.rng, 30)), lm.candidate("A", gaussian(lm.rng, 30))};
  CHECK_THROWS_WITH(diagnose(in), Catch::Contains("appears twice"));
  in.candidates.pop_back();
  in.residual(3) = std::nan("");
  CHECK_THROWS_WITH(diagnose(in), Catch::Contains("residual: non-finite"));
  in.residual(3) = 0;
  in.covariance(0, 0) = -1;
  CHECK_THROWS_WITH(diagnose(in), Catch::Contains("covariance: not positive definite"));
  in.covariance = Eigen::MatrixXd::Identity(29, 29);
  CHECK_THROWS_WITH(diagnose(in), Catch::Contains("covariance: 29 x 29"));
  in.covariance = Eigen::MatrixXd::Identity(30, 30);
  in.jacobian = Eigen::MatrixXd::Ones(20, 2);
  CHECK_THROWS_WITH(diagnose(in), Catch::Contains("jacobian: 20 rows"));
  in.jacobian = lm.J;
  in.options.alpha = 1.5;
  CHECK_THROWS_WITH(diagnose(in), Catch::Contains("alpha: must be in (0, 1)"));
}
