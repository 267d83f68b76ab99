// Lua runtime: runs an experiment script (`paddy run SCRIPT.lua`).
//
// The script composes the experiment through the `paddy` module (parameters, simulations,
// results); the engine owns the time loop. runScript() does the whole job of one run: it
// prepares the output directory, runs the script, and writes DIR/result.json on success or
// DIR/error.json on failure. See docs/scripting.md for the Lua API.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

struct lua_State;

namespace paddy::lua {

// Process exit codes of `paddy run`.
enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitInput = 2, kExitInstability = 3 };

struct ScriptOptions {
  std::string script;                                     // path of the .lua file
  std::vector<std::pair<std::string, std::string>> sets;  // --set name=value, in order
  std::string out_dir;           // output directory; "" = "out/<script stem>"
  int threads = 0;               // 0 = all hardware threads
  std::uint64_t seed = 1;
  bool help = false;             // list the script's parameters instead of running it
  std::string experiments_dir;   // added to package.path ("" = none)
};

// A Lua C module that `require(name)` finds without a file (package.preload).
using OpenFunction = int (*)(lua_State*);
void addPreload(const std::string& module_name, OpenFunction open);

// Splits "name=value"; throws InputError when there is no '=' or the name is empty.
std::pair<std::string, std::string> parseAssignment(const std::string& text);

// Runs the script and returns the exit code. Messages go to `err` (errors, progress is on
// stderr), the parameter listing of --help to `out`.
int runScript(const ScriptOptions& options, std::ostream& out, std::ostream& err);

// The engine's version string ("0.1.0").
const char* version();

}  // namespace paddy::lua
