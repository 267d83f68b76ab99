#include "paddy/doe/discovery.hpp"

#include "paddy/doe/covariance.hpp"
#include "paddy/doe/error.hpp"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <numeric>
#include <optional>
#include <set>

namespace paddy::doe {

namespace {

void checkInput(const DiagnoseInput& in) {
  const auto m = in.residual.size();
  if (m < 1) throw DoeError("residual: empty");
  if (!in.residual.allFinite()) throw DoeError("residual: non-finite value");
  if (in.covariance.rows() != m || in.covariance.cols() != m)
    throw DoeError("covariance: " + std::to_string(in.covariance.rows()) + " x " + std::to_string(in.covariance.cols()) +
                   " but the residual has " + std::to_string(m) + " entries");
  if (in.jacobian.cols() > 0 && in.jacobian.rows() != m)
    throw DoeError("jacobian: " + std::to_string(in.jacobian.rows()) + " rows but the residual has " +
                   std::to_string(m) + " entries");
  if (!in.jacobian.allFinite()) throw DoeError("jacobian: non-finite value");
  std::set<std::string> names;
  for (std::size_t k = 0; k < in.candidates.size(); ++k) {
    const auto& c = in.candidates[k];
    const std::string where = "candidates[" + std::to_string(k + 1) + "]" + (c.name.empty() ? "" : " (" + c.name + ")");
    if (c.name.empty()) throw DoeError(where + ": name is empty");
    if (!names.insert(c.name).second) throw DoeError(where + ": name '" + c.name + "' appears twice");
    if (c.signature.size() != m)
      throw DoeError(where + ": signature has " + std::to_string(c.signature.size()) + " entries, the residual " +
                     std::to_string(m));
    if (!c.signature.allFinite()) throw DoeError(where + ": signature has a non-finite value");
    if (std::isnan(c.low) || std::isnan(c.high) || !(c.low <= c.high))
      throw DoeError(where + ": need low <= high, got [" + std::to_string(c.low) + ", " + std::to_string(c.high) + "]");
    if (!(std::isfinite(c.relevant) && c.relevant >= c.low && (c.relevant < c.high || (c.relevant == 0 && c.high == 0))))
      throw DoeError(where + ": relevant = " + std::to_string(c.relevant) + " must lie in [low, high) = [" + std::to_string(c.low) +
                     ", " + std::to_string(c.high) + ")");
    if (c.priorSd && !(*c.priorSd > 0 && std::isfinite(*c.priorSd)))
      throw DoeError(where + ": prior_sd must be finite and > 0");
    if (c.signatureSeeds.size() == 1)
      throw DoeError(where + ": signature_seeds has 1 entry: give at least 2 (their spread is the signature's noise) or none");
    for (std::size_t s = 0; s < c.signatureSeeds.size(); ++s) {
      const std::string at = where + ": signature_seeds[" + std::to_string(s + 1) + "]";
      if (c.signatureSeeds[s].size() != m)
        throw DoeError(at + " has " + std::to_string(c.signatureSeeds[s].size()) + " entries, the residual " + std::to_string(m));
      if (!c.signatureSeeds[s].allFinite()) throw DoeError(at + " has a non-finite value");
    }
  }
  if (!in.labels.empty() && static_cast<Eigen::Index>(in.labels.size()) != m)
    throw DoeError("labels: " + std::to_string(in.labels.size()) + " names for " + std::to_string(m) + " observables");
  if (!in.blocks.empty() && static_cast<Eigen::Index>(in.blocks.size()) != m)
    throw DoeError("blocks: " + std::to_string(in.blocks.size()) + " names for " + std::to_string(m) + " observables");
  const auto& o = in.options;
  if (!(o.alpha > 0 && o.alpha < 1)) throw DoeError("alpha: must be in (0, 1), got " + std::to_string(o.alpha));
  if (!(o.alphaAfter > 0 && o.alphaAfter < 1))
    throw DoeError("alpha_after: must be in (0, 1), got " + std::to_string(o.alphaAfter));
  if (!(o.confusable > 0 && o.confusable <= 1))
    throw DoeError("confusable: must be in (0, 1], got " + std::to_string(o.confusable));
  if (!(o.bayesMargin >= 1)) throw DoeError("bayes_margin: must be >= 1, got " + std::to_string(o.bayesMargin));
  if (!(o.strongMargin >= o.bayesMargin))
    throw DoeError("strong_margin: must be >= bayes_margin (" + std::to_string(o.bayesMargin) + "), got " + std::to_string(o.strongMargin));
  if (!(o.absorbedTolerance >= 0 && o.absorbedTolerance < 1))
    throw DoeError("absorbed_tolerance: must be in [0, 1), got " + std::to_string(o.absorbedTolerance));
  if (!(o.minRangeZ >= 0)) throw DoeError("min_range_z: must be >= 0");
  if (!(o.detectionPower > 0 && o.detectionPower < 1))
    throw DoeError("detection_power: must be in (0, 1), got " + std::to_string(o.detectionPower));
}

std::optional<double> priorScale(const Candidate& c) {
  if (c.priorSd) return c.priorSd;
  const double w = c.high - c.low;
  if (std::isfinite(w) && w > 0) return w;
  return std::nullopt;
}

// Joint linearised fit of theta and lambda_k: whitened residual left after projecting off [J, g_k].
Eigen::VectorXd residualAfter(const ScoreTests& st, int k) {
  if (k < 0) return st.projectedResidual;
  const auto& s = st.candidates[static_cast<std::size_t>(k)];
  const double lambda = std::max(s.strength, 0.0);
  return st.projectedResidual - lambda * st.projectedSignatures.col(k);
}

}  // namespace

std::vector<double> holmAdjust(const std::vector<double>& p) {
  const std::size_t n = p.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
  std::vector<double> adj(n);
  double running = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    running = std::max(running, std::min(1.0, static_cast<double>(n - i) * p[order[i]]));
    adj[order[i]] = running;
  }
  return adj;
}

std::vector<BlockSeparation> blockSeparations(const Eigen::VectorXd& u, const Eigen::VectorXd& v, double strength,
                                              const std::vector<std::string>& blocks) {
  std::vector<std::string> names;
  for (const auto& b : blocks)
    if (std::find(names.begin(), names.end(), b) == names.end()) names.push_back(b);
  std::vector<BlockSeparation> out;
  for (const auto& name : names) {
    double uu = 0, vv = 0, uv = 0;
    for (std::size_t i = 0; i < blocks.size(); ++i)
      if (blocks[i] == name) {
        const auto j = static_cast<Eigen::Index>(i);
        uu += u(j) * u(j);
        vv += v(j) * v(j);
        uv += u(j) * v(j);
      }
    BlockSeparation s{name, 0.0, 0.0};
    if (uu > 0) {
      const double c2 = vv > 0 ? uv * uv / (uu * vv) : 0.0;
      s.separation = 1.0 - c2;
      s.tCriterion = strength * strength * uu * (1.0 - c2);
    }
    out.push_back(s);
  }
  return out;
}

Diagnosis diagnose(const DiagnoseInput& in) {
  checkInput(in);
  const auto m = in.residual.size();
  const auto K = static_cast<Eigen::Index>(in.candidates.size());
  const auto& o = in.options;
  const Whitening W(in.covariance, "covariance");
  const Eigen::VectorXd r = W.apply(in.residual);
  const Eigen::MatrixXd J = W.apply(in.jacobian.cols() > 0 ? in.jacobian : Eigen::MatrixXd::Zero(m, 0));
  Eigen::MatrixXd Graw(m, K);
  std::vector<std::optional<double>> tau;
  for (Eigen::Index k = 0; k < K; ++k) {
    Graw.col(k) = in.candidates[static_cast<std::size_t>(k)].signature;
    tau.push_back(priorScale(in.candidates[static_cast<std::size_t>(k)]));
  }
  const Eigen::MatrixXd G = W.apply(Graw);
  const ScoreTests st = scoreTests(r, J, G, tau);

  Diagnosis d;
  d.q0 = st.q0;
  d.q0Df = st.df;
  d.q0P = st.q0P;
  d.rank = st.rank;
  d.confusability = st.confusability;
  d.whitenedResidual = r;
  d.projectedResidual = st.projectedResidual;
  d.misfit = std::sqrt(r.squaredNorm() / static_cast<double>(m));
  d.misfitProjected = std::sqrt(st.q0 / static_cast<double>(m));

  // 1. identifiability
  for (Eigen::Index k = 0; k < K; ++k) {
    const auto& c = in.candidates[static_cast<std::size_t>(k)];
    CandidateReport rep;
    rep.name = c.name;
    rep.score = st.candidates[static_cast<std::size_t>(k)];
    const double gNorm = G.col(k).norm();
    const double reach = std::isfinite(c.high) ? std::max(std::abs(c.high), std::abs(c.low)) * std::sqrt(rep.score.a)
                                               : (rep.score.a > 0 ? std::numeric_limits<double>::infinity() : 0.0);
    if (!(gNorm > 0) || 1.0 - rep.score.absorbedFraction < o.absorbedTolerance) {
      rep.identifiable = false;
      rep.notIdentifiableReason = gNorm > 0 ? "absorbed by recalibration" : "no sensitivity (zero signature)";
    } else if (reach < o.minRangeZ) {
      rep.identifiable = false;
      rep.notIdentifiableReason = "no sensitivity in [low, high]";
    }
    rep.zRelevant = c.relevant == 0.0 ? rep.score.z : rep.score.z - c.relevant * std::sqrt(rep.score.a);
    rep.pRelevant = c.relevant == 0.0 ? rep.score.p : boost::math::cdf(boost::math::complement(boost::math::normal(), rep.zRelevant));
    rep.score_rank = rep.score.logBayesFactor ? *rep.score.logBayesFactor : 0.5 * rep.score.z * std::abs(rep.score.z);
    d.candidates.push_back(rep);
  }

  // 2. tests: Holm over Q0 and the identifiable candidates, or empirical thresholds
  std::vector<double> family{st.q0P};
  std::vector<std::size_t> member;
  for (std::size_t k = 0; k < d.candidates.size(); ++k)
    if (d.candidates[k].identifiable) {
      family.push_back(d.candidates[k].pRelevant);
      member.push_back(k);
    }
  const auto adj = holmAdjust(family);
  d.q0PHolm = adj[0];
  for (std::size_t i = 0; i < member.size(); ++i) d.candidates[member[i]].pHolm = adj[i + 1];
  d.q0Significant = o.q0Threshold ? st.q0 > *o.q0Threshold : d.q0PHolm < o.alpha;
  const double zHalf = boost::math::quantile(boost::math::complement(boost::math::normal(), o.alpha / 2));
  for (auto& c : d.candidates) {
    if (!c.identifiable) continue;
    c.passes = o.zThreshold ? c.zRelevant > *o.zThreshold : c.pHolm < o.alpha;
    const auto& cand = *std::find_if(in.candidates.begin(), in.candidates.end(), [&](const Candidate& x) { return x.name == c.name; });
    c.inRange = c.score.strength + zHalf * c.score.strengthSe >= cand.low &&
                c.score.strength - zHalf * c.score.strengthSe <= cand.high;
    c.plausible = c.passes && c.inRange;
  }

  // Detection limits (detection.hpp): the seeds' deviations from their mean, whitened and projected.
  d.detectionThreshold = o.zThreshold ? *o.zThreshold
                                      : boost::math::quantile(boost::math::complement(boost::math::normal(), o.alpha / static_cast<double>(family.size())));
  std::optional<Projection> P;  // only for candidates given with per-seed signatures
  for (Eigen::Index k = 0; k < K; ++k) {
    const auto& c = in.candidates[static_cast<std::size_t>(k)];
    auto& rep = d.candidates[static_cast<std::size_t>(k)];
    std::vector<Eigen::VectorXd> dev;
    if (!c.signatureSeeds.empty() && !P) P.emplace(J);
    for (const auto& gs : c.signatureSeeds) dev.push_back(P->apply(W.apply(Eigen::VectorXd(gs - c.signature))));
    rep.detection = detectability(rep.score.a, rep.score.b, signatureNoise(dev), d.detectionThreshold, o.detectionPower, c.relevant);
    rep.detectable = rep.detection.detectionLimit <= c.high;
  }

  // 3. best plausible candidate
  int best = -1;
  for (std::size_t k = 0; k < d.candidates.size(); ++k)
    if (d.candidates[k].plausible && (best < 0 || d.candidates[k].score_rank > d.candidates[static_cast<std::size_t>(best)].score_rank))
      best = static_cast<int>(k);
  if (best >= 0) d.best = d.candidates[static_cast<std::size_t>(best)].name;

  // 4. decision
  const bool anyPass = std::any_of(d.candidates.begin(), d.candidates.end(), [](const CandidateReport& c) { return c.passes; });
  std::vector<int> rivals;
  if (best >= 0) {
    const auto& b = d.candidates[static_cast<std::size_t>(best)];
    for (std::size_t l = 0; l < d.candidates.size(); ++l) {
      // A rival with close evidence need not pass its own test: with its strength in range it
      // explains the misfit alike (its relevance test may fail only for a larger threshold). A
      // confusable rival with weaker evidence must pass.
      if (static_cast<int>(l) == best || !d.candidates[l].identifiable || !d.candidates[l].inRange) continue;
      const double c = st.confusability(best, static_cast<Eigen::Index>(l));
      const double logRatio = b.score_rank - d.candidates[l].score_rank;
      const bool closeEvidence = logRatio < std::log(o.bayesMargin);
      const bool confusableUndecided = d.candidates[l].plausible && c >= o.confusable && logRatio < std::log(o.strongMargin);
      if (closeEvidence || confusableUndecided) rivals.push_back(static_cast<int>(l));
    }
    std::sort(rivals.begin(), rivals.end(),
              [&](int x, int y) { return d.candidates[static_cast<std::size_t>(x)].score_rank > d.candidates[static_cast<std::size_t>(y)].score_rank; });
  }
  if (!anyPass) {
    d.decision = d.q0Significant ? "unknown" : "none";
    d.reason = d.q0Significant ? "the global misfit is significant but no candidate's score passes"
                               : "neither the global misfit nor any candidate's score is significant";
  } else if (best < 0) {
    d.decision = "unknown";
    d.reason = "candidates pass, but each would need a strength outside its physical range";
  } else if (!rivals.empty()) {
    d.decision = "ambiguous";
    d.ambiguousWith.push_back(d.best);
    for (int l : rivals) d.ambiguousWith.push_back(d.candidates[static_cast<std::size_t>(l)].name);
    d.reason = d.best + " and " + d.ambiguousWith[1] + " explain the misfit alike (confusability " +
               std::to_string(st.confusability(best, rivals[0])) + ")";
    if (!in.blocks.empty()) {
      d.blockSeparations = blockSeparations(st.projectedSignatures.col(best), st.projectedSignatures.col(rivals[0]),
                                            d.candidates[static_cast<std::size_t>(best)].score.strength, in.blocks);
      const auto it = std::max_element(d.blockSeparations.begin(), d.blockSeparations.end(),
                                       [](const BlockSeparation& x, const BlockSeparation& y) { return x.tCriterion < y.tCriterion; });
      if (it != d.blockSeparations.end() && it->tCriterion > 0) d.separatingBlock = it->block;
    }
  } else {
    const auto& b = d.candidates[static_cast<std::size_t>(best)];
    const bool remains = o.qAfterThreshold ? b.score.qAfter > *o.qAfterThreshold : b.score.qAfterP < o.alphaAfter;
    if (remains) {
      d.decision = "unknown";
      d.reason = d.best + " explains part of the misfit, but a significant misfit remains after adding it";
    } else {
      d.decision = "effect";
      d.named = d.best;
      d.reason = d.best + " passes, lies in its physical range, has no rival the data cannot tell from it and leaves no significant misfit";
    }
  }

  // 5. residual map: before, and after recalibration with the named (or best) effect
  const int shown = best;
  const Eigen::VectorXd rAfterW = residualAfter(st, shown);
  d.misfitAfter = std::sqrt(rAfterW.squaredNorm() / static_cast<double>(m));
  // raw residual after the joint fit: solve [J g] beta = r in the whitened least-squares sense
  Eigen::MatrixXd X(m, J.cols() + (shown >= 0 ? 1 : 0));
  if (J.cols() > 0) X.leftCols(J.cols()) = J;
  Eigen::MatrixXd Xraw(m, X.cols());
  if (J.cols() > 0) Xraw.leftCols(J.cols()) = in.jacobian;
  if (shown >= 0) {
    X.col(X.cols() - 1) = G.col(shown);
    Xraw.col(X.cols() - 1) = Graw.col(shown);
  }
  Eigen::VectorXd rawAfter = in.residual;
  if (X.cols() > 0) {
    Eigen::VectorXd beta = X.completeOrthogonalDecomposition().solve(r);
    if (shown >= 0) {  // lambda >= 0: refit without the effect if the joint estimate is negative
      if (beta(beta.size() - 1) < 0 && J.cols() > 0) {
        beta.setZero();
        beta.head(J.cols()) = J.completeOrthogonalDecomposition().solve(r);
      } else if (beta(beta.size() - 1) < 0) {
        beta.setZero();
      }
    }
    rawAfter = in.residual - Xraw * beta;
  }
  for (Eigen::Index i = 0; i < m; ++i) {
    ResidualRow row;
    row.label = in.labels.empty() ? "y" + std::to_string(i + 1) : in.labels[static_cast<std::size_t>(i)];
    row.block = in.blocks.empty() ? "" : in.blocks[static_cast<std::size_t>(i)];
    row.raw = in.residual(i);
    row.standardised = in.residual(i) / W.sd()(i);
    row.standardisedAfter = rawAfter(i) / W.sd()(i);
    row.whitened = r(i);
    row.projected = st.projectedResidual(i);
    d.residualMap.push_back(row);
  }
  return d;
}

}  // namespace paddy::doe
