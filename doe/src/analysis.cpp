#include "paddy/doe/analysis.hpp"

#include "paddy/doe/error.hpp"

namespace paddy::doe {

Analysis analyzeTable(const Table& table, const AnalysisRequest& req) {
  if (req.factors.empty()) throw DoeError("analyze: no factors given");
  if (req.responses.empty()) throw DoeError("analyze: no responses given");
  if (table.rows() == 0) throw DoeError(table.source + ": no data rows");
  Analysis a;
  const int n = table.rows(), k = static_cast<int>(req.factors.size());
  a.real.resize(n, k);
  a.coded.resize(n, k);
  for (int j = 0; j < k; ++j) {
    const auto& name = req.factors[j];
    for (int i = 0; i < j; ++i)
      if (req.factors[i] == name) throw DoeError("analyze: factor '" + name + "' given twice");
    if (name.empty() || name == "Intercept" || name.find_first_of(":^,+ ") != std::string::npos)
      throw DoeError("analyze: factor name '" + name + "' cannot be used in model terms (avoid ':', '^', ',', '+', "
                     "blanks and the name Intercept)");
    a.real.col(j) = table.numeric(name);
    Factor f{name, a.real.col(j).minCoeff(), a.real.col(j).maxCoeff()};
    if (auto it = req.levels.find(name); it != req.levels.end()) {
      f.low = it->second.first;
      f.high = it->second.second;
    }
    if (!(f.high != f.low))
      throw DoeError("analyze: factor '" + name + "' does not vary (" + std::to_string(f.low) +
                     " in every run); it cannot be coded");
    a.factors.push_back(f);
    for (int i = 0; i < n; ++i) a.coded(i, j) = f.toCoded(a.real(i, j));
  }
  for (const auto& [name, lv] : req.levels) {
    bool known = false;
    for (const auto& f : req.factors) known = known || f == name;
    if (!known) throw DoeError("analyze: levels given for '" + name + "', which is not one of the factors");
  }
  const std::vector<std::string>& names = req.factors;
  const std::string m = req.model;
  if (m == "linear" || m == "linear+curvature" || m == "2fi" || m == "quadratic") {
    const ModelKind kind = parseModelKind(m);
    a.model = Model::make(kind, names);
    a.curvature = kind == ModelKind::LinearCurvature;
    a.modelName = m;
  } else {
    a.model = Model::parse(names, m);
    a.modelName = "custom";
  }
  AnalysisOptions opt;
  opt.curvature = a.curvature;
  opt.confidence = req.confidence;
  for (const auto& r : req.responses) {
    for (const auto& f : req.factors)
      if (f == r) throw DoeError("analyze: '" + r + "' is given both as a factor and as a response");
    a.responses.push_back(analyzeResponse(a.model, a.coded, table.numeric(r), r, opt));
  }
  return a;
}

}  // namespace paddy::doe
