#include "paddy/doe/steepest_ascent.hpp"

#include "paddy/doe/error.hpp"

#include <cmath>

namespace paddy::doe {

std::vector<PathPoint> steepestPath(const std::vector<Factor>& factors,
                                    const Eigen::VectorXd& b, const PathOptions& opt) {
  const int k = static_cast<int>(factors.size());
  if (b.size() != k) throw DoeError("steepest ascent: need one coefficient per factor");
  if (opt.steps < 0) throw DoeError("steepest ascent: number of steps must be >= 0");
  const double dir = opt.ascent ? 1.0 : -1.0;
  Eigen::VectorXd stepCoded(k);
  if (!opt.realSteps.empty()) {
    if (static_cast<int>(opt.realSteps.size()) != k)
      throw DoeError("steepest ascent: need one real step per factor");
    for (int j = 0; j < k; ++j) {
      const double s = b(j) > 0 ? 1.0 : (b(j) < 0 ? -1.0 : 0.0);
      stepCoded(j) = dir * s * std::abs(opt.realSteps[j]) / factors[j].halfRange();
    }
  } else {
    int key = 0;
    if (opt.keyFactor) key = *opt.keyFactor;
    else b.cwiseAbs().maxCoeff(&key);
    if (key < 0 || key >= k) throw DoeError("steepest ascent: key factor out of range");
    if (b(key) == 0.0) throw DoeError("steepest ascent: key factor " + factors[key].name + " has a zero coefficient");
    const double keyCoded = opt.keyStepReal ? opt.keyStep / factors[key].halfRange() : opt.keyStep;
    stepCoded = dir * b * (std::abs(keyCoded) / std::abs(b(key)));
  }
  const Eigen::VectorXd origin = opt.originReal ? toCoded(factors, *opt.originReal) : Eigen::VectorXd::Zero(k);
  if (origin.size() != k) throw DoeError("steepest ascent: origin has the wrong number of factors");
  std::vector<PathPoint> path;
  for (int s = 0; s <= opt.steps; ++s) {
    PathPoint pt;
    pt.step = s;
    pt.coded = origin + s * stepCoded;
    pt.real = toReal(factors, pt.coded);
    path.push_back(pt);
  }
  return path;
}

double relativeError(double measured, double simulated) {
  if (measured == 0.0) throw DoeError("relative error: the measured value is zero");
  return std::abs(measured - simulated) / std::abs(measured);
}

}  // namespace paddy::doe
