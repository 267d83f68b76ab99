// MeshWall loads: recordLoads appends a sample of the wall's force, torque (about the current
// point of the rotation axis) and axial torque T·a, with the distance and angle travelled up to
// that time over all changes of motion (geometry::Motion); the history is written as CSV or as
// one HDF5 group named after the wall (load_history.cpp, load_history_h5.cpp).
#include <paddy/geometry/mesh_wall.hpp>

#include <string>

namespace paddy {

void MeshWall::recordLoads(double t) {
  geometry::LoadSample s;
  s.t = t;
  s.force = force();
  s.torque = torque();
  s.axial_torque = axialTorque();
  const geometry::Motion::State m = t == time_ ? state_ : motion_.at(t);
  s.distance = m.distance;
  s.angle = m.angle;
  history_.push_back(s);
}

void MeshWall::writeLoadHistoryCsv(const std::string& path) const { geometry::writeLoadHistoryCsv(path, history_, name_); }

void MeshWall::writeLoadHistoryH5(const std::string& path) const {
  geometry::writeLoadHistoryH5(path, {{name_, &history_}});
}

}  // namespace paddy
