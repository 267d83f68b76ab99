// Shared by the fuzz targets that go through `paddy run` (paddy::lua::runScript): a fixed script
// in the scratch directory, run with the given --set assignments. A refused input must end with
// exit code 2 (input error) and a message; a crash, leak, UB or another exit code is a finding
// (exit code 3, an instability of the simulated physics, only where the caller allows it).
#pragma once

#include "fuzz_input_file.hpp"

#include <paddy/lua/runtime.hpp>

#include <sstream>
#include <algorithm>
#include <utility>
#include <vector>

namespace paddy::fuzz {

struct ScriptRun {
  int code;
  std::string err;
};

// The script runs with experiments/ on its package.path (PADDY_EXPERIMENTS_DIR), as `paddy run` does.
inline ScriptRun runFixedScript(const std::string& name, const std::string& text,
                                std::vector<std::pair<std::string, std::string>> sets = {},
                                bool instability_allowed = false) {
  const auto script = scratchDir() / (name + ".lua");
  if (!std::filesystem::exists(script)) std::ofstream(script) << text;
  paddy::lua::ScriptOptions o;
  o.script = script.string();
  o.out_dir = (scratchDir() / (name + "_out")).string();
  o.sets = std::move(sets);
  o.threads = 1;
#ifdef PADDY_EXPERIMENTS_DIR
  o.experiments_dir = PADDY_EXPERIMENTS_DIR;
#endif
  std::ostringstream out, err;
  const int code = paddy::lua::runScript(o, out, err);
  if (code != paddy::lua::kExitOk && code != paddy::lua::kExitInput &&
      !(instability_allowed && code == paddy::lua::kExitInstability)) {
    std::fprintf(stderr, "unexpected exit code %d: %s\n", code, err.str().c_str());
    std::abort();
  }
  return {code, err.str()};
}

}  // namespace paddy::fuzz
