// NeighbourList: cell list + half Verlet list with a skin, and the contact history that lives on
// its slots.
//
// Each pair is stored once, under the particle with the smaller persistent id (the "owner"), so
// a pair's history always has the same orientation, whatever the storage order. At a rebuild the
// history of every pair that is still listed is copied from the old list (looked up by the
// partner's id), so it survives rebuilds and spatial re-sorting.
#pragma once

#include "contact_law.hpp"

#include <paddy/simulation.hpp>

#include <cstdint>
#include <vector>

namespace paddy {

// Uniform grid of cells over the particles' bounding box; the particles of each cell are
// contiguous in `order`, and the cells of a row along x are contiguous in the cell order. The
// cells are `size` wide along y and z and size / x_split along x (x_split = 1: cubes).
struct CellGrid {
  Vec3 origin = Vec3::Zero();
  double size = 0.0;    // along y and z
  double size_x = 0.0;  // along x: size / x_split
  int nx = 1, ny = 1, nz = 1;
  std::vector<std::uint32_t> cell_start;  // size nx*ny*nz + 1 (particle counts fit: indices are 32-bit)
  std::vector<std::uint32_t> order;     // particle indices grouped by cell
  std::vector<std::uint32_t> cell_of;   // cell of each particle

  void build(const std::vector<Vec3>& x, double cell_size, int x_split = 1);
  int cellIndex(int ix, int iy, int iz) const { return (iz * ny + iy) * nx + ix; }
};

struct NeighbourList {
  std::vector<std::size_t> start;          // owner i's slots: [start[i], start[i+1])
  std::vector<std::uint32_t> partner;      // partner's current index
  std::vector<std::uint64_t> partner_id;   // partner's persistent id
  std::vector<double> range2;              // (R_i + R_j + max separation)², interaction range
  std::vector<std::int32_t> law;           // contact law of the pair
  std::vector<double> history;             // slot-major blocks of `stride` doubles
  std::vector<std::uint8_t> live;          // 1 if the slot's history may be non-zero
  std::size_t stride = 0;
  std::vector<Vec3> x_at_build;            // positions at the build (for the skin criterion)
  double cell_size = 0.0;

  std::size_t slots() const { return partner.size(); }

  // A pair found by the search, before the slots are laid out.
  struct Entry {
    std::uint32_t j;
    std::int32_t law;
    double range2;
  };

  // Rebuilds for the current particle state. `prev_index[i]` is particle i's index at the
  // previous build (SIZE_MAX for new particles). Throws InputError if two materials that meet
  // have no interaction.
  void build(const ParticleArrays& p, const std::vector<std::size_t>& prev_index, double skin,
             std::size_t history_stride, const std::vector<ContactLaw>& laws,
             const std::vector<int>& law_index, const std::vector<Material>& materials, int threads);

 private:
  // Scratch kept between builds (build() reuses their memory): the list before this build, the
  // search's entries per thread, the cell grid.
  std::vector<std::size_t> old_start_;
  std::vector<std::uint64_t> old_partner_id_;
  std::vector<double> old_history_;
  std::vector<std::uint8_t> old_live_;
  std::vector<std::vector<Entry>> per_thread_;
  CellGrid grid_;
};


}  // namespace paddy
