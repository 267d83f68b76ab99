// Prescribed rigid-body motion of a wall: translation along a direction and rotation about an
// axis (point + direction), each with a piecewise-linear speed schedule, active in a time window.
//
// Pose at time t (body point X, initial placement x ← R0·X + x0, axis point a0, unit axis â):
//   u(t) = d̂ · ∫ v(s) ds,   θ(t) = ∫ ω(s) ds     (integrals over [t_start, min(t, t_end)])
//   x(X, t) = Q(θ)·(R0·X + x0 − a0) + a0 + u(t),    Q(θ) = rotation by θ about â
//   velocity of the material point at p: u̇ + ω â × (p − (a0 + u)),  angular velocity ω â.
// The integrals are exact (trapezoids of the piecewise-linear schedule), so the pose has no
// time-stepping error.
//
// Motion: a sequence of Kinematics segments, each continuing from where the previous one left
// the wall. Segment i acts from t_i (t_0 = −∞) with the base pose P_i = pose of segment i−1 at
// t_i (P_0 = the placement), its window clamped to start no earlier than t_i:
//   x(X, t) = Q_i(θ_i(t))·(R_i·X + x_i − a_i) + a_i + u_i(t)      for t ∈ [t_i, t_{i+1})
//   distance(t) = Σ_{j<i} d_j(t_{j+1}) + d_i(t),  angle(t) = Σ_{j<i} θ_j(t_{j+1}) + θ_i(t)
//   translation(t) = Σ_{j<i} u_j(t_{j+1}) + u_i(t)
// (d = ∫ v, θ = ∫ ω of each segment's own window). Each segment is a closed form, so a change of
// motion adds no time-stepping error, and pose, distance and angle are continuous at t_i.
#pragma once

#include <paddy/contact_batch.hpp>

#include <Eigen/Geometry>
#include <limits>
#include <utility>
#include <vector>

namespace paddy::geometry {

// Piecewise-linear function of time through knots (t_i, v_i), t non-decreasing. Two knots at the
// same time make a step (the later value holds from that time on). Constant before the first
// and after the last knot.
class SpeedSchedule {
 public:
  SpeedSchedule() = default;                       // 0 everywhere
  static SpeedSchedule constant(double v);
  // Throws InputError if times decrease or a value is not finite.
  explicit SpeedSchedule(std::vector<std::pair<double, double>> knots);
  SpeedSchedule& then(double t, double v);          // appends a knot
  double value(double t) const;
  double integral(double t0, double t1) const;      // ∫_{t0}^{t1} value, exact
  const std::vector<std::pair<double, double>>& knots() const { return knots_; }
 private:
  double limitLeft(double t) const;   // value just before t
  std::vector<std::pair<double, double>> knots_;
};

struct Pose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Vec3 x = Vec3::Zero();
  Vec3 apply(const Vec3& body) const { return R * body + x; }
  Vec3 toBody(const Vec3& world) const { return R.transpose() * (world - x); }
};

struct Kinematics {
  Vec3 direction = Vec3::UnitZ();        // translation direction (normalised on use)
  SpeedSchedule speed;                   // [m/s] along direction
  Vec3 axis_point = Vec3::Zero();        // a0: a point on the rotation axis at t_start [m]
  Vec3 axis = Vec3::UnitZ();             // rotation axis (normalised on use)
  SpeedSchedule angular_speed;           // [rad/s], right-hand rule about axis
  double t_start = 0.0;
  double t_end = std::numeric_limits<double>::infinity();

  static Kinematics still() { return {}; }
  // Constant velocity v (e.g. the cone lift: (0, 0, 0.05) m/s) in [t_start, t_end].
  static Kinematics translation(const Vec3& velocity, double t_start = 0.0,
                                double t_end = std::numeric_limits<double>::infinity());
  // Rotation about the axis through `point` along `axis` with the given schedule [rad/s].
  static Kinematics rotation(const Vec3& point, const Vec3& axis, SpeedSchedule omega,
                             double t_start = 0.0,
                             double t_end = std::numeric_limits<double>::infinity());

  void validate() const;  // throws InputError (zero axis/direction, t_end < t_start, NaN)
  bool active(double t) const { return t >= t_start && t < t_end; }
  double speedAt(double t) const { return active(t) ? speed.value(t) : 0.0; }
  double angularSpeedAt(double t) const { return active(t) ? angular_speed.value(t) : 0.0; }
  double distance(double t) const;   // ∫ speed over the window up to t
  double angle(double t) const;      // ∫ angular speed over the window up to t
  Vec3 unitDirection() const { return direction.normalized(); }
  Vec3 unitAxis() const { return axis.normalized(); }
  // Pose at t given the initial placement.
  Pose poseAt(double t, const Pose& placement) const;
};

// Piecewise motion (see the header comment): where the wall is, how fast it moves, and how far
// it has travelled and turned, at any time, across changes of Kinematics.
class Motion {
 public:
  struct State {
    Pose pose;                       // body → world
    Vec3 velocity = Vec3::Zero();    // translation velocity u̇ [m/s]
    Vec3 omega = Vec3::Zero();       // angular velocity ω â [rad/s]
    Vec3 axis_point = Vec3::Zero();  // current point of the rotation axis, a_i + u_i(t) [m]
    Vec3 axis = Vec3::UnitZ();       // unit rotation axis of the segment at t
    double distance = 0.0;           // accumulated ∫ v over all segments [m]
    double angle = 0.0;              // accumulated ∫ ω over all segments [rad]
    Vec3 translation = Vec3::Zero(); // accumulated translation Σ u_j [m]
  };

  explicit Motion(const Pose& placement = {}, Kinematics k = Kinematics::still());
  // The whole motion is k, measured from the placement (drops every earlier change).
  void reset(Kinematics k);
  // From t_switch on the wall follows k, starting from its pose at t_switch; k's window is
  // clamped to [max(t_start, t_switch), max(t_end, that)). Changes made at or after t_switch are
  // dropped. Throws InputError for a non-finite t_switch or invalid k.
  void change(double t_switch, Kinematics k);
  State at(double t) const;
  const Pose& placement() const { return segments_.front().base; }
  const Kinematics& current() const { return segments_.back().kin; }  // the latest segment's
  std::size_t segmentCount() const { return segments_.size(); }

 private:
  struct Segment {
    double t_from;    // acts for t >= t_from
    Pose base;        // pose at t_from (the placement for the first segment)
    Kinematics kin;
    double distance0 = 0.0, angle0 = 0.0;  // accumulated up to t_from
    Vec3 translation0 = Vec3::Zero();
  };
  const Segment& segmentAt(double t) const;
  std::vector<Segment> segments_;
};

}  // namespace paddy::geometry
