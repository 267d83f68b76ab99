// Published examples with known answers.
#include "paddy/doe/analysis.hpp"
#include "paddy/doe/regression.hpp"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

using namespace paddy::doe;

namespace {
// Montgomery, Design and Analysis of Experiments, Example 11.2 (chemical process, rotatable CCD,
// 5 centre points): time 80..90 min and temperature 170..180 F coded -1..+1, yield (%). The book's
// table prints the axial points as +-1.414 (92.07, 77.93 ...); its Design-Expert output was
// computed with the exact rotatable alpha sqrt(2), which is what reproduces the printed ANOVA.
std::string montgomery112() {
  const std::string a = std::to_string(std::sqrt(2.0));
  return "time,temp,yield\n"
         "-1,-1,76.5\n-1,1,77.0\n1,-1,78.0\n1,1,79.5\n"
         "0,0,79.9\n0,0,80.3\n0,0,80.0\n0,0,79.7\n0,0,79.8\n" +
         a + ",0,78.4\n-" + a + ",0,75.6\n0," + a + ",78.5\n0,-" + a + ",77.0\n";
}

const char* kLongley =
    // NIST StRD "Longley" (Longley 1967): y = total employment, x1..x6 = GNP deflator, GNP,
    // unemployed, armed forces, population, year.
    "y,x1,x2,x3,x4,x5,x6\n"
    "60323,83.0,234289,2356,1590,107608,1947\n"
    "61122,88.5,259426,2325,1456,108632,1948\n"
    "60171,88.2,258054,3682,1616,109773,1949\n"
    "61187,89.5,284599,3351,1650,110929,1950\n"
    "63221,96.2,328975,2099,3099,112075,1951\n"
    "63639,98.1,346999,1932,3594,113270,1952\n"
    "64989,99.0,365385,1870,3547,115094,1953\n"
    "63761,100.0,363112,3578,3350,116219,1954\n"
    "66019,101.2,397469,2904,3048,117388,1955\n"
    "67857,104.6,419180,2822,2857,118734,1956\n"
    "68169,108.4,442769,2936,2798,120445,1957\n"
    "66513,110.8,444546,4681,2637,121950,1958\n"
    "68655,112.6,482704,3813,2552,123366,1959\n"
    "69564,114.2,502601,3931,2514,125368,1960\n"
    "69331,115.7,518173,4806,2572,127852,1961\n"
    "70551,116.9,554894,4007,2827,130081,1962\n";
}  // namespace

TEST_CASE("doe/published: Montgomery Example 11.2 CCD, quadratic model for yield", "[doe]") {
  AnalysisRequest req;
  req.factors = {"time", "temp"};
  req.responses = {"yield"};
  req.model = "quadratic";
  req.levels = {{"time", {-1, 1}}, {"temp", {-1, 1}}};  // the data are already coded
  const Analysis a = analyzeTable(parseCsv(montgomery112(), "ex11_2"), req);
  const auto& r = a.responses[0];
  // fitted model (book): 79.94 + 0.995 x1 + 0.515 x2 + 0.25 x1x2 - 1.376 x1^2 - 1.001 x2^2
  const std::vector<std::pair<std::string, double>> coef{{"Intercept", 79.94}, {"time", 0.995}, {"temp", 0.515},
                                                         {"time:temp", 0.25}, {"time^2", -1.376}, {"temp^2", -1.001}};
  for (std::size_t i = 0; i < coef.size(); ++i) {
    INFO(coef[i].first);
    CHECK(r.coefficients[i].term == coef[i].first);
    CHECK(r.coefficients[i].estimate == Approx(coef[i].second).margin(0.0006));
  }
  // ANOVA (book): Model 28.25 (5), A 7.92, B 2.12, AB 0.25, A^2 13.18, B^2 6.97,
  // Residual 0.50 (7), Lack of fit 0.28 (3), Pure error 0.21 (4), Total 28.74 (12)
  const std::vector<std::tuple<std::string, double, int>> ss{
      {"Model", 28.25, 5},    {"time", 7.92, 1},       {"temp", 2.12, 1},     {"time:temp", 0.25, 1},
      {"time^2", 13.18, 1},   {"temp^2", 6.97, 1},     {"Residual", 0.50, 7}, {"Lack of Fit", 0.28, 3},
      {"Pure Error", 0.21, 4}, {"Total", 28.74, 12}};
  for (const auto& [src, value, df] : ss) {
    INFO(src);
    REQUIRE(r.row(src) != nullptr);
    CHECK(r.row(src)->ss == Approx(value).margin(0.005));
    CHECK(r.row(src)->df == df);
  }
  CHECK(r.row("Model")->F == Approx(79.85).margin(0.005));
  CHECK(r.row("Model")->p < 1e-4);
  CHECK(r.row("Lack of Fit")->F == Approx(1.78).margin(0.005));
  CHECK(r.row("Lack of Fit")->p == Approx(0.2897).margin(0.00005));
  // rotatable-ish CCD with alpha 1.414: VIF of the squares is slightly above 1, linear terms 1
  CHECK(r.coefficients[1].vif == Approx(1.0).margin(1e-3));
}

TEST_CASE("doe/published: NIST StRD Longley certified values", "[doe]") {
  AnalysisRequest req;
  req.factors = {"x1", "x2", "x3", "x4", "x5", "x6"};
  req.responses = {"y"};
  req.model = "linear";
  const Analysis a = analyzeTable(parseCsv(kLongley, "longley"), req);
  const auto& r = a.responses[0];
  Eigen::VectorXd c(6), h(6);
  for (int j = 0; j < 6; ++j) c(j) = a.factors[j].center(), h(j) = a.factors[j].halfRange();
  const auto actual = actualCoefficients(r.model, r.beta, c, h);
  const double certified[7] = {-3482258.63459582, 15.0618722713733,  -0.358191792925910e-1, -2.02022980381683,
                               -1.03322686717359,  -0.511041056535807e-1, 1829.15146461355};
  const double certifiedSd[7] = {890420.383607373, 84.9149257747669,  0.334910077722432e-1, 0.488399681651699,
                                 0.214274163161675, 0.226073200069370, 455.478499142212};
  for (int i = 0; i < 7; ++i) {
    INFO("B" << i);
    CHECK(actual[i].coefficient == Approx(certified[i]).epsilon(1e-7));
    if (i > 0) CHECK(r.coefficients[i].se / h(i - 1) == Approx(certifiedSd[i]).epsilon(1e-7));
  }
  CHECK(r.stdDev == Approx(304.854073561965).epsilon(1e-9));
  CHECK(r.r2 == Approx(0.995479004577296).epsilon(1e-9));
  CHECK(r.row("Model")->ss == Approx(184172401.944494).epsilon(1e-9));
  CHECK(r.row("Residual")->ss == Approx(836424.055505915).epsilon(1e-8));
  CHECK(r.row("Model")->F == Approx(330.285339234588).epsilon(1e-8));

  // The same regression directly in raw (uncoded) units, including the intercept's certified SD.
  const Table t = parseCsv(kLongley, "longley");
  Eigen::MatrixXd X(16, 7);
  X.col(0).setOnes();
  for (int j = 0; j < 6; ++j) X.col(j + 1) = t.numeric("x" + std::to_string(j + 1));
  const auto ls = leastSquares(X, t.numeric("y"), {"b0", "b1", "b2", "b3", "b4", "b5", "b6"});
  for (int i = 0; i < 7; ++i) {
    INFO("raw B" << i);
    CHECK(ls.beta(i) == Approx(certified[i]).epsilon(1e-7));
    CHECK(std::sqrt(ls.sse / 9.0 * ls.xtxInv(i, i)) == Approx(certifiedSd[i]).epsilon(1e-6));
  }
}
