#include "doe_lua_state.hpp"

#include <catch2/catch.hpp>
#include <lua.hpp>
#include <string>

TEST_CASE("doe/lua: design, analyze, optimize, steepest_ascent", "[doe]") {
  doe_test::LuaState lua;
  const std::string ok = lua.run(R"(
    local doe = require("paddy.doe")
    local d = doe.design{type = "bbd", names = {"A", "B", "C"}, center = 5,
                         levels = {A = {0.07, 0.13}, B = {0.4, 0.6}, C = {0.07, 0.13}}}
    assert(#d.runs == 17, "runs " .. #d.runs)
    assert(math.abs(d.runs[1].real.A - 0.07) < 1e-12 and d.runs[1].coded.A == -1)
    local data = {}
    for i, r in ipairs(d.runs) do
      local a, b, c = r.coded.A, r.coded.B, r.coded.C
      data[i] = {A = r.real.A, B = r.real.B, C = r.real.C,
                 y = 240 - 6*a - 8*b + 2*c + 1.5*a*b - 3*a*a + 0.01*((i*7) % 5 - 2)}
    end
    local fit = doe.analyze{data = data, factors = {"A", "B", "C"}, responses = {"y"}, model = "quadratic"}
    local y = fit.responses.y
    assert(math.abs(y.coefficients["A:B"] - 1.5) < 0.02)
    assert(y.anova[1].source == "Model" and y.r2 > 0.99)
    local s = doe.optimize{fit = fit, goals = {"y=target:241"}}
    assert(math.abs(s.solutions[1].predicted.y - 241) < 0.01)
    local s2 = doe.optimize{fit = fit, goals = {{response = "y", goal = "max"}}}
    assert(s2.solutions[1].desirability > 0.99)
    local p = doe.steepest_ascent{factors = {{name = "A", low = 0.01, high = 0.1}},
                                  coefficients = {-4.8}, descent = true, real_steps = {0.03},
                                  origin = {0.01}, steps = 3}
    assert(#p == 4 and math.abs(p[4].real.A - 0.10) < 1e-12)
  )");
  CHECK(ok == "");
}

TEST_CASE("doe/lua: errors are raised with clear messages", "[doe]") {
  doe_test::LuaState lua;
  CHECK_THAT(lua.run(R"(require("paddy.doe").design{type = "bbd", factors = 9})"),
             Catch::Contains("paddy.doe.design") && Catch::Contains("3 to 7 factors"));
  CHECK_THAT(lua.run(R"(require("paddy.doe").analyze{data = {{A = 1, y = 2}, {A = "x", y = 3}},
                                                     factors = {"A"}, responses = {"y"}})"),
             Catch::Contains("paddy.doe.analyze") && Catch::Contains("row 2"));
  CHECK_THAT(lua.run(R"(require("paddy.doe").analyze(5))"), Catch::Contains("table of options"));
}
