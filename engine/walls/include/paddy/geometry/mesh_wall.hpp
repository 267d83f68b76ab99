// MeshWall: a rigid triangle-mesh wall with prescribed kinematics (paddy::Wall implementation).
//
// Geometry is kept in body coordinates; a particle centre c is taken into the body frame
// (X = Rᵀ(c − x)) and tested there, so the mesh is never re-transformed.
//
// Candidates (buildCandidates): a uniform grid over the body-frame mesh; a triangle is listed
// in every cell whose centre lies within half a cell diagonal of it. Cell size = 2·(largest
// radius + range) (enlarged if the grid would exceed 4 M cells), so a particle's query touches at
// most 8 cells and its cost does not grow with the number of triangles. Each particle within
// radius + range of the wall keeps the triangles within radius + range of its centre. With the
// engine's refresh rule (a particle and the wall together moved more than the skin) these lists
// contain every triangle that can come within radius + max_gap, provided range ≥ max_gap + skin.
//
// Contacts (findContacts), per particle, all in the body frame:
//  1. closest point on each candidate triangle (Ericson §5.1.5, closest_point.hpp), kept if the
//     distance d < radius + max_gap;
//  2. faces are grouped into smooth regions at construction: neighbouring triangles whose normals
//     differ by less than `region_angle_deg` (default 30°) are joined (union-find over shared
//     edges) — a flat plate, the faceted inside of the cone, the cup side are one region each;
//  3. per region the closest hit is the region's contact (exact closest point of that region);
//     further hits in the region start a new contact only if their normal differs by more than
//     `cluster_angle_deg` from the region's contacts AND they are a local minimum of the distance;
//  4. local-minimum test: a hit on an edge or vertex is dropped if any triangle sharing that
//     edge/vertex is strictly closer (the sphere then touches that triangle's face instead);
//     this removes the spurious edge contacts next to sharp convex edges (vane blades);
//  5. contacts of different regions whose normals differ by less than `merge_angle_deg` are one
//     contact (the deepest): at a sharp convex edge both regions report the same edge point.
// Result: one contact per flat/smooth region (no double counting across shared edges and vertices,
// continuous overlap and normal), two at concave corners between regions (cup bottom + side).
// Normal = (c − q)/|c − q| (the face normal for face points); for closed components a centre
// inside the solid (face: behind the outward normal; edge/vertex: behind the angle-weighted
// pseudo-normal, Bærentzen & Aanæs 2005) gets the outward normal and overlap = radius + d.
//
// Keys: a region's contact has key = region id, so history survives while the sphere slides
// across the triangles of a flat or smooth region (e.g. from triangle A's face to B's face on a
// plane, or around the faceted cone). Merged contacts (sharp convex edge) take the smaller region
// id of the two; extra contacts within one region (rare: sphere touching a region twice) get
// key = region_count + triangle id.
#pragma once

#include <paddy/geometry.hpp>
#include <paddy/geometry/kinematics.hpp>
#include <paddy/geometry/load_history.hpp>
#include <paddy/wall.hpp>

#include <string>
#include <vector>

namespace paddy {

struct MeshWallOptions {
  double region_angle_deg = 30.0;   // adjacent faces closer than this in normal → one region
  double cluster_angle_deg = 45.0;  // within a region, hits closer than this → one contact
  double merge_angle_deg = 30.0;    // contacts of different regions closer than this → one
};

class MeshWall : public Wall {
 public:
  // `body_mesh` in body coordinates (validated; InputError names `name`); the initial world pose
  // is `placement`; `kinematics` moves it from there (Kinematics::poseAt), later changes of
  // motion from wherever it is then (changeKinematics, geometry::Motion).
  MeshWall(std::string name, int material, TriangleMesh body_mesh,
           const geometry::Pose& placement = {},
           geometry::Kinematics kinematics = geometry::Kinematics::still(),
           const MeshWallOptions& options = {});
  ~MeshWall() override;

  // ---- paddy::Wall ---------------------------------------------------------------------------
  std::string name() const override { return name_; }
  int material() const override { return material_; }
  void moveTo(double t) override;
  Vec3 velocityAt(const Vec3& p) const override;
  Vec3 angularVelocity() const override;
  double displacementSinceListBuild() const override;
  void buildCandidates(const ParticleView& particles, double range) override;
  void markListBuilt() override;
  void findContacts(const ParticleView& particles, double max_gap,
                    std::vector<WallContact>& out) const override;
  Vec3 torqueOrigin() const override;  // current point of the rotation axis

  // ---- kinematics (geometry::Motion: segments of Kinematics) --------------------------------
  const geometry::Kinematics& kinematics() const { return motion_.current(); }  // latest segment
  const geometry::Motion& motion() const { return motion_; }
  // Replaces the whole motion, measured from the placement; re-applies moveTo(time()).
  void setKinematics(geometry::Kinematics k);
  // From t_switch on, follows k starting from the pose at t_switch (no jump; distance and angle
  // keep accumulating); re-applies moveTo(time()). See Motion::change.
  void changeKinematics(double t_switch, geometry::Kinematics k);
  const geometry::Pose& placement() const { return motion_.placement(); }
  const geometry::Pose& pose() const { return state_.pose; }  // current body → world
  double time() const { return time_; }
  Vec3 axis() const { return state_.axis; }                   // unit rotation axis (world)
  double axialTorque() const { return torque().dot(axis()); }
  double distanceTravelled() const { return state_.distance; }  // Σ ∫ v [m]
  double angleTurned() const { return state_.angle; }           // Σ ∫ ω [rad]
  Vec3 translationTravelled() const { return state_.translation; }  // Σ u [m]

  // ---- geometry ------------------------------------------------------------------------------
  const TriangleMesh& bodyMesh() const { return mesh_; }
  TriangleMesh worldMesh() const;
  std::size_t regionCount() const { return region_count_; }
  std::uint32_t regionOf(std::size_t triangle) const { return region_[triangle]; }
  // Contacts of one sphere against the whole mesh (no candidate list; for tests and tools).
  void contactsOfSphere(const Vec3& centre, double radius, double max_gap, std::uint32_t particle,
                        std::vector<WallContact>& out) const;
  std::size_t candidateParticles() const { return cand_particle_.size(); }
  std::size_t candidatePairs() const { return cand_tri_.size(); }

  // ---- loads ---------------------------------------------------------------------------------
  // Appends the current force()/torque() as a sample at time t, with the distance and angle
  // accumulated up to t over all changes of motion.
  void recordLoads(double t);
  const std::vector<geometry::LoadSample>& loadHistory() const { return history_; }
  void clearLoadHistory() { history_.clear(); }
  void writeLoadHistoryCsv(const std::string& path) const;
  void writeLoadHistoryH5(const std::string& path) const;  // one group named after the wall

 private:
  struct Hit;
  struct Grid;
  void buildTopology();
  void buildGrid(double query_radius);
  // Calls visit(triangle) for every item of the grid cells that the query box (centre xb,
  // half-width reach) overlaps: a triangle listed in several of them comes once per cell
  // (every triangle once when there is no grid).
  template <class Visit>
  void forEachCellItem(const Vec3& xb, double reach, Visit&& visit) const;
  // The same triangles, sorted and each once.
  void gatherTriangles(const Vec3& xb, double reach, std::vector<std::uint32_t>& tris) const;
  // Appends a Hit for each triangle in [first, last) whose closest point is nearer than reach.
  void closestHits(const Vec3& xb, double reach, const std::uint32_t* first, const std::uint32_t* last,
                   std::vector<Hit>& hits) const;
  void reduce(const Vec3& xb, double radius, std::uint32_t particle, std::vector<Hit>& hits,
              std::vector<WallContact>& out) const;
  bool isLocalMinimum(const Hit& h, const Vec3& xb) const;

  std::string name_;
  int material_;
  TriangleMesh mesh_;
  MeshWallOptions opt_;
  double cos_cluster_ = 1.0, cos_merge_ = 1.0;  // cosines of opt_'s cluster and merge angles
  geometry::Motion motion_;
  geometry::Motion::State state_;  // at time_
  geometry::Pose pose_at_build_;
  double time_ = 0.0;
  // topology
  std::vector<Vec3> tri_normal_;                 // unit
  std::vector<std::uint8_t> tri_closed_;         // triangle in a closed component
  std::vector<std::uint32_t> region_;
  std::size_t region_count_ = 0;
  std::vector<std::uint32_t> edge_nb_off_, edge_nb_;  // per (triangle, edge): other triangles
  std::vector<std::uint32_t> vert_tri_off_, vert_tri_;  // per vertex: incident triangles
  std::vector<Vec3> edge_pseudo_;                // per (triangle, edge), closed components
  std::vector<Vec3> vert_pseudo_;                // per vertex, angle-weighted
  Vec3 bcentre_ = Vec3::Zero();
  double bradius_ = 0.0;
  // candidates
  std::unique_ptr<Grid> grid_;
  std::vector<std::uint32_t> cand_particle_, cand_off_, cand_tri_;
  mutable std::vector<std::vector<WallContact>> contacts_per_thread_;  // findContacts scratch
  // loads
  std::vector<geometry::LoadSample> history_;
};

}  // namespace paddy
