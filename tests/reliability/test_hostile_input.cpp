// Hostile text (quotes, $(...), backticks, ;, newlines, ../, non-ASCII) through the two places
// where Paddy turns text into commands or files: the shell quoting of the Slurm batch scripts
// (campaign/runner.cpp shellQuote, shellJoin) and `paddy run --set` into result.json.
// docs/reliability.md, "Hostile input".
#include "runner.hpp"

#include <paddy/lua/runtime.hpp>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("paddy_hostile_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Each string would run `touch <canary>` or escape its quotes if it were not quoted correctly.
std::vector<std::string> hostileTexts(const fs::path& canary) {
  const std::string c = canary.string();
  return {"$(touch " + c + ")", "`touch " + c + "`", "a'; touch " + c + "; echo '", "a\"; touch " + c + "; echo \"",
          "x\ntouch " + c, "; touch " + c, "|| touch " + c, "../../../etc/passwd", "é ñ 日本 \u2028 \U0001F600",
          "'", "\"", "\\", "$HOME ${PATH} !x *", "-rf", " leading and trailing ", ""};
}

}  // namespace

TEST_CASE("reliability: shell quoting of batch scripts runs no command and keeps every byte", "[reliability][hostile]") {
  const fs::path dir = scratch("shell");
  const fs::path canary = dir / "canary";
  const auto texts = hostileTexts(canary);
  std::vector<std::string> argv{"printf", "%s\\0"};
  argv.insert(argv.end(), texts.begin(), texts.end());
  const fs::path script = dir / "job.sh";
  std::ofstream(script) << "#!/bin/bash\ncd " << paddy::campaign::detail::shellQuote(dir.string()) << " || exit 1\n"
                        << paddy::campaign::detail::shellJoin(argv) << " > out.bin\n";
  REQUIRE(std::system(("/bin/bash " + paddy::campaign::detail::shellQuote(script.string())).c_str()) == 0);
  CHECK_FALSE(fs::exists(canary));
  std::ifstream in(dir / "out.bin", std::ios::binary);
  std::string got((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string want;
  for (const auto& t : texts) want += t + '\0';
  CHECK(got == want);
}

TEST_CASE("reliability: hostile --set text reaches result.json escaped, nothing runs or escapes the output", "[reliability][hostile]") {
  const fs::path dir = scratch("set");
  const fs::path canary = dir / "canary";
  std::ofstream(dir / "script.lua") << R"(
local P = paddy.parameters{label = {default = "x", description = "free text"}}
paddy.write_json("label.json", {label = P.label})
paddy.result{label = P.label}
)";
  for (const auto& text : hostileTexts(canary)) {
    paddy::lua::ScriptOptions o;
    o.script = (dir / "script.lua").string();
    o.out_dir = (dir / "out").string();
    o.sets = {{"label", text}};
    o.threads = 1;
    std::ostringstream out, err;
    INFO("--set label=" << text);
    REQUIRE(paddy::lua::runScript(o, out, err) == 0);
    std::ifstream r(dir / "out" / "result.json");
    const auto doc = nlohmann::json::parse(r);  // well-formed whatever the text
    CHECK(doc["results"]["label"] == text);
    CHECK(doc["metadata"]["parameters"]["label"] == text);
    std::ifstream l(dir / "out" / "label.json");
    CHECK(nlohmann::json::parse(l)["label"] == text);
  }
  CHECK_FALSE(fs::exists(canary));
  // Only the script, the output directory and its files: nothing written beside or above them.
  std::vector<std::string> top;
  for (const auto& e : fs::directory_iterator(dir)) top.push_back(e.path().filename().string());
  std::sort(top.begin(), top.end());
  CHECK(top == std::vector<std::string>{"out", "script.lua"});
  fs::remove_all(dir.parent_path());
}
