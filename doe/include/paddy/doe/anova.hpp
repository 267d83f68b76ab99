// Analysis of a response: ANOVA, fit statistics, coefficient table, residual diagnostics, with
// the conventions Design-Expert prints (Design-Expert documentation "ANOVA output"; Montgomery,
// Design and Analysis of Experiments, ch. 6, 10, 11).
//
// Sums of squares: Model SS = SS(model terms | intercept); term SS = partial (Type III) SS
// b_j^2 / [(X^T X)^-1]_jj (equal to sequential SS for orthogonal designs). F = MS / MS_residual,
// p = upper tail of F(df, df_res) (boost::math::fisher_f).
// Curvature (linear+curvature): a centre-point indicator column is added after the model;
// its SS is the extra SS, n_f n_c (ybar_f - ybar_c)^2 / (n_f + n_c) for orthogonal designs. The
// curvature SS is taken out of the total for R^2: R^2 = SS_model / (SS_total - SS_curv),
// adj R^2 = 1 - MS_res / ((SS_total - SS_curv) / (df_total - 1)).
// Lack of fit / pure error: pure error from runs with identical factor settings.
// Pred R^2 = 1 - PRESS / (SS_total - SS_curv), PRESS = sum (e_i / (1 - h_ii))^2; undefined (NaN,
// printed N/A) when some h_ii = 1. C.V. % = 100 sqrt(MS_res) / mean(y over all runs).
// Adequate precision = (max yhat - min yhat) / sqrt(mean_i V(yhat_i)), V(yhat_i) = sigma^2 h_ii,
// whose mean is p sigma^2 / n (p counts the curvature column when fitted).
// Coefficients: se_j = sqrt(MS_res [(X^T X)^-1]_jj), 95 % CI b_j +- t(0.975, df_res) se_j,
// VIF_j = 1 / (1 - R_j^2) from the centred model columns.
// Diagnostics: internally studentised r_i = e_i / sqrt(MS_res (1 - h_ii)); externally studentised
// t_i = r_i sqrt((n - p - 1) / (n - p - r_i^2)); Cook's D_i = r_i^2 h_ii / (p (1 - h_ii)).
#pragma once
#include "paddy/doe/model.hpp"

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace paddy::doe {

struct AnovaRow {
  std::string source;
  double ss = 0, df = 0, ms = 0;
  double F = 0, p = 0;  ///< NaN where not applicable
};

struct CoefficientRow {
  std::string term;
  double estimate = 0, se = 0, ciLow = 0, ciHigh = 0, vif = 0, t = 0, p = 0;
};

struct Diagnostic {
  int run = 0;  ///< 1-based data row
  double actual = 0, predicted = 0, residual = 0, leverage = 0;
  double studentized = 0, externallyStudentized = 0, cooksDistance = 0;
};

struct ResponseAnalysis {
  std::string response;
  Model model;
  bool curvature = false;
  Eigen::VectorXd beta;          ///< model coefficients (coded), without the curvature column
  double curvatureCoefficient = 0;
  std::vector<AnovaRow> anova;
  std::vector<CoefficientRow> coefficients;
  std::vector<Diagnostic> diagnostics;
  double r2 = 0, adjR2 = 0, predR2 = 0, press = 0, cvPercent = 0, adeqPrecision = 0;
  double mean = 0, stdDev = 0, msResidual = 0, dfResidual = 0, tCritical = 0;
  double yMin = 0, yMax = 0;
  const AnovaRow* row(const std::string& source) const;  ///< nullptr if absent
};

struct AnalysisOptions {
  bool curvature = false;
  double confidence = 0.95;
  double centerTolerance = 1e-9;   ///< |coded| below this counts as a centre setting
};

ResponseAnalysis analyzeResponse(const Model& model, const Eigen::MatrixXd& coded,
                                 const Eigen::VectorXd& y, const std::string& responseName,
                                 const AnalysisOptions& opt = {});

/// Upper-tail p of F(df1, df2) and two-sided t quantile, from Boost.Math.
double fPValue(double F, double df1, double df2);
double tQuantile(double prob, double df);
double normalQuantile(double prob);

}  // namespace paddy::doe
