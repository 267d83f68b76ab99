// MeshWall contact reduction: one sphere's hits (mesh_wall_contacts.cpp) → its contacts.
//  1. normal and overlap of each hit: a face point takes the face normal n (overlap r − n·(X − q);
//     on an open surface the side the centre is on, overlap r − |n·(X − q)|); an edge or vertex
//     point takes (X − q)/d with overlap r − d, flipped to the outside with overlap r + d when
//     the centre of a closed component lies behind the angle-weighted pseudo-normal (Bærentzen &
//     Aanæs 2005, mesh_wall_topology.cpp); a centre on the edge or vertex itself (d ≤ 1e-12 r)
//     takes the pseudo-normal (closed) or the face normal, overlap r;
//     the side of a closed surface the centre is on is that of its closest hit (inside or
//     outside, by the sign test of 1.): hits of closed triangles that say the other side are
//     dropped. A thin closed part (a 2 mm vane blade) within reach r + max_gap on both faces
//     would otherwise give the far face as a penetration of r + d although the centre is outside;
//  2. per smooth region, closest first: the closest hit is the region's contact (key = region
//     id); a further hit starts a new contact (key = region_count + triangle) only if its normal
//     differs from each of the region's contacts by more than cluster_angle_deg and it is a local
//     minimum of the distance (isLocalMinimum: no triangle sharing its edge or vertex is closer
//     by more than 1e-9·d + 1e-15);
//  3. across regions, deepest first: a contact whose normal is within merge_angle_deg of a kept
//     one joins it (the smaller key survives).
// Contacts are returned in the world frame (normal R n, point x + R q).
#include "mesh_wall_internal.hpp"

#include <algorithm>
#include <vector>

namespace paddy {
using geometry::TriFeature;

bool MeshWall::isLocalMinimum(const Hit& h, const Vec3& xb) const {
  if (h.feature == TriFeature::Face) return true;
  const double eps = 1e-9 * h.d + 1e-15;
  auto closer = [&](std::uint32_t o) {
    if (o == h.tri) return false;
    const auto& tri = mesh_.triangles[o];
    const auto cp = geometry::closestPointOnTriangle(xb, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]);
    return (cp.point - xb).norm() < h.d - eps;
  };
  if (geometry::isEdge(h.feature)) {
    const std::size_t e = 3 * h.tri + static_cast<std::size_t>(geometry::edgeIndex(h.feature));
    for (std::uint32_t k = edge_nb_off_[e]; k < edge_nb_off_[e + 1]; ++k)
      if (closer(edge_nb_[k])) return false;
  } else {
    const std::uint32_t v = mesh_.triangles[h.tri][static_cast<std::size_t>(geometry::vertexIndex(h.feature))];
    for (std::uint32_t k = vert_tri_off_[v]; k < vert_tri_off_[v + 1]; ++k)
      if (closer(vert_tri_[k])) return false;
  }
  return true;
}

void MeshWall::reduce(const Vec3& xb, double radius, std::uint32_t particle, std::vector<Hit>& hits,
                      std::vector<WallContact>& out) const {
  if (hits.empty()) return;
  // Normals and overlaps; h.behind: the sign test puts the centre inside a closed component.
  for (Hit& h : hits) {
    const Vec3 diff = xb - h.q;
    const Vec3& fn = tri_normal_[h.tri];
    const bool closed = tri_closed_[h.tri] != 0;
    if (h.feature == TriFeature::Face) {
      const double s = fn.dot(diff);
      if (closed) {
        h.n = fn;
        h.overlap = radius - s;
        h.behind = s < 0.0;
      } else {
        h.n = s >= 0.0 ? fn : Vec3(-fn);
        h.overlap = radius - std::abs(s);
      }
    } else {
      Vec3 pseudo = geometry::isEdge(h.feature)
                        ? edge_pseudo_[3 * h.tri + static_cast<std::size_t>(geometry::edgeIndex(h.feature))]
                        : vert_pseudo_[mesh_.triangles[h.tri][static_cast<std::size_t>(geometry::vertexIndex(h.feature))]];
      if (h.d > 1e-12 * radius) {
        h.n = diff / h.d;
        h.overlap = radius - h.d;
        if (closed && diff.dot(pseudo) < 0.0) {
          h.n = -h.n;
          h.overlap = radius + h.d;
          h.behind = true;
        }
      } else {
        h.n = closed && pseudo.norm() > 0.0 ? Vec3(pseudo.normalized()) : fn;
        h.overlap = radius;
      }
    }
  }
  // The side of the closed surface: that of the closest closed hit (the smaller triangle on a tie).
  std::size_t closest = hits.size();
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (tri_closed_[hits[i].tri] == 0) continue;
    if (closest == hits.size() || hits[i].d < hits[closest].d || (hits[i].d == hits[closest].d && hits[i].tri < hits[closest].tri))
      closest = i;
  }
  if (closest < hits.size()) {
    const bool side = hits[closest].behind;
    std::size_t n = 0;
    for (std::size_t i = 0; i < hits.size(); ++i)
      if (tri_closed_[hits[i].tri] == 0 || hits[i].behind == side) hits[n++] = hits[i];
    hits.resize(n);
  }
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
    return a.region < b.region || (a.region == b.region && (a.d < b.d || (a.d == b.d && a.tri < b.tri)));
  });
  const double cos_cluster = cos_cluster_, cos_merge = cos_merge_;
  // Accepted contacts, compacted to the front of `hits`.
  std::size_t accepted = 0, region_begin = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (i == 0 || hits[i].region != hits[i - 1].region) region_begin = accepted;
    Hit& h = hits[i];
    bool absorbed = false;
    for (std::size_t a = region_begin; a < accepted && !absorbed; ++a) absorbed = hits[a].n.dot(h.n) >= cos_cluster;
    if (absorbed || !isLocalMinimum(h, xb)) continue;
    h.key = accepted == region_begin ? h.region : static_cast<std::uint32_t>(region_count_ + h.tri);
    hits[accepted++] = h;
  }
  hits.resize(accepted);
  // Merge across regions: deepest first; a contact within merge angle of a kept one joins it.
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
    return a.overlap > b.overlap || (a.overlap == b.overlap && a.key < b.key);
  });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    bool merged = false;
    for (std::size_t k = 0; k < kept && !merged; ++k)
      if (hits[k].n.dot(hits[i].n) >= cos_merge) {
        hits[k].key = std::min(hits[k].key, hits[i].key);
        merged = true;
      }
    if (!merged) hits[kept++] = hits[i];
  }
  for (std::size_t k = 0; k < kept; ++k) {
    const Hit& h = hits[k];
    out.push_back({particle, h.key, h.overlap, state_.pose.R * h.n, state_.pose.apply(h.q)});
  }
}

}  // namespace paddy
