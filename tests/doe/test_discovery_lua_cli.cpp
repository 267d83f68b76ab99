// The discovery statistics through Lua (paddy.doe.noise_covariance, diagnose, gauss_newton,
// compare_fits, null_thresholds, bootstrap_thresholds) and the command line (paddy doe diagnose).
#include "doe_lua_state.hpp"
#include "doe_test_util.hpp"
#include "paddy/doe/cli.hpp"

#include <catch2/catch.hpp>
#include <fstream>
#include <lua.hpp>
#include <nlohmann/json.hpp>
#include <sstream>

namespace {
// The hand-worked example of test_discovery_score.cpp, plus a second, unrelated candidate.
const char* kInput = R"({
  "residual": [1, 2, 6], "sigma": [1, 1, 1], "jacobian": [[1], [1], [1]],
  "candidates": [{"name": "wall_adhesion", "signature": [0, 0, 1], "low": 0, "high": 10},
                 {"name": "lubrication", "signature": [1, -1, 0], "low": 0, "high": 10}],
  "labels": ["slump", "flow", "torque"], "blocks": ["slump", "slump", "rheometer"]})";
}  // namespace

TEST_CASE("discovery/lua: the workflow's API", "[doe][discovery]") {
  doe_test::LuaState lua;
  const std::string ok = lua.run(R"(
    local doe = require("paddy.doe")
    local cov = doe.noise_covariance{replicates = {{1, 2, 0}, {2, 1, 1}, {3, 4, 1}, {6, 5, 2}}, sigma = {0.5, 0, 1}, n_avg = 2}
    assert(math.abs(cov.shrinkage - 1/3) < 1e-12, cov.shrinkage)
    assert(#cov.covariance == 3 and #cov.covariance[1] == 3 and #cov.seed_sd == 3)
    assert(math.abs(cov.covariance[1][1] - (0.25 + 14/3/2)) < 1e-12)
    local d = doe.diagnose{residual = {1, 2, 6}, sigma = {1, 1, 1}, jacobian = {{1}, {1}, {1}},
                           candidates = {{name = "wall_adhesion", signature = {0, 0, 1}, low = 0, high = 10}},
                           labels = {"slump", "flow", "torque"}}
    assert(math.abs(d.q0 - 14) < 1e-12 and d.q0_df == 2)
    local c = d.candidates[1]
    assert(c.name == "wall_adhesion" and math.abs(c.strength - 4.5) < 1e-12 and math.abs(c.a - 2/3) < 1e-12)
    assert(math.abs(c.z - 3 / math.sqrt(2/3)) < 1e-12 and c.identifiable == true)
    assert(c.p_holm >= c.p and c.q_after_p > 0 and c.bayes_factor > 1)
    assert(d.decision == "effect" and d.named == "wall_adhesion", d.decision)
    assert(#d.whitened_residual == 3 and #d.projected_residual == 3 and #d.confusability == 1)
    assert(d.residual_map[3].label == "torque")
    assert(c.z_relevant == c.z and c.p_relevant == c.p)
    -- a smallest relevant strength of 4: lambda^ = 4.5 is not far enough above it to name the effect,
    -- and the misfit (Q0 = 14 on 2 df) stays significant: unknown
    local dr = doe.diagnose{residual = {1, 2, 6}, sigma = {1, 1, 1}, jacobian = {{1}, {1}, {1}},
                            candidates = {{name = "wall_adhesion", signature = {0, 0, 1}, low = 0, high = 10, relevant = 4}}}
    local cr = dr.candidates[1]
    assert(math.abs(cr.z_relevant - 0.5 * math.sqrt(2/3)) < 1e-12 and cr.z == c.z, cr.z_relevant)
    assert(cr.passes == false and dr.decision == "unknown", dr.decision)
    assert(math.abs(d.misfit - math.sqrt(41/3)) < 1e-12)
    -- no free parameters (empty Jacobian table)
    local d0 = doe.diagnose{residual = {0.1, -0.2, 0.3}, sigma = {1, 1, 1}, jacobian = {}, candidates = {}}
    assert(d0.decision == "none" and d0.q0_df == 3 and d0.named == nil)
    local s = doe.gauss_newton{theta = {0, 0}, residual = {2, 1}, jacobian = {{1, 1}, {0, 1}},
                               lower = {-5, -5}, upper = {0.5, 5}}
    assert(math.abs(s.theta[1] - 0.5) < 1e-12 and math.abs(s.theta[2] - 1.25) < 1e-12)
    assert(#s.covariance == 2 and #s.se == 2 and s.misfit_predicted > 0)
    local lr = doe.compare_fits{q_before = 20, q_after = 10.3, df = 1, n = 30, k_before = 3, k_after = 4}
    assert(math.abs(lr.lr - 9.7) < 1e-12 and lr.p < 0.01 and math.abs(lr.delta_bic - (-9.7 + math.log(30))) < 1e-12)
    local t = doe.null_thresholds{z_max = {0.1, 0.5, 2.0, 1.0}, q0 = {10, 12, 30, 11}, alpha = 0.25}
    assert(t.z_threshold == 1.0 and t.q0_threshold == 12 and t.alarms == 1)
    -- Bootstrap thresholds: Sigma of 6 observables from 5 replicates widens Q0 well past the
    -- chi^2(5) table's 95 % point (11.07); the same seed gives the same thresholds.
    local I = {}
    for i = 1, 6 do I[i] = {}; for j = 1, 6 do I[i][j] = i == j and 1 or 0 end end
    local args = {seed_covariance = I, replicates = 5, jacobian = {{1}, {1}, {1}, {1}, {1}, {1}},
                  candidates = {{name = "a", signature = {1, -1, 0, 0, 1, -1}, low = 0, high = 10},
                                {name = "b", signature = {0, 0, 1, -1, 0, 0}, low = 0, high = 10}},
                  trials = 300, seed = 3}
    local b1, b2 = doe.bootstrap_thresholds(args), doe.bootstrap_thresholds(args)
    assert(b1.method == "bootstrap" and b1.trials == 300, b1.method)
    assert(b1.q0_threshold == b2.q0_threshold and b1.z_threshold == b2.z_threshold)
    assert(b1.q0_threshold > 11.07, b1.q0_threshold)
  )");
  CHECK(ok == "");
  CHECK_THAT(lua.run(R"(require("paddy.doe").bootstrap_thresholds{seed_covariance = {{1, 0}, {0, 1}}, replicates = 1})"),
             Catch::Contains("paddy.doe.bootstrap_thresholds") && Catch::Contains("replicates"));
  CHECK_THAT(lua.run(R"(require("paddy.doe").diagnose{residual = {1, 2}, sigma = {1, 1, 1}})"),
             Catch::Contains("paddy.doe.diagnose") && Catch::Contains("sigma: 3 entries"));
  CHECK_THAT(lua.run(R"(require("paddy.doe").diagnose{residual = {1, 2, 3}, covariance = {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}}})"),
             Catch::Contains("covariance: not positive definite"));
  CHECK_THAT(lua.run(R"(require("paddy.doe").diagnose{residual = {1, 0/0, 3}, sigma = {1, 1, 1}})"),
             Catch::Contains("residual[2]: not finite"));
  CHECK_THAT(lua.run(R"(require("paddy.doe").gauss_newton{theta = {0}, residual = {1, 2}, jacobian = {{1}, {1}}, lower = {1}})"),
             Catch::Contains("theta: parameter 1 = 0") && Catch::Contains("outside"));
}

TEST_CASE("discovery/cli: paddy doe diagnose", "[doe][discovery]") {
  const auto dir = doe_test::tempDir("diagnose");
  const std::string in = (dir / "input.json").string(), out = (dir / "out.json").string();
  std::ofstream(in) << kInput;
  std::ostringstream o, e;
  REQUIRE(paddy::doe::runCli({"doe", "diagnose", in, "--json", out}, o, e) == 0);
  CHECK_THAT(o.str(), Catch::Contains("decision: effect (wall_adhesion)") && Catch::Contains("torque"));
  std::ifstream f(out);
  const auto j = nlohmann::json::parse(f);
  CHECK(j["decision"] == "effect");
  CHECK(j["named"] == "wall_adhesion");
  CHECK(j["q0"].get<double>() == Approx(14.0));
  CHECK(j["candidates"][1]["name"] == "lubrication");
  CHECK(j["residual_map"][0]["block"] == "slump");
  // bad input: the message names the field
  std::ofstream(in) << R"({"residual": [1, 2, 6], "sigma": [1, 1, 1], "jacobian": [[1], [1]]})";
  std::ostringstream o2, e2;
  CHECK(paddy::doe::runCli({"doe", "diagnose", in}, o2, e2) == 2);
  CHECK_THAT(e2.str(), Catch::Contains("jacobian: 2 rows but the residual has 3"));
  std::filesystem::remove_all(dir);
}
