// Connected clusters of spheres: i and j are connected when their surfaces are closer than a gap,
//   |x_i − x_j| ≤ r_i + r_j + gap,
// and clusters are the connected components of that graph (union–find over a cell list,
// O(N log N)). Used to ignore loose particles that are not part of the pile.
#pragma once

#include <paddy/measure/common.hpp>

#include <cstddef>
#include <vector>

namespace paddy::measure {

struct Clusters {
  std::vector<int> label;          // cluster index of each particle, 0 .. size.size()-1
  std::vector<std::size_t> size;   // particles per cluster
  int largest = -1;                // index of the largest cluster (-1 for no particles)
};

// gap ≥ 0 [m]. Throws InputError on bad particle data or a negative/non-finite gap.
Clusters connectedClusters(const std::vector<Vec3>& positions, const std::vector<double>& radii,
                           double gap);

}  // namespace paddy::measure
