#include "paddy/doe/factorial.hpp"

#include "paddy/doe/error.hpp"

#include <cctype>

namespace paddy::doe {

Design fullFactorial(int k) {
  if (k < 1 || k > 20) throw DoeError("full factorial: number of factors must be 1..20");
  const int n = 1 << k;
  Eigen::MatrixXd x(n, k);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < k; ++j) x(i, j) = ((i >> j) & 1) ? 1.0 : -1.0;
  return makeDesign(defaultFactors(k), x, std::vector<PointType>(n, PointType::Factorial));
}

Design fractionalFactorial(int k, const std::vector<std::string>& generators) {
  const int p = static_cast<int>(generators.size());
  const int base = k - p;
  if (base < 2) throw DoeError("fractional factorial: too many generators for " + std::to_string(k) + " factors");
  Design d = fullFactorial(base);
  Eigen::MatrixXd x(d.runs(), k);
  x.leftCols(base) = d.coded;
  std::vector<bool> defined(k, false);
  for (int j = 0; j < base; ++j) defined[j] = true;
  for (const auto& g : generators) {
    std::string s;
    for (char c : g)
      if (!std::isspace(static_cast<unsigned char>(c))) s += static_cast<char>(std::toupper(c));
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0) throw DoeError("generator '" + g + "': expected e.g. D=ABC");
    int target = -1;
    for (int j = 0; j < k; ++j)
      if (factorLetter(j) == s.substr(0, eq)) target = j;
    if (target < base || defined[target])
      throw DoeError("generator '" + g + "': left side must be one of the added factors " +
                     factorLetter(base) + ".." + factorLetter(k - 1) + ", each defined once");
    std::string rhs = s.substr(eq + 1);
    double sign = 1.0;
    if (!rhs.empty() && (rhs[0] == '-' || rhs[0] == '+')) {
      sign = rhs[0] == '-' ? -1.0 : 1.0;
      rhs.erase(0, 1);
    }
    if (rhs.empty()) throw DoeError("generator '" + g + "': empty word");
    Eigen::VectorXd col = Eigen::VectorXd::Constant(d.runs(), sign);
    for (char c : rhs) {
      int j = -1;
      for (int b = 0; b < base; ++b)
        if (factorLetter(b)[0] == c) j = b;
      if (j < 0) throw DoeError("generator '" + g + "': '" + std::string(1, c) + "' is not a basic factor");
      col = col.cwiseProduct(x.col(j));
    }
    x.col(target) = col;
    defined[target] = true;
  }
  for (int j = 0; j < k; ++j)
    if (!defined[j]) throw DoeError("fractional factorial: no generator for factor " + factorLetter(j));
  return makeDesign(defaultFactors(k), x, std::vector<PointType>(d.runs(), PointType::Factorial));
}

}  // namespace paddy::doe
