// Noise covariance with Schäfer–Strimmer shrinkage, whitening, bounded Gauss–Newton step, fit
// comparison, null-trial thresholds and Clopper–Pearson bounds, against closed forms.
#include "paddy/doe/covariance.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/gauss_newton.hpp"
#include "paddy/doe/null_calibration.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

using namespace paddy::doe;

TEST_CASE("discovery/covariance: Schäfer–Strimmer shrinkage on a hand-worked example", "[doe][discovery]") {
  // 4 replicates of 3 observables. Sample variances 14/3, 10/3, 2/3; sample correlations
  // r01 = 6/sqrt(14*10/... ) etc.; with w_kij the products of standardised columns,
  // sum_{i<j} Var(r_ij) / sum_{i<j} r_ij^2 = 1/3 exactly (worked with rational arithmetic).
  Eigen::MatrixXd X(4, 3);
  X << 1, 2, 0, 2, 1, 1, 3, 4, 1, 6, 5, 2;
  const NoiseCovariance c = noiseCovariance(X, Eigen::Vector3d(0.5, 0.0, 1.0), 2.0);
  CHECK(c.shrinkage == Approx(1.0 / 3.0).epsilon(1e-12));
  CHECK(c.seedSd(0) == Approx(std::sqrt(14.0 / 3.0)).epsilon(1e-12));
  CHECK(c.seedSd(2) == Approx(std::sqrt(2.0 / 3.0)).epsilon(1e-12));
  // sample correlation of columns 0 and 2: sum dev0 dev2 / 3 / (sd0 sd2) = (2/3*... ) = 0.944911...
  const double r02 = 0.944911182523068;
  CHECK(c.seedCovariance(0, 2) == Approx((1.0 - 1.0 / 3.0) * r02 * std::sqrt(14.0 / 3.0 * 2.0 / 3.0)).epsilon(1e-12));
  CHECK(c.seedCovariance(1, 1) == Approx(10.0 / 3.0).epsilon(1e-12));
  // Sigma = Sigma_meas + Sigma_seed / n_avg
  CHECK(c.covariance(0, 0) == Approx(0.25 + 14.0 / 3.0 / 2.0).epsilon(1e-12));
  CHECK(c.covariance(2, 2) == Approx(1.0 + 2.0 / 3.0 / 2.0).epsilon(1e-12));
  CHECK(c.covariance(0, 2) == Approx(c.seedCovariance(0, 2) / 2.0).epsilon(1e-12));
}

TEST_CASE("discovery/covariance: few replicates and long vectors stay positive definite", "[doe][discovery]") {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> N;
  Eigen::MatrixXd X(5, 40);  // 5 replicates, 40 observables: the sample covariance has rank 4
  for (Eigen::Index i = 0; i < X.rows(); ++i)
    for (Eigen::Index j = 0; j < X.cols(); ++j) X(i, j) = N(rng);
  const NoiseCovariance c = noiseCovariance(X, Eigen::VectorXd(), 1.0);
  CHECK(c.shrinkage > 0.5);  // independent columns: the estimator shrinks most of the way
  CHECK(c.shrinkage <= 1.0);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(c.covariance);
  CHECK(es.eigenvalues()(0) > 0);
  // strongly correlated columns (a common factor) keep their correlation
  Eigen::MatrixXd Y(30, 6);
  for (Eigen::Index i = 0; i < Y.rows(); ++i) {
    const double f = N(rng);
    for (Eigen::Index j = 0; j < Y.cols(); ++j) Y(i, j) = f + 0.2 * N(rng);
  }
  CHECK(correlationShrinkage(Y) < 0.05);
  // whitening makes W Sigma W^T = I
  const Whitening W(c.covariance);
  const Eigen::MatrixXd WS = W.apply(Eigen::MatrixXd(W.apply(c.covariance).transpose()));
  CHECK((WS - Eigen::MatrixXd::Identity(40, 40)).cwiseAbs().maxCoeff() < 1e-10);
}

TEST_CASE("discovery/covariance: errors", "[doe][discovery]") {
  CHECK_THROWS_WITH(noiseCovariance(Eigen::MatrixXd::Ones(1, 3), Eigen::VectorXd(), 1.0),
                    Catch::Contains("at least 2 replicate runs"));
  Eigen::MatrixXd X(3, 2);
  X << 1, 5, 2, 5, 3, 5;  // observable 2 has no scatter
  CHECK_THROWS_WITH(noiseCovariance(X, Eigen::VectorXd(), 1.0), Catch::Contains("observable 2 has zero variance"));
  CHECK_NOTHROW(noiseCovariance(X, Eigen::Vector2d(0.1, 0.1), 1.0));
  CHECK_THROWS_WITH(noiseCovariance(X, Eigen::Vector3d(1, 1, 1), 1.0), Catch::Contains("sigma: 3 entries"));
  CHECK_THROWS_WITH(noiseCovariance(X, Eigen::Vector2d(1, 1), 0.0), Catch::Contains("n_avg: must be > 0"));
  CHECK_THROWS_WITH(noiseCovariance(X, Eigen::Vector2d(1, 1), -1.0), Catch::Contains("n_avg"));
  // An effective count below 1 (a measurement with seed-like scatter of its own) is allowed and
  // scales the seed part alone: Sigma = diag(sigma^2) + Sigma_seed / n_avg.
  Eigen::MatrixXd Y(3, 2);
  Y << 1, 4, 2, 5, 3, 7;
  const auto one = noiseCovariance(Y, Eigen::Vector2d(0.5, 0.5), 1.0);
  const auto half = noiseCovariance(Y, Eigen::Vector2d(0.5, 0.5), 0.5);
  CHECK((half.covariance - Eigen::Matrix2d::Identity() * 0.25 - 2.0 * (one.covariance - Eigen::Matrix2d::Identity() * 0.25))
            .cwiseAbs().maxCoeff() < 1e-12);
  Eigen::Matrix2d S;
  S << 1, 2, 2, 1;
  CHECK_THROWS_WITH(Whitening(S), Catch::Contains("not positive definite (smallest eigenvalue -1"));
}

TEST_CASE("discovery/gauss_newton: unbounded, bounded and damped steps", "[doe][discovery]") {
  Eigen::MatrixXd J(2, 2);
  J << 1, 1, 0, 1;
  const Eigen::Vector2d r(2, 1), theta(0.0, 0.0);
  const Eigen::Vector2d none;
  // unbounded: J d = r -> d = (1, 1), covariance (J^T J)^-1
  const BoundedStep s = boundedGaussNewtonStep(theta, r, J, Eigen::VectorXd(), Eigen::VectorXd(), 0.0);
  CHECK(s.theta.isApprox(Eigen::Vector2d(1, 1), 1e-12));
  CHECK(s.covariance.isApprox((J.transpose() * J).inverse(), 1e-12));
  CHECK(s.se(1) == Approx(std::sqrt((J.transpose() * J).inverse()(1, 1))).epsilon(1e-12));
  CHECK(s.misfitPredicted == Approx(0.0).margin(1e-12));
  // d1 <= 0.5: minimise (1.5 - d2)^2 + (1 - d2)^2 -> d2 = 1.25; KKT holds (gradient -0.25 at the upper bound)
  const BoundedStep b = boundedGaussNewtonStep(theta, r, J, Eigen::Vector2d(-5, -5), Eigen::Vector2d(0.5, 5), 0.0);
  CHECK(b.theta.isApprox(Eigen::Vector2d(0.5, 1.25), 1e-12));
  CHECK(b.atBound[0] == 1);
  CHECK(b.atBound[1] == 0);
  CHECK(b.misfitPredicted == Approx(std::sqrt((0.25 * 0.25 + 0.25 * 0.25) / 2.0)).epsilon(1e-12));
  // a bound that starts active and must be released: theta1 at its lower bound, the step wants to go up
  const BoundedStep rel = boundedGaussNewtonStep(Eigen::Vector2d(0, 0), r, J, Eigen::Vector2d(0, 0), Eigen::Vector2d(3, 3), 0.0);
  CHECK(rel.theta.isApprox(Eigen::Vector2d(1, 1), 1e-12));
  // both bounds active: step toward (1, 1) clipped in a box that excludes it
  const BoundedStep box = boundedGaussNewtonStep(Eigen::Vector2d(0, 0), r, J, Eigen::Vector2d(-1, -1), Eigen::Vector2d(0.2, 0.2), 0.0);
  CHECK(box.theta.isApprox(Eigen::Vector2d(0.2, 0.2), 1e-12));
  // Marquardt damping: d = (J^T J + mu diag(J^T J))^-1 J^T r
  const double mu = 0.3;
  const Eigen::Matrix2d H = J.transpose() * J;
  const Eigen::Matrix2d damped = H + mu * Eigen::Matrix2d(H.diagonal().asDiagonal());
  const Eigen::Vector2d expected = damped.inverse() * (J.transpose() * r);
  const BoundedStep dmp = boundedGaussNewtonStep(theta, r, J, Eigen::VectorXd(), Eigen::VectorXd(), mu);
  CHECK(dmp.step.isApprox(expected, 1e-12));
  (void)none;
}

TEST_CASE("discovery/gauss_newton: rank-deficient Jacobian and errors", "[doe][discovery]") {
  Eigen::MatrixXd J(3, 2);
  J << 1, 2, 1, 2, 0, 0;  // column 2 = 2 x column 1
  const BoundedStep s = boundedGaussNewtonStep(Eigen::Vector2d(0, 0), Eigen::Vector3d(1, 1, 0), J, Eigen::VectorXd(), Eigen::VectorXd(), 0.0);
  CHECK(s.rank == 1);
  CHECK(std::isinf(s.se(0)));
  CHECK(std::isinf(s.se(1)));
  CHECK((J * s.step - Eigen::Vector3d(1, 1, 0)).norm() < 1e-12);  // still fits what it can
  CHECK_THROWS_WITH(boundedGaussNewtonStep(Eigen::Vector2d(2, 0), Eigen::Vector3d(1, 1, 0), J, Eigen::Vector2d(0, 0),
                                           Eigen::Vector2d(1, 1), 0.0),
                    Catch::Contains("theta: parameter 1 = 2") && Catch::Contains("outside [0"));
  CHECK_THROWS_WITH(boundedGaussNewtonStep(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), J, Eigen::VectorXd(), Eigen::VectorXd(), 0.0),
                    Catch::Contains("jacobian: must be 2 x 2"));
  CHECK_THROWS_WITH(boundedGaussNewtonStep(Eigen::Vector2d(0, 0), Eigen::Vector3d(1, 1, 0), J, Eigen::VectorXd(), Eigen::VectorXd(), -1.0),
                    Catch::Contains("damping"));
}

TEST_CASE("discovery/compare_fits: likelihood ratio and Delta BIC", "[doe][discovery]") {
  const FitComparison c = compareFits(20.0, 10.3, 1, 30, 3, 4);
  CHECK(c.lr == Approx(9.7));
  CHECK(c.p == Approx(std::erfc(std::sqrt(9.7 / 2.0))).epsilon(1e-10));  // chi^2_1 upper tail
  CHECK(c.deltaBic == Approx(-9.7 + std::log(30.0)).epsilon(1e-12));
  CHECK(c.evidence == "strong");
  CHECK(compareFits(20.0, 19.5, 1, 30, 3, 4).evidence == "against the added effect");
  CHECK_THROWS_WITH(compareFits(20.0, 10.0, 0, 30, 3, 4), Catch::Contains("df"));
}

TEST_CASE("discovery/null_calibration: Clopper–Pearson bounds and empirical thresholds", "[doe][discovery]") {
  // the design note's figures: 0/20 -> 13.9 %, 0/30 -> 9.5 %, 0/50 -> 5.8 %; 96/100 correct is
  // the fewest out of 100 whose lower bound reaches 90 %
  CHECK(clopperPearson(0, 20).upper == Approx(1.0 - std::pow(0.05, 1.0 / 20)).epsilon(1e-10));
  CHECK(clopperPearson(0, 30).upper == Approx(0.0950).margin(5e-4));
  CHECK(clopperPearson(0, 50).upper == Approx(0.0582).margin(5e-4));
  CHECK(clopperPearson(30, 30).lower == Approx(std::pow(0.05, 1.0 / 30)).epsilon(1e-10));
  CHECK(clopperPearson(96, 100).lower >= 0.90);
  CHECK(clopperPearson(95, 100).lower < 0.90);
  CHECK(clopperPearson(49, 50).lower >= 0.90);
  CHECK(clopperPearson(59, 60).lower >= 0.90);

  // thresholds at order statistics: no more than alpha N alarms, one more alarm at the next pair down
  std::mt19937_64 rng(3);
  std::normal_distribution<double> N;
  std::chi_squared_distribution<double> chi(20);
  std::vector<double> z, q;
  for (int i = 0; i < 1000; ++i) {
    z.push_back(N(rng));
    q.push_back(chi(rng));
  }
  const NullThresholds t = nullThresholds(z, q, 0.05);
  int alarms = 0;
  for (int i = 0; i < 1000; ++i) alarms += (z[static_cast<std::size_t>(i)] > t.zThreshold || q[static_cast<std::size_t>(i)] > t.q0Threshold) ? 1 : 0;
  CHECK(alarms == t.alarms);
  CHECK(alarms <= 50);
  CHECK(alarms >= 49);  // lowering both thresholds one order statistic adds at most two alarms
  // independent statistics: each marginal tail ~ 2.5 %: z threshold near the normal 0.975 quantile
  CHECK(t.zThreshold == Approx(1.96).margin(0.2));
  CHECK_THROWS_WITH(nullThresholds({}, q, 0.05), Catch::Contains("z_max: no null-trial values"));
  CHECK_THROWS_WITH(nullThresholds(z, q, 1.0), Catch::Contains("alpha"));
}
