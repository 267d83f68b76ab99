#include "paddy/doe/desirability.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/optimizer.hpp"

#include <catch2/catch.hpp>

using namespace paddy::doe;

TEST_CASE("doe/desirability: individual functions", "[doe]") {
  GoalSpec g{"y", Goal::Maximize, 0, 10, 0, 1, 1, 3};
  CHECK(desirability(g, -1) == 0.0);
  CHECK(desirability(g, 5) == Approx(0.5));
  CHECK(desirability(g, 12) == 1.0);
  g.weight1 = 2;
  CHECK(desirability(g, 5) == Approx(0.25));
  g.weight1 = 0.5;
  CHECK(desirability(g, 5) == Approx(0.70710678));
  GoalSpec m{"y", Goal::Minimize, 0, 10, 0, 1, 1, 3};
  CHECK(desirability(m, 2.5) == Approx(0.75));
  CHECK(desirability(m, -3) == 1.0);
  CHECK(desirability(m, 10) == 0.0);
  GoalSpec t{"y", Goal::Target, 0, 10, 4, 1, 2, 3};
  CHECK(desirability(t, 4) == Approx(1.0));
  CHECK(desirability(t, 2) == Approx(0.5));
  CHECK(desirability(t, 7) == Approx(0.25));  // ((10-7)/6)^2
  CHECK(desirability(t, 10.5) == 0.0);
  GoalSpec r{"y", Goal::InRange, 1, 2, 0, 1, 1, 3};
  CHECK(desirability(r, 1.5) == 1.0);
  CHECK(desirability(r, 2.5) == 0.0);
}

TEST_CASE("doe/desirability: overall D is the importance-weighted geometric mean", "[doe]") {
  GoalSpec a{"a", Goal::Maximize, 0, 1, 0, 1, 1, 1};
  GoalSpec b{"b", Goal::Maximize, 0, 1, 0, 1, 1, 3};
  CHECK(overallDesirability({a, b}, {0.5, 0.8}) == Approx(0.711312).margin(1e-6));  // (0.5 * 0.8^3)^(1/4)
  b.importance = 1;
  CHECK(overallDesirability({a, b}, {0.5, 0.8}) == Approx(0.632456).margin(1e-6));  // sqrt(0.4)
  CHECK(overallDesirability({a, b}, {0.0, 0.8}) == 0.0);
}

TEST_CASE("doe/desirability: goal parsing and validation", "[doe]") {
  const auto g = parseGoal("slump=target:231,lo=220,hi=250,w=2,imp=5", 200, 300);
  CHECK(g.goal == Goal::Target);
  CHECK(g.target == 231);
  CHECK(g.lower == 220);
  CHECK(g.upper == 250);
  CHECK(g.weight1 == 2);
  CHECK(g.importance == 5);
  CHECK(parseGoal("y=max", 1, 2).lower == 1);
  CHECK_THROWS_AS(parseGoal("y=target:5", 10, 20), DoeError);  // target outside the limits
  CHECK_THROWS_WITH(parseGoal("y=best", 0, 1), Catch::Contains("unknown goal"));
  CHECK_THROWS_WITH(parseGoal("y=max,imp=7", 0, 1), Catch::Contains("importance"));
}

TEST_CASE("doe/optimizer: finds the known optimum of a quadratic", "[doe]") {
  // y = 10 - (x1 - 0.3)^2 - 2 (x2 + 0.4)^2 + 0.5 x1 x2 in coded units; stationary point solves
  // dy/dx1 = -2(x1-0.3) + 0.5 x2 = 0, dy/dx2 = -4(x2+0.4) + 0.5 x1 = 0.
  const std::vector<std::string> names{"A", "B"};
  ResponseModel y{"y", Model::quadratic(names), Eigen::VectorXd(6), 0, 10.5};
  // terms: Intercept, A, B, A:B, A^2, B^2
  y.beta << 10 - 0.09 - 0.32, 0.6, -1.6, 0.5, -1.0, -2.0;
  const double x2 = (-1.6 + 0.25 * 0.6 / 2 * 2) / (4 - 0.125);  // solve the 2x2 system
  const double x1 = 0.3 + 0.25 * x2;
  std::vector<Factor> f{{"A", 10, 20}, {"B", 0.1, 0.5}};
  GoalSpec g{"y", Goal::Maximize, 5, 10.5, 0, 1, 1, 3};
  const auto sols = optimizeDesirability(f, {y}, {g});
  REQUIRE(!sols.empty());
  CHECK(sols[0].coded(0) == Approx(x1).margin(1e-4));
  CHECK(sols[0].coded(1) == Approx(x2).margin(1e-4));
  CHECK(sols[0].real(0) == Approx(15 + 5 * x1).margin(1e-3));
  CHECK(sols[0].predicted[0] == Approx(y.predict(Eigen::Vector2d(x1, x2))).margin(1e-8));

  // two linear responses with targets: the unique solution is A = 0.2, B = -0.5 (coded)
  ResponseModel r1{"r1", Model::linear(names), Eigen::Vector3d(0, 1, 0), -1, 1};
  ResponseModel r2{"r2", Model::linear(names), Eigen::Vector3d(0, 0, 1), -1, 1};
  GoalSpec t1{"r1", Goal::Target, -1, 1, 0.2, 1, 1, 3}, t2{"r2", Goal::Target, -1, 1, -0.5, 1, 1, 3};
  const auto s2 = optimizeDesirability(f, {r1, r2}, {t1, t2});
  CHECK(s2[0].overall == Approx(1.0).margin(1e-5));
  CHECK(s2[0].coded(0) == Approx(0.2).margin(1e-4));
  CHECK(s2[0].coded(1) == Approx(-0.5).margin(1e-4));
  // solutions are ranked and de-duplicated
  for (std::size_t i = 1; i < s2.size(); ++i) {
    CHECK(s2[i].overall <= s2[i - 1].overall);
    CHECK((s2[i].coded - s2[0].coded).cwiseAbs().maxCoeff() >= 0.02);
  }
  // a maximum on the boundary of the box; starts from a flat D = 0 region still succeed
  ResponseModel s{"s", Model::linear(names), Eigen::Vector3d(0, 1, 1), -2, 2};
  GoalSpec gs{"s", Goal::Maximize, 1.5, 2, 0, 1, 1, 3};
  const auto s3 = optimizeDesirability(f, {s}, {gs});
  CHECK(s3[0].overall == Approx(1.0));
  CHECK(s3[0].predicted[0] >= 2.0 - 1e-6);
}
