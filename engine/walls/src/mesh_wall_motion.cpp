// MeshWall motion: the wall's state at time t comes from geometry::Motion (kinematics.hpp, a
// chain of Kinematics segments); from it the rigid-body velocity of a point,
//   v(p) = v + ω × (p − a)   (a: a point on the rotation axis),
// and the displacement since the last candidate-list build. A body point X moves by
//   Δ(X) = (R − R₀) X + (x − x₀),
// affine in X, so |Δ| is convex and its maximum over the mesh is at a vertex: exact (a pass over
// the vertices) up to 200k vertices; above, the bounding-sphere bound
//   |Δ(c)| + ‖R − R₀‖₂ ρ,   ‖R − R₀‖₂ = sqrt(3 − tr(R R₀ᵀ))
// (c, ρ: centre and radius of the bounding sphere, mesh_wall_topology.cpp). A wall that has not
// turned since the build moved every point by |x − x₀| exactly.
#include <paddy/geometry/mesh_wall.hpp>

#include <algorithm>
#include <cmath>

namespace paddy {

void MeshWall::moveTo(double t) {
  time_ = t;
  state_ = motion_.at(t);
}

void MeshWall::setKinematics(geometry::Kinematics k) {
  motion_.reset(std::move(k));
  moveTo(time_);
}

void MeshWall::changeKinematics(double t_switch, geometry::Kinematics k) {
  motion_.change(t_switch, std::move(k));
  moveTo(time_);
}

Vec3 MeshWall::velocityAt(const Vec3& p) const { return state_.velocity + state_.omega.cross(p - state_.axis_point); }
Vec3 MeshWall::angularVelocity() const { return state_.omega; }
Vec3 MeshWall::torqueOrigin() const { return state_.axis_point; }

double MeshWall::displacementSinceListBuild() const {
  // max over X of |Δ(X)| (see the top of this file).
  const Eigen::Matrix3d dR = state_.pose.R - pose_at_build_.R;
  const Vec3 dx = state_.pose.x - pose_at_build_.x;
  // Not turned since the build (a fixed or translating wall): every point moved by dx exactly.
  if ((dR.array() == 0.0).all()) return std::sqrt(dx.squaredNorm());
  if (mesh_.vertices.size() <= 200000) {
    double m2 = 0.0;
    for (const Vec3& v : mesh_.vertices) m2 = std::max(m2, (dR * v + dx).squaredNorm());
    return std::sqrt(m2);
  }
  const double tr = (state_.pose.R * pose_at_build_.R.transpose()).trace();
  return (dR * bcentre_ + dx).norm() + std::sqrt(std::max(0.0, 3.0 - tr)) * bradius_;
}

void MeshWall::markListBuilt() { pose_at_build_ = state_.pose; }

TriangleMesh MeshWall::worldMesh() const {
  TriangleMesh m = mesh_;
  for (Vec3& v : m.vertices) v = state_.pose.apply(v);
  return m;
}

}  // namespace paddy
