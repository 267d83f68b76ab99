// Multi-start numerical optimisation of the overall desirability inside the design region
// (Design-Expert "numerical optimization": many starting points, local hill climbing, ranked
// de-duplicated solutions).
//
// Starts: the region centre plus a Latin hypercube drawn from std::mt19937_64(seed). Each start is
// refined with NLopt LN_COBYLA under box bounds. Where D = 0 the objective is replaced by minus the
// summed shortfall outside the desirable ranges (desirabilityShortfall), so the search can climb
// out of flat zero regions. Solutions closer than `dedupTolerance` (coded units, max norm) to a
// better one are dropped.
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
