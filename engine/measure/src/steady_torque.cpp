// Steady-state criterion for the vane torque of one speed step (batch means in the rotation
// angle, trend t test, drift tolerance). Formulas in paddy/measure/steady_torque.hpp.
#include <paddy/errors.hpp>
#include <paddy/measure/steady_torque.hpp>

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace paddy::measure {

namespace {

void checkOptions(const SteadyTorqueOptions& o) {
  std::ostringstream s;
  if (!(o.window_angle > 0.0) || !std::isfinite(o.window_angle))
    s << "window_angle = " << o.window_angle << " rad must be finite and > 0";
  else if (o.windows < 3) s << "windows = " << o.windows << " must be >= 3 (a trend needs k - 2 >= 1 degrees of freedom)";
  else if (!(o.min_angle >= 0.0) || !std::isfinite(o.min_angle)) s << "min_angle = " << o.min_angle << " rad must be finite and >= 0";
  else if (!(o.alpha > 0.0 && o.alpha < 1.0)) s << "alpha = " << o.alpha << " must be in (0, 1)";
  else if (!(o.drift_tolerance > 0.0) || !std::isfinite(o.drift_tolerance))
    s << "drift_tolerance = " << o.drift_tolerance << " must be finite and > 0";
  if (!s.str().empty()) throw InputError("steady torque: " + s.str());
}

}  // namespace

SteadyTorqueResult steadyTorque(const std::vector<double>& angle, const std::vector<double>& torque,
                                const SteadyTorqueOptions& o) {
  checkOptions(o);
  if (angle.size() != torque.size())
    throw InputError("steady torque: " + std::to_string(angle.size()) + " angles but " + std::to_string(torque.size()) +
                     " torques");
  for (std::size_t i = 0; i < angle.size(); ++i) {
    if (!std::isfinite(angle[i]) || !std::isfinite(torque[i]) || angle[i] < 0.0) {
      std::ostringstream s;
      s << "steady torque: sample " << i << " has angle " << angle[i] << " rad and torque " << torque[i]
        << " N m; the angle must be finite and >= 0, the torque finite";
      throw InputError(s.str());
    }
    if (i > 0 && angle[i] < angle[i - 1])
      throw InputError("steady torque: the angle decreases at sample " + std::to_string(i));
  }
  SteadyTorqueResult r;
  if (angle.empty()) {
    r.reason = "no samples";
    return r;
  }
  const double w = o.window_angle;
  r.angle = angle.back();
  r.complete_windows = int(std::floor(r.angle / w));
  const int k = std::min(o.windows, r.complete_windows);
  r.compared_windows = k;
  if (k == 0) {  // no complete window: the mean of all samples, nothing else
    double sum = 0.0;
    for (double t : torque) sum += t;
    r.mean = sum / double(torque.size());
    r.reason = "no complete window yet";
    return r;
  }
  // Window means of the last k complete windows j = first .. first + k − 1.
  const int first = r.complete_windows - k;
  std::vector<double> sum(std::size_t(k), 0.0);
  std::vector<int> count(std::size_t(k), 0);
  for (std::size_t i = 0; i < angle.size(); ++i) {
    const int j = int(std::floor(angle[i] / w)) - first;
    if (j < 0 || j >= k) continue;
    sum[std::size_t(j)] += torque[i];
    ++count[std::size_t(j)];
  }
  r.window_means.resize(std::size_t(k));
  for (int j = 0; j < k; ++j) {
    if (count[std::size_t(j)] == 0) {
      std::ostringstream s;
      s << "steady torque: window " << first + j << " (" << (first + j) * w << " to " << (first + j + 1) * w
        << " rad) has no sample; sample more often than every window_angle = " << w << " rad";
      throw InputError(s.str());
    }
    r.window_means[std::size_t(j)] = sum[std::size_t(j)] / count[std::size_t(j)];
  }
  double m = 0.0;
  for (double v : r.window_means) m += v;
  m /= k;
  r.mean = m;
  if (k >= 2) {
    double ss = 0.0;
    for (double v : r.window_means) ss += (v - m) * (v - m);
    r.standard_error = std::sqrt(ss / (k - 1) / k);
  }
  if (k < 3) {
    r.reason = "only " + std::to_string(k) + " complete windows";
    return r;
  }
  // Trend: least squares through the window centres (uniformly spaced: θ_j − θ̄ = (j − (k−1)/2)Δθ).
  double sxx = 0.0, sxy = 0.0;
  for (int j = 0; j < k; ++j) {
    const double x = (j - 0.5 * (k - 1)) * w;
    sxx += x * x;
    sxy += x * (r.window_means[std::size_t(j)] - m);
  }
  const double b = sxy / sxx;
  double sse = 0.0;
  for (int j = 0; j < k; ++j) {
    const double e = r.window_means[std::size_t(j)] - m - b * (j - 0.5 * (k - 1)) * w;
    sse += e * e;
  }
  r.trend = b;
  r.trend_standard_error = std::sqrt(sse / (k - 2) / sxx);
  if (r.trend_standard_error > 0.0) {
    const boost::math::students_t dist(double(k - 2));
    r.trend_p_value = 2.0 * boost::math::cdf(boost::math::complement(dist, std::abs(b) / r.trend_standard_error));
  } else {
    r.trend_p_value = b == 0.0 ? 1.0 : 0.0;  // no scatter: any slope is certain
  }
  const double change = std::abs(b) * k * w;
  r.drift = m != 0.0 ? change / std::abs(m) : (change == 0.0 ? 0.0 : std::numeric_limits<double>::infinity());

  std::ostringstream why;
  if (r.complete_windows < o.windows) why << "only " << r.complete_windows << " of " << o.windows << " windows complete";
  else if (r.angle < o.min_angle) why << "turned " << r.angle << " rad, less than min_angle " << o.min_angle << " rad";
  else if (r.trend_p_value < o.alpha) why << "significant trend (p = " << r.trend_p_value << " < " << o.alpha << ")";
  else if (r.drift > o.drift_tolerance) why << "drift " << r.drift << " of the mean exceeds " << o.drift_tolerance;
  r.reason = why.str();
  r.steady = r.reason.empty();
  return r;
}

}  // namespace paddy::measure
