// MeshWall construction: validates the body mesh (mesh_check.hpp), the placement (a finite proper
// rotation, ‖R Rᵀ − I‖ ≤ 1e-9 and det R ≥ 0) and the angle options, then builds the topology
// (mesh_wall_topology.cpp) and takes the pose at t = 0. The algorithm is described in
// mesh_wall.hpp; mesh_wall_internal.hpp lists the files that implement it.
#include "mesh_wall_internal.hpp"

#include <paddy/errors.hpp>
#include <paddy/geometry/mesh_check.hpp>

namespace paddy {

MeshWall::MeshWall(std::string name, int material, TriangleMesh body_mesh, const geometry::Pose& placement,
                   geometry::Kinematics kinematics, const MeshWallOptions& options)
    : name_(std::move(name)), material_(material), mesh_(std::move(body_mesh)), opt_(options),
      motion_(placement, std::move(kinematics)) {
  geometry::MeshCheckOptions check;
  check.source = "mesh wall '" + name_ + "'";
  geometry::validateMesh(mesh_, check);
  if (!placement.x.allFinite() || !placement.R.allFinite() ||
      (placement.R * placement.R.transpose() - Eigen::Matrix3d::Identity()).norm() > 1e-9 ||
      placement.R.determinant() < 0.0)
    throw InputError(check.source + ": the placement must be a finite proper rotation and translation");
  checkRange(check.source + " region_angle_deg", opt_.region_angle_deg, 0.0, 90.0, "deg");
  checkRange(check.source + " cluster_angle_deg", opt_.cluster_angle_deg, 0.0, 180.0, "deg");
  checkRange(check.source + " merge_angle_deg", opt_.merge_angle_deg, 0.0, 90.0, "deg");
  cos_cluster_ = mesh_wall_detail::cosDeg(opt_.cluster_angle_deg);  // once, not per sphere (reduce)
  cos_merge_ = mesh_wall_detail::cosDeg(opt_.merge_angle_deg);
  buildTopology();
  moveTo(0.0);
  pose_at_build_ = state_.pose;
}

MeshWall::~MeshWall() = default;  // here, where Grid is complete (std::unique_ptr<Grid>)

}  // namespace paddy
