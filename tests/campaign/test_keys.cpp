// Job keys: stable, and changed by exactly what decides a result (script and required modules,
// parameters, seed, code version), not by the thread count.
#include <paddy/campaign/job.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace paddy::campaign;

namespace {

fs::path tempDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("paddy_campaign_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void writeText(const fs::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
}

}  // namespace

TEST_CASE("campaign: numbers are printed exactly", "[campaign]") {
  CHECK(formatNumber(3.0) == "3");
  CHECK(formatNumber(-2.0) == "-2");
  CHECK(formatNumber(0.1) == "0.10000000000000001");
  CHECK(std::stod(formatNumber(0.13)) == 0.13);
  CHECK(std::stod(formatNumber(1.0 / 3.0)) == 1.0 / 3.0);
  JobSpec s;
  s.set("a", 0.5).set("n", 3000).set("wet", true).set("mode", "dry");
  CHECK(s.params.at("a") == "0.5");
  CHECK(s.params.at("n") == "3000");
  CHECK(s.params.at("wet") == "true");
  CHECK(s.params.at("mode") == "dry");
}

TEST_CASE("campaign: SHA-256 matches the standard test vector", "[campaign]") {
  CHECK(sha256Hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256Hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST_CASE("campaign: keys are stable and change with script, modules, params, seed, code", "[campaign]") {
  const fs::path dir = tempDir("keys");
  const fs::path script = dir / "exp.lua";
  writeText(script, "local helper = require(\"helper\")\npaddy.result{x = helper.value}\n");
  writeText(dir / "helper.lua", "return {value = 1}\n");

  JobSpec base;
  base.script = script.string();
  base.set("restitution", 0.1).set("friction", 0.5);
  base.seed = 7;
  const std::string k0 = jobKey(base, "v1");
  CHECK(k0.size() == 64);
  CHECK(jobKey(base, "v1") == k0);  // stable

  SECTION("parameter order does not matter") {
    JobSpec other;
    other.script = script.string();
    other.seed = 7;
    other.set("friction", 0.5).set("restitution", 0.1);
    CHECK(jobKey(other, "v1") == k0);
  }
  SECTION("threads do not change the key") {
    JobSpec other = base;
    other.threads = 4;
    CHECK(jobKey(other, "v1") == k0);
  }
  SECTION("a parameter value changes it") {
    JobSpec other = base;
    other.set("restitution", 0.10000000000000002);
    CHECK(jobKey(other, "v1") != k0);
  }
  SECTION("an extra parameter changes it") {
    JobSpec other = base;
    other.set("gamma", 0.096);
    CHECK(jobKey(other, "v1") != k0);
  }
  SECTION("the seed changes it") {
    JobSpec other = base;
    other.seed = 8;
    CHECK(jobKey(other, "v1") != k0);
  }
  SECTION("the code version changes it") { CHECK(jobKey(base, "v2") != k0); }
  SECTION("the script content changes it") {
    writeText(script, "local helper = require(\"helper\")\npaddy.result{x = helper.value + 0}\n");
    CHECK(jobKey(base, "v1") != k0);
  }
  SECTION("a required module's content changes it") {
    const auto mods = requiredModules(script, {});
    REQUIRE(mods.size() == 1);
    CHECK(mods.begin()->first == "helper");
    writeText(dir / "helper.lua", "return {value = 2}\n");
    CHECK(jobKey(base, "v1") != k0);
  }
  SECTION("an explicit command changes it") {
    JobSpec other = base;
    other.command = {"/bin/true"};
    CHECK(jobKey(other, "v1") != k0);
  }
  fs::remove_all(dir);
}

TEST_CASE("campaign: the default code version names the engine library", "[campaign]") {
  const std::string v = defaultCodeVersion("");
  CHECK(v.rfind("paddy ", 0) == 0);
  CHECK(v.find(" lib:") != std::string::npos);
}
