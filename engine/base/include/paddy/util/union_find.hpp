// UnionFind: disjoint sets with path halving; the representative of a set is its smallest
// element, so labels do not depend on the order of unions (used for smooth mesh regions, mesh
// components and particle clusters).
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

namespace paddy {

template <class Index = std::size_t>
struct UnionFind {
  std::vector<Index> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), Index{0}); }
  Index find(Index x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

}  // namespace paddy
