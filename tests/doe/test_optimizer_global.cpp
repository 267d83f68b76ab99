// The desirability optimiser finds the global optimum of D over the box, wherever it lies: on a
// vertex, an edge, a face or inside. Reference: an exhaustive grid of spacing h over [-1, 1]^3.
// The grid's best value is a lower bound of the true maximum, so the optimiser must reach it (up to
// its convergence tolerance); the grid point nearest the optimiser's point must be as good as the
// grid's best up to the change of D over one grid step per coordinate.
#include "paddy/doe/box_behnken.hpp"
#include <paddy/lua/doe.hpp>
#include "paddy/doe/optimizer.hpp"
#include "paddy/doe/regression.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <lua.hpp>
#include <map>
#include <random>

using namespace paddy::doe;

namespace {

const std::vector<std::string> kNames{"A", "B", "C"};
const std::vector<Factor> kFactors{{"A", 0.07, 0.13}, {"B", 0.4, 0.6}, {"C", 0.07, 0.13}};

// Quadratic in coded A, B, C with the named coefficients (others 0).
ResponseModel quadratic(const std::string& name, const std::map<std::string, double>& coef) {
  ResponseModel r{name, Model::quadratic(kNames), {}, 0, 0};
  r.beta = Eigen::VectorXd::Zero(r.model.p());
  const auto terms = r.model.termNames();
  for (const auto& [term, c] : coef) {
    const auto it = std::find(terms.begin(), terms.end(), term);
    REQUIRE(it != terms.end());
    r.beta(it - terms.begin()) = c;
  }
  return r;
}

double overallAt(const std::vector<ResponseModel>& rs, const std::vector<GoalSpec>& goals, const Eigen::VectorXd& x) {
  std::vector<double> y;
  for (const auto& g : goals)
    for (const auto& r : rs)
      if (r.name == g.response) y.push_back(r.predict(x));
  return overallDesirability(goals, y);
}

struct Grid {
  int n;                  // points per axis
  double h;               // spacing
  std::vector<double> D;  // n^3 values, index (i * n + j) * n + l
  double best = -1;
  Eigen::Vector3d bestPoint;
  double maxStep = 0;  // largest |D| change between neighbouring grid points
  double coord(int i) const { return -1.0 + i * h; }
  int nearest(double x) const { return std::clamp(static_cast<int>(std::lround((x + 1.0) / h)), 0, n - 1); }
  double at(const Eigen::VectorXd& x) const { return D[(nearest(x(0)) * n + nearest(x(1))) * n + nearest(x(2))]; }
};

Grid exhaustiveGrid(const std::vector<ResponseModel>& rs, const std::vector<GoalSpec>& goals, int intervals) {
  Grid g{intervals + 1, 2.0 / intervals, {}, -1, {}, 0};
  g.D.resize(static_cast<std::size_t>(g.n) * g.n * g.n);
  for (int i = 0; i < g.n; ++i)
    for (int j = 0; j < g.n; ++j)
      for (int l = 0; l < g.n; ++l) {
        const Eigen::Vector3d x(g.coord(i), g.coord(j), g.coord(l));
        const double d = overallAt(rs, goals, x);
        g.D[(i * g.n + j) * g.n + l] = d;
        if (d > g.best) {
          g.best = d;
          g.bestPoint = x;
        }
      }
  for (int i = 0; i < g.n; ++i)
    for (int j = 0; j < g.n; ++j)
      for (int l = 0; l < g.n; ++l) {
        const double d = g.D[(i * g.n + j) * g.n + l];
        if (i + 1 < g.n) g.maxStep = std::max(g.maxStep, std::abs(d - g.D[((i + 1) * g.n + j) * g.n + l]));
        if (j + 1 < g.n) g.maxStep = std::max(g.maxStep, std::abs(d - g.D[(i * g.n + j + 1) * g.n + l]));
        if (l + 1 < g.n) g.maxStep = std::max(g.maxStep, std::abs(d - g.D[(i * g.n + j) * g.n + l + 1]));
      }
  return g;
}

// The checks shared by every case; returns the optimiser's best solution.
Solution checkAgainstGrid(const std::vector<ResponseModel>& rs, const std::vector<GoalSpec>& goals, int intervals) {
  const auto sols = optimizeDesirability(kFactors, rs, goals);
  REQUIRE(!sols.empty());
  const Solution& s = sols[0];
  const Grid grid = exhaustiveGrid(rs, goals, intervals);
  // D changes by at most maxStep per grid step; the nearest grid point is half a step away in each
  // of the 3 coordinates, so within 3 * maxStep / 2 (taken as 3 * maxStep for curvature).
  const double gridTolerance = 3.0 * grid.maxStep;
  INFO("optimiser D = " << s.overall << " at " << s.coded.transpose() << "; grid best D = " << grid.best
                        << " at " << grid.bestPoint.transpose() << " (h = " << grid.h << ")");
  CHECK(s.coded.cwiseAbs().maxCoeff() <= 1.0);
  CHECK(s.overall == Approx(overallAt(rs, goals, s.coded)).margin(1e-12));  // reported D is D at the point
  CHECK(s.overall >= grid.best - 1e-7);                                      // no grid point is better
  CHECK(grid.at(s.coded) >= grid.best - gridTolerance);                       // the grid agrees on the place
  CHECK(s.overall <= grid.best + gridTolerance);                              // and on the value
  return s;
}

GoalSpec target(const std::string& r, double lower, double t, double upper) {
  return GoalSpec{r, Goal::Target, lower, upper, t, 1, 1, 3};
}
GoalSpec maximize(const std::string& r, double lower, double upper) {
  return GoalSpec{r, Goal::Maximize, lower, upper, 0, 1, 1, 3};
}

}  // namespace

TEST_CASE("doe/optimizer: global optimum on a vertex, an edge, a face and inside", "[doe]") {
  SECTION("vertex (1, 1, 1)") {
    // y1 = A + B + C + 0.3 AB increases in every factor on the box: its maximum 3.3 is at (1,1,1),
    // below the upper limit 4, so d1 < 1 is largest there; y2 = A - C + 0.2 B^2 meets its target
    // 0.2 at that vertex (d2 = 1). D = sqrt(d1 d2) is largest there and nowhere else.
    const std::vector<ResponseModel> rs{quadratic("y1", {{"A", 1}, {"B", 1}, {"C", 1}, {"A:B", 0.3}}),
                                        quadratic("y2", {{"A", 1}, {"C", -1}, {"B^2", 0.2}})};
    const std::vector<GoalSpec> goals{maximize("y1", -4, 4), target("y2", -3, 0.2, 3)};
    const auto s = checkAgainstGrid(rs, goals, 80);
    CHECK((s.coded - Eigen::Vector3d(1, 1, 1)).cwiseAbs().maxCoeff() < 1e-6);
    CHECK(s.overall == Approx(std::sqrt(7.3 / 8.0)).epsilon(1e-9));
  }
  SECTION("edge A = B = 1, C = 0.4, two target goals") {
    // y1 = A + B + 0.1 AB is largest (2.1) at A = B = 1, short of its target 3: d1 = 5.1/6 there
    // and less elsewhere. y2 = C + 0.3 A - 0.2 B + 0.5 C^2 meets its target 0.58 at A = B = 1 only
    // with C = 0.4 (C + 0.5 C^2 increases on [-1, 1]).
    const std::vector<ResponseModel> rs{quadratic("y1", {{"A", 1}, {"B", 1}, {"A:B", 0.1}}),
                                        quadratic("y2", {{"C", 1}, {"A", 0.3}, {"B", -0.2}, {"C^2", 0.5}})};
    const std::vector<GoalSpec> goals{target("y1", -3, 3, 3.5), target("y2", -2, 0.58, 2)};
    const auto s = checkAgainstGrid(rs, goals, 80);
    CHECK((s.coded - Eigen::Vector3d(1, 1, 0.4)).cwiseAbs().maxCoeff() < 1e-4);
    CHECK(s.overall == Approx(std::sqrt(5.1 / 6.0)).epsilon(1e-6));
  }
  SECTION("face A = -1, B = 0.2, C = -0.4") {
    // y1 = -2A - (B - 0.2)^2 - (C + 0.4)^2 has its unique box maximum 2 at (-1, 0.2, -0.4), below
    // the upper limit 3; y2 = B + C + 0.5 AB meets its target -0.3 there.
    const std::vector<ResponseModel> rs{
        quadratic("y1", {{"Intercept", -0.2}, {"A", -2}, {"B", 0.4}, {"C", -0.8}, {"B^2", -1}, {"C^2", -1}}),
        quadratic("y2", {{"B", 1}, {"C", 1}, {"A:B", 0.5}})};
    const std::vector<GoalSpec> goals{maximize("y1", -8, 3), target("y2", -2, -0.3, 2)};
    const auto s = checkAgainstGrid(rs, goals, 80);
    CHECK((s.coded - Eigen::Vector3d(-1, 0.2, -0.4)).cwiseAbs().maxCoeff() < 1e-3);
    CHECK(s.overall == Approx(std::sqrt(10.0 / 11.0)).epsilon(1e-6));
  }
  SECTION("inside (0.1, -0.3, 0.5)") {
    // y1 = -(A - 0.1)^2 - (B + 0.3)^2 - (C - 0.5)^2 peaks (0) at (0.1, -0.3, 0.5), below its upper
    // limit 1; y2 = A + B + C + 0.3 AC meets its target 0.315 there.
    const std::vector<ResponseModel> rs{
        quadratic("y1", {{"Intercept", -0.35}, {"A", 0.2}, {"B", -0.6}, {"C", 1.0}, {"A^2", -1}, {"B^2", -1}, {"C^2", -1}}),
        quadratic("y2", {{"A", 1}, {"B", 1}, {"C", 1}, {"A:C", 0.3}})};
    const std::vector<GoalSpec> goals{maximize("y1", -10, 1), target("y2", -4, 0.315, 4)};
    const auto s = checkAgainstGrid(rs, goals, 80);
    CHECK((s.coded - Eigen::Vector3d(0.1, -0.3, 0.5)).cwiseAbs().maxCoeff() < 1e-3);
    CHECK(s.overall == Approx(std::sqrt(10.0 / 11.0)).epsilon(1e-6));
  }
}

TEST_CASE("doe/optimizer: global optimum of random quadratics fitted to a Box-Behnken design", "[doe]") {
  // Each response is a random quadratic (coefficients N(0, 1)) observed with noise on the 17-run
  // Box-Behnken design and fitted by least squares, as `paddy doe analyze` does. Two target goals:
  // one target inside the response's range over the box, one beyond its largest value (which
  // pushes the optimum to the boundary), limits half a range outside.
  const Design bbd = boxBehnken(3, 5);
  const Model model = Model::quadratic(kNames);
  const Eigen::MatrixXd X = model.matrix(bbd.coded);
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    DYNAMIC_SECTION("seed " << seed) {
      std::mt19937_64 rng(seed);
      std::normal_distribution<double> normal(0.0, 1.0);
      std::vector<ResponseModel> rs;
      std::vector<GoalSpec> goals;
      for (int r = 0; r < 2; ++r) {
        Eigen::VectorXd truth(model.p());
        for (int i = 0; i < model.p(); ++i) truth(i) = normal(rng);
        Eigen::VectorXd y = X * truth;
        for (int i = 0; i < y.size(); ++i) y(i) += 0.05 * normal(rng);
        const std::string name = "y" + std::to_string(r + 1);
        ResponseModel m{name, model, leastSquares(X, y, model.termNames()).beta, y.minCoeff(), y.maxCoeff()};
        // range of the fitted response over the box (from a coarse scan)
        double lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i <= 20; ++i)
          for (int j = 0; j <= 20; ++j)
            for (int l = 0; l <= 20; ++l) {
              const double v = m.predict(Eigen::Vector3d(-1 + 0.1 * i, -1 + 0.1 * j, -1 + 0.1 * l));
              lo = std::min(lo, v);
              hi = std::max(hi, v);
            }
        const double span = hi - lo;
        const double t = r == 0 ? lo + std::uniform_real_distribution<double>(0.2, 0.8)(rng) * span : hi + 0.25 * span;
        goals.push_back(target(name, lo - 0.5 * span, t, hi + 0.5 * span));
        rs.push_back(m);
      }
      checkAgainstGrid(rs, goals, 60);
    }
  }
}

TEST_CASE("doe/optimizer: the Lua optimize (used by the calibration) finds the edge optimum", "[doe]") {
  // The edge case above through paddy.doe.optimize on a fit analysed from exact data.
  lua_State* L = luaL_newstate();
  luaL_openlibs(L);
  luaL_requiref(L, "paddy.doe", luaopen_paddy_doe, 0);
  lua_pop(L, 1);
  const int rc = luaL_dostring(L, R"(
    local doe = require("paddy.doe")
    local d = doe.design{type = "bbd", names = {"A", "B", "C"}, center = 5,
                         levels = {A = {-1, 1}, B = {-1, 1}, C = {-1, 1}}}
    local data = {}
    for i, r in ipairs(d.runs) do
      local a, b, c = r.coded.A, r.coded.B, r.coded.C
      data[i] = {A = a, B = b, C = c, y1 = a + b + 0.1 * a * b, y2 = c + 0.3 * a - 0.2 * b + 0.5 * c * c}
    end
    local fit = doe.analyze{data = data, factors = {"A", "B", "C"}, responses = {"y1", "y2"}, model = "quadratic"}
    local s = doe.optimize{fit = fit, goals = {{response = "y1", goal = "target", target = 3, lower = -3, upper = 3.5},
                                               {response = "y2", goal = "target", target = 0.58, lower = -2, upper = 2}}}
    local x = s.solutions[1].factors
    assert(math.abs(x.A - 1) < 1e-6 and math.abs(x.B - 1) < 1e-6 and math.abs(x.C - 0.4) < 1e-4,
           string.format("optimum at A = %.6g, B = %.6g, C = %.6g", x.A, x.B, x.C))
    assert(math.abs(s.solutions[1].desirability - math.sqrt(5.1 / 6)) < 1e-6)
  )");
  std::string err = rc == LUA_OK ? "" : lua_tostring(L, -1);
  lua_close(L);
  CHECK(err == "");
}
