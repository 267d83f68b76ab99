// Plugin loading: the ABI is checked before a plugin runs, broken libraries on the search path are
// reported and skipped, and a name registered by two libraries follows the first-wins rule with a
// warning naming both. The deliberately broken plugins are built from tests/sdk/loader_plugins/.
#include <paddy/errors.hpp>
#include <paddy/plugin_manager.hpp>

#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <string>

using paddy::PluginManager;
using paddy::SubModelKind;

namespace {

const std::string kDir = PADDY_LOADER_TEST_DIR;
const std::string kBroken = kDir + "/broken";

std::string lib(const std::string& dir, const std::string& name) { return dir + "/libpaddy_loadertest_" + name + ".so"; }

std::vector<std::string> normalNames(const PluginManager& pm) {
  std::vector<std::string> out;
  for (const auto* info : pm.subModels(SubModelKind::Normal)) out.push_back(info->name);
  return out;
}

const paddy::PluginLoadFailure* failureOf(const PluginManager& pm, const std::string& name) {
  for (const auto& f : pm.failures())
    if (f.path.find("libpaddy_loadertest_" + name + ".so") != std::string::npos) return &f;
  return nullptr;
}

// Runs a shell command, returns its exit status and fills `out` with stdout and stderr.
int run(const std::string& command, std::string& out) {
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  REQUIRE(p != nullptr);
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  return pclose(p);
}

}  // namespace

TEST_CASE("plugins/loading: a plugin built for another ABI runs no code and registers nothing", "[plugins]") {
  unsetenv("PADDY_LOADER_TEST_WRONG_ABI_REGISTERED");
  PluginManager pm;
  const std::string other = std::to_string(PADDY_PLUGIN_ABI_VERSION + 1);
  CHECK_THROWS_WITH(pm.loadLibrary(lib(kBroken, "wrong_abi")),
                    Catch::Contains("libpaddy_loadertest_wrong_abi.so") &&
                        Catch::Contains("built for plugin ABI " + other) &&
                        Catch::Contains("this Paddy has ABI " + std::to_string(PADDY_PLUGIN_ABI_VERSION)));
  CHECK(std::getenv("PADDY_LOADER_TEST_WRONG_ABI_REGISTERED") == nullptr);  // its register function never ran
  CHECK(pm.loaded().empty());
  CHECK(normalNames(pm).empty());
  CHECK_THROWS_AS(pm.subModel("loader_test_wrong_abi", SubModelKind::Normal), paddy::InputError);
  // the run goes on: a good plugin loads into the same manager afterwards
  pm.loadLibrary(lib(kBroken, "good"));
  CHECK(normalNames(pm) == std::vector<std::string>{"loader_test_good"});
}

TEST_CASE("plugins/loading: a register function that throws leaves nothing behind", "[plugins]") {
  PluginManager pm;
  CHECK_THROWS_WITH(pm.loadLibrary(lib(kBroken, "register_throws")),
                    Catch::Contains("libpaddy_loadertest_register_throws.so") &&
                        Catch::Contains("deliberate failure during registration"));
  CHECK(pm.loaded().empty());
  CHECK(normalNames(pm).empty());  // it registered "loader_test_register_throws" before throwing
}

TEST_CASE("plugins/loading: broken libraries on the search path are reported and skipped", "[plugins]") {
  unsetenv("PADDY_LOADER_TEST_WRONG_ABI_REGISTERED");
  PluginManager pm;
  REQUIRE_NOTHROW(pm.loadDirectories({kBroken}));
  REQUIRE(pm.loaded().size() == 1);
  CHECK(pm.loaded()[0].path == lib(kBroken, "good"));
  CHECK(normalNames(pm) == std::vector<std::string>{"loader_test_good"});
  CHECK(std::getenv("PADDY_LOADER_TEST_WRONG_ABI_REGISTERED") == nullptr);
  CHECK(pm.failures().size() == 7);
  const struct {
    const char* name;
    const char* reason;
  } expected[] = {
      {"not_a_shared_object", "invalid ELF header"},
      {"wrong_abi", "was built for plugin ABI"},
      {"no_abi_symbol", "does not export paddy_plugin_abi_version"},
      {"no_entry_point", "does not export the entry point paddy_register_plugin"},
      {"undefined_symbol", "undefined symbol: paddy_loader_test_symbol_nobody_defines"},
      {"missing_dependency", "libpaddy_loader_test_dependency.so: cannot open shared object file"},
      {"register_throws", "deliberate failure during registration"},
  };
  for (const auto& e : expected) {
    INFO(e.name);
    const auto* f = failureOf(pm, e.name);
    REQUIRE(f != nullptr);
    CHECK_THAT(f->reason, Catch::Contains(e.reason) && Catch::Contains(f->path));
  }
}

TEST_CASE("plugins/loading: a name registered by two libraries keeps the first, with a warning", "[plugins]") {
  const std::string a = lib(kDir + "/dup_a", "dup_a"), b = lib(kDir + "/dup_b", "dup_b");
  {
    PluginManager pm;
    pm.loadDirectories({kDir + "/dup_a", kDir + "/dup_b"});
    CHECK(pm.loaded().size() == 2);  // both libraries load; only the name clashes
    CHECK(pm.subModel("loader_test_duplicate", SubModelKind::Normal).description == "copy a");
    REQUIRE(pm.warnings().size() == 1);
    CHECK_THAT(pm.warnings()[0], Catch::Contains("normal:loader_test_duplicate") && Catch::Contains(a) &&
                                     Catch::Contains(b) && Catch::Contains("keeping the first (" + a + ")"));
  }
  {  // the same rule by search-path order: b first now
    PluginManager pm;
    pm.loadDirectories({kDir + "/dup_b", kDir + "/dup_a"});
    CHECK(pm.subModel("loader_test_duplicate", SubModelKind::Normal).description == "copy b");
    REQUIRE(pm.warnings().size() == 1);
    CHECK_THAT(pm.warnings()[0], Catch::Contains("keeping the first (" + b + ")"));
  }
  {  // the same file twice on the path is loaded once, without a warning
    PluginManager pm;
    pm.loadDirectories({kDir + "/dup_a", kDir + "/dup_a"});
    CHECK(pm.loaded().size() == 1);
    CHECK(pm.warnings().empty());
  }
}

TEST_CASE("plugins/loading: `paddy plugins` lists the libraries skipped and the names registered twice", "[plugins]") {
  std::string out;
  const int status = run("PADDY_PLUGIN_PATH='" + kBroken + ":" + kDir + "/dup_a:" + kDir + "/dup_b' '" +
                             PADDY_EXECUTABLE + "' plugins",
                         out);
  INFO(out);
  CHECK(status == 0);
  CHECK_THAT(out, Catch::Contains("Plugins skipped (could not be loaded):"));
  for (const char* name : {"not_a_shared_object", "wrong_abi", "no_abi_symbol", "no_entry_point", "undefined_symbol",
                           "missing_dependency", "register_throws"})
    CHECK_THAT(out, Catch::Contains("  " + lib(kBroken, name) + "\n    reason: "));
  CHECK_THAT(out, Catch::Contains("Names registered twice (the first is kept):"));
  CHECK_THAT(out, Catch::Contains("normal:loader_test_duplicate is registered by both " +
                                  lib(kDir + "/dup_a", "dup_a") + " and " + lib(kDir + "/dup_b", "dup_b")));
  CHECK_THAT(out, Catch::Contains("loader_test_good"));  // the working plugin is listed
}
