// MeshWall contact search, per sphere, in the body frame (centre X = Rᵀ(c − x)):
// closestHits takes the closest point q of each candidate triangle (Voronoi regions, C. Ericson,
// "Real-Time Collision Detection", 2005, §5.1.5; closest_point.hpp) and keeps it as a Hit when
// d = |X − q| < radius + max_gap (a triangle whose plane is farther than that is skipped before
// its closest point is taken: the plane's distance is a lower bound of d); reduce
// (mesh_wall_reduce.cpp) turns one sphere's hits into contacts. findContacts runs over the
// candidate lists (mesh_wall_grid.cpp) on the simulation's threads, static chunks in thread
// order, so the contacts come out in candidate order whatever the thread count; contactsOfSphere
// takes one sphere's triangles from the grid (mesh_wall_grid.cpp; every triangle when none is
// built). Contacts with overlap ≤ −max_gap are dropped.
#include "mesh_wall_internal.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace paddy {

void MeshWall::closestHits(const Vec3& xb, double reach, const std::uint32_t* first, const std::uint32_t* last,
                           std::vector<Hit>& hits) const {
  // The distance to a triangle's plane is a lower bound of the distance to the triangle: a
  // triangle whose plane lies beyond reach is no hit, found without its closest point (the
  // relative margin keeps the rounding of the two distances from dropping a hit).
  const double plane_reach = reach * (1.0 + 1e-9);
  for (const std::uint32_t* it = first; it != last; ++it) {
    const std::uint32_t t = *it;
    const auto& tri = mesh_.triangles[t];
    if (std::abs(tri_normal_[t].dot(xb - mesh_.vertices[tri[0]])) > plane_reach) continue;
    const auto cp = geometry::closestPointOnTriangle(xb, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]);
    const double d = (cp.point - xb).norm();
    if (d >= reach) continue;
    Hit h;
    h.tri = t;
    h.region = region_[t];
    h.feature = cp.feature;
    h.d = d;
    h.q = cp.point;
    hits.push_back(h);
  }
}

void MeshWall::findContacts(const ParticleView& p, double max_gap, std::vector<WallContact>& out) const {
  const long nc = static_cast<long>(cand_particle_.size());
  const int nthreads = std::max(1, p.threads);
  std::vector<std::vector<WallContact>>& local = contacts_per_thread_;
  local.resize(static_cast<std::size_t>(nthreads));
  for (auto& l : local) l.clear();
  // Static chunks in thread order: concatenated, the contacts are in candidate order whatever the
  // thread count.
#pragma omp parallel num_threads(nthreads) if (nc >= mesh_wall_detail::kParallelMin)
  {
    const auto tid = static_cast<std::size_t>(omp_get_thread_num());
    std::vector<Hit> hits;
#pragma omp for schedule(static)
    for (long c = 0; c < nc; ++c) {
      const std::uint32_t i = cand_particle_[static_cast<std::size_t>(c)];
      if (i >= p.n) continue;
      const Vec3 xb = state_.pose.toBody(p.position[i]);
      const double r = p.radius[i], reach = r + max_gap;
      hits.clear();
      const std::uint32_t* tris = cand_tri_.data();
      closestHits(xb, reach, tris + cand_off_[static_cast<std::size_t>(c)], tris + cand_off_[static_cast<std::size_t>(c) + 1], hits);
      if (!hits.empty()) reduce(xb, r, i, hits, local[tid]);
    }
  }
  for (auto& l : local)
    for (const WallContact& c : l)
      if (c.overlap > -max_gap) out.push_back(c);
}

void MeshWall::contactsOfSphere(const Vec3& centre, double radius, double max_gap, std::uint32_t particle,
                                std::vector<WallContact>& out) const {
  const Vec3 xb = state_.pose.toBody(centre);
  std::vector<std::uint32_t> tris;
  gatherTriangles(xb, radius + max_gap, tris);
  std::vector<Hit> hits;
  closestHits(xb, radius + max_gap, tris.data(), tris.data() + tris.size(), hits);
  std::vector<WallContact> found;
  reduce(xb, radius, particle, hits, found);
  for (const WallContact& c : found)
    if (c.overlap > -max_gap) out.push_back(c);
}

}  // namespace paddy
