// MeshWall candidate search: the spatial grid and the per-particle candidate lists.
//
// Grid (buildGrid, gatherTriangles): a uniform cell grid over the body-frame mesh, in CSR form
// (Grid in mesh_wall_internal.hpp). Cell size h = 2·query (query = largest radius + range),
// enlarged by 1.25× until the grid has at most 4 M cells, so a query box of half-width query
// touches at most 2×2×2 cells. A triangle is listed in every cell of its bounding box whose centre
// lies within the cell's circumradius (√3/2)·h of it: first the plane distance |n·(centre − a)|,
// then the exact closest point (C. Ericson, "Real-Time Collision Detection", 2005, §5.1.5;
// closest_point.hpp). gatherTriangles returns the sorted, unique triangles of the cells a query
// box overlaps (every triangle when there is no grid).
//
// Candidate lists (buildCandidates): each particle within radius + range of the wall keeps the
// triangles whose closest point lies within radius + range of its centre, taken into the body
// frame (X = Rᵀ(c − x)). Each triangle of the particle's cells is looked at once (a stamp per
// triangle), and one whose plane lies beyond reach is dropped before its closest point is taken
// (the plane's distance is a lower bound of the triangle's). The grid is rebuilt when the query
// radius is more than twice or less than a quarter of the one it was built for. With the
// engine's refresh rule (a particle and the wall together > skin) the lists hold every triangle that can come
// within radius + max_gap provided range ≥ max_gap + skin. CSR lists: cand_particle_[c] has the
// triangles cand_tri_[cand_off_[c] .. cand_off_[c + 1]), ascending, in particle order whatever
// the thread count.
//
// The three functions share one file on purpose: with closestPointOnTriangle called from both
// buildGrid and buildCandidates the compiler keeps it out of line in both, as it did before the
// file was split, so the generated code (and every result) stays the same.
#include "mesh_wall_internal.hpp"

#include <paddy/geometry/mesh_check.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace paddy {

void MeshWall::buildGrid(double query) {
  auto g = std::make_unique<Grid>();
  const geometry::Bounds b = geometry::bounds(mesh_);
  double h = std::max(2.0 * query, 1e-9 * std::max(1.0, b.size().maxCoeff()));
  const Vec3 size = b.size();
  auto dims = [&](double cell) {
    return Eigen::Vector3i(static_cast<int>(std::floor(size.x() / cell)) + 1, static_cast<int>(std::floor(size.y() / cell)) + 1,
                           static_cast<int>(std::floor(size.z() / cell)) + 1);
  };
  while (true) {
    const Eigen::Vector3i d = dims(h);
    if (static_cast<double>(d.x()) * d.y() * d.z() <= 4.0e6) break;
    h *= 1.25;
  }
  const Eigen::Vector3i d = dims(h);
  g->h = h;
  g->nx = d.x();
  g->ny = d.y();
  g->nz = d.z();
  g->lo = b.lo;
  g->built_for = query;
  const double reach = 0.5 * std::sqrt(3.0) * h;  // circumradius of a cell
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (cell, triangle)
  for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
    const auto& tri = mesh_.triangles[t];
    const Vec3 &a = mesh_.vertices[tri[0]], &bb = mesh_.vertices[tri[1]], &c = mesh_.vertices[tri[2]];
    const Vec3 tlo = a.cwiseMin(bb).cwiseMin(c), thi = a.cwiseMax(bb).cwiseMax(c);
    Eigen::Vector3i i0, i1;
    for (int k = 0; k < 3; ++k) {
      i0[k] = std::clamp(static_cast<int>(std::floor((tlo[k] - g->lo[k]) / h)), 0, d[k] - 1);
      i1[k] = std::clamp(static_cast<int>(std::floor((thi[k] - g->lo[k]) / h)), 0, d[k] - 1);
    }
    for (int k = i0.z(); k <= i1.z(); ++k)
      for (int j = i0.y(); j <= i1.y(); ++j)
        for (int i = i0.x(); i <= i1.x(); ++i) {
          const Vec3 centre = g->lo + h * Vec3(i + 0.5, j + 0.5, k + 0.5);
          if (std::abs(tri_normal_[t].dot(centre - a)) > reach) continue;
          if ((geometry::closestPointOnTriangle(centre, a, bb, c).point - centre).norm() > reach) continue;
          pairs.emplace_back(static_cast<std::uint32_t>(g->index(i, j, k)), static_cast<std::uint32_t>(t));
        }
  }
  const std::size_t ncell = static_cast<std::size_t>(d.x()) * d.y() * d.z();
  g->start.assign(ncell + 1, 0);
  for (const auto& p : pairs) ++g->start[p.first + 1];
  for (std::size_t i = 0; i < ncell; ++i) g->start[i + 1] += g->start[i];
  g->items.assign(pairs.size(), 0);
  std::vector<std::uint32_t> fill(g->start.begin(), g->start.end() - 1);
  for (const auto& p : pairs) g->items[fill[p.first]++] = p.second;
  grid_ = std::move(g);
}

template <class Visit>
void MeshWall::forEachCellItem(const Vec3& xb, double reach, Visit&& visit) const {
  if (!grid_) {
    for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) visit(static_cast<std::uint32_t>(t));
    return;
  }
  const Grid& g = *grid_;
  int lo[3], hi[3];
  const int n[3] = {g.nx, g.ny, g.nz};
  for (int k = 0; k < 3; ++k) {
    const double a = (xb[k] - reach - g.lo[k]) / g.h, b = (xb[k] + reach - g.lo[k]) / g.h;
    if (b < 0.0 || a >= n[k]) return;  // query box outside the grid
    lo[k] = std::max(0, static_cast<int>(std::floor(a)));
    hi[k] = std::min(n[k] - 1, static_cast<int>(std::floor(b)));
  }
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const std::size_t c = g.index(i, j, k);
        for (std::uint32_t q = g.start[c]; q < g.start[c + 1]; ++q) visit(g.items[q]);
      }
}

void MeshWall::gatherTriangles(const Vec3& xb, double reach, std::vector<std::uint32_t>& tris) const {
  tris.clear();
  forEachCellItem(xb, reach, [&](std::uint32_t t) { tris.push_back(t); });
  std::sort(tris.begin(), tris.end());
  tris.erase(std::unique(tris.begin(), tris.end()), tris.end());
}


void MeshWall::buildCandidates(const ParticleView& p, double range) {
  double rmax = 0.0;
  for (std::size_t i = 0; i < p.n; ++i) rmax = std::max(rmax, p.radius[i]);
  const double query = rmax + std::max(range, 0.0);
  if (!grid_ || query > 2.0 * grid_->built_for || query < 0.25 * grid_->built_for) buildGrid(query);

  const int nthreads = std::max(1, p.threads);
  std::vector<std::vector<std::uint32_t>> lpart(static_cast<std::size_t>(nthreads)), lcount(static_cast<std::size_t>(nthreads)),
      ltri(static_cast<std::size_t>(nthreads));
  const long n = static_cast<long>(p.n);
  // The simulation's threads, static chunks in thread order: the lists come out in particle order
  // whatever the thread count.
#pragma omp parallel num_threads(nthreads) if (n >= mesh_wall_detail::kParallelMin)
  {
    const auto tid = static_cast<std::size_t>(omp_get_thread_num());
    // Per thread: the last particle (index + 1) that looked at each triangle, so that a triangle
    // listed in several of the particle's cells is tested once, and the triangles kept.
    std::vector<std::uint32_t> seen_by(mesh_.triangles.size(), 0), kept;
#pragma omp for schedule(static)
    for (long i = 0; i < n; ++i) {
      const Vec3 xb = state_.pose.toBody(p.position[i]);
      const double reach = p.radius[i] + range;
      // The plane's distance is a lower bound of the triangle's: beyond reach (with a relative
      // margin for rounding), the triangle is out without its closest point.
      const double plane_reach = reach * (1.0 + 1e-9);
      const auto stamp = static_cast<std::uint32_t>(i) + 1;
      kept.clear();
      forEachCellItem(xb, reach, [&](std::uint32_t t) {
        if (seen_by[t] == stamp) return;
        seen_by[t] = stamp;
        const auto& tri = mesh_.triangles[t];
        if (std::abs(tri_normal_[t].dot(xb - mesh_.vertices[tri[0]])) > plane_reach) return;
        const auto cp = geometry::closestPointOnTriangle(xb, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]);
        if ((cp.point - xb).squaredNorm() <= reach * reach) kept.push_back(t);
      });
      if (kept.empty()) continue;
      std::sort(kept.begin(), kept.end());  // ascending, as gatherTriangles lists them
      ltri[tid].insert(ltri[tid].end(), kept.begin(), kept.end());
      lpart[tid].push_back(static_cast<std::uint32_t>(i));
      lcount[tid].push_back(static_cast<std::uint32_t>(kept.size()));
    }
  }
  cand_particle_.clear();
  cand_off_.assign(1, 0);
  cand_tri_.clear();
  for (std::size_t t = 0; t < lpart.size(); ++t) {
    cand_particle_.insert(cand_particle_.end(), lpart[t].begin(), lpart[t].end());
    for (auto c : lcount[t]) cand_off_.push_back(cand_off_.back() + c);
    cand_tri_.insert(cand_tri_.end(), ltri[t].begin(), ltri[t].end());
  }
}

}  // namespace paddy
