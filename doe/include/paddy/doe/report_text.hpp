// Plain-text reports laid out like Design-Expert's ANOVA, fit-statistics and coefficient tables
// (Design-Expert documentation, "ANOVA output"): p-values below 0.0001 print as "< 0.0001",
// undefined values as "N/A".
#pragma once
#include "paddy/doe/analysis.hpp"
#include "paddy/doe/optimizer.hpp"
#include "paddy/doe/report_json.hpp"

#include <ostream>

namespace paddy::doe {

void printAnalysis(std::ostream& out, const Analysis& a);
void printResponse(std::ostream& out, const Analysis& a, const ResponseAnalysis& r);
void printDesign(std::ostream& out, const Design& d);
void printSolutions(std::ostream& out, const FitModels& fit, const std::vector<GoalSpec>& goals,
                    const std::vector<Solution>& solutions);
std::string formatP(double p);

}  // namespace paddy::doe
