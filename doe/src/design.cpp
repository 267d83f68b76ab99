#include "paddy/doe/design.hpp"

#include "paddy/doe/error.hpp"

#include <random>

namespace paddy::doe {

std::string pointTypeName(PointType t) {
  switch (t) {
    case PointType::Factorial: return "factorial";
    case PointType::Axial: return "axial";
    case PointType::Edge: return "edge";
    case PointType::Center: return "center";
  }
  return "?";
}

Eigen::MatrixXd Design::real() const {
  Eigen::MatrixXd r(coded.rows(), coded.cols());
  for (int j = 0; j < k(); ++j)
    for (int i = 0; i < runs(); ++i) r(i, j) = factors[j].toReal(coded(i, j));
  return r;
}

std::string factorLetter(int index) {
  static const std::string letters = "ABCDEFGHJKLMNOPQRSTUVWXYZ";
  if (index < static_cast<int>(letters.size())) return std::string(1, letters[index]);
  return "X" + std::to_string(index + 1);
}

std::vector<Factor> defaultFactors(int k) {
  std::vector<Factor> f;
  for (int j = 0; j < k; ++j) f.push_back({factorLetter(j), -1.0, 1.0});
  return f;
}

Design makeDesign(std::vector<Factor> factors, Eigen::MatrixXd coded, std::vector<PointType> type) {
  Design d;
  d.factors = std::move(factors);
  d.coded = std::move(coded);
  d.type = std::move(type);
  for (int i = 0; i < d.runs(); ++i) d.stdOrder.push_back(i + 1);
  return d;
}

void addCenterPoints(Design& d, int n) {
  if (n < 0) throw DoeError("number of centre points must be >= 0");
  const Eigen::Index old = d.coded.rows();
  d.coded.conservativeResize(old + n, d.coded.cols());
  d.coded.bottomRows(n).setZero();
  for (int i = 0; i < n; ++i) {
    d.type.push_back(PointType::Center);
    d.stdOrder.push_back(static_cast<int>(old) + i + 1);
  }
}

Design replicate(const Design& d, int n) {
  if (n < 1) throw DoeError("number of replicates must be >= 1");
  Design r;
  r.factors = d.factors;
  r.coded.resize(d.runs() * n, d.k());
  for (int c = 0; c < n; ++c)
    for (int i = 0; i < d.runs(); ++i) {
      r.coded.row(c * d.runs() + i) = d.coded.row(i);
      r.type.push_back(d.type[i]);
      r.stdOrder.push_back(d.stdOrder[i]);
    }
  return r;
}

namespace {
// Uniform integer in [0, bound) by rejection, independent of the standard library's distributions.
std::uint64_t uniformBelow(std::mt19937_64& g, std::uint64_t bound) {
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() -
                              std::numeric_limits<std::uint64_t>::max() % bound;
  std::uint64_t v;
  do v = g();
  while (v >= limit);
  return v % bound;
}
}  // namespace

void randomize(Design& d, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::vector<int> perm(d.runs());
  for (int i = 0; i < d.runs(); ++i) perm[i] = i;
  for (int i = d.runs() - 1; i > 0; --i)
    std::swap(perm[i], perm[uniformBelow(g, static_cast<std::uint64_t>(i) + 1)]);
  Design r = d;
  for (int i = 0; i < d.runs(); ++i) {
    r.coded.row(i) = d.coded.row(perm[i]);
    r.type[i] = d.type[perm[i]];
    r.stdOrder[i] = d.stdOrder[perm[i]];
  }
  d = std::move(r);
}

void setFactors(Design& d, std::vector<Factor> factors) {
  if (static_cast<int>(factors.size()) != d.k())
    throw DoeError("design has " + std::to_string(d.k()) + " factors but " +
                   std::to_string(factors.size()) + " were given");
  for (const auto& f : factors)
    if (!(f.high != f.low)) throw DoeError("factor " + f.name + ": low and high levels must differ");
  d.factors = std::move(factors);
}

Eigen::VectorXd toCoded(const std::vector<Factor>& f, const Eigen::VectorXd& real) {
  Eigen::VectorXd c(real.size());
  for (Eigen::Index j = 0; j < real.size(); ++j) c(j) = f[j].toCoded(real(j));
  return c;
}

Eigen::VectorXd toReal(const std::vector<Factor>& f, const Eigen::VectorXd& coded) {
  Eigen::VectorXd r(coded.size());
  for (Eigen::Index j = 0; j < coded.size(); ++j) r(j) = f[j].toReal(coded(j));
  return r;
}

}  // namespace paddy::doe
