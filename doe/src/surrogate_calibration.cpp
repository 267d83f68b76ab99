#include "paddy/doe/surrogate_calibration.hpp"

#include "paddy/doe/error.hpp"

#include <algorithm>
#include <limits>
#include <nlopt.hpp>
#include <random>
#include <string>

namespace paddy::doe {

namespace {

struct EiProblem {
  const std::vector<GaussianProcess>* models;
  const Eigen::VectorXd* targets;
  double incumbent;
  const Eigen::MatrixXd* draws;
};

double nloptEi(unsigned n, const double* x, double*, void* data) {
  const auto* p = static_cast<const EiProblem*>(data);
  return compositeExpectedImprovement(*p->models, Eigen::Map<const Eigen::VectorXd>(x, n), *p->targets,
                                      p->incumbent, *p->draws);
}

Eigen::VectorXd means(const std::vector<GaussianProcess>& models, const Eigen::VectorXd& x,
                      std::vector<GpPrediction>* out = nullptr) {
  Eigen::VectorXd mu(static_cast<Eigen::Index>(models.size()));
  for (std::size_t r = 0; r < models.size(); ++r) {
    const auto p = models[r].predict(x);
    mu(static_cast<Eigen::Index>(r)) = p.mean;
    if (out) out->push_back(p);
  }
  return mu;
}

}  // namespace

double compositeError(const Eigen::VectorXd& y, const Eigen::VectorXd& targets) {
  return ((y - targets).array().abs() / targets.array().abs()).maxCoeff();
}

double compositeExpectedImprovement(const std::vector<GaussianProcess>& models, const Eigen::VectorXd& x,
                                    const Eigen::VectorXd& targets, double incumbent,
                                    const Eigen::MatrixXd& draws) {
  const Eigen::Index R = static_cast<Eigen::Index>(models.size());
  Eigen::VectorXd mu(R), sd(R);
  for (Eigen::Index r = 0; r < R; ++r) {
    const auto p = models[static_cast<std::size_t>(r)].predict(x);
    mu(r) = p.mean, sd(r) = p.sd();
  }
  double sum = 0;
  for (Eigen::Index m = 0; m < draws.rows(); ++m) {
    const Eigen::VectorXd y = mu + sd.cwiseProduct(draws.row(m).transpose());
    sum += std::max(0.0, incumbent - compositeError(y, targets));
  }
  return sum / static_cast<double>(draws.rows());
}

SurrogateStep suggestCalibrationPoints(const Eigen::MatrixXd& X, const Eigen::MatrixXd& Y,
                                       const Eigen::VectorXd& targets, const SurrogateOptions& o) {
  if (X.rows() != Y.rows()) throw DoeError("surrogate: " + std::to_string(X.rows()) + " points but " +
                                           std::to_string(Y.rows()) + " rows of responses");
  if (Y.cols() != targets.size() || targets.size() == 0)
    throw DoeError("surrogate: one target per response column needed");
  if ((targets.array() == 0).any()) throw DoeError("surrogate: a target is 0 (relative errors undefined)");
  if (X.rows() < 2) throw DoeError("surrogate: needs at least 2 simulations to start from");
  if ((X.array() < -1e-12).any() || (X.array() > 1 + 1e-12).any())
    throw DoeError("surrogate: points must lie in the unit cube (scale them by the search box)");
  if (o.batch < 1 || o.samples < 1 || o.candidates < 1) throw DoeError("surrogate: batch, samples and candidates must be >= 1");
  const int d = static_cast<int>(X.cols());
  const Eigen::Index R = Y.cols();

  SurrogateStep step;
  std::vector<GaussianProcess> models(static_cast<std::size_t>(R));
  for (Eigen::Index r = 0; r < R; ++r) {
    GpFitOptions fo = o.gp;
    fo.seed = o.gp.seed + static_cast<std::uint64_t>(r);
    models[static_cast<std::size_t>(r)].fit(X, Y.col(r), fo);
    step.hyperparameters.push_back(models[static_cast<std::size_t>(r)].hyperparameters());
  }

  std::mt19937_64 rng(o.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  Eigen::MatrixXd draws(o.samples, R);
  for (Eigen::Index m = 0; m < draws.rows(); ++m)
    for (Eigen::Index r = 0; r < R; ++r) draws(m, r) = normal(rng);

  Eigen::MatrixXd Xa = X, Ya = Y;  // grows with believer points
  for (int q = 0; q < o.batch; ++q) {
    if (q > 0)
      for (Eigen::Index r = 0; r < R; ++r)
        models[static_cast<std::size_t>(r)].fitFixed(Xa, Ya.col(r), step.hyperparameters[static_cast<std::size_t>(r)]);
    double incumbent = std::numeric_limits<double>::infinity();
    int incumbentIndex = -1;
    for (Eigen::Index i = 0; i < Xa.rows(); ++i) {
      const double J = compositeError(means(models, Xa.row(i).transpose()), targets);
      if (J < incumbent) incumbent = J, incumbentIndex = static_cast<int>(i);
    }
    if (q == 0) step.incumbent_error = incumbent, step.incumbent_index = incumbentIndex;

    // Candidates: half uniform in the box, half around the incumbent (sd 0.1 of the box).
    EiProblem prob{&models, &targets, incumbent, &draws};
    const Eigen::VectorXd centre = Xa.row(incumbentIndex).transpose();
    Eigen::VectorXd best = centre;
    double bestEi = -1;
    for (int c = 0; c < o.candidates; ++c) {
      Eigen::VectorXd x(d);
      for (int j = 0; j < d; ++j)
        x(j) = c % 2 == 0 ? uniform(rng) : std::clamp(centre(j) + 0.1 * normal(rng), 0.0, 1.0);
      const double ei = compositeExpectedImprovement(models, x, targets, incumbent, draws);
      if (ei > bestEi) bestEi = ei, best = x;
    }
    // Refine locally.
    std::vector<double> xv(best.data(), best.data() + d);
    nlopt::opt opt(nlopt::LN_COBYLA, static_cast<unsigned>(d));
    opt.set_lower_bounds(std::vector<double>(static_cast<std::size_t>(d), 0.0));
    opt.set_upper_bounds(std::vector<double>(static_cast<std::size_t>(d), 1.0));
    opt.set_max_objective(nloptEi, &prob);
    opt.set_xtol_abs(1e-4);
    opt.set_maxeval(300);
    double value = bestEi;
    try {
      opt.optimize(xv, value);
    } catch (const std::exception&) {
      value = -1;  // keep the best candidate
    }
    if (value > bestEi) best = Eigen::Map<Eigen::VectorXd>(xv.data(), d).cwiseMax(0.0).cwiseMin(1.0), bestEi = value;

    SurrogateSuggestion s;
    s.x = best;
    const Eigen::VectorXd mu = means(models, best, &s.predicted);
    s.expected_improvement = std::max(bestEi, 0.0);
    s.predicted_error = compositeError(mu, targets);
    step.suggestions.push_back(s);

    Xa.conservativeResize(Xa.rows() + 1, Eigen::NoChange);
    Ya.conservativeResize(Ya.rows() + 1, Eigen::NoChange);
    Xa.row(Xa.rows() - 1) = best.transpose();
    Ya.row(Ya.rows() - 1) = mu.transpose();
  }
  return step;
}

}  // namespace paddy::doe
