// Force/torque history of a wall over time, and its CSV writer. The CSV is written to
// "<path>.tmp" and renamed over <path>, so a reader never sees a half-written file.
// Columns: t [s], Fx Fy Fz [N], Tx Ty Tz [N m] about the torque origin, T_axis [N m] (torque
// component along the rotation axis), distance [m] travelled along the translation direction,
// angle [rad] turned about the axis. The same samples are available as a vector for HDF5 output.
#pragma once

#include <paddy/contact_batch.hpp>

#include <string>
#include <vector>

namespace paddy::geometry {

struct LoadSample {
  double t = 0.0;
  Vec3 force = Vec3::Zero();
  Vec3 torque = Vec3::Zero();
  double axial_torque = 0.0;
  double distance = 0.0;
  double angle = 0.0;
};

void writeLoadHistoryCsv(const std::string& path, const std::vector<LoadSample>& samples,
                         const std::string& wall_name = "");

}  // namespace paddy::geometry
