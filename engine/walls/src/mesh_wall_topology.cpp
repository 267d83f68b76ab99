// MeshWall topology, built once from the body mesh at construction:
//  - unit face normals (geometry::triangleNormal);
//  - edge adjacency: per (triangle, local edge k joining corners k and k+1) the other triangles
//    sharing that edge, found by sorting the edge records by their vertex-pair key (CSR:
//    edge_nb_off_, edge_nb_), and per vertex its incident triangles (vert_tri_off_, vert_tri_);
//  - closed components: a connected component is a solid when every edge is shared by exactly
//    two triangles (a boundary or non-manifold edge makes it open);
//  - smooth regions: neighbours across a shared edge whose normals differ by less than
//    region_angle_deg (n₁·n₂ ≥ cos θ, n₂ flipped when the two are inconsistently oriented) are
//    joined by union-find; roots get dense ids in order of their first triangle;
//  - pseudo-normals (J. A. Bærentzen and H. Aanæs, "Signed distance computation using the angle
//    weighted pseudonormal", IEEE TVCG 11(3), 2005): edge = sum of the two face normals,
//    vertex = Σ αᵢ nᵢ over the incident faces with αᵢ the corner angle; they decide inside/outside
//    for edge and vertex hits on closed components (mesh_wall_reduce.cpp);
//  - a bounding sphere about the bounding-box centre (mesh_wall_motion.cpp's displacement bound).
#include "mesh_wall_internal.hpp"

#include <paddy/geometry/mesh_check.hpp>
#include <paddy/util/union_find.hpp>

#include <algorithm>
#include <cmath>

namespace paddy {

void MeshWall::buildTopology() {
  const std::size_t nt = mesh_.triangles.size(), nv = mesh_.vertices.size();
  tri_normal_.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) tri_normal_[t] = geometry::triangleNormal(mesh_, t);

  // Edge records (key, triangle, local edge), sorted so equal edges are adjacent.
  struct Rec { std::uint64_t key; std::uint32_t tri; std::uint8_t k; };
  std::vector<Rec> recs;
  recs.reserve(3 * nt);
  for (std::size_t t = 0; t < nt; ++t)
    for (std::uint8_t k = 0; k < 3; ++k) {
      std::uint32_t a = mesh_.triangles[t][k], b = mesh_.triangles[t][(k + 1) % 3];
      if (a > b) std::swap(a, b);
      recs.push_back({(static_cast<std::uint64_t>(a) << 32) | b, static_cast<std::uint32_t>(t), k});
    }
  std::sort(recs.begin(), recs.end(), [](const Rec& x, const Rec& y) {
    return x.key < y.key || (x.key == y.key && x.tri < y.tri);
  });
  std::vector<std::uint32_t> count(3 * nt, 0);
  std::vector<std::uint8_t> comp_open;
  std::size_t ncomp = 0;
  const auto comp = geometry::connectedComponents(mesh_, &ncomp);
  comp_open.assign(ncomp, 0);
  UnionFind<std::uint32_t> regions(nt);  // smooth regions
  const double cos_region = mesh_wall_detail::cosDeg(opt_.region_angle_deg);
  for (std::size_t i = 0; i < recs.size();) {
    std::size_t j = i;
    while (j < recs.size() && recs[j].key == recs[i].key) ++j;
    const std::size_t n = j - i;
    if (n != 2) comp_open[comp[recs[i].tri]] = 1;  // boundary or non-manifold: not a solid
    for (std::size_t a = i; a < j; ++a) count[3 * recs[a].tri + recs[a].k] = static_cast<std::uint32_t>(n - 1);
    if (n == 2) {
      const Rec &r1 = recs[i], &r2 = recs[i + 1];
      // Consistently oriented neighbours traverse the shared edge in opposite directions.
      const bool consistent = mesh_.triangles[r1.tri][r1.k] != mesh_.triangles[r2.tri][r2.k];
      const Vec3 n2 = consistent ? tri_normal_[r2.tri] : Vec3(-tri_normal_[r2.tri]);
      if (tri_normal_[r1.tri].dot(n2) >= cos_region) regions.unite(r1.tri, r2.tri);
    }
    i = j;
  }
  edge_nb_off_.assign(3 * nt + 1, 0);
  for (std::size_t e = 0; e < 3 * nt; ++e) edge_nb_off_[e + 1] = edge_nb_off_[e] + count[e];
  edge_nb_.assign(edge_nb_off_.back(), 0);
  {
    std::vector<std::uint32_t> fill(edge_nb_off_.begin(), edge_nb_off_.end() - 1);
    for (std::size_t i = 0; i < recs.size();) {
      std::size_t j = i;
      while (j < recs.size() && recs[j].key == recs[i].key) ++j;
      for (std::size_t a = i; a < j; ++a)
        for (std::size_t b = i; b < j; ++b)
          if (a != b) edge_nb_[fill[3 * recs[a].tri + recs[a].k]++] = recs[b].tri;
      i = j;
    }
  }
  // Regions: union-find roots → dense ids in order of first triangle.
  region_.assign(nt, 0);
  std::vector<std::uint32_t> label(nt, UINT32_MAX);
  region_count_ = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    const std::uint32_t r = regions.find(static_cast<std::uint32_t>(t));
    if (label[r] == UINT32_MAX) label[r] = static_cast<std::uint32_t>(region_count_++);
    region_[t] = label[r];
  }
  tri_closed_.assign(nt, 0);
  for (std::size_t t = 0; t < nt; ++t) tri_closed_[t] = comp_open[comp[t]] ? 0 : 1;

  // Vertex → triangles.
  vert_tri_off_.assign(nv + 1, 0);
  for (const auto& tri : mesh_.triangles)
    for (auto v : tri) ++vert_tri_off_[v + 1];
  for (std::size_t v = 0; v < nv; ++v) vert_tri_off_[v + 1] += vert_tri_off_[v];
  vert_tri_.assign(vert_tri_off_.back(), 0);
  {
    std::vector<std::uint32_t> fill(vert_tri_off_.begin(), vert_tri_off_.end() - 1);
    for (std::size_t t = 0; t < nt; ++t)
      for (auto v : mesh_.triangles[t]) vert_tri_[fill[v]++] = static_cast<std::uint32_t>(t);
  }
  // Pseudo-normals (Bærentzen & Aanæs 2005): edge = sum of the two face normals; vertex = sum of
  // the incident face normals weighted by the corner angle. Used for closed components only.
  edge_pseudo_.assign(3 * nt, Vec3::Zero());
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      Vec3 s = tri_normal_[t];
      for (std::uint32_t e = edge_nb_off_[3 * t + k]; e < edge_nb_off_[3 * t + k + 1]; ++e) s += tri_normal_[edge_nb_[e]];
      edge_pseudo_[3 * t + k] = s;
    }
  vert_pseudo_.assign(nv, Vec3::Zero());
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh_.vertices[mesh_.triangles[t][k]];
      const Vec3 a = (mesh_.vertices[mesh_.triangles[t][(k + 1) % 3]] - p).normalized();
      const Vec3 b = (mesh_.vertices[mesh_.triangles[t][(k + 2) % 3]] - p).normalized();
      const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
      vert_pseudo_[mesh_.triangles[t][k]] += angle * tri_normal_[t];
    }
  // Bounding sphere about the box centre (for the displacement bound).
  const geometry::Bounds b = geometry::bounds(mesh_);
  bcentre_ = 0.5 * (b.lo + b.hi);
  bradius_ = 0.0;
  for (const Vec3& v : mesh_.vertices) bradius_ = std::max(bradius_, (v - bcentre_).norm());
}

}  // namespace paddy
