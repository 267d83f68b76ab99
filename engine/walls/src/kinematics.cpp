// Prescribed kinematics (see kinematics.hpp). The schedule integral is the exact area under the
// piecewise-linear curve: a trapezoid per knot interval, constant extrapolation outside.
#include <paddy/errors.hpp>
#include <paddy/geometry/kinematics.hpp>

#include <algorithm>
#include <cmath>

namespace paddy::geometry {

SpeedSchedule SpeedSchedule::constant(double v) { return SpeedSchedule({{0.0, v}}); }

SpeedSchedule::SpeedSchedule(std::vector<std::pair<double, double>> knots) : knots_(std::move(knots)) {
  for (std::size_t i = 0; i < knots_.size(); ++i) {
    if (!std::isfinite(knots_[i].first) || !std::isfinite(knots_[i].second))
      throw InputError("speed schedule: knot " + std::to_string(i) + " is not finite");
    if (i > 0 && knots_[i].first < knots_[i - 1].first)
      throw InputError("speed schedule: knot " + std::to_string(i) + " at t = " + std::to_string(knots_[i].first) +
                       " s comes before the previous knot at t = " + std::to_string(knots_[i - 1].first) + " s");
  }
}

SpeedSchedule& SpeedSchedule::then(double t, double v) {
  auto k = knots_;
  k.emplace_back(t, v);
  *this = SpeedSchedule(std::move(k));
  return *this;
}

double SpeedSchedule::value(double t) const {
  if (knots_.empty()) return 0.0;
  if (t < knots_.front().first) return knots_.front().second;
  // Last knot with time <= t (right-continuous at steps).
  auto it = std::upper_bound(knots_.begin(), knots_.end(), t,
                             [](double x, const std::pair<double, double>& k) { return x < k.first; });
  const auto& a = *(it - 1);
  if (it == knots_.end()) return a.second;
  const auto& b = *it;
  return a.second + (b.second - a.second) * (t - a.first) / (b.first - a.first);
}

double SpeedSchedule::integral(double t0, double t1) const {
  if (knots_.empty() || t1 == t0) return 0.0;
  if (t1 < t0) return -integral(t1, t0);
  // Breakpoints inside (t0, t1): on each piece the function is linear, so the trapezoid is exact.
  std::vector<double> pts{t0};
  for (const auto& k : knots_)
    if (k.first > t0 && k.first < t1) pts.push_back(k.first);
  pts.push_back(t1);
  double sum = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const double a = pts[i - 1], b = pts[i];
    if (b <= a) continue;
    // Linear on (a, b): the right limit at a (value() is right-continuous) and the left limit
    // at b, so steps at a or b are attributed to the correct side.
    sum += 0.5 * (value(a) + limitLeft(b)) * (b - a);
  }
  return sum;
}

double SpeedSchedule::limitLeft(double t) const {
  if (knots_.empty()) return 0.0;
  if (t <= knots_.front().first) return knots_.front().second;
  // First knot with time >= t; the piece ending at t runs from the knot before it.
  auto it = std::lower_bound(knots_.begin(), knots_.end(), t,
                             [](const std::pair<double, double>& k, double x) { return k.first < x; });
  if (it == knots_.end()) return knots_.back().second;
  const auto& b = *it;
  const auto& a = *(it - 1);
  return a.second + (b.second - a.second) * (t - a.first) / (b.first - a.first);
}

Kinematics Kinematics::translation(const Vec3& velocity, double t_start, double t_end) {
  Kinematics k;
  const double v = velocity.norm();
  k.direction = v > 0.0 ? Vec3(velocity / v) : Vec3::UnitZ();
  k.speed = SpeedSchedule::constant(v);
  k.t_start = t_start;
  k.t_end = t_end;
  k.validate();
  return k;
}

Kinematics Kinematics::rotation(const Vec3& point, const Vec3& axis, SpeedSchedule omega, double t_start, double t_end) {
  Kinematics k;
  k.axis_point = point;
  k.axis = axis;
  k.angular_speed = std::move(omega);
  k.t_start = t_start;
  k.t_end = t_end;
  k.validate();
  return k;
}

void Kinematics::validate() const {
  if (!(direction.norm() > 0.0) || !direction.allFinite()) throw InputError("kinematics: translation direction must be a finite non-zero vector");
  if (!(axis.norm() > 0.0) || !axis.allFinite()) throw InputError("kinematics: rotation axis must be a finite non-zero vector");
  if (!axis_point.allFinite()) throw InputError("kinematics: rotation axis point must be finite");
  if (std::isnan(t_start) || std::isnan(t_end) || !(t_end >= t_start) || std::isinf(t_start))
    throw InputError("kinematics: time window [" + std::to_string(t_start) + ", " + std::to_string(t_end) +
                     "] s is empty or not finite at its start");
}

double Kinematics::distance(double t) const {
  if (t <= t_start) return 0.0;
  return speed.integral(t_start, std::min(t, t_end));
}

double Kinematics::angle(double t) const {
  if (t <= t_start) return 0.0;
  return angular_speed.integral(t_start, std::min(t, t_end));
}

Pose Kinematics::poseAt(double t, const Pose& placement) const {
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(angle(t), unitAxis()).toRotationMatrix();
  const Vec3 u = unitDirection() * distance(t);
  Pose p;
  p.R = Q * placement.R;
  p.x = Q * (placement.x - axis_point) + axis_point + u;
  return p;
}

}  // namespace paddy::geometry
