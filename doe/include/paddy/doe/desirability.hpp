// Derringer-Suich desirability functions (Derringer & Suich 1980, "Simultaneous optimization of
// several response variables", J. Quality Technology 12; Design-Expert "numerical optimization").
//
// Individual desirability d(y) in [0, 1] with lower limit L, upper limit U, target T, shape
// exponents (weights) w1, w2:
//   maximise: 0 for y <= L, ((y - L)/(U - L))^w1 for L < y < U, 1 for y >= U
//   minimise: 1 for y <= L, ((U - y)/(U - L))^w1 for L < y < U, 0 for y >= U
//   target  : ((y - L)/(T - L))^w1 for L <= y <= T, ((U - y)/(U - T))^w2 for T <= y <= U, else 0
//   in range: 1 for L <= y <= U, else 0
// Overall D = (prod_i d_i^(r_i))^(1 / sum_i r_i) with importances r_i in 1..5.
#pragma once
#include <string>
#include <vector>

namespace paddy::doe {

enum class Goal { Maximize, Minimize, Target, InRange };

struct GoalSpec {
  std::string response;
  Goal goal = Goal::Target;
  double lower = 0, upper = 1, target = 0;
  double weight1 = 1, weight2 = 1;
  int importance = 3;
};

double desirability(const GoalSpec& g, double y);
/// Geometric mean of the d_i weighted by importance.
double overallDesirability(const std::vector<GoalSpec>& goals, const std::vector<double>& y);
/// Distance (in units of U - L) by which y lies outside the region where d > 0; 0 inside.
double desirabilityShortfall(const GoalSpec& g, double y);
/// Throws DoeError if limits/target/weights/importance are inconsistent.
void validateGoal(const GoalSpec& g);

/// Parse "Y=target:231", "Y=max", "Y=min", "Y=range", with optional ",lo=..,hi=..,w=..,w2=..,imp=.."
/// (limits default to the observed response range yMin..yMax, as Design-Expert does).
GoalSpec parseGoal(const std::string& spec, double yMin, double yMax);
std::string goalName(Goal g);

}  // namespace paddy::doe
