#include "paddy/doe/plackett_burman.hpp"

#include "paddy/doe/error.hpp"

#include <string>

namespace paddy::doe {

std::vector<int> plackettBurmanGenerator(int n) {
  std::string s;
  switch (n) {
    case 8: s = "+++-+--"; break;
    case 12: s = "++-+++---+-"; break;
    case 16: s = "++++-+-++--+---"; break;
    case 20: s = "++--++++-+-+----++-"; break;
    case 24: s = "+++++-+-++--++--+-+----"; break;
    default: throw DoeError("Plackett-Burman: supported run counts are 8, 12, 16, 20, 24 (got " + std::to_string(n) + ")");
  }
  std::vector<int> g;
  for (char c : s) g.push_back(c == '+' ? 1 : -1);
  return g;
}

Design plackettBurman(int n, int k) {
  const auto g = plackettBurmanGenerator(n);
  if (k < 0) k = n - 1;
  if (k < 1 || k > n - 1)
    throw DoeError("Plackett-Burman with " + std::to_string(n) + " runs takes 1.." + std::to_string(n - 1) + " factors");
  Eigen::MatrixXd x(n, k);
  for (int i = 0; i < n - 1; ++i)
    for (int j = 0; j < k; ++j) x(i, j) = g[((j - i) % (n - 1) + (n - 1)) % (n - 1)];
  x.row(n - 1).setConstant(-1.0);
  return makeDesign(defaultFactors(k), x, std::vector<PointType>(n, PointType::Factorial));
}

int plackettBurmanRunsFor(int k) {
  for (int n : {8, 12, 16, 20, 24})
    if (n >= k + 1) return n;
  throw DoeError("Plackett-Burman: at most 23 factors are supported");
}

}  // namespace paddy::doe
