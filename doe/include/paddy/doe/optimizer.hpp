// Global optimisation of the overall desirability inside the box-shaped design region
// (Design-Expert "numerical optimization": many starting points, local hill climbing, ranked
// de-duplicated solutions), extended so that optima on the region's boundary or on a ridge of D
// are not missed.
//
// D is smooth except on the faces of the box and on the surfaces where a goal sits at the kink of
// its desirability (y = T for a target goal, y = U for a maximise goal, y = L for a minimise goal),
// and its maximum lies in the relative interior of one piece cut out by them: an interior point
// (no factor at a bound), a point of a facet (one factor at a bound), ..., of an edge or a vertex
// of the box, possibly on such a ridge. Each piece is searched as its own smooth problem: for every
// face of the box (a vertex is evaluated) and every set of at most min(3, d) goals held at their
// kinks as equality constraints, NLopt LN_COBYLA climbs D in the face's free factors under its
// bounds from its centre plus a Latin hypercube of max(2, ceil(starts * d / k)) starts (the
// interior gets `starts`), all drawn in a fixed order from std::mt19937_64(seed). The best point of
// all is returned first. With k variable factors there are 3^k faces; all are searched for k <= 6,
// beyond that (or with maxFixedFactors >= 0) only faces with at most that many factors at a bound,
// plus the 2^k vertices (k <= 16).
//
// Where D = 0 the objective is replaced by minus the summed shortfall outside the desirable ranges
// (desirabilityShortfall), so the search can climb out of flat zero regions. Every solution's D is
// evaluated at the point returned. Solutions closer than `dedupTolerance` (coded units, max norm)
// to a better one are dropped.
#pragma once
#include "paddy/doe/design.hpp"
#include "paddy/doe/desirability.hpp"
#include "paddy/doe/model.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace paddy::doe {

struct ResponseModel {
  std::string name;
  Model model;
  Eigen::VectorXd beta;  ///< coded-unit coefficients
  double yMin = 0, yMax = 0;
  double predict(const Eigen::VectorXd& coded) const { return model.predict(beta, coded); }
};

struct OptimizeOptions {
  int starts = 40;
  std::uint64_t seed = 12345;
  double dedupTolerance = 0.02;
  int maxSolutions = 10;
  Eigen::VectorXd lowerCoded, upperCoded;  ///< default: -1 .. +1 for every factor
  /// Faces searched: those with at most this many factors at a bound (plus the vertices);
  /// -1 = automatic (every face for up to 6 factors, else 2).
  int maxFixedFactors = -1;
};

struct Solution {
  Eigen::VectorXd coded, real;
  std::vector<double> predicted;     ///< one per response model
  std::vector<double> desirability;  ///< one per goal
  double overall = 0;
};

std::vector<Solution> optimizeDesirability(const std::vector<Factor>& factors,
                                           const std::vector<ResponseModel>& responses,
                                           const std::vector<GoalSpec>& goals,
                                           const OptimizeOptions& opt = {});

}  // namespace paddy::doe
