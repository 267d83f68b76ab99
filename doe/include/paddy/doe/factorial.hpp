// Two-level full and fractional factorial designs.
//
// Full 2^k: all sign combinations in standard (Yates) order, the first factor alternating fastest
// (Montgomery, Design and Analysis of Experiments, ch. 6).
// Fractional 2^(k-p): a full factorial in the k-p basic factors; each added factor is defined by
// a generator such as "D=ABC" or "E=-ABD" (column = signed product of basic columns), which fixes
// the defining relation I = ABCD ... (Montgomery ch. 8).
#pragma once
#include "paddy/doe/design.hpp"

#include <string>
#include <vector>

namespace paddy::doe {

Design fullFactorial(int k);
/// k factors named A, B, ...; generators name the added factors (the last p letters).
Design fractionalFactorial(int k, const std::vector<std::string>& generators);

}  // namespace paddy::doe
