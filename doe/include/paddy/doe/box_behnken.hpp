// Box-Behnken designs (Box & Behnken 1960, "Some new three level designs for the study of
// quantitative variables", Technometrics 2).
//
// Each block of factors of a (balanced or partially balanced) incomplete block design is crossed
// with a 2^m factorial at +-1 while the other factors stay at 0, then centre points are added.
//   k = 3, 4, 5: all pairs of factors        -> 12, 24, 40 edge runs
//   k = 6:       6 blocks of 3 factors        -> 48 runs  (blocks from Box & Behnken's table)
//   k = 7:       7 blocks of 3 factors (BIBD) -> 56 runs
#pragma once
#include "paddy/doe/design.hpp"

#include <vector>

namespace paddy::doe {

/// Blocks (0-based factor indices) used for k factors, 3 <= k <= 7.
std::vector<std::vector<int>> boxBehnkenBlocks(int k);
Design boxBehnken(int k, int centerPoints);

}  // namespace paddy::doe
