#include "paddy/doe/box_behnken.hpp"
#include "paddy/doe/central_composite.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/factorial.hpp"
#include "paddy/doe/model.hpp"
#include "paddy/doe/plackett_burman.hpp"
#include "paddy/doe/regression.hpp"
#include "paddy/doe/steepest_ascent.hpp"

#include <catch2/catch.hpp>
#include <map>

using namespace paddy::doe;

namespace {
bool fullRank(const Design& d, const Model& m) {
  try {
    leastSquares(m.matrix(d.coded), Eigen::VectorXd::Zero(d.runs()), m.termNames());
    return true;
  } catch (const DoeError&) {
    return false;
  }
}
std::vector<std::string> names(int k) {
  std::vector<std::string> v;
  for (const auto& f : defaultFactors(k)) v.push_back(f.name);
  return v;
}
}  // namespace

TEST_CASE("doe/designs: Plackett-Burman columns are balanced and orthogonal", "[doe]") {
  for (int n : {8, 12, 16, 20, 24}) {
    INFO("N = " << n);
    const Design d = plackettBurman(n);
    REQUIRE(d.runs() == n);
    REQUIRE(d.k() == n - 1);
    const Eigen::MatrixXd xtx = d.coded.transpose() * d.coded;
    CHECK((xtx - n * Eigen::MatrixXd::Identity(n - 1, n - 1)).cwiseAbs().maxCoeff() == 0.0);
    CHECK(d.coded.colwise().sum().cwiseAbs().maxCoeff() == 0.0);
    CHECK(d.coded.row(n - 1).sum() == -(n - 1));
  }
  CHECK(plackettBurman(12, 7).k() == 7);
  CHECK(plackettBurmanRunsFor(7) == 8);
  CHECK(plackettBurmanRunsFor(11) == 12);
  CHECK_THROWS_AS(plackettBurman(10), DoeError);
}

TEST_CASE("doe/designs: full and fractional factorials", "[doe]") {
  const Design f = fullFactorial(3);
  CHECK(f.runs() == 8);
  CHECK(f.coded.row(0) == Eigen::RowVector3d(-1, -1, -1));
  CHECK(f.coded.row(1) == Eigen::RowVector3d(1, -1, -1));  // standard order: A fastest
  const Design h = fractionalFactorial(4, {"D=ABC"});
  CHECK(h.runs() == 8);
  for (int i = 0; i < 8; ++i) CHECK(h.coded(i, 3) == h.coded(i, 0) * h.coded(i, 1) * h.coded(i, 2));
  CHECK((h.coded.transpose() * h.coded - 8 * Eigen::MatrixXd::Identity(4, 4)).norm() == 0.0);
  const Design q = fractionalFactorial(5, {"D=-AB", "E=AC"});
  CHECK(q.runs() == 8);
  for (int i = 0; i < 8; ++i) CHECK(q.coded(i, 3) == -q.coded(i, 0) * q.coded(i, 1));
  CHECK_THROWS_WITH(fractionalFactorial(4, {"D=AZ"}), Catch::Contains("not a basic factor"));
  // AB and CD are aliased in the resolution IV half fraction I = ABCD: singular, aliases named
  const Model m = Model::parse(names(4), "A,B,C,D,A:B,C:D");
  CHECK_THROWS_WITH(leastSquares(m.matrix(h.coded), Eigen::VectorXd::Zero(8), m.termNames()),
                    Catch::Contains("singular") && (Catch::Contains("A:B") || Catch::Contains("C:D")));
}

TEST_CASE("doe/designs: Box-Behnken run counts and balance for 3 to 7 factors", "[doe]") {
  const int expected[] = {0, 0, 0, 12, 24, 40, 48, 56};
  for (int k = 3; k <= 7; ++k) {
    INFO("k = " << k);
    const Design d = boxBehnken(k, 3);
    CHECK(d.runs() == expected[k] + 3);
    const Eigen::MatrixXd e = d.coded.topRows(expected[k]);
    CHECK(e.colwise().sum().cwiseAbs().maxCoeff() == 0.0);                       // each factor balanced
    CHECK((e.array().abs() > 0.5).colwise().count().minCoeff() ==
          (e.array().abs() > 0.5).colwise().count().maxCoeff());                   // equal use of factors
    const Eigen::MatrixXd xtx = e.transpose() * e;                                  // orthogonal main effects
    CHECK((xtx - Eigen::MatrixXd(xtx.diagonal().asDiagonal())).cwiseAbs().maxCoeff() == 0.0);
    CHECK(e.cwiseAbs().maxCoeff() == 1.0);
    CHECK(fullRank(d, Model::quadratic(names(k))));                                // full quadratic estimable
  }
  // k = 7 uses a balanced incomplete block design: every pair of factors shares exactly one block
  std::map<std::pair<int, int>, int> pairs;
  for (const auto& blk : boxBehnkenBlocks(7))
    for (std::size_t i = 0; i < blk.size(); ++i)
      for (std::size_t j = i + 1; j < blk.size(); ++j) ++pairs[{std::min(blk[i], blk[j]), std::max(blk[i], blk[j])}];
  CHECK(pairs.size() == 21);
  for (const auto& [pr, count] : pairs) CHECK(count == 1);
  const Design b = boxBehnken(3, 5);  // the reference study's design: 12 edge points + 5 centre points
  CHECK(b.runs() == 17);
  CHECK_THROWS_AS(boxBehnken(2, 1), DoeError);
  CHECK_THROWS_AS(boxBehnken(8, 1), DoeError);
}

TEST_CASE("doe/designs: central composite alpha values and variants", "[doe]") {
  CHECK(rotatableAlpha(4) == Approx(1.414213562));
  CHECK(rotatableAlpha(8) == Approx(1.681792831));
  CHECK(rotatableAlpha(16) == Approx(2.0));
  CcdOptions o;
  o.centerPoints = 5;
  const Design c = centralComposite(2, o);
  CHECK(c.runs() == 13);
  CHECK(c.coded.col(0).maxCoeff() == Approx(std::sqrt(2.0)));
  // rotatable: the fourth moment sum x_i^4 = 3 sum x_i^2 x_j^2 over the non-centre points
  const Design c3 = centralComposite(3, o);
  CHECK(c3.runs() == 8 + 6 + 5);
  const double m4 = c3.coded.col(0).array().pow(4).sum();
  const double m22 = (c3.coded.col(0).array().square() * c3.coded.col(1).array().square()).sum();
  CHECK(m4 == Approx(3 * m22));
  o.type = CcdType::Inscribed;
  const Design ci = centralComposite(3, o);
  CHECK(ci.coded.cwiseAbs().maxCoeff() == Approx(1.0));
  CHECK(ci.coded(0, 0) == Approx(-1.0 / std::pow(8.0, 0.25)));
  o.type = CcdType::FaceCentred;
  CHECK(centralComposite(3, o).coded.cwiseAbs().maxCoeff() == 1.0);
  o.type = CcdType::Circumscribed;
  o.alpha = 1.5;
  CHECK(centralComposite(2, o).coded.col(1).maxCoeff() == 1.5);
  o.alpha.reset();
  o.generators = {"E=ABCD"};
  const Design half = centralComposite(5, o);
  CHECK(half.runs() == 16 + 10 + 5);
  CHECK(half.coded.col(0).maxCoeff() == Approx(2.0));  // alpha = 16^(1/4)
  CHECK(fullRank(half, Model::quadratic(names(5))));
}

TEST_CASE("doe/designs: coding, replicates, centre points and seeded randomisation", "[doe]") {
  Factor f{"T", 170, 180};
  CHECK(f.toCoded(170) == -1.0);
  CHECK(f.toCoded(182.07) == Approx(1.414));
  CHECK(f.toReal(0.5) == 177.5);
  Design d = fullFactorial(2);
  addCenterPoints(d, 2);
  d = replicate(d, 3);
  CHECK(d.runs() == 18);
  CHECK(std::count(d.type.begin(), d.type.end(), PointType::Center) == 6);
  Design r1 = d, r2 = d, r3 = d;
  randomize(r1, 42);
  randomize(r2, 42);
  randomize(r3, 43);
  CHECK(r1.coded == r2.coded);
  CHECK(r1.stdOrder == r2.stdOrder);
  CHECK(r1.stdOrder != r3.stdOrder);
  CHECK(r1.coded.sum() == Approx(d.coded.sum()));
  for (int i = 0; i < r1.runs(); ++i) CHECK(r1.coded.row(i) == d.coded.row(r1.stdOrder[i] - 1));
  std::vector<int> sorted = r1.stdOrder;
  std::sort(sorted.begin(), sorted.end());
  CHECK(sorted.front() == 1);
  CHECK(sorted.back() == 6);
}

TEST_CASE("doe/designs: steepest ascent by Montgomery's key-factor rule", "[doe]") {
  // Montgomery Example 11.1: yhat = 40.44 + 0.775 x1 + 0.325 x2; time 30..40 min (h = 5),
  // temperature 150..160 F (h = 5); key factor time with a 5 min step: dx1 = 1, dx2 = 0.42.
  std::vector<Factor> f{{"time", 30, 40}, {"temp", 150, 160}};
  PathOptions o;
  o.keyStep = 5.0;
  o.keyStepReal = true;
  o.steps = 3;
  const auto p = steepestPath(f, Eigen::Vector2d(0.775, 0.325), o);
  CHECK(p[1].coded(0) == Approx(1.0));
  CHECK(p[1].coded(1) == Approx(0.325 / 0.775));
  CHECK(p[1].real(0) == Approx(40.0));
  CHECK(p[1].real(1) == Approx(155 + 5 * 0.325 / 0.775));
  CHECK(p[3].real(0) == Approx(50.0));
  o.ascent = false;
  CHECK(steepestPath(f, Eigen::Vector2d(0.775, 0.325), o)[1].real(0) == Approx(30.0));
}
