// Gaussian process and surrogate calibration: closed forms (Matérn 5/2, the two-point posterior,
// the marginal likelihood by determinant, Jones' expected improvement against quadrature) and a
// calibration loop on a known function that must reach its targets.
#include "paddy/doe/error.hpp"
#include "paddy/doe/gaussian_process.hpp"
#include "paddy/doe/surrogate_calibration.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace paddy::doe;

namespace {

GpHyperparameters hyper(double l, double s2, double n2, int d = 1) {
  GpHyperparameters h;
  h.length_scales = Eigen::VectorXd::Constant(d, l);
  h.signal_variance = s2;
  h.noise_variance = n2;
  return h;
}

double matern52(double r, double s2) {
  return s2 * (1 + std::sqrt(5.0) * r + 5 * r * r / 3) * std::exp(-std::sqrt(5.0) * r);
}

double normalPdf(double u) { return std::exp(-0.5 * u * u) / std::sqrt(2 * M_PI); }

}  // namespace

TEST_CASE("doe/gp: Matern 5/2 kernel with ARD length scales", "[doe][gp]") {
  GaussianProcess gp;
  Eigen::MatrixXd X(2, 2);
  X << 0, 0, 1, 1;
  GpHyperparameters h = hyper(1, 2.5, 0, 2);
  h.length_scales << 0.5, 2.0;
  gp.fitFixed(X, Eigen::Vector2d(1, 2), h);
  Eigen::Vector2d a(0.1, 0.2), b(0.4, -0.6);
  const double r = std::hypot(0.3 / 0.5, 0.8 / 2.0);
  CHECK(gp.kernel(a, b) == Approx(matern52(r, 2.5)).epsilon(1e-14));
  CHECK(gp.kernel(a, a) == Approx(2.5).epsilon(1e-15));
}

TEST_CASE("doe/gp: two-point posterior equals the hand-computed closed form", "[doe][gp]") {
  // Standardised data z = (y - mean)/sd: y = {1, 3} gives z = {-1, 1}.
  Eigen::MatrixXd X(2, 1);
  X << 0.2, 0.7;
  const double l = 0.4, s2 = 1.3, n2 = 0.01;
  GaussianProcess gp;
  gp.fitFixed(X, Eigen::Vector2d(1, 3), hyper(l, s2, n2));
  const double k12 = matern52(0.5 / l, s2), a = s2 + n2;
  const double det = a * a - k12 * k12;
  const double xs = 0.5;
  const double k1 = matern52(0.3 / l, s2), k2 = matern52(0.2 / l, s2);
  // K^-1 = [a -k12; -k12 a] / det
  const double w1 = (a * k1 - k12 * k2) / det, w2 = (a * k2 - k12 * k1) / det;
  const double mean_z = -w1 + w2;
  const double var_z = s2 - (k1 * w1 + k2 * w2);
  const auto p = gp.predict(Eigen::VectorXd::Constant(1, xs));
  CHECK(p.mean == Approx(2 + 1 * mean_z).epsilon(1e-12));   // y = mean + sd·z, mean 2, sd 1
  CHECK(p.variance == Approx(var_z).epsilon(1e-12));
  // log p(z) = -1/2 zᵀK⁻¹z - 1/2 log det K - log 2π
  const double quad = (a * 1 + a * 1 - 2 * k12 * (-1) * 1) / det;
  CHECK(gp.logMarginalLikelihood() == Approx(-0.5 * quad - 0.5 * std::log(det) - std::log(2 * M_PI)).epsilon(1e-12));
}

TEST_CASE("doe/gp: maximum-likelihood fit interpolates a smooth function", "[doe][gp]") {
  const int n = 9;
  Eigen::MatrixXd X(n, 1);
  Eigen::VectorXd y(n);
  for (int i = 0; i < n; ++i) {
    X(i, 0) = i / double(n - 1);
    y(i) = 10 + 4 * std::sin(5 * X(i, 0));
  }
  GaussianProcess gp;
  gp.fit(X, y);
  for (int i = 0; i < n; ++i) CHECK(gp.predict(X.row(i).transpose()).mean == Approx(y(i)).margin(0.02));
  double worst = 0;
  for (double x = 0.0625; x < 1; x += 0.125) {
    const auto p = gp.predict(Eigen::VectorXd::Constant(1, x));
    worst = std::max(worst, std::abs(p.mean - (10 + 4 * std::sin(5 * x))));
  }
  CHECK(worst < 0.05);
  // Far from the data the uncertainty grows back towards the prior.
  CHECK(gp.predict(Eigen::VectorXd::Constant(1, 0.0625)).sd() < gp.predict(Eigen::VectorXd::Constant(1, 3.0)).sd());
  CHECK(gp.hyperparameters().noise_variance < 1e-3);
}

TEST_CASE("doe/gp: input warping is the Kumaraswamy CDF, and a = b = 1 is no warping", "[doe][gp]") {
  Eigen::MatrixXd X(3, 2);
  X << 0.1, 0.9, 0.5, 0.2, 0.8, 0.6;
  Eigen::VectorXd y(3);
  y << 1.0, 3.0, 2.0;
  GpHyperparameters h = hyper(0.4, 1.3, 1e-4, 2);
  GaussianProcess plain;
  plain.fitFixed(X, y, h);
  h.warp_a = Eigen::VectorXd::Ones(2), h.warp_b = Eigen::VectorXd::Ones(2);
  GaussianProcess identity;
  identity.fitFixed(X, y, h);
  const Eigen::Vector2d x(0.3, 0.45);
  CHECK(identity.predict(x).mean == Approx(plain.predict(x).mean).epsilon(1e-14));
  CHECK(identity.predict(x).variance == Approx(plain.predict(x).variance).epsilon(1e-14));
  CHECK(identity.logMarginalLikelihood() == Approx(plain.logMarginalLikelihood()).epsilon(1e-14));

  h.warp_a << 0.5, 2.0;
  h.warp_b << 1.5, 0.7;
  GaussianProcess warped;
  warped.fitFixed(X, y, h);
  const Eigen::VectorXd w = warped.warp(x);
  CHECK(w(0) == Approx(1 - std::pow(1 - std::pow(0.3, 0.5), 1.5)).epsilon(1e-14));
  CHECK(w(1) == Approx(1 - std::pow(1 - std::pow(0.45, 2.0), 0.7)).epsilon(1e-14));
  CHECK(warped.warp(Eigen::Vector2d(0, 1)) == Eigen::Vector2d(0, 1));  // the ends stay where they are
  // The warped model is the plain model on the warped inputs.
  Eigen::MatrixXd Xw(3, 2);
  for (int i = 0; i < 3; ++i) Xw.row(i) = warped.warp(X.row(i).transpose()).transpose();
  GpHyperparameters hp = h;
  hp.warp_a.resize(0), hp.warp_b.resize(0);
  GaussianProcess onWarped;
  onWarped.fitFixed(Xw, y, hp);
  CHECK(warped.predict(x).mean == Approx(onWarped.predict(w).mean).epsilon(1e-13));
  CHECK(warped.predict(x).variance == Approx(onWarped.predict(w).variance).epsilon(1e-13));

  h.warp_b.resize(1);
  CHECK_THROWS_WITH(warped.fitFixed(X, y, h), Catch::Contains("one a > 0 and one b > 0 per input"));
  GpFitOptions o;
  o.warp_inputs = true, o.warp_prior_sd = 0;
  CHECK_THROWS_WITH(warped.fit(X, y, o), Catch::Contains("warp_prior_sd"));
}

TEST_CASE("doe/gp: a learned warping fits a response that is steep near one end", "[doe][gp]") {
  // y = log(x + 0.01): its slope falls 100-fold across [0, 1], which one stationary length scale
  // cannot follow; w(x) with a < 1 stretches the steep end.
  const auto f = [](double x) { return std::log(x + 0.01); };
  const int n = 10;
  Eigen::MatrixXd X(n, 1);
  Eigen::VectorXd y(n);
  for (int i = 0; i < n; ++i) X(i, 0) = (i + 0.5) / n, y(i) = f(X(i, 0));
  GpFitOptions o;
  GaussianProcess plain, warped;
  plain.fit(X, y, o);
  o.warp_inputs = true;
  warped.fit(X, y, o);
  double e_plain = 0, e_warped = 0;
  int m = 0;
  for (double x = 0.01; x < 1; x += 0.01, ++m) {
    const Eigen::VectorXd xv = Eigen::VectorXd::Constant(1, x);
    e_plain += std::pow(plain.predict(xv).mean - f(x), 2);
    e_warped += std::pow(warped.predict(xv).mean - f(x), 2);
  }
  e_plain = std::sqrt(e_plain / m), e_warped = std::sqrt(e_warped / m);
  INFO("RMS error plain " << e_plain << ", warped " << e_warped << ", a = " << warped.hyperparameters().warp_a(0)
                          << ", b = " << warped.hyperparameters().warp_b(0));
  CHECK(warped.hyperparameters().warp_a(0) < 1.0);
  CHECK(e_warped < 0.5 * e_plain);
  CHECK(plain.hyperparameters().warp_a.size() == 0);  // off unless asked for
}

TEST_CASE("doe/gp: expected improvement matches Jones et al. and quadrature", "[doe][gp]") {
  CHECK(expectedImprovement(0, 1, 0) == Approx(1 / std::sqrt(2 * M_PI)).epsilon(1e-14));
  CHECK(expectedImprovement(3, 0, 5) == 2.0);
  CHECK(expectedImprovement(6, 0, 5) == 0.0);
  // E[max(0, best - Y)], Y ~ N(mu, sigma²), by the trapezoidal rule.
  const double mu = 1.3, sigma = 0.7, best = 1.0;
  double q = 0;
  const double h = 1e-4;
  for (double y = mu - 10 * sigma; y < best; y += h) q += (best - y) * normalPdf((y - mu) / sigma) / sigma * h;
  CHECK(expectedImprovement(mu, sigma, best) == Approx(q).epsilon(1e-4));
}

TEST_CASE("doe/surrogate: Monte Carlo composite EI converges to the closed form for one response", "[doe][gp]") {
  // One response, J = |y - t|/t. With y < t everywhere likely (mu far below t), J = (t - y)/t and
  // EI of J is Jones' EI of -y/t: E[max(0, J* - (t - Y)/t)].
  Eigen::MatrixXd X(3, 1);
  X << 0.0, 0.5, 1.0;
  GaussianProcess gp;
  gp.fitFixed(X, Eigen::Vector3d(10, 11, 12), hyper(0.3, 1.0, 1e-6));
  const Eigen::VectorXd x = Eigen::VectorXd::Constant(1, 0.25);
  const auto p = gp.predict(x);
  const double t = 100, Jstar = 0.895;
  Eigen::MatrixXd draws(200000, 1);
  std::mt19937_64 rng(7);
  std::normal_distribution<double> N;
  for (int m = 0; m < draws.rows(); ++m) draws(m, 0) = N(rng);
  const Eigen::VectorXd targets = Eigen::VectorXd::Constant(1, t);
  const double mc = compositeExpectedImprovement({gp}, x, targets, Jstar, draws);
  // J = 1 - Y/t: improvement max(0, J* - 1 + Y/t) = (1/t) max(0, Y - t(1 - J*)): EI of maximising Y.
  const double closed = expectedImprovement(-p.mean, p.sd(), -t * (1 - Jstar)) / t;
  REQUIRE(closed > 1e-4);
  CHECK(mc == Approx(closed).epsilon(0.02));
  CHECK(compositeError(Eigen::Vector2d(233, 470), Eigen::Vector2d(231, 480)) == Approx(10.0 / 480));
}

TEST_CASE("doe/surrogate: a calibration loop reaches its targets on a known model", "[doe][gp]") {
  // Two responses of two inputs in the unit cube, monotone like slump and slump-flow; the
  // targets are met exactly at (0.62, 0.35).
  auto model = [](const Eigen::VectorXd& x) {
    Eigen::Vector2d y;
    y(0) = 260 - 40 * x(0) - 10 * x(1) + 5 * x(0) * x(1);
    y(1) = 620 - 120 * x(0) - 200 * x(1) + 30 * x(1) * x(1);
    return y;
  };
  Eigen::Vector2d xs(0.62, 0.35);
  const Eigen::Vector2d targets = model(xs);
  Eigen::MatrixXd X(4, 2);
  X << 0.1, 0.1, 0.9, 0.2, 0.3, 0.9, 0.8, 0.8;
  Eigen::MatrixXd Y(4, 2);
  for (int i = 0; i < 4; ++i) Y.row(i) = model(X.row(i).transpose()).transpose();
  SurrogateOptions o;
  o.batch = 2;
  o.candidates = 1500;
  int evaluations = 4;
  double best = 1;
  while (evaluations < 24 && best > 0.02) {
    const auto step = suggestCalibrationPoints(X, Y, targets, o);
    REQUIRE(step.suggestions.size() == 2);
    for (const auto& s : step.suggestions) {
      REQUIRE(((s.x.array() >= 0) && (s.x.array() <= 1)).all());
      X.conservativeResize(X.rows() + 1, Eigen::NoChange);
      Y.conservativeResize(Y.rows() + 1, Eigen::NoChange);
      X.row(X.rows() - 1) = s.x.transpose();
      Y.row(Y.rows() - 1) = model(s.x).transpose();
      best = std::min(best, compositeError(Y.row(Y.rows() - 1).transpose(), targets));
      ++evaluations;
    }
  }
  INFO("evaluations " << evaluations << ", best error " << best);
  CHECK(best <= 0.02);
  CHECK(evaluations <= 16);
  // Deterministic: the same data and seed give the same suggestion.
  const auto a = suggestCalibrationPoints(X, Y, targets, o), b = suggestCalibrationPoints(X, Y, targets, o);
  CHECK(a.suggestions[0].x == b.suggestions[0].x);
}

TEST_CASE("doe/surrogate: bad input is refused with the reason", "[doe][gp]") {
  Eigen::MatrixXd X(2, 1);
  X << 0.1, 0.9;
  Eigen::MatrixXd Y(2, 1);
  Y << 1, 2;
  CHECK_THROWS_WITH(suggestCalibrationPoints(X, Y, Eigen::VectorXd::Zero(1)), Catch::Contains("target is 0"));
  CHECK_THROWS_WITH(suggestCalibrationPoints(X * 2, Y, Eigen::VectorXd::Ones(1)), Catch::Contains("unit cube"));
  CHECK_THROWS_WITH(suggestCalibrationPoints(X, Y, Eigen::VectorXd::Ones(2)), Catch::Contains("one target per response"));
  GaussianProcess gp;
  CHECK_THROWS_WITH(gp.fit(X.topRows(1), Y.col(0).head(1)), Catch::Contains("at least 2 points"));
}
