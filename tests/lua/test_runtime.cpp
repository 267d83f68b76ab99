// In-process tests of paddy::lua::runScript: parameters, results, error kinds and messages.
#include <paddy/lua/runtime.hpp>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using paddy::lua::ScriptOptions;

namespace {

struct Run {
  int code;
  std::string out, err;
  fs::path dir;
  nlohmann::json result() const {
    std::ifstream in(dir / "out" / "result.json");
    return nlohmann::json::parse(in);
  }
};

fs::path workDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("paddy_lua_test_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Run run(const std::string& name, const std::string& script, std::vector<std::pair<std::string, std::string>> sets = {},
        bool help = false) {
  Run r;
  r.dir = workDir(name);
  std::ofstream(r.dir / "script.lua") << script;
  ScriptOptions o;
  o.script = (r.dir / "script.lua").string();
  o.out_dir = (r.dir / "out").string();
  o.sets = std::move(sets);
  o.help = help;
  o.threads = 1;
  std::ostringstream out, err;
  r.code = paddy::lua::runScript(o, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

const char* kParams = R"(
local P = paddy.parameters{
  speed = {default = 0.05, unit = "m/s", min = 0, max = 1, description = "lift speed"},
  count = {default = 3, type = "integer", min = 1, max = 10},
  label = {default = "x"},
  flag = {default = true},
}
)";

}  // namespace

TEST_CASE("lua: parameters take defaults and --set overrides", "[lua]") {
  const std::string script = std::string(kParams) +
                             "paddy.result{speed = P.speed, count = P.count, label = P.label, flag = P.flag,"
                             " is_int = math.type(P.count)}\n";
  auto r = run("params", script, {{"speed", "0.5"}, {"label", "hello"}, {"flag", "no"}});
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto doc = r.result();
  CHECK(doc["results"]["speed"] == 0.5);
  CHECK(doc["results"]["count"] == 3);
  CHECK(doc["results"]["label"] == "hello");
  CHECK(doc["results"]["flag"] == false);
  CHECK(doc["results"]["is_int"] == "integer");
  CHECK(doc["metadata"]["parameters"]["speed"] == 0.5);
  CHECK(doc["status"] == "complete");
}

TEST_CASE("lua: parameter table rejects unknown names and writes", "[lua]") {
  auto r = run("typo", std::string(kParams) + "local x = P.sped\n");
  CHECK(r.code == paddy::lua::kExitInput);
  CHECK_THAT(r.err, Catch::Contains("script.lua:8:") && Catch::Contains("unknown parameter 'sped'"));
  r = run("write", std::string(kParams) + "P.speed = 3\n");
  CHECK(r.code == paddy::lua::kExitInput);
  CHECK_THAT(r.err, Catch::Contains("read-only"));
}

TEST_CASE("lua: bad declarations name the parameter", "[lua]") {
  auto r = run("decl", "paddy.parameters{ a = {default = 5, min = 0, max = 1} }\n");
  CHECK(r.code == paddy::lua::kExitInput);
  CHECK_THAT(r.err, Catch::Contains("'a' = 5 is outside the allowed range [0, 1]"));
  r = run("nodefault", "paddy.parameters{ a = {min = 0} }\n");
  CHECK_THAT(r.err, Catch::Contains("parameter 'a'") && Catch::Contains("default"));
}

TEST_CASE("lua: help lists parameters and stops before the simulation", "[lua]") {
  const auto r = run("help", std::string(kParams) + "error('the script must not get here')\n", {}, true);
  INFO(r.err);
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("speed") && Catch::Contains("m/s") && Catch::Contains("[0, 1]") &&
                        Catch::Contains("lift speed") && Catch::Contains("true|false"));
  CHECK_FALSE(fs::exists(r.dir / "out"));
}

TEST_CASE("lua: results convert nested tables to JSON", "[lua]") {
  const auto r = run("json", "paddy.result{a = {1, 2, {x = 'y'}}, b = {[\"k\"] = 1.5}, c = 'z'}\n"
                             "paddy.result{c = 'w', d = true, e = {}}\n");
  INFO(r.err);
  REQUIRE(r.code == 0);
  const auto res = r.result()["results"];
  CHECK(res["a"][2]["x"] == "y");
  CHECK(res["b"]["k"] == 1.5);
  CHECK(res["c"] == "w");
  CHECK(res["d"] == true);
  CHECK(res["e"].is_object());
}

TEST_CASE("lua: errors from scripts are input errors with file and line", "[lua]") {
  auto r = run("runtime", "local t = nil\n\nlocal x = t.field\n");
  CHECK(r.code == paddy::lua::kExitInput);
  CHECK_THAT(r.err, Catch::Contains("script.lua:3:"));
  CHECK_FALSE(fs::exists(r.dir / "out" / "result.json"));
  std::ifstream in(r.dir / "out" / "error.json");
  const auto err = nlohmann::json::parse(in);
  CHECK(err["status"] == "failed");
  CHECK_THAT(err["error"].get<std::string>(), Catch::Contains("script.lua:3:"));

  r = run("function", "paddy.result(42)\n");
  CHECK(r.code == paddy::lua::kExitInput);
  CHECK_THAT(r.err, Catch::Contains("script.lua:1:") && Catch::Contains("paddy.result"));
}

TEST_CASE("lua: assignments parse name=value", "[lua]") {
  CHECK(paddy::lua::parseAssignment("a=1") == std::pair<std::string, std::string>{"a", "1"});
  CHECK(paddy::lua::parseAssignment("a=b=c").second == "b=c");
  CHECK_THROWS(paddy::lua::parseAssignment("=1"));
  CHECK_THROWS(paddy::lua::parseAssignment("abc"));
}

#include "thread_contention.hpp"

TEST_CASE("lua: warning for threads on busy cores", "[lua][threads]") {
  using paddy::lua::contentionWarning;
  using paddy::lua::CpuLoad;
  CHECK(contentionWarning(1, CpuLoad{7.0, 2}).empty());  // one thread never waits for another
  CHECK(contentionWarning(2, CpuLoad{0.1, 2}).empty());  // quiet machine
  CHECK(contentionWarning(2, CpuLoad{0.4, 2}).empty());  // 1.6 idle + 0.5 slack holds 2
  CHECK(contentionWarning(8, CpuLoad{2.0, 16}).empty());
  const std::string busy = contentionWarning(2, CpuLoad{2.0, 2});  // two other runs on a 2-core machine
  CHECK(busy.find("2 threads") != std::string::npos);
  CHECK(busy.find("load average is 2.0 on 2 CPUs") != std::string::npos);
  CHECK(busy.find("--threads 1") != std::string::npos);
  CHECK(busy.find("OMP_WAIT_POLICY=passive") != std::string::npos);  // the remedy when threads spin
  CHECK(contentionWarning(2, CpuLoad{2.0, 2}, true).find("OMP_WAIT_POLICY") == std::string::npos);  // already set
  CHECK_FALSE(contentionWarning(2, CpuLoad{1.0, 2}).empty());  // one core busy: still waits
  CHECK(contentionWarning(16, CpuLoad{10.0, 16}).find("--threads 6") != std::string::npos);  // 6 idle
  // The machine's figures can be read here.
  const auto now = paddy::lua::currentCpuLoad();
  REQUIRE(now.has_value());
  CHECK(now->cpus >= 1);
  CHECK(now->load1 >= 0.0);
}

TEST_CASE("lua: a script in a subdirectory of an experiments tree loads that tree's libraries first", "[lua]") {
  // tree/lib/probe.lua and installed/lib/probe.lua say where they are; tree/validation/script.lua
  // must get the tree's, and a script beside the installed tree's root the installed one's.
  const fs::path dir = workDir("own_tree");
  for (const auto& [where, tag] : {std::pair<std::string, std::string>{"tree", "tree"}, {"installed", "installed"}}) {
    fs::create_directories(dir / where / "lib");
    std::ofstream(dir / where / "lib" / "probe.lua") << "return '" << tag << "'\n";
  }
  fs::create_directories(dir / "tree" / "validation");
  std::ofstream(dir / "tree" / "validation" / "script.lua") << "paddy.result{from = require('lib.probe')}\n";
  fs::create_directories(dir / "loose");
  std::ofstream(dir / "loose" / "script.lua") << "paddy.result{from = require('lib.probe')}\n";
  auto runFrom = [&](const fs::path& script, const std::string& out) {
    ScriptOptions o;
    o.script = script.string();
    o.out_dir = (dir / out).string();
    o.experiments_dir = (dir / "installed").string();
    o.threads = 1;
    std::ostringstream sout, serr;
    REQUIRE(paddy::lua::runScript(o, sout, serr) == 0);
    std::ifstream in(dir / out / "result.json");
    return nlohmann::json::parse(in)["results"]["from"].get<std::string>();
  };
  CHECK(runFrom(dir / "tree" / "validation" / "script.lua", "out_tree") == "tree");
  CHECK(runFrom(dir / "loose" / "script.lua", "out_loose") == "installed");
}
