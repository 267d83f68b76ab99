// Force/torque history of a wall over time, and its CSV writer. The CSV is written to
// "<path>.tmp" and renamed over <path>, so a reader never sees a half-written file.
// Columns: t [s], Fx Fy Fz [N], Tx Ty Tz [N m] about the torque origin, T_axis [N m] (torque
// component along the rotation axis), distance [m] travelled along the translation direction,
// angle [rad] turned about the axis.
//
// HDF5 (writeLoadHistoryH5): one group per wall, named after the wall, holding the datasets
//   t (N) [s], force (N×3) [N], torque (N×3) [N m], axial_torque (N) [N m], distance (N) [m],
//   angle (N) [rad]
// each with the string attributes `unit` and `description` (vectors also `columns` = "x,y,z");
// the group has the attributes `wall` (its name) and `samples` (N); the root `format` =
// "paddy wall loads" and `version` = 1. Written to a temporary name and renamed over the target.
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

// One wall's history for writeLoadHistoryH5 (the samples are not copied).
struct NamedLoadHistory {
  std::string wall;
  const std::vector<LoadSample>* samples = nullptr;
};

// Writes the histories of one or more walls into one HDF5 file (layout above). Throws
// InputError for an empty, duplicate or unusable group name ('/' or "."), or when the file
// cannot be written.
void writeLoadHistoryH5(const std::string& path, const std::vector<NamedLoadHistory>& walls);

}  // namespace paddy::geometry
