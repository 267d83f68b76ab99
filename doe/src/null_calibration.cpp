#include "paddy/doe/null_calibration.hpp"

#include "paddy/doe/error.hpp"

#include <algorithm>
#include <boost/math/distributions/beta.hpp>
#include <cmath>
#include <functional>
#include <string>

namespace paddy::doe {

namespace {

void checkList(const std::vector<double>& v, const char* what) {
  if (v.empty()) throw DoeError(std::string(what) + ": no null-trial values");
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i])) throw DoeError(std::string(what) + "[" + std::to_string(i + 1) + "]: not finite");
}

// The value with `exceed` values strictly above it in a descending sort (the (exceed+1)-th largest).
double upperOrderStatistic(std::vector<double> v, std::size_t exceed) {
  std::sort(v.begin(), v.end(), std::greater<>());
  return v[std::min(exceed, v.size() - 1)];
}

}  // namespace

BinomialBounds clopperPearson(int x, int n, double confidence) {
  if (n < 1 || x < 0 || x > n) throw DoeError("clopperPearson: need 0 <= successes <= trials, trials >= 1");
  if (!(confidence > 0 && confidence < 1)) throw DoeError("clopperPearson: confidence must be in (0, 1)");
  BinomialBounds b;
  b.rate = static_cast<double>(x) / n;
  const double tail = 1.0 - confidence;
  b.lower = x == 0 ? 0.0 : boost::math::quantile(boost::math::beta_distribution<>(x, n - x + 1), tail);
  b.upper = x == n ? 1.0 : boost::math::quantile(boost::math::beta_distribution<>(x + 1, n - x), confidence);
  return b;
}

NullThresholds nullThresholds(const std::vector<double>& zMax, const std::vector<double>& q0, double alpha,
                              const std::vector<double>& qAfter) {
  checkList(zMax, "z_max");
  checkList(q0, "q0");
  if (!qAfter.empty()) checkList(qAfter, "q_after");
  if (!(alpha > 0 && alpha < 1)) throw DoeError("alpha: must be in (0, 1), got " + std::to_string(alpha));
  NullThresholds t;
  if (zMax.size() == q0.size()) {
    const std::size_t n = zMax.size();
    const auto allowed = static_cast<std::size_t>(std::floor(alpha * static_cast<double>(n)));
    std::size_t j = 0;
    int alarms = 0;
    // largest j whose thresholds give at most `allowed` alarms (alarms grow with j)
    for (std::size_t cand = 0; cand < n; ++cand) {
      const double tz = upperOrderStatistic(zMax, cand), tq = upperOrderStatistic(q0, cand);
      int count = 0;
      for (std::size_t i = 0; i < n; ++i) count += (zMax[i] > tz || q0[i] > tq) ? 1 : 0;
      if (static_cast<std::size_t>(count) > allowed) break;
      j = cand;
      alarms = count;
      t.zThreshold = tz;
      t.q0Threshold = tq;
    }
    if (j == 0) {
      t.zThreshold = upperOrderStatistic(zMax, 0);
      t.q0Threshold = upperOrderStatistic(q0, 0);
      alarms = 0;
    }
    t.trials = static_cast<int>(n);
    t.alarms = alarms;
    t.paired = true;
  } else {
    const auto ez = static_cast<std::size_t>(std::floor(alpha / 2 * static_cast<double>(zMax.size())));
    const auto eq = static_cast<std::size_t>(std::floor(alpha / 2 * static_cast<double>(q0.size())));
    t.zThreshold = upperOrderStatistic(zMax, ez);
    t.q0Threshold = upperOrderStatistic(q0, eq);
    t.trials = static_cast<int>(std::min(zMax.size(), q0.size()));
    int az = 0, aq = 0;
    for (double z : zMax) az += z > t.zThreshold ? 1 : 0;
    for (double q : q0) aq += q > t.q0Threshold ? 1 : 0;
    t.alarms = std::min(t.trials, static_cast<int>(std::lround(static_cast<double>(az) / zMax.size() * t.trials +
                                                               static_cast<double>(aq) / q0.size() * t.trials)));
    t.paired = false;
  }
  const auto cp = clopperPearson(t.alarms, t.trials, 0.95);
  t.alarmRate = cp.rate;
  t.alarmRateUpper = cp.upper;
  if (!qAfter.empty())
    t.qAfterThreshold = upperOrderStatistic(qAfter, static_cast<std::size_t>(std::floor(alpha * static_cast<double>(qAfter.size()))));
  return t;
}

}  // namespace paddy::doe
