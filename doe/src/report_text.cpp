#include "paddy/doe/report_text.hpp"

#include <cmath>
#include <fmt/format.h>

namespace paddy::doe {

std::string formatP(double p) {
  if (std::isnan(p)) return "";
  if (p < 1e-4) return "< 0.0001";
  return fmt::format("{:.4f}", p);
}

namespace {
std::string fix(double v, int prec) { return std::isfinite(v) ? fmt::format("{:.{}f}", v, prec) : "N/A"; }
std::string sig(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : "N/A"; }
}  // namespace

void printResponse(std::ostream& out, const Analysis& a, const ResponseAnalysis& r) {
  out << fmt::format("\nResponse {}: {} model{}\n", r.response, a.modelName,
                     r.curvature ? " (curvature tested with the centre points)" : "");
  out << "ANOVA (partial sum of squares - Type III)\n";
  out << fmt::format("{:<16}{:>16}{:>5}{:>16}{:>11}{:>11}\n", "Source", "Sum of Squares", "df", "Mean Square",
                     "F-value", "p-value");
  for (const auto& row : r.anova) {
    std::string flag;
    if (!std::isnan(row.p) && (row.source == "Model" || row.source == "Curvature" || row.source == "Lack of Fit"))
      flag = row.p < 0.05 ? "  significant" : "  not significant";
    out << fmt::format("{:<16}{:>16}{:>5}{:>16}{:>11}{:>11}{}\n", row.source, sig(row.ss), row.df,
                       std::isnan(row.ms) ? "" : sig(row.ms), std::isnan(row.F) ? "" : fix(row.F, 2),
                       formatP(row.p), flag);
  }
  out << fmt::format("\n{:<12}{:>12}    {:<16}{:>10}\n", "Std. Dev.", sig(r.stdDev), "R²", fix(r.r2, 4));
  out << fmt::format("{:<12}{:>12}    {:<16}{:>10}\n", "Mean", sig(r.mean), "Adjusted R²", fix(r.adjR2, 4));
  out << fmt::format("{:<12}{:>12}    {:<16}{:>10}\n", "C.V. %", fix(r.cvPercent, 2), "Predicted R²", fix(r.predR2, 4));
  out << fmt::format("{:<12}{:>12}    {:<16}{:>10}\n", "PRESS", sig(r.press), "Adeq Precision", fix(r.adeqPrecision, 4));
  out << "\nCoefficients in terms of coded factors\n";
  out << fmt::format("{:<14}{:>14}{:>12}{:>14}{:>14}{:>10}\n", "Term", "Estimate", "Std Error", "95% CI Low",
                     "95% CI High", "VIF");
  for (const auto& c : r.coefficients)
    out << fmt::format("{:<14}{:>14}{:>12}{:>14}{:>14}{:>10}\n", c.term, sig(c.estimate), sig(c.se), sig(c.ciLow),
                       sig(c.ciHigh), std::isnan(c.vif) ? "" : fix(c.vif, 2));
  Eigen::VectorXd cen(a.factors.size()), half(a.factors.size());
  for (std::size_t j = 0; j < a.factors.size(); ++j) {
    cen(j) = a.factors[j].center();
    half(j) = a.factors[j].halfRange();
  }
  out << "\nFinal equation in terms of actual factors\n";
  out << fmt::format("  {} =\n", r.response);
  for (const auto& t : actualCoefficients(r.model, r.beta, cen, half)) {
    Model one{r.model.factorNames, {t.term}};
    const std::string name = t.term.isIntercept() ? "" : " * " + one.termName(0);
    out << fmt::format("    {:+.8g}{}\n", t.coefficient, name);
  }
}

void printAnalysis(std::ostream& out, const Analysis& a) {
  out << fmt::format("{} runs, factors (coded -1 .. +1):", a.real.rows());
  for (const auto& f : a.factors) out << fmt::format("  {} = {:g} .. {:g}", f.name, f.low, f.high);
  out << "\n";
  for (const auto& r : a.responses) printResponse(out, a, r);
}

void printDesign(std::ostream& out, const Design& d) {
  const Eigen::MatrixXd real = d.real();
  out << fmt::format("{:>4}{:>5}  {:<10}", "Run", "Std", "Type");
  for (const auto& f : d.factors) out << fmt::format("{:>12}", f.name);
  out << "\n";
  for (int i = 0; i < d.runs(); ++i) {
    out << fmt::format("{:>4}{:>5}  {:<10}", i + 1, d.stdOrder[i], pointTypeName(d.type[i]));
    for (int j = 0; j < d.k(); ++j) out << fmt::format("{:>12.6g}", real(i, j));
    out << "\n";
  }
}

void printSolutions(std::ostream& out, const FitModels& fit, const std::vector<GoalSpec>& goals,
                    const std::vector<Solution>& sols) {
  out << "Goals:";
  for (const auto& g : goals) {
    out << fmt::format("  {} {} [{:g}, {:g}]", g.response, goalName(g.goal), g.lower, g.upper);
    if (g.goal == Goal::Target) out << fmt::format(" target {:g}", g.target);
  }
  out << fmt::format("\n{:>3}", "#");
  for (const auto& f : fit.factors) out << fmt::format("{:>12}", f.name);
  for (const auto& r : fit.responses) out << fmt::format("{:>14}", r.name);
  out << fmt::format("{:>14}\n", "Desirability");
  for (std::size_t s = 0; s < sols.size(); ++s) {
    out << fmt::format("{:>3}", s + 1);
    for (Eigen::Index j = 0; j < sols[s].real.size(); ++j) out << fmt::format("{:>12.5g}", sols[s].real(j));
    for (double p : sols[s].predicted) out << fmt::format("{:>14.6g}", p);
    out << fmt::format("{:>14.4f}\n", sols[s].overall);
  }
}

}  // namespace paddy::doe
