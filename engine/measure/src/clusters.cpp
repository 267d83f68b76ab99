// Connected clusters of spheres (surface gap ≤ gap): union–find over a sorted cell list
// (cells hashed to their particle ranges).
#include <paddy/util/union_find.hpp>
#include <paddy/errors.hpp>
#include <paddy/measure/clusters.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace paddy::measure {

namespace {

using DisjointSets = paddy::UnionFind<std::size_t>;

// 21 bits per coordinate, offset so negative cells stay distinct.
std::uint64_t cellKey(std::int64_t i, std::int64_t j, std::int64_t k) {
  constexpr std::int64_t off = 1 << 20;
  auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v + off) & 0x1FFFFF; };
  return (u(i) << 42) | (u(j) << 21) | u(k);
}

}  // namespace

Clusters connectedClusters(const std::vector<Vec3>& x, const std::vector<double>& r, double gap) {
  checkParticles(x, r, "connectedClusters");
  if (!(gap >= 0.0) || !std::isfinite(gap))
    throw InputError("connectedClusters: gap = " + std::to_string(gap) + " must be finite and >= 0");
  const std::size_t n = x.size();
  const double r_max = *std::max_element(r.begin(), r.end());
  Vec3 lo = x[0];
  for (const auto& p : x) lo = lo.cwiseMin(p);
  double cell = 2.0 * r_max + gap;
  // Keep cell indices within the 21-bit key range.
  Vec3 hi = x[0];
  for (const auto& p : x) hi = hi.cwiseMax(p);
  cell = std::max(cell, (hi - lo).maxCoeff() / 1.0e6);

  std::vector<std::int64_t> ci(n), cj(n), ck(n);
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed(n);
  for (std::size_t p = 0; p < n; ++p) {
    ci[p] = static_cast<std::int64_t>(std::floor((x[p].x() - lo.x()) / cell));
    cj[p] = static_cast<std::int64_t>(std::floor((x[p].y() - lo.y()) / cell));
    ck[p] = static_cast<std::int64_t>(std::floor((x[p].z() - lo.z()) / cell));
    keyed[p] = {cellKey(ci[p], cj[p], ck[p]), p};
  }
  std::sort(keyed.begin(), keyed.end());
  std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> cells;  // key → [begin, end)
  cells.reserve(n);
  for (std::size_t b = 0; b < n;) {
    std::size_t e = b + 1;
    while (e < n && keyed[e].first == keyed[b].first) ++e;
    cells.emplace(keyed[b].first, std::make_pair(b, e));
    b = e;
  }

  DisjointSets uf(n);
  // Half shell: the own cell (pairs q > p) and the 13 cells with offset (di, dj, dk) > 0 in
  // lexicographic order; union is symmetric, so every pair is seen once.
  for (std::size_t p = 0; p < n; ++p) {
    for (int di = 0; di <= 1; ++di)
      for (int dj = (di == 0 ? 0 : -1); dj <= 1; ++dj)
        for (int dk = (di == 0 && dj == 0 ? 0 : -1); dk <= 1; ++dk) {
          const bool own = di == 0 && dj == 0 && dk == 0;
          const std::uint64_t key = cellKey(ci[p] + di, cj[p] + dj, ck[p] + dk);
          const auto cell_it = cells.find(key);
          if (cell_it == cells.end()) continue;
          for (std::size_t k = cell_it->second.first; k < cell_it->second.second; ++k) {
            const std::size_t q = keyed[k].second;
            if (own && q <= p) continue;
            const double reach = r[p] + r[q] + gap;
            if ((x[p] - x[q]).squaredNorm() <= reach * reach) uf.unite(p, q);
          }
        }
  }

  Clusters c;
  c.label.assign(n, -1);
  std::vector<int> root_label(n, -1);
  for (std::size_t p = 0; p < n; ++p) {
    const std::size_t root = uf.find(p);
    if (root_label[root] < 0) {
      root_label[root] = static_cast<int>(c.size.size());
      c.size.push_back(0);
    }
    c.label[p] = root_label[root];
    ++c.size[static_cast<std::size_t>(c.label[p])];
  }
  c.largest = static_cast<int>(std::max_element(c.size.begin(), c.size.end()) - c.size.begin());
  return c;
}

}  // namespace paddy::measure
