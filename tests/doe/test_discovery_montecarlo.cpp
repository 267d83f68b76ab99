// Error rates of the decision rule by Monte Carlo (fast version of paddy_discovery_error_rates;
// full tables in docs/discovery.md). Each rate is asserted through its one-sided 95 %
// Clopper–Pearson bound, on a fixed seed.
#include "paddy/doe/discovery_trials.hpp"
#include "paddy/doe/null_calibration.hpp"
#include "paddy/doe/score_test.hpp"

#include <boost/math/distributions/normal.hpp>
#include <catch2/catch.hpp>
#include <random>

using namespace paddy::doe;

TEST_CASE("discovery/montecarlo: the score test has its nominal size and power", "[doe][discovery]") {
  // One candidate, Gaussian noise: P(z > 1.645) = 5 % under the null, Phi(delta - 1.645) at size delta.
  const TrialModel model = syntheticTrialModel();
  const Projection P(model.jacobian);
  const Eigen::MatrixXd G = model.candidates[0].signature;
  const double norm = model.projectedNorm(0);
  std::mt19937_64 rng(99);
  std::normal_distribution<double> N;
  const int n = 1000;
  for (const double delta : {0.0, 2.0}) {
    int pass = 0;
    for (int t = 0; t < n; ++t) {
      Eigen::VectorXd r = delta / norm * model.candidates[0].signature;
      for (Eigen::Index i = 0; i < r.size(); ++i) r(i) += N(rng);
      pass += scoreTests(r, model.jacobian, G).candidates[0].z > 1.6448536 ? 1 : 0;
    }
    const double expected = boost::math::cdf(boost::math::normal(), delta - 1.6448536);
    const auto cp = clopperPearson(pass, n, 0.995);  // two-sided 99 %
    INFO("delta " << delta << ": " << pass << "/" << n << " pass, expected rate " << expected);
    CHECK(cp.lower <= expected);
    CHECK(cp.upper >= expected);
  }
}

TEST_CASE("discovery/montecarlo: false alarms, correct names and the confusable pair", "[doe][discovery]") {
  const TrialModel model = syntheticTrialModel();
  const int n = 400;
  SECTION("Gaussian noise, chi^2 tables with Holm") {
    const TrialCounts null = runTrials(model, {"none", 0, NoiseKind::Gaussian, 0}, n, 11);
    INFO("null: " << null.trials - null.none << " alarms in " << n);
    CHECK(clopperPearson(null.trials - null.none, n).lower <= 0.05);  // consistent with <= 5 %
    const TrialCounts a = runTrials(model, {"A", 6.0, NoiseKind::Gaussian, 0}, n, 12);
    INFO("A at 6: " << a.correct << " correct, " << a.wrongName << " wrong");
    CHECK(clopperPearson(a.correct, n).lower >= 0.85);
    CHECK(clopperPearson(a.wrongName, n).lower <= 0.01);
    const TrialCounts weak = runTrials(model, {"A", 1.0, NoiseKind::Gaussian, 0}, n, 13);
    CHECK(clopperPearson(weak.correct, n).upper < 0.5);  // a size-1 effect is mostly missed...
    CHECK(clopperPearson(weak.wrongName, n).lower <= 0.02);  // ...but not misnamed
    const TrialCounts c = runTrials(model, {"C", 6.0, NoiseKind::Gaussian, 0}, n, 14);
    INFO("C at 6: " << c.ambiguousWithTruth << " ambiguous with C, " << c.correct << " named C, " << c.wrongName << " wrong");
    CHECK(clopperPearson(c.ambiguousWithTruth, n).lower >= 0.8);
    CHECK(clopperPearson(c.wrongName, n).lower <= 0.02);
    // With a strong margin of 20 the same trials also name C on strong evidence over its
    // confusable rival D (right too); both answers happen, and D alone stays rare.
    DecisionOptions strong;
    strong.strongMargin = 20.0;
    const TrialCounts cs = runTrials(model, {"C", 6.0, NoiseKind::Gaussian, 0}, n, 14, strong);
    INFO("C at 6, strong margin 20: " << cs.ambiguousWithTruth << " ambiguous with C, " << cs.correct << " named C, " << cs.wrongName << " wrong");
    CHECK(cs.expected == cs.ambiguousWithTruth + cs.correct);
    CHECK(clopperPearson(cs.expected, n).lower >= 0.8);
    CHECK(cs.correct > 0);
    CHECK(cs.ambiguousWithTruth > cs.correct);
    CHECK(clopperPearson(cs.wrongName, n).lower <= 0.02);
    const TrialCounts out = runTrials(model, {"outside", 8.0, NoiseKind::Gaussian, 0}, n, 15);
    INFO("outside at 8: " << out.unknown << " unknown, " << out.wrongName << " wrong");
    CHECK(clopperPearson(out.unknown, n).lower >= 0.85);
    CHECK(clopperPearson(out.wrongName, n).lower <= 0.02);
  }
  SECTION("t5 noise: empirical thresholds from null trials restore the false-alarm rate") {
    NullStatistics ns;
    runTrials(model, {"none", 0, NoiseKind::StudentT5, 0}, 4000, 21, {}, &ns);
    const NullThresholds t = nullThresholds(ns.zMax, ns.q0, 0.05, ns.qAfter);
    DecisionOptions opt;
    opt.zThreshold = t.zThreshold;
    opt.q0Threshold = t.q0Threshold;
    opt.qAfterThreshold = t.qAfterThreshold;
    const int nNull = 1000;
    const TrialCounts null = runTrials(model, {"none", 0, NoiseKind::StudentT5, 0}, nNull, 22, opt);
    INFO("t5 null with empirical thresholds: " << null.trials - null.none << " alarms in " << nNull);
    CHECK(clopperPearson(null.trials - null.none, nNull).lower <= 0.05);
    const TrialCounts a = runTrials(model, {"A", 6.0, NoiseKind::StudentT5, 0}, n, 23, opt);
    CHECK(clopperPearson(a.correct, n).lower >= 0.8);
    CHECK(clopperPearson(a.wrongName, n).lower <= 0.01);
  }
}
