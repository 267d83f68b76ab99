#include "paddy/doe/discovery_trials.hpp"

#include "paddy/doe/bootstrap_null.hpp"
#include "paddy/doe/covariance.hpp"
#include "paddy/doe/error.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace paddy::doe {

namespace {

constexpr int kObservables = 30, kParameters = 3, kBlockSize = 10;

Eigen::VectorXd gaussianVector(std::mt19937_64& rng, Eigen::Index n) {
  std::normal_distribution<double> N(0.0, 1.0);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = N(rng);
  return v;
}

Eigen::VectorXd noiseVector(std::mt19937_64& rng, Eigen::Index n, NoiseKind kind) {
  std::normal_distribution<double> N(0.0, 1.0);
  std::chi_squared_distribution<double> chi5(5.0), chi4(4.0);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    switch (kind) {
      case NoiseKind::Gaussian: v(i) = N(rng); break;
      case NoiseKind::StudentT5: {
        const double z = N(rng), c = chi5(rng);
        v(i) = z / std::sqrt(c / 5.0) * std::sqrt(3.0 / 5.0);  // Var t5 = 5/3
        break;
      }
      case NoiseKind::Skewed: v(i) = (chi4(rng) - 4.0) / std::sqrt(8.0); break;
    }
  }
  return v;
}

}  // namespace

std::string noiseKindName(NoiseKind k) {
  switch (k) {
    case NoiseKind::Gaussian: return "gaussian";
    case NoiseKind::StudentT5: return "t5";
    case NoiseKind::Skewed: return "skewed";
  }
  return "?";
}

TrialModel syntheticTrialModel(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  TrialModel t;
  const Eigen::Index m = kObservables;
  t.jacobian.resize(m, kParameters);
  for (int j = 0; j < kParameters; ++j) t.jacobian.col(j) = gaussianVector(rng, m);
  const Projection P(t.jacobian);
  Eigen::MatrixXd G(m, 4);
  G.col(0) = gaussianVector(rng, m);
  G.col(1) = gaussianVector(rng, m);
  G.col(2) = gaussianVector(rng, m);
  // D: projected part at cos 0.95 to C's, plus a component recalibration absorbs
  const Eigen::VectorXd uC = P.apply(Eigen::VectorXd(G.col(2))).normalized();
  Eigen::VectorXd w = P.apply(gaussianVector(rng, m));
  w -= uC * uC.dot(w);
  w.normalize();
  const double scaleD = 1.3 * P.apply(Eigen::VectorXd(G.col(2))).norm();
  G.col(3) = scaleD * (0.95 * uC + std::sqrt(1.0 - 0.95 * 0.95) * w) + t.jacobian * gaussianVector(rng, kParameters) * 0.5;
  const char* names[] = {"A", "B", "C", "D"};
  t.projectedNorm.resize(4);
  for (int k = 0; k < 4; ++k) {
    Candidate c;
    c.name = names[k];
    c.signature = G.col(k);
    t.projectedNorm(k) = P.apply(Eigen::VectorXd(G.col(k))).norm();
    c.low = 0.0;
    c.high = 10.0 / t.projectedNorm(k);
    t.candidates.push_back(c);
  }
  Eigen::MatrixXd JG(m, kParameters + 4);
  JG << t.jacobian, G;
  t.outside = Projection(JG).apply(gaussianVector(rng, m)).normalized();
  for (Eigen::Index i = 0; i < m; ++i) {
    const char* b[] = {"slump", "rheometer", "lift"};
    t.blocks.push_back(b[i / kBlockSize]);
  }
  return t;
}

TrialCounts runTrials(const TrialModel& model, const TrialScenario& sc, int trials, std::uint64_t seed,
                      const DecisionOptions& options, NullStatistics* collect) {
  if (trials < 1) throw DoeError("runTrials: trials must be >= 1");
  if (sc.replicates == 1 || sc.replicates < 0) throw DoeError("runTrials: replicates must be 0 (Sigma known) or >= 2");
  if (sc.bootstrap < 0 || (sc.bootstrap > 0 && sc.replicates < 2))
    throw DoeError("runTrials: bootstrap thresholds need Sigma estimated from >= 2 replicates");
  const Eigen::Index m = model.jacobian.rows();
  Eigen::VectorXd effect = Eigen::VectorXd::Zero(m);
  int truthIndex = -1;
  if (sc.truth == "outside") {
    effect = sc.size * model.outside;
  } else if (sc.truth != "none") {
    for (std::size_t k = 0; k < model.candidates.size(); ++k)
      if (model.candidates[k].name == sc.truth) truthIndex = static_cast<int>(k);
    if (truthIndex < 0) throw DoeError("runTrials: unknown truth '" + sc.truth + "'");
    effect = sc.size / model.projectedNorm(truthIndex) * model.candidates[static_cast<std::size_t>(truthIndex)].signature;
  }
  const bool confusablePair = sc.truth == "C" || sc.truth == "D";
  std::mt19937_64 rng(seed);
  DiagnoseInput in;
  in.jacobian = model.jacobian;
  in.candidates = model.candidates;
  in.blocks = model.blocks;
  in.options = options;
  in.covariance = Eigen::MatrixXd::Identity(m, m);
  TrialCounts c;
  c.trials = trials;
  for (int t = 0; t < trials; ++t) {
    // y_measured - y_sim(theta^) with theta^ off by a random amount (absorbed by recalibration)
    in.residual = effect + noiseVector(rng, m, sc.noise) + model.jacobian * gaussianVector(rng, model.jacobian.cols());
    if (sc.replicates >= 2) {
      Eigen::MatrixXd X(sc.replicates, m);
      for (int r = 0; r < sc.replicates; ++r) X.row(r) = noiseVector(rng, m, sc.noise).transpose();
      const NoiseCovariance nc = noiseCovariance(X, Eigen::VectorXd(), 1.0);
      in.covariance = nc.covariance;
      if (sc.bootstrap > 0) {
        BootstrapNullInput b;
        b.jacobian = model.jacobian;
        b.candidates = model.candidates;
        b.seedCovariance = nc.seedCovariance;
        b.replicates = sc.replicates;
        b.trials = sc.bootstrap;
        b.seed = rng();
        b.options = options;
        const NullThresholds thr = bootstrapNullThresholds(b);
        in.options.zThreshold = thr.zThreshold;
        in.options.q0Threshold = thr.q0Threshold;
        in.options.qAfterThreshold = thr.qAfterThreshold;
      }
    }
    const Diagnosis d = diagnose(in);
    const bool truthListed = truthIndex >= 0 &&
                             std::find(d.ambiguousWith.begin(), d.ambiguousWith.end(), sc.truth) != d.ambiguousWith.end();
    if (d.decision == "effect") (d.named == sc.truth ? c.correct : c.wrongName)++;
    else if (d.decision == "ambiguous") (truthListed ? c.ambiguousWithTruth : c.ambiguousOther)++;
    else if (d.decision == "unknown") c.unknown++;
    else c.none++;
    if (collect) {
      double zMax = -std::numeric_limits<double>::infinity();
      for (const auto& cr : d.candidates)
        if (cr.identifiable) {
          zMax = std::max(zMax, cr.score.z);
          collect->qAfter.push_back(d.q0 - cr.score.z * cr.score.z);
        }
      collect->zMax.push_back(zMax);
      collect->q0.push_back(d.q0);
    }
  }
  if (sc.truth == "none") c.expected = c.none;
  else if (sc.truth == "outside") c.expected = c.unknown;
  // A confusable pair: ambiguous listing the truth; with a finite strong margin also the truth named
  // on strong evidence (both right; never the rival alone).
  // Below the truth's smallest relevant strength (candidate.relevant): the right answer is not to name it.
  else if (truthIndex >= 0 && sc.size <= model.candidates[static_cast<std::size_t>(truthIndex)].relevant * model.projectedNorm(truthIndex))
    c.expected = c.trials - c.correct - c.wrongName;
  else if (confusablePair) c.expected = c.ambiguousWithTruth + (std::isfinite(options.strongMargin) ? c.correct : 0);
  else c.expected = c.correct;
  return c;
}

}  // namespace paddy::doe
