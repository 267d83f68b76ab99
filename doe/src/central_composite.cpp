#include "paddy/doe/central_composite.hpp"

#include "paddy/doe/error.hpp"
#include "paddy/doe/factorial.hpp"

#include <cmath>

namespace paddy::doe {

double rotatableAlpha(int factorialRuns) { return std::pow(static_cast<double>(factorialRuns), 0.25); }

Design centralComposite(int k, const CcdOptions& opt) {
  if (k < 2) throw DoeError("central composite design needs at least 2 factors");
  Design cube = opt.generators.empty() ? fullFactorial(k) : fractionalFactorial(k, opt.generators);
  const int nf = cube.runs();
  double alpha = opt.alpha.value_or(rotatableAlpha(nf));
  if (opt.type == CcdType::FaceCentred) alpha = 1.0;
  if (!(alpha > 0.0)) throw DoeError("central composite design: alpha must be > 0");
  const double scale = opt.type == CcdType::Inscribed ? 1.0 / alpha : 1.0;
  Eigen::MatrixXd x(nf + 2 * k, k);
  x.topRows(nf) = cube.coded * scale;
  std::vector<PointType> type(nf, PointType::Factorial);
  for (int j = 0; j < k; ++j)
    for (int s = 0; s < 2; ++s) {
      Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(k);
      r(j) = (s == 0 ? -alpha : alpha) * scale;
      x.row(nf + 2 * j + s) = r;
      type.push_back(PointType::Axial);
    }
  Design d = makeDesign(defaultFactors(k), x, type);
  addCenterPoints(d, opt.centerPoints);
  return d;
}

}  // namespace paddy::doe
