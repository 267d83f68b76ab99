// Plackett-Burman two-level screening designs (Plackett & Burman 1946, "The design of optimum
// multifactorial experiments", Biometrika 33).
//
// For N = 8, 12, 16, 20, 24 runs the first row is the published generator of N-1 signs; rows
// 2..N-1 are cyclic shifts of it (each row is the previous one shifted right by one place) and the
// last row is all minus. The N-1 columns are mutually orthogonal: X^T X = N I.
#pragma once
#include "paddy/doe/design.hpp"

#include <vector>

namespace paddy::doe {

/// The published generator row for N runs (N in {8, 12, 16, 20, 24}).
std::vector<int> plackettBurmanGenerator(int n);
/// N-run design using the first k columns (k <= N-1; default all N-1).
Design plackettBurman(int n, int k = -1);
/// Smallest supported N with N >= k + 1.
int plackettBurmanRunsFor(int k);

}  // namespace paddy::doe
