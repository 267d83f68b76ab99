// JSON reports (nlohmann::json), layout documented in docs/doe.md.
//   analysisToJson: {"factors": [{name, low, high}], "coding": "...", "model": name,
//     "terms": [...], "curvature": bool, "responses": {NAME: {coefficients: {term: value},
//     coefficients_actual, coefficient_table, anova: [{source, ss, df, ms, F, p}], r2, adj_r2,
//     pred_r2, cv_percent, adeq_precision, mean, std_dev, press, min, max, diagnostics}}}
//   Values that are not defined (e.g. Pred R^2 with a leverage-1 run) are null.
//   fitFromJson rebuilds the factors and response models (for optimize) from that document.
#pragma once
#include "paddy/doe/analysis.hpp"
#include "paddy/doe/optimizer.hpp"
#include "paddy/doe/steepest_ascent.hpp"

#include <nlohmann/json.hpp>

namespace paddy::doe {

nlohmann::json analysisToJson(const Analysis& a);

struct FitModels {
  std::vector<Factor> factors;
  std::vector<ResponseModel> responses;
  std::vector<double> dataMin, dataMax;  ///< range of each factor in the analysed data (real units)
  const ResponseModel& response(const std::string& name) const;  ///< throws listing names
};
FitModels fitFromJson(const nlohmann::json& j);

nlohmann::json solutionsToJson(const FitModels& fit, const std::vector<GoalSpec>& goals,
                               const std::vector<Solution>& solutions);
nlohmann::json designToJson(const Design& d);
nlohmann::json pathToJson(const std::vector<Factor>& f, const std::vector<PathPoint>& path);

}  // namespace paddy::doe
