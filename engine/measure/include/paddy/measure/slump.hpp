// Slump of the virtual slump test (GB/T 50080-2016): slump = cone height − pile height, where the
// pile height is the height of the highest point of the slumped pile above the plate, read near
// the cone axis.
//
// Pile height (our definition, see docs/measurement.md):
//   1. keep the particles of the largest connected cluster (surfaces closer than `contact_gap`),
//      so loose particles that flew off or stuck to the lifted cone are ignored;
//   2. take the column of particles whose centres lie within r_axis of the axis (horizontal
//      distance); r_axis defaults to 3 mean particle diameters and is widened ×1.5 until the
//      column holds at least `min_particles`;
//   3. pile height = quantile q of (z + r − base_z) over the column; q = 1 (default) is the highest
//      point, what the standard's ruler touches. q < 1 ignores the top (1−q) fraction of tops,
//      at the cost of a downward bias of about (1−q)·h for a column of height h.
// Pile profile h(r): ring bins of width Δr about the axis, each ring cut into azimuthal cells
// of arc length ≈ `cell_arc`; surface height of a cell = highest (z + r − base_z) among the
// particles whose centres fall in it (0 for an empty cell); h = quantile `cell_quantile`
// (default the median) of the cells of the ring.
#pragma once

#include <paddy/measure/common.hpp>

#include <cstddef>
#include <vector>

namespace paddy::measure {

struct SlumpHeightOptions {
  Vec2 axis = Vec2::Zero();        // axis point (x, y) [m]
  double base_z = 0.0;             // height of the plate surface [m]
  double r_axis = 0.0;             // column radius [m]; 0 = 3 mean particle diameters
  std::size_t min_particles = 10;  // widen r_axis by ×1.5 until the column has this many
  double quantile = 1.0;           // of (z + r) in the column; 1 = the highest point
  bool largest_cluster = true;     // only particles of the largest connected cluster count
  double contact_gap = -1.0;       // connection gap [m]; < 0 = 0.1 × mean radius
};

struct SlumpHeightResult {
  double height = 0.0;          // pile height above base_z [m]
  double r_axis = 0.0;          // column radius actually used [m]
  std::size_t column = 0;       // particles in the column
  std::size_t cluster = 0;      // particles in the pile (largest cluster, or all)
  std::size_t ignored = 0;      // particles ignored as not connected to the pile
};

SlumpHeightResult slumpHeight(const std::vector<Vec3>& positions, const std::vector<double>& radii,
                              const SlumpHeightOptions& options = {});

// slump = cone_height − pile_height [m]. Throws InputError on non-finite input.
double slump(double cone_height, double pile_height);

struct ProfileOptions {
  Vec2 axis = Vec2::Zero();    // axis point (x, y) [m]
  double base_z = 0.0;         // plate surface [m]
  double bin_width = 0.0;      // Δr [m]; 0 = one mean particle diameter
  double r_max = 0.0;          // last bin ends at or beyond this [m]; 0 = farthest particle edge
  double cell_arc = 0.0;       // azimuthal cell length [m]; 0 = two mean particle diameters
  double cell_quantile = 0.5;  // quantile over the ring's cells (0.5 = median)
  bool largest_cluster = false;
  double contact_gap = -1.0;   // as SlumpHeightOptions
};

struct ProfileBin {
  double r_inner = 0.0, r_outer = 0.0, r_centre = 0.0;  // [m]
  double height = 0.0;     // surface height h(r) above base_z [m]: the cell_quantile of the cells' tops
  double mean_height = 0.0;  // mean of the cells' tops (0 for an empty cell) [m]: the ring's volume per
                             // area; moves continuously as the pile's edge crosses the ring, where the
                             // quantile jumps between 0 and a sphere's height
  double coverage = 0.0;   // fraction of the ring's cells holding a particle centre
  std::size_t particles = 0;
  std::size_t cells = 0;
};

std::vector<ProfileBin> pileProfile(const std::vector<Vec3>& positions,
                                    const std::vector<double>& radii,
                                    const ProfileOptions& options = {});

}  // namespace paddy::measure
