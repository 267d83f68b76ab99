#include "doe_test_util.hpp"
#include "paddy/doe/analysis.hpp"
#include "paddy/doe/cli.hpp"
#include "paddy/doe/error.hpp"
#include "paddy/doe/plots.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

using namespace paddy::doe;

namespace {
AnalysisRequest request(std::vector<std::string> f, std::vector<std::string> r, std::string model) {
  AnalysisRequest q;
  q.factors = std::move(f);
  q.responses = std::move(r);
  q.model = std::move(model);
  return q;
}

int cli(std::vector<std::string> args, std::string* out = nullptr, std::string* err = nullptr) {
  args.insert(args.begin(), "doe");
  std::ostringstream o, e;
  const int rc = runCli(args, o, e);
  if (out) *out = o.str();
  if (err) *err = e.str();
  return rc;
}

void write(const std::filesystem::path& p, const std::string& s) { std::ofstream(p) << s; }
}  // namespace

TEST_CASE("doe/errors: bad CSV cells name the row and the column", "[doe]") {
  const Table t = parseCsv("A,B,y\n1,2,3\n-1,,4\n1,x,5\n", "bad.csv");
  CHECK_THROWS_WITH(t.numeric("B"), Catch::Contains("row 2") && Catch::Contains("'B'") && Catch::Contains("missing"));
  const Table u = parseCsv("A,B,y\n1,2,3\n-1,1,4\n1,abc,5\n", "bad.csv");
  CHECK_THROWS_WITH(u.numeric("B"), Catch::Contains("row 3") && Catch::Contains("'abc' is not a finite number"));
  CHECK_THROWS_WITH(parseCsv("A,B\n1,2,3\n", "x.csv"), Catch::Contains("3 fields but the header has 2"));
  CHECK_THROWS_WITH(analyzeTable(t, request({"A", "C"}, {"y"}, "linear")),
                    Catch::Contains("no column named 'C'") && Catch::Contains("available columns: A, B, y"));
}

TEST_CASE("doe/csv: quoted fields hold commas and quotes, blanks around a field are dropped", "[doe]") {
  using V = std::vector<std::string>;
  CHECK(splitCsvLine("1,2,3", "x") == V{"1", "2", "3"});
  CHECK(splitCsvLine(" a , b ,", "x") == V{"a", "b", ""});
  CHECK(splitCsvLine("1,\"run 1, replicate 2\",3", "x") == V{"1", "run 1, replicate 2", "3"});
  CHECK(splitCsvLine("1, \"x, y\" ,3", "x") == V{"1", "x, y", "3"});         // blanks outside the quotes
  CHECK(splitCsvLine("\"q\"\"r\",,\" kept \"", "x") == V{"q\"r", "", " kept "});  // doubled quote, inner blanks
  CHECK_THROWS_WITH(splitCsvLine("1,\"open", "f.csv line 4"), Catch::Contains("f.csv line 4: unterminated quoted field"));
  const Table t = parseCsv("label,y\n\"run 1, replicate 1\",2\n", "q.csv");
  CHECK(t.cells[0][0] == "run 1, replicate 1");
  CHECK(t.numeric("y")(0) == 2.0);
}

TEST_CASE("doe/errors: too many terms, singular designs, saturated models", "[doe]") {
  const Table t = parseCsv("A,B,C,y\n-1,-1,-1,1\n1,-1,1,2\n-1,1,1,3\n1,1,-1,4\n0,0,0,2\n", "t.csv");
  CHECK_THROWS_WITH(analyzeTable(t, request({"A", "B", "C"}, {"y"}, "quadratic")),
                    Catch::Contains("10 terms but only 5 runs"));
  // C = -A*B in this half fraction: A:B is aliased with C
  CHECK_THROWS_WITH(analyzeTable(t, request({"A", "B", "C"}, {"y"}, "A,B,C,A:B")),
                    Catch::Contains("singular") && Catch::Contains("aliased"));
  const Table s = parseCsv("A,B,y\n-1,-1,1\n1,1,2\n-1,-1,3\n1,1,4\n0,0,5\n", "s.csv");  // B == A
  CHECK_THROWS_WITH(analyzeTable(s, request({"A", "B"}, {"y"}, "linear")), Catch::Contains("singular"));
  const Table sat = parseCsv("A,B,y\n-1,-1,1\n1,-1,2\n-1,1,3\n", "sat.csv");
  CHECK_THROWS_WITH(analyzeTable(sat, request({"A", "B"}, {"y"}, "linear")),
                    Catch::Contains("no residual degrees of freedom"));
  CHECK_THROWS_WITH(analyzeTable(t, request({"A", "B"}, {"y"}, "A,D")), Catch::Contains("unknown factor 'D'"));
  CHECK_THROWS_WITH(analyzeTable(t, request({"A", "B"}, {"y"}, "cubic")), Catch::Contains("unknown factor"));
  const Table c = parseCsv("A,y\n1,1\n1,2\n", "c.csv");
  CHECK_THROWS_WITH(analyzeTable(c, request({"A"}, {"y"}, "linear")), Catch::Contains("does not vary"));
}

TEST_CASE("doe/cli: design, analyze, optimize, path and bad input", "[doe]") {
  const auto dir = doe_test::tempDir("cli");
  const std::string csv = (dir / "bbd.csv").string();
  std::string out, err;
  REQUIRE(cli({"design", "bbd", "--names", "A,B,C", "--levels", "A=0.07:0.13", "B=0.4:0.6", "C=0.07:0.13",
               "--center", "5", "--seed", "7", "--csv", csv},
              &out, &err) == 0);
  const Table d = readCsv(csv);
  CHECK(d.rows() == 17);
  CHECK(d.numeric("A").maxCoeff() == Approx(0.13));
  CHECK(d.numeric("B_coded").minCoeff() == -1.0);

  // add a response with a known quadratic and analyse it
  std::string data = "A,B,C,y\n";
  for (int i = 0; i < d.rows(); ++i) {
    const double a = d.numeric("A_coded")(i), b = d.numeric("B_coded")(i), c = d.numeric("C_coded")(i);
    const double y = 240 - 6 * a - 8 * b + 2 * c + 1.5 * a * b - 3 * a * a + 0.01 * ((i * 7) % 5 - 2);
    data += d.cells[i][d.columnIndex("A")] + "," + d.cells[i][d.columnIndex("B")] + "," + d.cells[i][d.columnIndex("C")] +
            "," + std::to_string(y) + "\n";
  }
  write(dir / "data.csv", data);
  const std::string fit = (dir / "fit.json").string();
  REQUIRE(cli({"analyze", (dir / "data.csv").string(), "--factors", "A,B,C", "--responses", "y", "--model",
               "quadratic", "--json", fit},
              &out, &err) == 0);
  CHECK_THAT(out, Catch::Contains("Lack of Fit") && Catch::Contains("Pure Error") && Catch::Contains("Adeq Precision"));
  nlohmann::json j;
  std::ifstream(fit) >> j;
  CHECK(j["responses"]["y"]["coefficients"]["A:B"].get<double>() == Approx(1.5).margin(0.02));
  CHECK(j["responses"]["y"]["coefficients"]["A^2"].get<double>() == Approx(-3).margin(0.03));
  CHECK(j["responses"]["y"]["anova"][0]["source"] == "Model");
  CHECK(j["responses"]["y"]["r2"].get<double>() > 0.99);

  const std::string sol = (dir / "sol.json").string();
  REQUIRE(cli({"optimize", fit, "--goal", "y=target:241", "--json", sol}, &out, &err) == 0);
  nlohmann::json s;
  std::ifstream(sol) >> s;
  REQUIRE(!s["solutions"].empty());
  CHECK(s["solutions"][0]["desirability"].get<double>() == Approx(1.0).margin(1e-4));
  CHECK(s["solutions"][0]["predicted"]["y"].get<double>() == Approx(241).margin(0.01));
  const double a0 = s["solutions"][0]["factors"]["A"].get<double>();
  CHECK(a0 >= 0.07 - 1e-9);
  CHECK(a0 <= 0.13 + 1e-9);
  REQUIRE(cli({"optimize", fit, "--goal", "y=max", "--bounds", "A=0.08:0.09", "--json", sol}, &out, &err) == 0);
  std::ifstream(sol) >> s;
  CHECK(s["solutions"][0]["factors"]["A"].get<double>() <= 0.09 + 1e-9);

  REQUIRE(cli({"path", fit, "--response", "y", "--descent", "--steps", "2"}, &out, &err) == 0);
  CHECK_THAT(out, Catch::Contains("step,A,B,C,y_predicted"));

  // bad input: exit code 2 and a clear message
  CHECK(cli({"analyze", (dir / "data.csv").string(), "--factors", "A,Q", "--responses", "y"}, &out, &err) == 2);
  CHECK_THAT(err, Catch::Contains("no column named 'Q'") && Catch::Contains("available columns: A, B, C, y"));
  CHECK(cli({"optimize", fit, "--goal", "z=max"}, &out, &err) == 2);
  CHECK_THAT(err, Catch::Contains("no response named 'z'"));
  CHECK(cli({"design", "xyz", "--factors", "3", "--csv", csv}, &out, &err) == 2);
  CHECK_THAT(err, Catch::Contains("unknown design"));
  CHECK(cli({"design", "bbd", "--factors", "3"}, &out, &err) == 2);  // --csv missing
  CHECK(cli({"analyze", (dir / "missing.csv").string(), "--factors", "A", "--responses", "y"}, &out, &err) == 2);
  CHECK_THAT(err, Catch::Contains("cannot open"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("doe/plots: gnuplot writes PNG and SVG files", "[doe]") {
  if (!gnuplotAvailable()) {
    WARN("gnuplot not installed; plot test skipped");
    return;
  }
  const auto dir = doe_test::tempDir("plots");
  const Table t = parseCsv("A,B,y\n-1,-1,1\n1,-1,3\n-1,1,2\n1,1,5\n0,0,2.6\n0,0,2.9\n1.4,0,4.1\n-1.4,0,1.2\n0,1.4,3\n0,-1.4,2\n",
                           "p.csv");
  const Analysis a = analyzeTable(t, request({"A", "B"}, {"y"}, "quadratic"));
  const auto files = plotAnalysis(dir.string(), a);
  CHECK(files.size() == 10);  // pareto, pred/actual, normal, surface, contour x (png, svg)
  for (const auto& f : files) CHECK(std::filesystem::file_size(f) > 1000);
  std::filesystem::remove_all(dir);
}
