#include "neighbour_list.hpp"

#include <paddy/errors.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace paddy {

void CellGrid::build(const std::vector<Vec3>& x, double cell_size, int x_split) {
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
  const double split = static_cast<double>(std::max(x_split, 1));
  // Keep the grid at most ~8 cells per particle (x_split times that with split rows) even if a
  // few particles fly far away.
  const double max_cells = split * std::max<double>(1000.0, 8.0 * static_cast<double>(n));
  for (;;) {
    size_x = size / split;
    const Vec3 ext = hi - lo;
    const double cells =
        (std::floor(ext.x() / size_x) + 1) * (std::floor(ext.y() / size) + 1) * (std::floor(ext.z() / size) + 1);
    if (cells <= max_cells) break;
    size *= 1.5;
  }
  origin = lo;
  nx = static_cast<int>((hi.x() - lo.x()) / size_x) + 1;
  ny = static_cast<int>((hi.y() - lo.y()) / size) + 1;
  nz = static_cast<int>((hi.z() - lo.z()) / size) + 1;
  const std::size_t ncell = static_cast<std::size_t>(nx) * ny * nz;
  cell_start.assign(ncell + 1, 0);
  cell_of.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 r = x[i] - origin;
    const int ix = std::min(nx - 1, static_cast<int>(r.x() / size_x));
    const int iy = std::min(ny - 1, static_cast<int>(r.y() / size));
    const int iz = std::min(nz - 1, static_cast<int>(r.z() / size));
    cell_of[i] = static_cast<std::uint32_t>(cellIndex(ix, iy, iz));
    ++cell_start[cell_of[i] + 1];
  }
  // Counting sort in place: the prefix sums make cell_start[c] cell c's first slot; placing the
  // particles advances it to cell c + 1's first slot, and a shift by one cell restores it.
  for (std::size_t c = 0; c < ncell; ++c) cell_start[c + 1] += cell_start[c];
  order.resize(n);
  for (std::size_t i = 0; i < n; ++i) order[cell_start[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  for (std::size_t c = ncell - 1; c > 0; --c) cell_start[c] = cell_start[c - 1];
  cell_start[0] = 0;
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

  // Cells one list reach wide along y and z (a pair is in neighbouring rows), kXSplit times
  // narrower along x. Each owner searches the 3 × 3 rows of cells along x around its own, in each
  // only the cells within its x ± reach (2.25 reaches of row instead of the 3 of three cubes),
  // and skips a corner or edge row whose least y–z distance is beyond its reach: about 3/4 of the
  // candidates of the 3 × 3 × 3 cubes, the same pairs. (Narrowing each row's x range to
  // √(reach² − its least y–z distance²) tests fewer candidates still but costs more than it saves:
  // a square root per row. Finer rows, kXSplit = 8, save a little in the search and lose it in the
  // serial grid build.)
  constexpr int kXSplit = 4;
  CellGrid& grid = grid_;
  grid.build(p.position, cell_size, kXSplit);
  // The cell bounds are lower bounds of the distances only up to rounding: the search reaches
  // this much further (far more than the rounding of the coordinates, far less than a sphere).
  const double extent = std::max({double(grid.nx) * grid.size_x, double(grid.ny) * grid.size, double(grid.nz) * grid.size});
  const double margin = 1e-9 * cell_size + 1e-12 * (extent + grid.origin.cwiseAbs().maxCoeff());

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
    // The search loop's data as the thread's own locals (kept in registers, not reloaded from
    // the shared frame after every push_back).
    const Vec3* const X = p.position.data();
    const double* const Rad = p.radius.data();
    const std::uint64_t* const Id = p.id.data();
    const int* const Mat = p.material.data();
    const std::uint32_t* const Order = grid.order.data();
    const std::uint32_t* const CellStart = grid.cell_start.data();
    const std::uint32_t* const CellOf = grid.cell_of.data();
    const int nx = grid.nx, ny = grid.ny, nz = grid.nz;
    const double size_yz = grid.size, inv_x = 1.0 / grid.size_x;
    const Vec3 origin = grid.origin;
    const double rmax_reach = rmax + sep_max + skin + margin;
    out.clear();
    // The pair law's largest gap for the pair's R*, computed again only when the law or R* differs
    // from the previous pair's (once per law for a monodisperse fill).
    int sep_law = -1;
    double sep_r_eff = 0.0, sep_pair = 0.0;
    for (std::size_t i = lo; i < hi; ++i) {
      const Vec3 xi = X[i];
      const double ri = Rad[i];
      const std::uint64_t idi = Id[i];
      const int mat_i = Mat[i];
      const int c = static_cast<int>(CellOf[i]);
      const int iy = (c / nx) % ny, iz = c / (nx * ny);
      // Owner i's reach to any partner (rounding margin included), and where it sits in the grid.
      const double reach_i = ri + rmax_reach;
      const double reach_i2 = reach_i * reach_i;
      const Vec3 f = xi - origin;
      // The least distance along y (z) from i to the rows below, at and above its own.
      const double gap_y[3] = {std::max(0.0, f.y() - iy * size_yz - margin), 0.0,
                               std::max(0.0, (iy + 1) * size_yz - f.y() - margin)};
      const double gap_z[3] = {std::max(0.0, f.z() - iz * size_yz - margin), 0.0,
                               std::max(0.0, (iz + 1) * size_yz - f.z() - margin)};
      // The cells along x within reach, the same in every row.
      const int x0 = std::max(0, static_cast<int>(std::floor((f.x() - reach_i) * inv_x)));
      const int x1 = std::min(nx - 1, static_cast<int>(std::floor((f.x() + reach_i) * inv_x)));
      std::size_t m = 0;
      for (int dz = -1; dz <= 1; ++dz) {
        const int z = iz + dz;
        if (z < 0 || z >= nz) continue;
        const double gz2 = gap_z[dz + 1] * gap_z[dz + 1];
        for (int dy = -1; dy <= 1; ++dy) {
          const int y = iy + dy;
          if (y < 0 || y >= ny) continue;
          const double g2 = gz2 + gap_y[dy + 1] * gap_y[dy + 1];
          if (g2 >= reach_i2) continue;
          const std::size_t q_end = CellStart[static_cast<std::size_t>(grid.cellIndex(x1, y, z)) + 1];
          for (std::size_t q = CellStart[static_cast<std::size_t>(grid.cellIndex(x0, y, z))]; q < q_end; ++q) {
            const std::uint32_t j = Order[q];
            const double rj = Rad[j];
            const double d2 = (xi - X[j]).squaredNorm();
            const double reach_list = ri + rj + sep_max + skin;  // as reach_skin below, with sep_max ≥ sep_pair
            // One test for both conditions (the owner of a pair is its smaller id): most
            // candidates fail it, so one well-predicted branch instead of two coin flips.
            if (!((Id[j] > idi) & (d2 < reach_list * reach_list))) continue;
            const int law = law_index[static_cast<std::size_t>(mat_i * nmat + Mat[j])];
            if (law < 0) {
#pragma omp critical(paddy_missing_pair)
              missing_pair = materials[static_cast<std::size_t>(mat_i)].name + "' and '" +
                             materials[static_cast<std::size_t>(Mat[j])].name;
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
                [&](const Entry& a, const Entry& b) { return Id[a.j] < Id[b.j]; });
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
