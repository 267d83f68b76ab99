// End-to-end: the campaign runner with the real `paddy` executable (C++ API), and the Lua
// binding paddy.campaign driven by a script run through `paddy run`. Fails when
// ${PADDY_BINARY_DIR}/bin/paddy has not been built (a missing executable is a broken build, not a
// reason to pass).
#include <paddy/campaign/campaign.hpp>

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;
using namespace paddy::campaign;

namespace {

std::string paddyBinary() {
  const char* bin = std::getenv("PADDY_BINARY_DIR");
  if (!bin) return "";
  const fs::path p = fs::path(bin) / "bin" / "paddy";
  return fs::exists(p) ? p.string() : "";
}

fs::path tempDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("paddy_campaign_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

const char* kTinyScript = R"lua(
local P = paddy.parameters{
  a = {default = 1.0, min = -10, max = 10, description = "a number"},
  label = {default = "none", description = "a string"},
}
paddy.result{twice = 2 * P.a, label = P.label, seed = paddy.seed, threads = paddy.threads}
)lua";

}  // namespace

TEST_CASE("campaign: real paddy runs through the C++ API", "[campaign][e2e]") {
  const std::string paddy = paddyBinary();
  INFO("PADDY_BINARY_DIR = " << (std::getenv("PADDY_BINARY_DIR") ? std::getenv("PADDY_BINARY_DIR") : "(unset)"));
  REQUIRE_FALSE(paddy.empty());  // ${PADDY_BINARY_DIR}/bin/paddy must exist
  const fs::path dir = tempDir("e2e");
  std::ofstream(dir / "tiny.lua") << kTinyScript;
  std::ostringstream log;
  CampaignOptions o;
  o.dir = dir / "camp";
  o.max_parallel = 2;
  o.threads_per_job = 1;
  o.paddy_executable = paddy;
  o.log = &log;
  Campaign c(o);
  CHECK(c.codeVersion().find(" exe:") != std::string::npos);
  JobSpec j1;
  j1.script = (dir / "tiny.lua").string();
  j1.set("a", 0.25).set("label", "first");
  j1.seed = 3;
  JobSpec j2 = j1;
  j2.set("a", 1.5);
  JobSpec bad = j1;
  bad.set("a", 99.0);  // outside [min, max]: paddy exits 2 with error.json
  const auto k1 = c.submit(j1), k2 = c.submit(j2), kb = c.submit(bad);
  c.runAll();
  REQUIRE(c.status(k1) == JobStatus::Done);
  REQUIRE(c.status(k2) == JobStatus::Done);
  const auto r1 = c.result(k1);
  CHECK(r1["status"] == "complete");
  CHECK(r1["results"]["twice"].get<double>() == 0.5);
  CHECK(r1["results"]["label"] == "first");
  CHECK(r1["results"]["seed"] == 3);
  CHECK(r1["results"]["threads"] == 1);
  CHECK(c.result(k2)["results"]["twice"].get<double>() == 3.0);
  REQUIRE(c.status(kb) == JobStatus::Failed);
  CHECK(c.record(kb).exit_code == 2);
  CHECK(c.record(kb).error.find("outside") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("campaign: paddy.campaign from a Lua script", "[campaign][e2e]") {
  const std::string paddy = paddyBinary();
  INFO("PADDY_BINARY_DIR = " << (std::getenv("PADDY_BINARY_DIR") ? std::getenv("PADDY_BINARY_DIR") : "(unset)"));
  REQUIRE_FALSE(paddy.empty());  // ${PADDY_BINARY_DIR}/bin/paddy must exist
  const fs::path dir = tempDir("lua");
  std::ofstream(dir / "tiny.lua") << kTinyScript;
  std::ofstream(dir / "calibrate.lua") << R"lua(
local c = paddy.campaign{dir = paddy.out_dir .. "/camp", max_parallel = 2, threads_per_job = 1, progress = false}
local k1 = c:submit{script = "tiny.lua", params = {a = 0.25, label = "x"}, seed = 5}
local k2 = c:submit{script = "tiny.lua", params = {a = 2}}
local k3 = c:submit{script = "tiny.lua", params = {a = 50}}
local runs = c:run()
local again = c:run()  -- everything done: nothing runs again
local some = c:run{k3, k1}  -- only these, in this order
local ok, unknown = pcall(function() return c:run{"0123"} end)
paddy.result{some_n = #some, some1 = some[1].key == k3, some2 = some[2].key == k1, some_r = some[2].result.twice,
             unknown_ok = ok, unknown = tostring(unknown), n = #runs, k1 = k1, key1 = runs[1].key, s1 = runs[1].status, r1 = runs[1].result.twice,
             seed1 = runs[1].result.seed, r2 = c:result(k2).twice, s3 = runs[3].status,
             e3 = runs[3].error, st2 = c:status(k2), nkeys = #c:keys(), again = #again}
)lua";
  const std::string cmd = "cd '" + dir.string() + "' && '" + paddy + "' run calibrate.lua --out out > log.txt 2>&1";
  const int rc = std::system(cmd.c_str());
  std::ifstream logf(dir / "log.txt");
  std::stringstream logs;
  logs << logf.rdbuf();
  INFO(logs.str());
  REQUIRE(rc == 0);
  std::ifstream in(dir / "out" / "result.json");
  const auto doc = nlohmann::json::parse(in);
  const auto& r = doc["results"];
  CHECK(r["n"] == 3);
  CHECK(r["k1"] == r["key1"]);
  CHECK(r["s1"] == "done");
  CHECK(r["r1"].get<double>() == 0.5);
  CHECK(r["seed1"] == 5);
  CHECK(r["r2"].get<double>() == 4.0);
  CHECK(r["s3"] == "failed");
  CHECK(r["e3"].get<std::string>().find("outside") != std::string::npos);
  CHECK(r["st2"] == "done");
  CHECK(r["nkeys"] == 3);
  CHECK(r["again"] == 3);
  CHECK(r["some_n"] == 2);
  CHECK(r["some1"] == true);
  CHECK(r["some2"] == true);
  CHECK(r["some_r"].get<double>() == 0.5);
  CHECK(r["unknown_ok"] == false);
  CHECK(r["unknown"].get<std::string>().find("0123") != std::string::npos);
  fs::remove_all(dir);
}
