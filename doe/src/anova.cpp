#include "paddy/doe/anova.hpp"

#include "paddy/doe/error.hpp"
#include "paddy/doe/regression.hpp"

#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>

namespace paddy::doe {

namespace {
constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

AnovaRow makeRow(std::string source, double ss, double df) {
  return {std::move(source), ss, df, df > 0 ? ss / df : NaN, NaN, NaN};
}

void setF(AnovaRow& r, double msDenominator, double dfDenominator) {
  r.F = r.ms / msDenominator;
  r.p = fPValue(r.F, r.df, dfDenominator);
}

// Pure-error sum of squares and df from groups of runs with identical settings.
std::pair<double, int> pureError(const Eigen::MatrixXd& x, const Eigen::VectorXd& y) {
  const Eigen::Index n = x.rows();
  std::vector<int> group(n, -1);
  double ss = 0.0;
  int df = 0, groups = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (group[i] >= 0) continue;
    std::vector<Eigen::Index> members{i};
    group[i] = groups;
    for (Eigen::Index j = i + 1; j < n; ++j)
      if (group[j] < 0 && (x.row(i) - x.row(j)).cwiseAbs().maxCoeff() <= 1e-9 * (1.0 + x.row(i).cwiseAbs().maxCoeff())) {
        group[j] = groups;
        members.push_back(j);
      }
    ++groups;
    double m = 0.0;
    for (auto j : members) m += y(j);
    m /= static_cast<double>(members.size());
    for (auto j : members) ss += (y(j) - m) * (y(j) - m);
    df += static_cast<int>(members.size()) - 1;
  }
  return {ss, df};
}
}  // namespace

double fPValue(double F, double df1, double df2) {
  if (!std::isfinite(F) || df1 <= 0 || df2 <= 0) return std::isinf(F) ? 0.0 : NaN;
  if (F <= 0) return 1.0;
  return boost::math::cdf(boost::math::complement(boost::math::fisher_f(df1, df2), F));
}

double tQuantile(double prob, double df) {
  return boost::math::quantile(boost::math::students_t(df), prob);
}

double normalQuantile(double prob) { return boost::math::quantile(boost::math::normal(), prob); }

const AnovaRow* ResponseAnalysis::row(const std::string& source) const {
  for (const auto& r : anova)
    if (r.source == source) return &r;
  return nullptr;
}

ResponseAnalysis analyzeResponse(const Model& model, const Eigen::MatrixXd& coded,
                                 const Eigen::VectorXd& y, const std::string& name,
                                 const AnalysisOptions& opt) {
  const int n = static_cast<int>(coded.rows());
  if (y.size() != n) throw DoeError("response " + name + ": length does not match the design");
  if (!y.allFinite()) throw DoeError("response " + name + ": non-finite values");
  ResponseAnalysis a;
  a.response = name;
  a.model = model;
  a.curvature = opt.curvature;

  const Eigen::MatrixXd X = model.matrix(coded);
  auto names = model.termNames();
  const bool icpt = model.hasIntercept();
  Eigen::MatrixXd Xf = X;
  auto namesF = names;
  if (opt.curvature) {
    Eigen::VectorXd c(n);
    for (int i = 0; i < n; ++i) c(i) = coded.row(i).cwiseAbs().maxCoeff() <= opt.centerTolerance ? 1.0 : 0.0;
    const double nc = c.sum();
    if (nc < 1 || nc > n - 1)
      throw DoeError("response " + name + ": a curvature test needs both centre points and non-centre runs");
    Xf.conservativeResize(n, X.cols() + 1);
    Xf.col(X.cols()) = c;
    namesF.push_back("Curvature");
  }
  const LeastSquares full = leastSquares(Xf, y, namesF);
  const LeastSquares reduced = opt.curvature ? leastSquares(X, y, names) : full;
  const int pf = full.p;
  const int dfRes = n - pf;
  if (dfRes < 1)
    throw DoeError("response " + name + ": the model has " + std::to_string(pf) + " parameters for " +
                   std::to_string(n) + " runs, leaving no residual degrees of freedom for an ANOVA");
  const double msRes = full.sse / dfRes;

  a.mean = y.mean();
  const double sst = icpt ? (y.array() - a.mean).square().sum() : y.squaredNorm();
  const double dfTot = icpt ? n - 1 : n;
  const double ssModel = sst - reduced.sse;
  const double dfModel = model.p() - (icpt ? 1 : 0);
  const double ssCurv = opt.curvature ? reduced.sse - full.sse : 0.0;

  AnovaRow modelRow = makeRow("Model", ssModel, dfModel);
  setF(modelRow, msRes, dfRes);
  a.anova.push_back(modelRow);
  for (int j = 0; j < pf; ++j) {
    if (j < model.p() && model.terms[j].isIntercept()) continue;
    const double ss = full.beta(j) * full.beta(j) / full.xtxInv(j, j);
    AnovaRow r = makeRow(namesF[j], j < model.p() ? ss : ssCurv, 1);
    setF(r, msRes, dfRes);
    a.anova.push_back(r);
  }
  a.anova.push_back(makeRow("Residual", full.sse, dfRes));
  const auto [ssPe, dfPe] = pureError(coded, y);
  const int dfLof = dfRes - dfPe;
  if (dfPe > 0 && dfLof > 0) {
    AnovaRow lof = makeRow("Lack of Fit", full.sse - ssPe, dfLof);
    setF(lof, ssPe / dfPe, dfPe);
    a.anova.push_back(lof);
  }
  if (dfPe > 0) a.anova.push_back(makeRow("Pure Error", ssPe, dfPe));
  AnovaRow total = makeRow("Total", sst, dfTot);
  total.ms = NaN;  // Design-Expert prints no mean square for the (corrected) total
  a.anova.push_back(total);

  // fit statistics
  const double sstAdj = sst - ssCurv;
  const double dfTotAdj = dfTot - (opt.curvature ? 1 : 0);
  a.msResidual = msRes;
  a.dfResidual = dfRes;
  a.stdDev = std::sqrt(msRes);
  a.r2 = 1.0 - full.sse / sstAdj;
  a.adjR2 = 1.0 - msRes / (sstAdj / dfTotAdj);
  a.press = 0.0;
  for (int i = 0; i < n; ++i) {
    const double h = full.leverage(i);
    a.press = h > 1.0 - 1e-9 ? NaN : a.press + std::pow(full.residuals(i) / (1.0 - h), 2);
  }
  a.predR2 = 1.0 - a.press / sstAdj;
  a.cvPercent = 100.0 * a.stdDev / a.mean;
  a.adeqPrecision = (full.fitted.maxCoeff() - full.fitted.minCoeff()) / std::sqrt(msRes * full.leverage.mean());
  a.yMin = y.minCoeff();
  a.yMax = y.maxCoeff();

  // coefficients (model terms; the curvature coefficient is kept separately)
  a.beta = full.beta.head(model.p());
  if (opt.curvature) a.curvatureCoefficient = full.beta(model.p());
  a.tCritical = tQuantile(0.5 + 0.5 * opt.confidence, dfRes);
  Eigen::VectorXd vif = Eigen::VectorXd::Constant(model.p(), NaN);
  std::vector<int> cols;
  for (int j = 0; j < model.p(); ++j)
    if (!model.terms[j].isIntercept()) cols.push_back(j);
  if (icpt && !cols.empty()) {
    Eigen::MatrixXd Xc(n, cols.size());
    std::vector<std::string> cn;
    for (std::size_t c = 0; c < cols.size(); ++c) {
      Xc.col(c) = X.col(cols[c]).array() - X.col(cols[c]).mean();
      cn.push_back(names[cols[c]]);
    }
    const LeastSquares v = leastSquares(Xc, Eigen::VectorXd::Zero(n), cn);
    for (std::size_t c = 0; c < cols.size(); ++c) vif(cols[c]) = v.xtxInv(c, c) * Xc.col(c).squaredNorm();
  }
  for (int j = 0; j < model.p(); ++j) {
    CoefficientRow c;
    c.term = names[j];
    c.estimate = full.beta(j);
    c.se = std::sqrt(msRes * full.xtxInv(j, j));
    c.ciLow = c.estimate - a.tCritical * c.se;
    c.ciHigh = c.estimate + a.tCritical * c.se;
    c.vif = vif(j);
    c.t = c.estimate / c.se;
    c.p = 2.0 * boost::math::cdf(boost::math::complement(boost::math::students_t(dfRes), std::abs(c.t)));
    a.coefficients.push_back(c);
  }

  // residual diagnostics
  for (int i = 0; i < n; ++i) {
    Diagnostic d;
    d.run = i + 1;
    d.actual = y(i);
    d.predicted = full.fitted(i);
    d.residual = full.residuals(i);
    d.leverage = full.leverage(i);
    if (d.leverage > 1.0 - 1e-9) {
      d.studentized = d.externallyStudentized = d.cooksDistance = NaN;
    } else {
      d.studentized = d.residual / std::sqrt(msRes * (1.0 - d.leverage));
      const double r2 = d.studentized * d.studentized;
      d.externallyStudentized = dfRes > 1 && dfRes - r2 > 0 ? d.studentized * std::sqrt((dfRes - 1.0) / (dfRes - r2)) : NaN;
      d.cooksDistance = r2 * d.leverage / (pf * (1.0 - d.leverage));
    }
    a.diagnostics.push_back(d);
  }
  return a;
}

}  // namespace paddy::doe
