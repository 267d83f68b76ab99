// Herschel–Bulkley fit τ = τ0 + K·D^n: variable-projection grid start, then NLopt LN_BOBYQA.
// Method in paddy/measure/herschel_bulkley.hpp.
#include <paddy/errors.hpp>
#include <paddy/measure/herschel_bulkley.hpp>

#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace paddy::measure {

double HerschelBulkley::stress(double shear_rate) const { return tau0 + K * std::pow(shear_rate, n); }

namespace {

struct Problem {
  std::vector<double> x, y;  // D / D_ref, τ / τ_scale
  double best = std::numeric_limits<double>::infinity();
  std::vector<double> best_p;
  int evaluations = 0;

  double sse(double a, double b, double n) const {
    double s = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double e = y[i] - a - b * std::pow(x[i], n);
      s += e * e;
    }
    return s;
  }
};

double objective(const std::vector<double>& p, std::vector<double>& /*grad*/, void* data) {
  auto* pr = static_cast<Problem*>(data);
  ++pr->evaluations;
  const double s = pr->sse(p[0], p[1], p[2]);
  if (s < pr->best) {
    pr->best = s;
    pr->best_p = p;
  }
  return s;
}

// Best (a ≥ 0, b ≥ b_min) for fixed n: linear least squares with the bounds.
void linearFit(const Problem& pr, double n, double b_min, double& a, double& b) {
  const double m = static_cast<double>(pr.x.size());
  double su = 0, sy = 0, suu = 0, suy = 0;
  for (std::size_t i = 0; i < pr.x.size(); ++i) {
    const double u = std::pow(pr.x[i], n);
    su += u;
    sy += pr.y[i];
    suu += u * u;
    suy += u * pr.y[i];
  }
  const double var = suu - su * su / m;
  b = var > 0.0 ? (suy - su * sy / m) / var : 0.0;
  a = (sy - b * su) / m;
  if (a < 0.0) {
    a = 0.0;
    b = suu > 0.0 ? suy / suu : 0.0;
  }
  if (b < b_min) {
    b = b_min;
    a = std::max(0.0, (sy - b * su) / m);
  }
}

}  // namespace

HerschelBulkleyFit fitHerschelBulkley(const std::vector<double>& D, const std::vector<double>& tau,
                                      const HerschelBulkleyOptions& o) {
  if (D.size() != tau.size())
    throw InputError("fitHerschelBulkley: " + std::to_string(D.size()) + " shear rates but " +
                     std::to_string(tau.size()) + " shear stresses");
  if (D.size() < 3)
    throw InputError("fitHerschelBulkley: needs at least 3 (shear rate, stress) points for tau0, K, n; got " +
                     std::to_string(D.size()));
  if (!(o.n_min > 0.0 && o.n_max > o.n_min) || !std::isfinite(o.n_max))
    throw InputError("fitHerschelBulkley: flow-index bounds must satisfy 0 < n_min < n_max");
  for (std::size_t i = 0; i < D.size(); ++i) {
    std::ostringstream s;
    if (!std::isfinite(D[i]) || !std::isfinite(tau[i])) {
      s << "fitHerschelBulkley: point " << i << " is not a number (shear rate " << D[i] << ", stress " << tau[i] << ")";
      throw InputError(s.str());
    }
    if (D[i] <= 0.0) {
      s << "fitHerschelBulkley: shear rate " << D[i] << " 1/s at point " << i << " is not positive";
      throw InputError(s.str());
    }
    if (tau[i] < 0.0) {
      s << "fitHerschelBulkley: shear stress " << tau[i] << " Pa at point " << i << " is negative";
      throw InputError(s.str());
    }
  }
  if (std::set<double>(D.begin(), D.end()).size() < 3)
    throw InputError("fitHerschelBulkley: needs at least 3 distinct shear rates to determine n");

  // Scaled problem.
  Problem pr;
  double log_sum = 0.0, tau_scale = 0.0;
  for (std::size_t i = 0; i < D.size(); ++i) {
    log_sum += std::log(D[i]);
    tau_scale = std::max(tau_scale, tau[i]);
  }
  const double D_ref = std::exp(log_sum / static_cast<double>(D.size()));
  if (tau_scale <= 0.0) tau_scale = 1.0;
  for (std::size_t i = 0; i < D.size(); ++i) {
    pr.x.push_back(D[i] / D_ref);
    pr.y.push_back(tau[i] / tau_scale);
  }

  // Start: variable projection over a grid of n.
  constexpr double b_min = 1e-12;
  std::vector<double> p0{0.0, 1.0, 1.0};
  double s0 = std::numeric_limits<double>::infinity();
  constexpr int grid = 40;
  for (int k = 0; k < grid; ++k) {
    const double n = o.n_min + (o.n_max - o.n_min) * k / (grid - 1);
    double a, b;
    linearFit(pr, n, b_min, a, b);
    const double s = pr.sse(a, b, n);
    if (s < s0) {
      s0 = s;
      p0 = {a, b, n};
    }
  }

  // Refine with BOBYQA on (τ0', K', n).
  const double b_max = std::max(1e6, 10.0 * p0[1]);
  nlopt::opt opt(nlopt::LN_BOBYQA, 3);
  opt.set_lower_bounds({0.0, b_min, o.n_min});
  opt.set_upper_bounds({std::max(10.0, 2.0 * p0[0]), b_max, o.n_max});
  opt.set_min_objective(objective, &pr);
  opt.set_xtol_rel(o.xtol_rel);
  opt.set_ftol_abs(1e-30);
  opt.set_maxeval(o.max_evaluations);
  opt.set_initial_step({std::max(0.05, 0.1 * p0[0]), std::max(1e-3, 0.1 * p0[1]), 0.05});
  std::vector<double> p = p0;
  pr.best = s0;
  pr.best_p = p0;
  try {
    double f = 0.0;
    opt.optimize(p, f);
  } catch (const nlopt::roundoff_limited&) {
    // the best point found so far is kept below
  } catch (const std::exception& e) {
    throw InputError(std::string("fitHerschelBulkley: the optimiser failed: ") + e.what());
  }
  p = pr.best_p;

  HerschelBulkleyFit fit;
  fit.model.n = p[2];
  fit.model.tau0 = p[0] * tau_scale;
  fit.model.K = p[1] * tau_scale / std::pow(D_ref, p[2]);
  fit.evaluations = pr.evaluations;
  double mean = 0.0;
  for (double t : tau) mean += t;
  mean /= static_cast<double>(tau.size());
  double sse = 0.0, sst = 0.0;
  for (std::size_t i = 0; i < D.size(); ++i) {
    const double e = tau[i] - fit.model.stress(D[i]);
    sse += e * e;
    sst += (tau[i] - mean) * (tau[i] - mean);
  }
  fit.rmse = std::sqrt(sse / static_cast<double>(D.size()));
  fit.r2 = sst > 0.0 ? 1.0 - sse / sst : (sse == 0.0 ? 1.0 : 0.0);
  return fit;
}

}  // namespace paddy::measure
