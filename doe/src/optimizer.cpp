#include "paddy/doe/optimizer.hpp"

#include "paddy/doe/error.hpp"

#include <algorithm>
#include <nlopt.hpp>
#include <random>

namespace paddy::doe {

namespace {

struct Problem {
  const std::vector<ResponseModel>* responses;
  const std::vector<GoalSpec>* goals;
  std::vector<int> goalResponse;  // index of the response model for each goal
};

std::vector<double> predictAll(const std::vector<ResponseModel>& r, const Eigen::VectorXd& x) {
  std::vector<double> y;
  for (const auto& m : r) y.push_back(m.predict(x));
  return y;
}

double objective(const Problem& pb, const Eigen::VectorXd& x) {
  const auto y = predictAll(*pb.responses, x);
  std::vector<double> yg;
  for (int idx : pb.goalResponse) yg.push_back(y[idx]);
  const double D = overallDesirability(*pb.goals, yg);
  if (D > 0.0) return D;
  double shortfall = 0.0;
  for (std::size_t i = 0; i < yg.size(); ++i) shortfall += desirabilityShortfall((*pb.goals)[i], yg[i]);
  return -shortfall;
}

double nloptObjective(unsigned n, const double* x, double*, void* data) {
  const auto* pb = static_cast<const Problem*>(data);
  return objective(*pb, Eigen::Map<const Eigen::VectorXd>(x, n));
}

}  // namespace

std::vector<Solution> optimizeDesirability(const std::vector<Factor>& factors,
                                           const std::vector<ResponseModel>& responses,
                                           const std::vector<GoalSpec>& goals,
                                           const OptimizeOptions& opt) {
  const int k = static_cast<int>(factors.size());
  if (k == 0) throw DoeError("optimize: no factors");
  if (goals.empty()) throw DoeError("optimize: no goals given");
  Problem pb{&responses, &goals, {}};
  for (const auto& g : goals) {
    validateGoal(g);
    int idx = -1;
    std::string avail;
    for (std::size_t i = 0; i < responses.size(); ++i) {
      if (responses[i].name == g.response) idx = static_cast<int>(i);
      avail += (avail.empty() ? "" : ", ") + responses[i].name;
    }
    if (idx < 0) throw DoeError("optimize: goal for unknown response '" + g.response + "' (available: " + avail + ")");
    if (responses[idx].model.k() != k) throw DoeError("optimize: response model and factors disagree");
    pb.goalResponse.push_back(idx);
  }
  Eigen::VectorXd lo = opt.lowerCoded.size() ? opt.lowerCoded : Eigen::VectorXd::Constant(k, -1.0);
  Eigen::VectorXd hi = opt.upperCoded.size() ? opt.upperCoded : Eigen::VectorXd::Constant(k, 1.0);
  if (lo.size() != k || hi.size() != k) throw DoeError("optimize: bounds need one value per factor");
  for (int j = 0; j < k; ++j)
    if (!(hi(j) >= lo(j))) throw DoeError("optimize: empty search range for factor " + factors[j].name);

  // starts: centre + Latin hypercube
  std::mt19937_64 rng(opt.seed);
  const int m = std::max(1, opt.starts);
  std::vector<Eigen::VectorXd> starts{0.5 * (lo + hi)};
  std::vector<std::vector<int>> strata(k);
  for (int j = 0; j < k; ++j) {
    for (int s = 0; s < m; ++s) strata[j].push_back(s);
    for (int s = m - 1; s > 0; --s) std::swap(strata[j][s], strata[j][rng() % static_cast<std::uint64_t>(s + 1)]);
  }
  for (int s = 0; s < m; ++s) {
    Eigen::VectorXd x(k);
    for (int j = 0; j < k; ++j) {
      const double u = (strata[j][s] + (rng() >> 11) * 0x1.0p-53) / m;
      x(j) = lo(j) + u * (hi(j) - lo(j));
    }
    starts.push_back(x);
  }

  std::vector<Solution> found;
  for (const auto& x0 : starts) {
    std::vector<double> x(x0.data(), x0.data() + k);
    std::vector<double> lb(lo.data(), lo.data() + k), ub(hi.data(), hi.data() + k);
    bool fixedAll = true;
    for (int j = 0; j < k; ++j) fixedAll = fixedAll && lb[j] == ub[j];
    if (!fixedAll) {
      nlopt::opt o(nlopt::LN_COBYLA, static_cast<unsigned>(k));
      o.set_lower_bounds(lb);
      o.set_upper_bounds(ub);
      o.set_max_objective(nloptObjective, &pb);
      o.set_xtol_abs(1e-7);
      o.set_ftol_abs(1e-12);
      o.set_maxeval(2000);
      std::vector<double> step(k);
      for (int j = 0; j < k; ++j) step[j] = std::max(1e-6, 0.1 * (ub[j] - lb[j]));
      o.set_initial_step(step);
      double f = 0;
      try {
        o.optimize(x, f);
      } catch (const std::exception&) {
        // keep the best point NLopt reached (roundoff-limited etc.)
      }
    }
    Solution s;
    s.coded = Eigen::Map<Eigen::VectorXd>(x.data(), k).cwiseMax(lo).cwiseMin(hi);
    s.real = toReal(factors, s.coded);
    s.predicted = predictAll(responses, s.coded);
    for (std::size_t g = 0; g < goals.size(); ++g)
      s.desirability.push_back(desirability(goals[g], s.predicted[pb.goalResponse[g]]));
    std::vector<double> yg;
    for (int idx : pb.goalResponse) yg.push_back(s.predicted[idx]);
    s.overall = overallDesirability(goals, yg);
    found.push_back(s);
  }
  std::stable_sort(found.begin(), found.end(), [](const Solution& a, const Solution& b) { return a.overall > b.overall; });
  std::vector<Solution> out;
  for (const auto& s : found) {
    bool dup = false;
    for (const auto& o : out) dup = dup || (s.coded - o.coded).cwiseAbs().maxCoeff() < opt.dedupTolerance;
    if (!dup) out.push_back(s);
    if (static_cast<int>(out.size()) >= opt.maxSolutions) break;
  }
  return out;
}

}  // namespace paddy::doe
