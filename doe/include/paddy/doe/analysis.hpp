// Analysis of a whole experiment table: picks the factor and response columns, codes the factors
// (from explicit levels, else from each column's min/max: coded = (x - (min+max)/2)/((max-min)/2),
// as the CLI documents), fits one model per response (anova.hpp).
#pragma once
#include "paddy/doe/anova.hpp"
#include "paddy/doe/csv.hpp"
#include "paddy/doe/design.hpp"
#include "paddy/doe/model.hpp"

#include <map>
#include <string>
#include <vector>

namespace paddy::doe {

struct Analysis {
  std::vector<Factor> factors;
  std::string modelName;       ///< linear, linear+curvature, 2fi, quadratic or custom
  Model model;
  bool curvature = false;
  Eigen::MatrixXd real, coded; ///< runs x factors
  std::vector<ResponseAnalysis> responses;
};

struct AnalysisRequest {
  std::vector<std::string> factors, responses;
  std::string model = "linear";   ///< a model name or an explicit term list "A,B,A:B"
  std::map<std::string, std::pair<double, double>> levels;  ///< optional explicit low/high
  double confidence = 0.95;
};

Analysis analyzeTable(const Table& table, const AnalysisRequest& req);

}  // namespace paddy::doe
