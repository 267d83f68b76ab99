// Piecewise motion of a wall (see kinematics.hpp): segments of Kinematics, each re-based on the
// pose the previous one reached at its switch time, so the wall never jumps and pose, distance
// and angle stay closed forms.
#include <paddy/errors.hpp>
#include <paddy/geometry/kinematics.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace paddy::geometry {

Motion::Motion(const Pose& placement, Kinematics k) {
  k.validate();
  segments_.push_back({-std::numeric_limits<double>::infinity(), placement, std::move(k)});
}

void Motion::reset(Kinematics k) {
  k.validate();
  const Pose placement = segments_.front().base;
  segments_.clear();
  segments_.push_back({-std::numeric_limits<double>::infinity(), placement, std::move(k)});
}

void Motion::change(double t_switch, Kinematics k) {
  if (!std::isfinite(t_switch))
    throw InputError("motion change: switch time " + std::to_string(t_switch) + " s must be finite");
  k.validate();
  // The first segment starts at −∞, so at least it remains.
  while (segments_.back().t_from >= t_switch) segments_.pop_back();
  const State s = at(t_switch);
  k.t_start = std::max(k.t_start, t_switch);
  k.t_end = std::max(k.t_end, k.t_start);
  segments_.push_back({t_switch, s.pose, std::move(k), s.distance, s.angle, s.translation});
}

const Motion::Segment& Motion::segmentAt(double t) const {
  // Few segments (one per change of motion): search from the latest.
  for (auto it = segments_.rbegin(); it != segments_.rend(); ++it)
    if (t >= it->t_from) return *it;
  return segments_.front();  // t = NaN
}

Motion::State Motion::at(double t) const {
  const Segment& g = segmentAt(t);
  const Kinematics& k = g.kin;
  const Vec3 d = k.unitDirection();
  const double dist = k.distance(t);
  State s;
  s.pose = k.poseAt(t, g.base);
  s.velocity = d * k.speedAt(t);
  s.axis = k.unitAxis();
  s.omega = s.axis * k.angularSpeedAt(t);
  s.axis_point = k.axis_point + d * dist;
  s.distance = g.distance0 + dist;
  s.angle = g.angle0 + k.angle(t);
  s.translation = g.translation0 + d * dist;
  return s;
}

}  // namespace paddy::geometry
