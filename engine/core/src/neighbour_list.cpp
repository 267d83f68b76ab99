#include "neighbour_list.hpp"

#include <paddy/errors.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace paddy {

void CellGrid::build(const std::vector<Vec3>& x, double cell_size) {
  const std::size_t n = x.size();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max());
  Vec3 hi = Vec3::Constant(std::numeric_limits<double>::lowest());
  for (const auto& xi : x) {
    lo = lo.cwiseMin(xi);
    hi = hi.cwiseMax(xi);
  }
  if (n == 0) lo = hi = Vec3::Zero();
  // Positions spread beyond the largest double (e.g. from a hand-made checkpoint) would make the
  // cell count below infinite for every cell size: the loop would never end.
  if (!(hi - lo).allFinite())
    throw InstabilityError("particle positions span more than the largest number (" + std::to_string(lo.minCoeff()) +
                           " to " + std::to_string(hi.maxCoeff()) + " m): a particle has flown away");
  size = cell_size;
  // Keep the grid at most ~8 cells per particle even if a few particles fly far away.
  const double max_cells = std::max<double>(1000.0, 8.0 * static_cast<double>(n));
  for (;;) {
    const Vec3 ext = (hi - lo) / size;
    const double cells = (std::floor(ext.x()) + 1) * (std::floor(ext.y()) + 1) * (std::floor(ext.z()) + 1);
    if (cells <= max_cells) break;
    size *= 1.5;
  }
  origin = lo;
  nx = static_cast<int>((hi.x() - lo.x()) / size) + 1;
  ny = static_cast<int>((hi.y() - lo.y()) / size) + 1;
  nz = static_cast<int>((hi.z() - lo.z()) / size) + 1;
  const std::size_t ncell = static_cast<std::size_t>(nx) * ny * nz;
  cell_start.assign(ncell + 1, 0);
  cell_of.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 r = (x[i] - origin) / size;
    const int ix = std::min(nx - 1, static_cast<int>(r.x()));
    const int iy = std::min(ny - 1, static_cast<int>(r.y()));
    const int iz = std::min(nz - 1, static_cast<int>(r.z()));
    cell_of[i] = static_cast<std::uint32_t>(cellIndex(ix, iy, iz));
    ++cell_start[cell_of[i] + 1];
  }
  for (std::size_t c = 0; c < ncell; ++c) cell_start[c + 1] += cell_start[c];
  order.resize(n);
  std::vector<std::size_t> fill(cell_start.begin(), cell_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i) order[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
}

void NeighbourList::build(const ParticleArrays& p, const std::vector<std::size_t>& prev_index, double skin,
                          std::size_t history_stride, const std::vector<ContactLaw>& laws,
                          const std::vector<int>& law_index, const std::vector<Material>& materials,
                          int threads) {
  const std::size_t n = p.size();
  const int nmat = static_cast<int>(materials.size());
  double rmax = 0.0;
  for (double r : p.radius) rmax = std::max(rmax, r);
  double sep_max = 0.0;
  for (const auto& law : laws) sep_max = std::max(sep_max, law.maxSeparation(0.5 * rmax));
  cell_size = std::max(2.0 * rmax + sep_max + skin, 1e-12);

  CellGrid& grid = grid_;
  grid.build(p.position, cell_size);

  // The old list is kept for the history carry-over; its arrays trade places with the spare ones
  // of the build before, so the new list reuses their memory instead of allocating (and
  // faulting in) megabytes at every build.
  std::swap(old_start_, start);
  std::swap(old_partner_id_, partner_id);
  std::swap(old_history_, history);
  std::swap(old_live_, live);
  const std::size_t old_stride = stride;
  stride = history_stride;
  const bool can_copy = old_stride == stride && stride > 0 && old_start_.size() >= 2;

  start.assign(n + 1, 0);  // the counts per owner first (start[i + 1]), then their prefix sums
  per_thread_.resize(static_cast<std::size_t>(threads));
  std::string missing_pair;

#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    const int nt = omp_get_num_threads();
    const std::size_t lo = n * t / nt, hi = n * (t + 1) / nt;
    auto& out = per_thread_[static_cast<std::size_t>(t)];
    out.clear();
    // The pair law's largest gap for the pair's R*, computed again only when the law or R* differs
    // from the previous pair's (once per law for a monodisperse fill).
    int sep_law = -1;
    double sep_r_eff = 0.0, sep_pair = 0.0;
    for (std::size_t i = lo; i < hi; ++i) {
      const Vec3 xi = p.position[i];
      const double ri = p.radius[i];
      const std::uint64_t idi = p.id[i];
      const int c = static_cast<int>(grid.cell_of[i]);
      const int ix = c % grid.nx, iy = (c / grid.nx) % grid.ny, iz = c / (grid.nx * grid.ny);
      // The 3 × 3 columns of neighbour cells; the three cells of a column along x are adjacent in
      // the cell order, so each column is one contiguous run of grid.order.
      const int x0 = std::max(ix - 1, 0), x1 = std::min(ix + 1, grid.nx - 1);
      std::size_t m = 0;
      for (int dz = -1; dz <= 1; ++dz) {
        const int z = iz + dz;
        if (z < 0 || z >= grid.nz) continue;
        for (int dy = -1; dy <= 1; ++dy) {
          const int y = iy + dy;
          if (y < 0 || y >= grid.ny) continue;
          const std::size_t q_end = grid.cell_start[static_cast<std::size_t>(grid.cellIndex(x1, y, z)) + 1];
          for (std::size_t q = grid.cell_start[static_cast<std::size_t>(grid.cellIndex(x0, y, z))]; q < q_end; ++q) {
            const std::uint32_t j = grid.order[q];
            const double rj = p.radius[j];
            const double d2 = (xi - p.position[j]).squaredNorm();
            const double reach_list = ri + rj + sep_max + skin;
            // One test for both conditions (the owner of a pair is its smaller id): most
            // candidates fail it, so one well-predicted branch instead of two coin flips.
            if (!((p.id[j] > idi) & (d2 < reach_list * reach_list))) continue;
            const int law = law_index[static_cast<std::size_t>(p.material[i] * nmat + p.material[j])];
            if (law < 0) {
#pragma omp critical(paddy_missing_pair)
              missing_pair = materials[p.material[i]].name + "' and '" + materials[p.material[j]].name;
              continue;
            }
            const double r_eff = ri * rj / (ri + rj);
            if (law != sep_law || r_eff != sep_r_eff) {
              sep_law = law;
              sep_r_eff = r_eff;
              sep_pair = laws[law].maxSeparation(r_eff);
            }
            const double reach = ri + rj + sep_pair;
            const double reach_skin = reach + skin;
            if (d2 >= reach_skin * reach_skin) continue;
            out.push_back({j, law, reach * reach});
            ++m;
          }
        }
      }
      start[i + 1] = m;
      // Deterministic slot order within an owner: by partner id.
      std::sort(out.end() - static_cast<std::ptrdiff_t>(m), out.end(),
                [&](const Entry& a, const Entry& b) { return p.id[a.j] < p.id[b.j]; });
    }
#pragma omp barrier
#pragma omp single
    {
      for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
      const std::size_t total = start[n];
      partner.resize(total);
      partner_id.resize(total);
      range2.resize(total);
      law.resize(total);
      history.resize(total * stride);
      live.resize(total);
    }  // implicit barrier: every thread sees the offsets and the sized arrays
    // Each thread writes the slots of its own owners [lo, hi): its entries, in order, from start[lo].
    std::size_t k = start[lo];
    for (const Entry& e : out) {
      partner[k] = e.j;
      partner_id[k] = p.id[e.j];
      range2[k] = e.range2;
      law[k] = e.law;
      ++k;
    }
    std::fill(history.begin() + static_cast<std::ptrdiff_t>(start[lo] * stride),
              history.begin() + static_cast<std::ptrdiff_t>(start[hi] * stride), 0.0);
    std::fill(live.begin() + static_cast<std::ptrdiff_t>(start[lo]), live.begin() + static_cast<std::ptrdiff_t>(start[hi]),
              std::uint8_t{0});
    // Carry the history over from the old list (the same owners: no barrier needed).
    if (can_copy) {
      for (std::size_t i = lo; i < hi; ++i) {
        const std::size_t oi = i < prev_index.size() ? prev_index[i] : std::numeric_limits<std::size_t>::max();
        if (oi == std::numeric_limits<std::size_t>::max() || oi + 1 >= old_start_.size()) continue;
        std::size_t o = old_start_[oi];
        const std::size_t oend = old_start_[oi + 1];
        for (std::size_t s = start[i]; s < start[i + 1]; ++s) {
          // Both lists are sorted by partner id: merge.
          while (o < oend && old_partner_id_[o] < partner_id[s]) ++o;
          if (o < oend && old_partner_id_[o] == partner_id[s] && old_live_[o]) {
            std::copy_n(&old_history_[o * stride], stride, &history[s * stride]);
            live[s] = 1;
          }
        }
      }
    }
  }
  if (!missing_pair.empty())
    throw InputError("no interaction is defined between materials '" + missing_pair +
                     "'; add one with sim:interaction(...)");
  x_at_build = p.position;
}

}  // namespace paddy
