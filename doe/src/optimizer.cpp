#include "paddy/doe/optimizer.hpp"

#include "paddy/doe/error.hpp"

#include <algorithm>
#include <cmath>
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

// Automatic face selection: every face up to this many variable factors (3^6 = 729 faces),
// beyond it only the faces with at most kFixedBeyondAllFaces fixed factors, plus the vertices.
constexpr int kAllFacesUpTo = 6;
constexpr int kFixedBeyondAllFaces = 2;
// At most this many goals are pinned at their kinks at once (subsets of up to 3 of the goals).
constexpr int kMaxPinnedGoals = 3;
constexpr std::size_t kMaxGoals = 20;

// One face of the search box: every factor is fixed at its lower bound, fixed at its upper bound,
// or free inside its range. The interior is the face with every factor free, a vertex the face
// with none free.
struct Face {
  Eigen::VectorXd fixedPoint;  // the fixed coordinates (free ones hold the range centre)
  std::vector<int> free;       // indices of the free factors
};

// The objective restricted to a face: x_free -> D(point of the face).
struct FaceObjective {
  const Problem* pb;
  const Face* face;
  Eigen::VectorXd fullPoint(const double* xFree) const {
    Eigen::VectorXd x = face->fixedPoint;
    for (std::size_t i = 0; i < face->free.size(); ++i) x(face->free[i]) = xFree[i];
    return x;
  }
};

double nloptFaceObjective(unsigned, const double* x, double*, void* data) {
  const auto* fo = static_cast<const FaceObjective*>(data);
  return objective(*fo->pb, fo->fullPoint(x));
}

// Faces in a fixed order: interior first, then faces by increasing number of fixed factors, each
// fixed factor at its lower bound before its upper bound. A factor with an empty range (lo == hi)
// is fixed on every face. Faces with more than maxFixed fixed factors are left out, except the
// vertices (all factors fixed), which are included up to kMaxVertexFactors variable factors.
constexpr int kMaxVertexFactors = 16;

std::vector<Face> enumerateFaces(const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, int maxFixed) {
  const int k = static_cast<int>(lo.size());
  std::vector<int> variable;  // factors with a non-empty range
  for (int j = 0; j < k; ++j)
    if (hi(j) > lo(j)) variable.push_back(j);
  const int n = static_cast<int>(variable.size());
  std::vector<Face> faces;
  for (int fixedCount = 0; fixedCount <= n; ++fixedCount) {
    if (fixedCount > maxFixed && (fixedCount < n || n > kMaxVertexFactors)) continue;
    // choose which variable factors are fixed (lexicographic subsets), then their sides (binary)
    std::vector<int> pick(fixedCount);
    for (int i = 0; i < fixedCount; ++i) pick[i] = i;
    while (true) {
      for (std::uint64_t sides = 0; sides < (std::uint64_t{1} << fixedCount); ++sides) {
        Face f;
        f.fixedPoint = 0.5 * (lo + hi);
        for (int j = 0; j < k; ++j)
          if (!(hi(j) > lo(j))) f.fixedPoint(j) = lo(j);
        std::vector<bool> isFixed(k, false);
        for (int i = 0; i < fixedCount; ++i) {
          const int j = variable[pick[i]];
          isFixed[j] = true;
          f.fixedPoint(j) = ((sides >> i) & 1U) ? hi(j) : lo(j);
        }
        for (int j : variable)
          if (!isFixed[j]) f.free.push_back(j);
        faces.push_back(std::move(f));
      }
      // next subset
      int i = fixedCount - 1;
      while (i >= 0 && pick[i] == n - fixedCount + i) --i;
      if (i < 0) break;
      ++pick[i];
      for (int m = i + 1; m < fixedCount; ++m) pick[m] = pick[m - 1] + 1;
    }
  }
  return faces;
}

// Centre of the face plus a Latin hypercube of m points over its free factors.
std::vector<std::vector<double>> faceStarts(const Face& f, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                                            int m, std::mt19937_64& rng) {
  const int d = static_cast<int>(f.free.size());
  std::vector<std::vector<double>> starts;
  std::vector<double> centre;
  for (int j : f.free) centre.push_back(0.5 * (lo(j) + hi(j)));
  starts.push_back(centre);
  std::vector<std::vector<int>> strata(d);
  for (int i = 0; i < d; ++i) {
    for (int s = 0; s < m; ++s) strata[i].push_back(s);
    for (int s = m - 1; s > 0; --s) std::swap(strata[i][s], strata[i][rng() % static_cast<std::uint64_t>(s + 1)]);
  }
  for (int s = 0; s < m; ++s) {
    std::vector<double> x(d);
    for (int i = 0; i < d; ++i) {
      const int j = f.free[i];
      const double u = (strata[i][s] + (rng() >> 11) * 0x1.0p-53) / m;
      x[i] = lo(j) + u * (hi(j) - lo(j));
    }
    starts.push_back(x);
  }
  return starts;
}

// The value at which goal g's desirability has a kink that can carry the maximum on a ridge: the
// target of a target goal, the upper limit of a maximise goal, the lower limit of a minimise goal
// (NaN for an in-range goal, whose d is flat).
double kinkValue(const GoalSpec& g) {
  switch (g.goal) {
    case Goal::Target: return g.target;
    case Goal::Maximize: return g.upper;
    case Goal::Minimize: return g.lower;
    case Goal::InRange: break;
  }
  return std::nan("");
}

// Equality constraint y_g(x) = kink value of goal g, on a face.
struct KinkConstraint {
  const FaceObjective* fo;
  int goal;
  double value;
};

double nloptKinkConstraint(unsigned, const double* x, double*, void* data) {
  const auto* c = static_cast<const KinkConstraint*>(data);
  const Problem& pb = *c->fo->pb;
  return (*pb.responses)[pb.goalResponse[c->goal]].predict(c->fo->fullPoint(x)) - c->value;
}

// Local maximisation on one face from one start (LN_COBYLA under the face's box bounds), with the
// goals in `pinned` held at their kink values as equality constraints.
Eigen::VectorXd climbFace(const Problem& pb, const Face& f, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                          const std::vector<int>& pinned, std::vector<double> x) {
  const int d = static_cast<int>(f.free.size());
  FaceObjective fo{&pb, &f};
  std::vector<KinkConstraint> constraints;
  for (int g : pinned) constraints.push_back({&fo, g, kinkValue((*pb.goals)[g])});
  std::vector<double> lb(d), ub(d), step(d);
  for (int i = 0; i < d; ++i) {
    lb[i] = lo(f.free[i]);
    ub[i] = hi(f.free[i]);
    step[i] = std::max(1e-6, 0.1 * (ub[i] - lb[i]));
  }
  nlopt::opt o(nlopt::LN_COBYLA, static_cast<unsigned>(d));
  o.set_lower_bounds(lb);
  o.set_upper_bounds(ub);
  o.set_max_objective(nloptFaceObjective, &fo);
  o.set_xtol_abs(1e-7);
  o.set_ftol_abs(1e-12);
  o.set_maxeval(2000);
  o.set_initial_step(step);
  for (auto& c : constraints) {
    const GoalSpec& g = (*pb.goals)[c.goal];
    o.add_equality_constraint(nloptKinkConstraint, &c, 1e-10 * (g.upper - g.lower));
  }
  double value = 0;
  try {
    o.optimize(x, value);
  } catch (const std::exception&) {
    // keep the best point NLopt reached (roundoff-limited etc.)
  }
  for (int i = 0; i < d; ++i) x[i] = std::clamp(x[i], lb[i], ub[i]);
  return fo.fullPoint(x.data());
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
  if (goals.size() > kMaxGoals)
    throw DoeError("optimize: " + std::to_string(goals.size()) + " goals given, at most " + std::to_string(kMaxGoals));
  if (opt.starts < 1) throw DoeError("optimize: starts must be >= 1 (got " + std::to_string(opt.starts) + ")");
  if (opt.maxFixedFactors < -1)
    throw DoeError("optimize: maxFixedFactors must be -1 (automatic) or >= 0 (got " +
                   std::to_string(opt.maxFixedFactors) + ")");

  // Every face of the box (interior, faces, edges, vertices) is searched as its own bounded
  // problem in its free factors, from the face centre plus a Latin hypercube; the best point of
  // all faces is the global optimum up to the local searches' convergence.
  int variable = 0;
  for (int j = 0; j < k; ++j) variable += hi(j) > lo(j) ? 1 : 0;
  const int maxFixed = opt.maxFixedFactors >= 0 ? opt.maxFixedFactors
                                                : (variable <= kAllFacesUpTo ? variable : kFixedBeyondAllFaces);
  const auto faces = enumerateFaces(lo, hi, maxFixed);
  // Goals with a kink (all but in-range goals) and the subsets of them to pin, smallest first.
  std::vector<int> kinked;
  for (int g = 0; g < static_cast<int>(goals.size()); ++g)
    if (!std::isnan(kinkValue(goals[g]))) kinked.push_back(g);
  const int pinnable = std::min(static_cast<int>(kinked.size()), kMaxPinnedGoals);
  std::vector<std::vector<int>> pinnedSets;
  for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << kinked.size()); ++mask) {
    std::vector<int> set;
    for (std::size_t i = 0; i < kinked.size(); ++i)
      if ((mask >> i) & 1U) set.push_back(kinked[i]);
    if (static_cast<int>(set.size()) <= pinnable) pinnedSets.push_back(set);
  }
  std::stable_sort(pinnedSets.begin(), pinnedSets.end(),
                   [](const std::vector<int>& a, const std::vector<int>& b) { return a.size() < b.size(); });
  std::mt19937_64 rng(opt.seed);
  std::vector<Eigen::VectorXd> points;
  for (const auto& f : faces) {
    const int d = static_cast<int>(f.free.size());
    if (d == 0) {
      points.push_back(f.fixedPoint);
      continue;
    }
    // the interior gets opt.starts random starts, a face of dimension d proportionally fewer
    const int m = std::max(2, (opt.starts * d + variable - 1) / variable);
    // every set of goals pinned at their kinks, at most d of them (none first)
    for (const auto& pinned : pinnedSets) {
      if (static_cast<int>(pinned.size()) > d) continue;
      for (auto& x0 : faceStarts(f, lo, hi, m, rng)) points.push_back(climbFace(pb, f, lo, hi, pinned, std::move(x0)));
    }
  }

  std::vector<Solution> found;
  for (const auto& x : points) {
    Solution s;
    s.coded = x;
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
