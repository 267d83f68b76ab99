#include "paddy/doe/desirability.hpp"

#include "paddy/doe/error.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace paddy::doe {

std::string goalName(Goal g) {
  switch (g) {
    case Goal::Maximize: return "maximize";
    case Goal::Minimize: return "minimize";
    case Goal::Target: return "target";
    case Goal::InRange: return "in range";
  }
  return "?";
}

void validateGoal(const GoalSpec& g) {
  const std::string who = "goal for " + g.response + ": ";
  if (!(g.upper > g.lower)) throw DoeError(who + "upper limit must exceed lower limit");
  if (g.goal == Goal::Target && !(g.target >= g.lower && g.target <= g.upper)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "target %g must lie within the limits [%g, %g]", g.target, g.lower, g.upper);
    throw DoeError(who + buf + " (limits default to the observed range; set them with lo=...,hi=...)");
  }
  if (g.goal == Goal::Target && (g.target == g.lower || g.target == g.upper))
    throw DoeError(who + "target must lie strictly inside the limits");
  if (!(g.weight1 > 0) || !(g.weight2 > 0)) throw DoeError(who + "weights must be > 0");
  if (g.importance < 1 || g.importance > 5) throw DoeError(who + "importance must be 1..5");
}

double desirability(const GoalSpec& g, double y) {
  const double L = g.lower, U = g.upper;
  switch (g.goal) {
    case Goal::Maximize:
      if (y <= L) return 0.0;
      if (y >= U) return 1.0;
      return std::pow((y - L) / (U - L), g.weight1);
    case Goal::Minimize:
      if (y <= L) return 1.0;
      if (y >= U) return 0.0;
      return std::pow((U - y) / (U - L), g.weight1);
    case Goal::Target:
      if (y < L || y > U) return 0.0;
      if (y <= g.target) return std::pow((y - L) / (g.target - L), g.weight1);
      return std::pow((U - y) / (U - g.target), g.weight2);
    case Goal::InRange: return (y >= L && y <= U) ? 1.0 : 0.0;
  }
  return 0.0;
}

double desirabilityShortfall(const GoalSpec& g, double y) {
  const double span = g.upper - g.lower;
  double lo = g.lower, hi = g.upper;
  if (g.goal == Goal::Maximize) hi = INFINITY;
  if (g.goal == Goal::Minimize) lo = -INFINITY;
  if (y < lo) return (lo - y) / span;
  if (y > hi) return (y - hi) / span;
  return 0.0;
}

double overallDesirability(const std::vector<GoalSpec>& goals, const std::vector<double>& y) {
  if (goals.empty()) throw DoeError("desirability: no goals");
  if (y.size() != goals.size()) throw DoeError("desirability: one response value per goal needed");
  double logSum = 0.0, rSum = 0.0;
  for (std::size_t i = 0; i < goals.size(); ++i) {
    const double d = desirability(goals[i], y[i]);
    if (d <= 0.0) return 0.0;
    logSum += goals[i].importance * std::log(d);
    rSum += goals[i].importance;
  }
  return std::exp(logSum / rSum);
}

namespace {
double number(const std::string& s, const std::string& spec) {
  try {
    std::size_t pos = 0;
    const double v = std::stod(s, &pos);
    if (pos != s.size()) throw std::invalid_argument(s);
    return v;
  } catch (...) {
    throw DoeError("goal '" + spec + "': '" + s + "' is not a number");
  }
}
}  // namespace

GoalSpec parseGoal(const std::string& spec, double yMin, double yMax) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0)
    throw DoeError("goal '" + spec + "': expected NAME=target:VALUE, NAME=max, NAME=min or NAME=range");
  GoalSpec g;
  g.response = spec.substr(0, eq);
  g.lower = yMin;
  g.upper = yMax;
  std::stringstream ss(spec.substr(eq + 1));
  std::string part;
  bool first = true;
  while (std::getline(ss, part, ',')) {
    if (first) {
      first = false;
      const auto c = part.find(':');
      const std::string kind = part.substr(0, c);
      if (kind == "target") {
        if (c == std::string::npos) throw DoeError("goal '" + spec + "': target needs a value, e.g. target:231");
        g.goal = Goal::Target;
        g.target = number(part.substr(c + 1), spec);
      } else if (kind == "max" || kind == "maximize") g.goal = Goal::Maximize;
      else if (kind == "min" || kind == "minimize") g.goal = Goal::Minimize;
      else if (kind == "range" || kind == "inrange") g.goal = Goal::InRange;
      else throw DoeError("goal '" + spec + "': unknown goal '" + kind + "' (target, max, min, range)");
      continue;
    }
    const auto k = part.find('=');
    if (k == std::string::npos) throw DoeError("goal '" + spec + "': option '" + part + "' must be key=value");
    const std::string key = part.substr(0, k);
    const double v = number(part.substr(k + 1), spec);
    if (key == "lo") g.lower = v;
    else if (key == "hi") g.upper = v;
    else if (key == "w" || key == "w1") g.weight1 = v;
    else if (key == "w2") g.weight2 = v;
    else if (key == "imp") g.importance = static_cast<int>(v);
    else throw DoeError("goal '" + spec + "': unknown option '" + key + "' (lo, hi, w, w2, imp)");
  }
  validateGoal(g);
  return g;
}

}  // namespace paddy::doe
