// Quadratic response surface and its best-fitting point in a box (response_surface.hpp), against
// closed forms: exact recovery of a quadratic vector response, its minimiser inside the box and on
// its edge (checked by brute force on a fine grid), the linearised covariance, noise averaged out,
// and the input errors.
#include "paddy/doe/error.hpp"
#include "paddy/doe/response_surface.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace paddy::doe;

namespace {

// Three observables, quadratic in (a, b) on the box [0, 0.2] x [0, 0.3], with a curved valley:
//   f1 = 3 a + 2 b + 4 a b,  f2 = a^2 - b + 1,  f3 = 5 b^2 + a
Eigen::VectorXd response(double a, double b) {
  Eigen::VectorXd f(3);
  f << 3 * a + 2 * b + 4 * a * b, a * a - b + 1, 5 * b * b + a;
  return f;
}
Eigen::MatrixXd gradient(double a, double b) {
  Eigen::MatrixXd J(3, 2);
  J << 3 + 4 * b, 2 + 4 * a, 2 * a, -1, 1, 10 * b;
  return J;
}

ResponseSurfaceInput grid(int k, double noise = 0, unsigned seed = 1) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, noise > 0 ? noise : 1.0);
  ResponseSurfaceInput in;
  in.points.resize(k * k, 2);
  in.values.resize(k * k, 3);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) {
      const double a = 0.2 * i / (k - 1), b = 0.3 * j / (k - 1);
      in.points.row(i * k + j) << a, b;
      Eigen::VectorXd f = response(a, b);
      if (noise > 0)
        for (int o = 0; o < 3; ++o) f(o) += N(rng);
      in.values.row(i * k + j) = f.transpose();
    }
  in.lower = Eigen::VectorXd::Zero(2);
  in.upper = (Eigen::VectorXd(2) << 0.2, 0.3).finished();
  in.covariance = (Eigen::VectorXd(3) << 0.01, 0.04, 0.02).finished().asDiagonal();
  return in;
}

double misfit(const ResponseSurfaceInput& in, double a, double b) {
  const Eigen::VectorXd r = in.measured - response(a, b);
  return r.dot(in.covariance.inverse() * r);
}

}  // namespace

TEST_CASE("response surface: a quadratic response is recovered and its interior optimum found", "[doe][discovery]") {
  ResponseSurfaceInput in = grid(3);  // 9 points for 6 terms
  in.measured = response(0.07, 0.21);
  const ResponseSurfaceFit f = fitResponseSurface(in);
  CHECK(f.terms == 6);
  CHECK(f.x(0) == Approx(0.07).margin(1e-6));
  CHECK(f.x(1) == Approx(0.21).margin(1e-6));
  CHECK(f.misfitPredicted == Approx(0).margin(1e-6));
  for (int o = 0; o < 3; ++o) CHECK(f.residualSd(o) == Approx(0).margin(1e-10));
  // The gradient of the fitted surface at x* is the response's; the covariance (J^T S^-1 J)^-1.
  const Eigen::MatrixXd J = gradient(f.x(0), f.x(1));
  for (int o = 0; o < 3; ++o)
    for (int j = 0; j < 2; ++j) CHECK(f.jacobian(o, j) == Approx(J(o, j)).margin(1e-8));
  const Eigen::MatrixXd C = (J.transpose() * in.covariance.inverse() * J).inverse();
  CHECK(f.covariance(0, 0) == Approx(C(0, 0)).epsilon(1e-6));
  CHECK(f.covariance(0, 1) == Approx(C(0, 1)).epsilon(1e-6));
  CHECK(f.se(1) == Approx(std::sqrt(C(1, 1))).epsilon(1e-6));
  CHECK(f.atBound == std::vector<int>{0, 0});
  // f(x*) predicted
  for (int o = 0; o < 3; ++o) CHECK(f.predicted(o) == Approx(in.measured(o)).margin(1e-6));
}

TEST_CASE("response surface: an optimum outside the box is found on its edge, as a brute-force grid finds it", "[doe][discovery]") {
  ResponseSurfaceInput in = grid(4);
  in.measured = response(0.26, 0.12) + (Eigen::VectorXd(3) << 0.05, -0.1, 0.02).finished();  // beyond a = 0.2
  const ResponseSurfaceFit f = fitResponseSurface(in);
  double bestQ = 1e300, ba = 0, bb = 0;
  for (int i = 0; i <= 2000; ++i)
    for (int j = 0; j <= 3000; j += 1) {
      const double a = 0.2 * i / 2000, b = 0.3 * j / 3000;
      const double q = misfit(in, a, b);
      if (q < bestQ) bestQ = q, ba = a, bb = b;
    }
  CHECK(f.atBound[0] == 1);
  CHECK(f.atBound[1] == 0);
  CHECK(f.x(0) == Approx(0.2).margin(1e-12));
  CHECK(f.x(1) == Approx(bb).margin(2e-4));
  CHECK(f.misfitPredicted * f.misfitPredicted * 3 <= bestQ + 1e-9);
  CHECK(f.misfitPredicted * f.misfitPredicted * 3 == Approx(bestQ).epsilon(1e-4));  // the brute grid's resolution
  (void)ba;
}

TEST_CASE("response surface: seed-like noise on the points is averaged out", "[doe][discovery]") {
  // Noise of sd 0.05 on every value at 25 points, 40 seeds. Picking the best point run (what a
  // start scan does) lands on a noisy grid node; the surface's minimiser is closer to the truth
  // (0.1, 0.15) on average by far, and its residual sd estimates the noise.
  double surf2 = 0, pick2 = 0, sd = 0;
  const int seeds = 40;
  for (int s = 1; s <= seeds; ++s) {
    ResponseSurfaceInput in = grid(5, 0.05, static_cast<unsigned>(s));
    in.measured = response(0.1, 0.15);
    const ResponseSurfaceFit f = fitResponseSurface(in);
    surf2 += std::pow(f.x(0) - 0.1, 2) / 0.04 + std::pow(f.x(1) - 0.15, 2) / 0.09;  // in units of the ranges
    sd += f.residualSd.mean() / seeds;
    double bestQ = 1e300;
    Eigen::Index bestK = 0;
    for (Eigen::Index k = 0; k < in.points.rows(); ++k) {
      const Eigen::VectorXd r = in.measured - in.values.row(k).transpose();
      const double q = r.dot(in.covariance.inverse() * r);
      if (q < bestQ) bestQ = q, bestK = k;
    }
    pick2 += std::pow(in.points(bestK, 0) - 0.1, 2) / 0.04 + std::pow(in.points(bestK, 1) - 0.15, 2) / 0.09;
  }
  const double surf = std::sqrt(surf2 / seeds), pick = std::sqrt(pick2 / seeds);
  INFO("RMS error in units of the ranges: surface " << surf << ", best point " << pick << "; mean residual sd " << sd);
  CHECK(surf < 0.5 * pick);
  CHECK(surf < 0.1);
  CHECK(sd == Approx(0.05).epsilon(0.15));
}

TEST_CASE("response surface: one parameter", "[doe][discovery]") {
  ResponseSurfaceInput in;
  in.points.resize(4, 1);
  in.values.resize(4, 2);
  for (int i = 0; i < 4; ++i) {
    const double x = 1.0 + i;  // box [1, 4]
    in.points(i, 0) = x;
    in.values.row(i) << x * x, 2 * x;
  }
  in.lower = Eigen::VectorXd::Constant(1, 1.0);
  in.upper = Eigen::VectorXd::Constant(1, 4.0);
  in.covariance = Eigen::MatrixXd::Identity(2, 2);
  in.measured = (Eigen::VectorXd(2) << 6.25, 5.0).finished();  // x = 2.5
  const ResponseSurfaceFit f = fitResponseSurface(in);
  CHECK(f.terms == 3);
  CHECK(f.x(0) == Approx(2.5).margin(1e-6));
  CHECK(f.jacobian(0, 0) == Approx(5.0).margin(1e-6));
}

// Spread over specimens on a linear response, where it has a closed form: f(x) = a x, identity
// weights, so the minimiser for y + dev is x(y) + g . dev with g = a / (a . a), and specimen_se is
// the sample sd of g . d_k over the runs (K - 1 degrees of freedom).
TEST_CASE("response surface: spread over specimens on a linear response", "[doe][discovery]") {
  const Eigen::Vector4d a(1.0, 2.0, 0.5, 1.0);
  ResponseSurfaceInput in;
  in.points.resize(5, 1);
  in.values.resize(5, 4);
  for (int i = 0; i < 5; ++i) {
    const double x = -1.0 + 0.5 * i;
    in.points(i, 0) = x;
    in.values.row(i) = (a * x).transpose();
  }
  in.lower = Eigen::VectorXd::Constant(1, -1.0);
  in.upper = Eigen::VectorXd::Constant(1, 1.0);
  in.covariance = Eigen::MatrixXd::Identity(4, 4);
  in.measured = a * 0.2;
  CHECK(fitResponseSurface(in).specimenSe.size() == 0);  // no runs, no spread
  in.specimenRuns.resize(3, 4);
  in.specimenRuns << 0.05, -0.02, 0.01, 0.03, -0.04, 0.03, 0.0, -0.01, 0.01, 0.02, -0.03, 0.02;
  const Eigen::Vector4d g = a / a.squaredNorm();
  Eigen::Vector3d gd;
  const Eigen::Vector4d mean = in.specimenRuns.colwise().mean().transpose();
  for (int k = 0; k < 3; ++k) gd(k) = g.dot(in.specimenRuns.row(k).transpose() - mean);
  const double expected = std::sqrt((gd.array() - gd.mean()).square().sum() / 2.0);
  const ResponseSurfaceFit f = fitResponseSurface(in);
  REQUIRE(f.specimenSe.size() == 1);
  CHECK(f.x(0) == Approx(0.2).margin(1e-9));
  CHECK(f.specimenSe(0) == Approx(expected).epsilon(1e-6));
  // a deviation along a direction the response does not have moves nothing
  Eigen::Vector4d orth(2.0, -1.0, 0.0, 0.0);  // a . orth = 0
  in.specimenRuns.resize(2, 4);
  in.specimenRuns.row(0) = 0.01 * orth.transpose();
  in.specimenRuns.row(1) = -0.01 * orth.transpose();
  CHECK(fitResponseSurface(in).specimenSe(0) == Approx(0.0).margin(1e-9));
  in.specimenRuns.resize(1, 4);
  in.specimenRuns.setZero();
  CHECK_THROWS_WITH(fitResponseSurface(in), Catch::Contains("specimen_runs: at least two runs"));
  in.specimenRuns.resize(2, 3);
  in.specimenRuns.setZero();
  CHECK_THROWS_WITH(fitResponseSurface(in), Catch::Contains("specimen_runs: each run must have 4 entries"));
}

TEST_CASE("response surface: input errors name the field", "[doe][discovery]") {
  auto fails = [](const ResponseSurfaceInput& in, const char* what) {
    try {
      fitResponseSurface(in);
      FAIL("accepted; expected an error about " << what);
    } catch (const DoeError& e) {
      CHECK_THAT(e.what(), Catch::Contains(what));
    }
  };
  ResponseSurfaceInput in = grid(3);
  in.measured = response(0.1, 0.1);
  ResponseSurfaceInput few = in;
  few.points = in.points.topRows(5);
  few.values = in.values.topRows(5);
  fails(few, "at least 6 points");
  ResponseSurfaceInput line = in;  // every point on a = 2 b / 3: no surface across the valley
  for (Eigen::Index k = 0; k < line.points.rows(); ++k) line.points(k, 0) = line.points(k, 1) * 2.0 / 3.0;
  fails(line, "does not determine a quadratic surface");
  ResponseSurfaceInput outside = in;
  outside.points(4, 1) = 0.31;
  fails(outside, "point 5, parameter 2 lies outside");
  ResponseSurfaceInput box = in;
  box.upper(0) = 0.0;
  fails(box, "lower < upper");
  ResponseSurfaceInput meas = in;
  meas.measured = Eigen::VectorXd::Ones(2);
  fails(meas, "measured: must have 3 entries");
  ResponseSurfaceInput nan = in;
  nan.values(2, 1) = std::nan("");
  fails(nan, "values: non-finite");
  ResponseSurfaceInput cov = in;
  cov.covariance(1, 1) = -1;
  fails(cov, "covariance");
}
