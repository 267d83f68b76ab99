#include "paddy/doe/box_behnken.hpp"

#include "paddy/doe/error.hpp"

#include <string>

namespace paddy::doe {

std::vector<std::vector<int>> boxBehnkenBlocks(int k) {
  if (k >= 3 && k <= 5) {
    std::vector<std::vector<int>> b;
    for (int i = 0; i < k; ++i)
      for (int j = i + 1; j < k; ++j) b.push_back({i, j});
    return b;
  }
  if (k == 6) return {{0, 1, 3}, {1, 2, 4}, {2, 3, 5}, {0, 3, 4}, {1, 4, 5}, {0, 2, 5}};
  if (k == 7) return {{3, 4, 5}, {0, 5, 6}, {1, 4, 6}, {0, 1, 3}, {2, 3, 6}, {0, 2, 4}, {1, 2, 5}};
  throw DoeError("Box-Behnken: 3 to 7 factors are supported (got " + std::to_string(k) + ")");
}

Design boxBehnken(int k, int centerPoints) {
  const auto blocks = boxBehnkenBlocks(k);
  std::vector<Eigen::VectorXd> rows;
  for (const auto& b : blocks) {
    const int m = static_cast<int>(b.size());
    for (int s = 0; s < (1 << m); ++s) {
      Eigen::VectorXd r = Eigen::VectorXd::Zero(k);
      // standard order within a block: the first factor of the block alternates fastest
      for (int t = 0; t < m; ++t) r(b[t]) = ((s >> t) & 1) ? 1.0 : -1.0;
      rows.push_back(r);
    }
  }
  Eigen::MatrixXd x(rows.size(), k);
  for (std::size_t i = 0; i < rows.size(); ++i) x.row(static_cast<Eigen::Index>(i)) = rows[i].transpose();
  Design d = makeDesign(defaultFactors(k), x, std::vector<PointType>(rows.size(), PointType::Edge));
  addCenterPoints(d, centerPoints);
  return d;
}

}  // namespace paddy::doe
