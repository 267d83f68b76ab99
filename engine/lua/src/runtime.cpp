// runScript(): one `paddy run` — output directory, Lua state, the script, result.json.
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"

#include <paddy/errors.hpp>
#include <paddy/io/atomic_file.hpp>
#include <paddy/plugin_manager.hpp>

#include <chrono>
#include <cstdlib>
#include <map>
#include <memory>
#include <ostream>
#include <thread>

#ifndef PADDY_VERSION
#define PADDY_VERSION "unknown"
#endif

namespace paddy::lua {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const char* kStateKey = "paddy.runtime";

std::map<std::string, OpenFunction>& preloads() {
  static std::map<std::string, OpenFunction> modules;
  return modules;
}

// Message handler of the top-level pcall: turns any error into a paddy error object and adds
// the Lua traceback.
int messageHandler(lua_State* L) {
  if (lua_type(L, 1) != LUA_TTABLE) {
    const std::string message = lua_isstring(L, 1) ? lua_tostring(L, 1) : luaL_tolstring(L, 1, nullptr);
    pushErrorObject(L, ErrorKind::Input, message);
    lua_replace(L, 1);
    lua_settop(L, 1);
  }
  luaL_traceback(L, L, nullptr, 1);
  lua_setfield(L, 1, "traceback");
  return 1;
}

// Whether dir/lib holds Lua modules (an experiments tree's root).
bool hasLuaLib(const fs::path& dir) {
  std::error_code ec;
  const fs::path lib = dir / "lib";
  if (!fs::is_directory(lib, ec)) return false;
  for (const auto& e : fs::directory_iterator(lib, ec)) {
    if (e.path().extension() == ".lua") return true;
  }
  return false;
}

// The root of the experiments tree a script belongs to, when the script sits in a subdirectory
// of it (validation/, calibration/): the nearest ancestor, at most three levels up, whose lib/
// holds Lua modules; empty when the script's own directory is such a root or none is found. A
// script in a copied tree then loads that tree's libraries before the installed ones.
fs::path ownTreeRoot(const fs::path& script_dir) {
  if (hasLuaLib(script_dir)) return {};
  fs::path p = script_dir;
  for (int level = 0; level < 3 && p.has_parent_path() && p.parent_path() != p; ++level) {
    p = p.parent_path();
    if (hasLuaLib(p)) return p;
  }
  return {};
}

void setPackagePath(lua_State* L, const RuntimeState& st) {
  std::string prefix;
  auto add = [&prefix](const fs::path& dir) {
    const std::string d = dir.empty() ? std::string(".") : dir.string();
    prefix += d + "/?.lua;" + d + "/?/init.lua;";
  };
  const fs::path script_dir = fs::absolute(st.script).parent_path();
  add(script_dir);
  if (const fs::path root = ownTreeRoot(script_dir); !root.empty()) add(root);
  if (!st.options.experiments_dir.empty()) add(st.options.experiments_dir);
  lua_getglobal(L, "package");
  lua_getfield(L, -1, "path");
  const std::string path = prefix + (lua_isstring(L, -1) ? lua_tostring(L, -1) : "");
  lua_pop(L, 1);
  lua_pushstring(L, path.c_str());
  lua_setfield(L, -2, "path");
  lua_getfield(L, -1, "preload");
  for (const auto& [name, open] : preloads()) {
    lua_pushcfunction(L, open);
    lua_setfield(L, -2, name.c_str());
  }
  lua_pop(L, 2);
}

void openPaddyModule(lua_State* L, const RuntimeState& st) {
  registerSimulationType(L);
  lua_newtable(L);
  for (const Binding& b : moduleFunctions()) {
    lua_pushcfunction(L, b.function);
    lua_setfield(L, -2, b.name.c_str());
  }
  lua_pushinteger(L, static_cast<lua_Integer>(st.options.seed));
  lua_setfield(L, -2, "seed");
  lua_pushinteger(L, st.threads);
  lua_setfield(L, -2, "threads");
  lua_pushstring(L, st.out_dir.string().c_str());
  lua_setfield(L, -2, "out_dir");
  lua_pushstring(L, PADDY_VERSION);
  lua_setfield(L, -2, "version");
  lua_pushstring(L, st.script.string().c_str());
  lua_setfield(L, -2, "script");
  lua_pushboolean(L, st.options.help);
  lua_setfield(L, -2, "help");
  // paddy.set_parameters: {name = text} of the --set overrides, so a script can tell a value the
  // user gave from a declared default (e.g. a material set supplying the defaults).
  lua_createtable(L, 0, static_cast<int>(st.options.sets.size()));
  for (const auto& [name, text] : st.options.sets) {
    lua_pushlstring(L, text.data(), text.size());
    lua_setfield(L, -2, name.c_str());
  }
  lua_setfield(L, -2, "set_parameters");
  lua_pushvalue(L, -1);
  lua_setglobal(L, "paddy");
  luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
  lua_insert(L, -2);
  lua_setfield(L, -2, "paddy");  // require("paddy") returns the same table
  lua_pop(L, 1);
}

json metadata(const RuntimeState& st, double wall_seconds) {
  json plugins = json::array();
  if (st.plugins) {
    for (const auto& lp : st.plugins->loaded()) {
      json used = json::array();
      for (const auto& p : lp.provides)
        if (st.models_used.count(p)) used.push_back(p);
      if (!used.empty()) plugins.push_back({{"path", lp.path}, {"used", used}});
    }
  }
  const auto& s = st.stats;
  return {{"paddy_version", PADDY_VERSION},
          {"script", fs::absolute(st.script).lexically_normal().string()},
          {"parameters", parameterValues(st)},
          {"seed", st.options.seed},
          {"threads", st.threads},
          {"particles", s.particles},
          {"simulated_time", s.simulated_time},
          {"steps", s.steps},
          {"wall_time", wall_seconds},
          {"run_wall_time", s.run_wall_seconds},
          {"particle_steps_per_second", s.run_wall_seconds > 0 ? s.particle_steps / s.run_wall_seconds : 0.0},
          {"final_state_hash", s.state_hash},
          {"contact_models", json(std::vector<std::string>(st.models_used.begin(), st.models_used.end()))},
          {"plugins", plugins}};
}

int exitCodeFor(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Input: return kExitInput;
    case ErrorKind::Instability: return kExitInstability;
    case ErrorKind::Runtime: return kExitFailure;
    case ErrorKind::Help: return kExitOk;
  }
  return kExitFailure;
}

const char* kindText(ErrorKind kind) {
  switch (kind) {
    case ErrorKind::Input: return "input";
    case ErrorKind::Instability: return "instability";
    case ErrorKind::Runtime: return "runtime";
    case ErrorKind::Help: return "help";
  }
  return "runtime";
}

struct LuaCloser {
  void operator()(lua_State* L) const { lua_close(L); }
};

// Runs the script in a fresh Lua state; returns the error kind and message on failure.
struct Outcome {
  bool ok = true;
  ErrorKind kind = ErrorKind::Input;
  std::string message, traceback;
};

Outcome execute(RuntimeState& st) {
  std::unique_ptr<lua_State, LuaCloser> owner(luaL_newstate());
  lua_State* L = owner.get();
  if (!L) return {false, ErrorKind::Runtime, "cannot create a Lua state (out of memory)", ""};
  luaL_openlibs(L);
  setRuntimeState(L, &st);
  setPackagePath(L, st);
  openPaddyModule(L, st);

  lua_pushcfunction(L, messageHandler);
  const int handler = lua_gettop(L);
  // luaL_loadfilex names the chunk "@<path>", so messages read "<path>:<line>: ...".
  if (luaL_loadfilex(L, st.script.c_str(), "t") != LUA_OK) {
    Outcome o{false, ErrorKind::Input, lua_tostring(L, -1) ? lua_tostring(L, -1) : "cannot load script", ""};
    return o;
  }
  if (lua_pcall(L, 0, 0, handler) == LUA_OK) return {};
  Outcome o{false, errorKind(L, -1), errorMessage(L, -1), ""};
  if (lua_type(L, -1) == LUA_TTABLE) {
    lua_getfield(L, -1, "traceback");
    if (lua_isstring(L, -1)) o.traceback = lua_tostring(L, -1);
    lua_pop(L, 1);
  }
  return o;
}

}  // namespace

RuntimeState& runtimeState(lua_State* L) {
  lua_getfield(L, LUA_REGISTRYINDEX, kStateKey);
  auto* st = static_cast<RuntimeState*>(lua_touserdata(L, -1));
  lua_pop(L, 1);
  if (!st) throw std::logic_error("paddy runtime state missing");
  return *st;
}

void setRuntimeState(lua_State* L, RuntimeState* state) {
  lua_pushlightuserdata(L, state);
  lua_setfield(L, LUA_REGISTRYINDEX, kStateKey);
}

std::shared_ptr<const PluginManager> RuntimeState::pluginManager() {
  if (!plugins) {
    plugins = std::make_shared<PluginManager>();
    plugins->loadDefault();
  }
  return plugins;
}

void addPreload(const std::string& module_name, OpenFunction open) { preloads()[module_name] = open; }

const char* version() { return PADDY_VERSION; }

std::pair<std::string, std::string> parseAssignment(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set '" + text + "': expected name=value");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

int runScript(const ScriptOptions& options, std::ostream& out, std::ostream& err) {
  const auto start = std::chrono::steady_clock::now();
  RuntimeState st;
  st.options = options;
  st.script = options.script;
  st.threads = options.threads > 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  std::error_code ec;
  if (!fs::is_regular_file(st.script, ec)) {
    err << "paddy: error: cannot open script '" << options.script << "'\n";
    return kExitInput;
  }
  if (!options.help) {
    st.out_dir = options.out_dir.empty() ? fs::path("out") / st.script.stem() : fs::path(options.out_dir);
    fs::create_directories(st.out_dir, ec);
    if (ec) {
      err << "paddy: error: cannot create output directory '" << st.out_dir.string() << "': " << ec.message() << "\n";
      return kExitInput;
    }
    // Never leave the outcome of an earlier run behind.
    fs::remove(st.out_dir / "result.json", ec);
    fs::remove(st.out_dir / "error.json", ec);
  }

  Outcome outcome;
  try {
    outcome = execute(st);
  } catch (const std::exception& e) {  // failures outside any binding (e.g. creating the state)
    outcome = {false, ErrorKind::Runtime, e.what(), ""};
  }
  if (outcome.ok && options.help) {
    out << parametersHelp(st);  // the script declares nothing and ran to its end
    return kExitOk;
  }
  if (outcome.ok && !st.parameters_declared && !options.sets.empty())
    outcome = {false, ErrorKind::Input, "--set was given but the script declares no parameters (paddy.parameters)", ""};
  if (!outcome.ok && outcome.kind == ErrorKind::Help) {
    out << parametersHelp(st);
    return kExitOk;
  }

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    if (outcome.ok) {
      json doc = {{"status", "complete"}, {"results", st.results}, {"metadata", metadata(st, wall)}};
      io::writeFileAtomic(st.out_dir / "result.json", doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
      return kExitOk;
    }
    err << "paddy: error: " << outcome.message << "\n";
    // Input errors already name the file and line; tracebacks on request (or for internal errors).
    if (!outcome.traceback.empty() && (outcome.kind == ErrorKind::Runtime || std::getenv("PADDY_TRACEBACK")))
      err << outcome.traceback << "\n";
    if (!st.out_dir.empty()) {
      json doc = {{"status", "failed"},
                  {"error", outcome.message},
                  {"kind", kindText(outcome.kind)},
                  {"traceback", outcome.traceback},
                  {"exit_code", exitCodeFor(outcome.kind)},
                  {"results", st.results},
                  {"metadata", metadata(st, wall)}};
      io::writeFileAtomic(st.out_dir / "error.json", doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n");
    }
  } catch (const std::exception& e) {
    err << "paddy: error: writing the outcome: " << e.what() << "\n";
    return kExitFailure;
  }
  return exitCodeFor(outcome.kind);
}

}  // namespace paddy::lua
