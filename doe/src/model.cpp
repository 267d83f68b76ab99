#include "paddy/doe/model.hpp"

#include "paddy/doe/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace paddy::doe {

int Term::degree() const {
  int d = 0;
  for (int e : powers) d += e;
  return d;
}

ModelKind parseModelKind(const std::string& s) {
  if (s == "linear") return ModelKind::Linear;
  if (s == "linear+curvature") return ModelKind::LinearCurvature;
  if (s == "2fi") return ModelKind::TwoFI;
  if (s == "quadratic") return ModelKind::Quadratic;
  throw DoeError("unknown model '" + s + "' (use linear, linear+curvature, 2fi, quadratic or a term list)");
}

std::string modelKindName(ModelKind k) {
  switch (k) {
    case ModelKind::Linear: return "linear";
    case ModelKind::LinearCurvature: return "linear+curvature";
    case ModelKind::TwoFI: return "2fi";
    case ModelKind::Quadratic: return "quadratic";
    case ModelKind::Custom: return "custom";
  }
  return "?";
}

namespace {
Term unit(int k, std::initializer_list<std::pair<int, int>> ps) {
  Term t{std::vector<int>(k, 0)};
  for (auto [j, e] : ps) t.powers[j] += e;
  return t;
}
}  // namespace

Model Model::linear(std::vector<std::string> names) {
  Model m{std::move(names), {}};
  const int k = m.k();
  m.terms.push_back(unit(k, {}));
  for (int j = 0; j < k; ++j) m.terms.push_back(unit(k, {{j, 1}}));
  return m;
}

Model Model::twoFI(std::vector<std::string> names) {
  Model m = linear(std::move(names));
  const int k = m.k();
  for (int i = 0; i < k; ++i)
    for (int j = i + 1; j < k; ++j) m.terms.push_back(unit(k, {{i, 1}, {j, 1}}));
  return m;
}

Model Model::quadratic(std::vector<std::string> names) {
  Model m = twoFI(std::move(names));
  for (int j = 0; j < m.k(); ++j) m.terms.push_back(unit(m.k(), {{j, 2}}));
  return m;
}

Model Model::make(ModelKind kind, std::vector<std::string> names) {
  switch (kind) {
    case ModelKind::Linear:
    case ModelKind::LinearCurvature: return linear(std::move(names));
    case ModelKind::TwoFI: return twoFI(std::move(names));
    case ModelKind::Quadratic: return quadratic(std::move(names));
    case ModelKind::Custom: break;
  }
  throw DoeError("Model::make: a custom model needs a term list");
}

namespace {
std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t");
  return s.substr(a, b - a + 1);
}

std::string joinNames(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& n : v) s += (s.empty() ? "" : ", ") + n;
  return s;
}
}  // namespace

Model Model::parse(std::vector<std::string> names, const std::string& spec, bool intercept) {
  Model m{std::move(names), {}};
  const int k = m.k();
  if (intercept) m.terms.push_back(unit(k, {}));
  std::string s = spec;
  std::replace(s.begin(), s.end(), '+', ',');
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
    item = trim(item);
    if (item.empty()) continue;
    if (item == "Intercept" || item == "1") {
      if (!m.hasIntercept()) m.terms.insert(m.terms.begin(), unit(k, {}));
      continue;
    }
    Term t{std::vector<int>(k, 0)};
    std::stringstream fs(item);
    std::string f;
    while (std::getline(fs, f, ':')) {
      f = trim(f);
      int power = 1;
      if (const auto c = f.find('^'); c != std::string::npos) {
        try {
          power = std::stoi(f.substr(c + 1));
        } catch (...) {
          throw DoeError("model term '" + item + "': bad power");
        }
        if (power < 1) throw DoeError("model term '" + item + "': power must be >= 1");
        f = trim(f.substr(0, c));
      }
      const auto it = std::find(m.factorNames.begin(), m.factorNames.end(), f);
      if (it == m.factorNames.end())
        throw DoeError("model term '" + item + "': unknown factor '" + f + "' (factors: " + joinNames(m.factorNames) + ")");
      t.powers[it - m.factorNames.begin()] += power;
    }
    if (std::find(m.terms.begin(), m.terms.end(), t) != m.terms.end())
      throw DoeError("model term '" + item + "' is listed twice");
    m.terms.push_back(t);
  }
  if (m.terms.empty()) throw DoeError("model has no terms");
  return m;
}

std::string Model::termName(int i) const {
  const Term& t = terms.at(i);
  if (t.isIntercept()) return "Intercept";
  std::string s;
  for (int j = 0; j < k(); ++j) {
    if (t.powers[j] == 0) continue;
    if (!s.empty()) s += ":";
    s += factorNames[j];
    if (t.powers[j] > 1) s += "^" + std::to_string(t.powers[j]);
  }
  return s;
}

std::vector<std::string> Model::termNames() const {
  std::vector<std::string> v;
  for (int i = 0; i < p(); ++i) v.push_back(termName(i));
  return v;
}

bool Model::hasIntercept() const {
  return std::any_of(terms.begin(), terms.end(), [](const Term& t) { return t.isIntercept(); });
}

Eigen::RowVectorXd Model::row(const Eigen::VectorXd& x) const {
  Eigen::RowVectorXd r(p());
  for (int i = 0; i < p(); ++i) {
    double v = 1.0;
    for (int j = 0; j < k(); ++j)
      for (int e = 0; e < terms[i].powers[j]; ++e) v *= x(j);
    r(i) = v;
  }
  return r;
}

Eigen::MatrixXd Model::matrix(const Eigen::MatrixXd& coded) const {
  if (coded.cols() != k()) throw DoeError("model matrix: wrong number of factor columns");
  Eigen::MatrixXd X(coded.rows(), p());
  for (Eigen::Index i = 0; i < coded.rows(); ++i) X.row(i) = row(coded.row(i).transpose());
  return X;
}

double Model::predict(const Eigen::VectorXd& beta, const Eigen::VectorXd& coded) const {
  return row(coded).dot(beta);
}

std::vector<ActualTerm> actualCoefficients(const Model& m, const Eigen::VectorXd& beta,
                                           const Eigen::VectorXd& centers,
                                           const Eigen::VectorXd& halfRanges) {
  // polynomial in real units: map monomial exponents -> coefficient
  std::map<std::vector<int>, double> poly;
  const int k = m.k();
  for (int i = 0; i < m.p(); ++i) {
    std::map<std::vector<int>, double> term{{std::vector<int>(k, 0), beta(i)}};
    for (int j = 0; j < k; ++j)
      for (int e = 0; e < m.terms[i].powers[j]; ++e) {
        // multiply by (x_j - c_j) / h_j
        std::map<std::vector<int>, double> next;
        for (const auto& [pw, c] : term) {
          auto up = pw;
          up[j] += 1;
          next[up] += c / halfRanges(j);
          next[pw] += -c * centers(j) / halfRanges(j);
        }
        term = std::move(next);
      }
    for (const auto& [pw, c] : term) poly[pw] += c;
  }
  std::vector<ActualTerm> out;
  // order as in the model: each model term's monomial, then any extra monomials
  for (const auto& t : m.terms) {
    auto it = poly.find(t.powers);
    out.push_back({t, it == poly.end() ? 0.0 : it->second});
    if (it != poly.end()) poly.erase(it);
  }
  for (const auto& [pw, c] : poly)
    if (std::abs(c) > 0.0) out.push_back({Term{pw}, c});
  return out;
}

}  // namespace paddy::doe
