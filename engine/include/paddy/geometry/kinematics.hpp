// Prescribed rigid-body motion of a wall: translation along a direction and rotation about an
// axis (point + direction), each with a piecewise-linear speed schedule, active in a time window.
//
// Pose at time t (body point X, initial placement x ← R0·X + x0, axis point a0, unit axis â):
//   u(t) = d̂ · ∫ v(s) ds,   θ(t) = ∫ ω(s) ds     (integrals over [t_start, min(t, t_end)])
//   x(X, t) = Q(θ)·(R0·X + x0 − a0) + a0 + u(t),    Q(θ) = rotation by θ about â
//   velocity of the material point at p: u̇ + ω â × (p − (a0 + u)),  angular velocity ω â.
// The integrals are exact (trapezoids of the piecewise-linear schedule), so the pose has no
// time-stepping error.
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

}  // namespace paddy::geometry
