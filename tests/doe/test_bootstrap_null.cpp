// Bootstrap thresholds of the decision rule (bootstrap_null.hpp): deterministic, refused on bad
// input, and — the point of them — a false-alarm rate at the level alpha when Sigma is estimated
// from few replicates, where the chi^2 tables raise far more alarms.
#include "paddy/doe/bootstrap_null.hpp"
#include "paddy/doe/covariance.hpp"
#include "paddy/doe/discovery_trials.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/null_calibration.hpp"

#include <catch2/catch.hpp>

using namespace paddy::doe;

namespace {

BootstrapNullInput syntheticInput(int trials, std::uint64_t seed) {
  const TrialModel model = syntheticTrialModel();
  BootstrapNullInput in;
  in.jacobian = model.jacobian;
  in.candidates = model.candidates;
  in.seedCovariance = Eigen::MatrixXd::Identity(model.jacobian.rows(), model.jacobian.rows());
  in.replicates = 8;
  in.trials = trials;
  in.seed = seed;
  return in;
}

}  // namespace

TEST_CASE("bootstrap thresholds: same seed, same thresholds; another seed, others", "[doe][discovery][bootstrap]") {
  const NullThresholds a = bootstrapNullThresholds(syntheticInput(200, 7));
  const NullThresholds b = bootstrapNullThresholds(syntheticInput(200, 7));
  const NullThresholds c = bootstrapNullThresholds(syntheticInput(200, 8));
  CHECK(a.zThreshold == b.zThreshold);
  CHECK(a.q0Threshold == b.q0Threshold);
  CHECK(*a.qAfterThreshold == *b.qAfterThreshold);
  CHECK((a.zThreshold != c.zThreshold || a.q0Threshold != c.q0Threshold));
  CHECK(a.trials == 200);
  CHECK(a.alarmRate <= 0.05);
}

TEST_CASE("bootstrap thresholds: with Sigma from few replicates they sit above the chi^2 tables",
          "[doe][discovery][bootstrap]") {
  // 8 replicates of a 30-vector: Q0 under the null is far wider than chi^2(27), whose upper 5 %
  // point is 40.1; the bootstrap must see that.
  const NullThresholds t = bootstrapNullThresholds(syntheticInput(400, 3));
  CHECK(t.q0Threshold > 45.0);
  CHECK(t.zThreshold > 1.96);
}

TEST_CASE("bootstrap thresholds: false alarms at alpha with Sigma from 8 replicates, the chi^2 tables far above",
          "[doe][discovery][bootstrap]") {
  // Nested Monte Carlo on the synthetic model with nothing missing: each trial estimates Sigma from
  // 8 replicates, sets its thresholds from 500 bootstrap trials of that estimate (as the measured
  // table of docs/discovery.md), and diagnoses.
  const TrialModel model = syntheticTrialModel();
  const int trials = 400;
  const TrialCounts boot = runTrials(model, {"none", 0.0, NoiseKind::Gaussian, 8, 500}, trials, 11);
  const TrialCounts tables = runTrials(model, {"none", 0.0, NoiseKind::Gaussian, 8, 0}, trials, 11);
  const int bootAlarms = trials - boot.none, tableAlarms = trials - tables.none;
  // The rate is consistent with <= 5 %: its one-sided 95 % Clopper-Pearson lower bound is below 5 %.
  CHECK(clopperPearson(bootAlarms, trials).lower < 0.05);
  // The tables' rate is not (docs/discovery.md measured 28.8 %), so this test can tell the two apart.
  CHECK(clopperPearson(tableAlarms, trials).lower > 0.10);
}

TEST_CASE("bootstrap thresholds: bad input is refused naming the field", "[doe][discovery][bootstrap]") {
  BootstrapNullInput in = syntheticInput(100, 1);
  in.replicates = 1;
  CHECK_THROWS_WITH(bootstrapNullThresholds(in), Catch::Contains("replicates"));
  in = syntheticInput(10, 1);
  CHECK_THROWS_WITH(bootstrapNullThresholds(in), Catch::Contains("trials"));
  in = syntheticInput(100, 1);
  in.seedCovariance(0, 0) = -1.0;
  CHECK_THROWS_WITH(bootstrapNullThresholds(in), Catch::Contains("positive semi-definite"));
  in = syntheticInput(100, 1);
  in.seedCovariance(0, 1) = 0.5;
  CHECK_THROWS_WITH(bootstrapNullThresholds(in), Catch::Contains("symmetric"));
  in = syntheticInput(100, 1);
  in.sigma = Eigen::VectorXd::Ones(3);
  CHECK_THROWS_WITH(bootstrapNullThresholds(in), Catch::Contains("sigma"));
}
