// State of one script run, shared by the Lua bindings (private to engine/lua/src). One
// RuntimeState lives for the duration of runScript(); the Lua registry holds a pointer to it.
#pragma once

#include <paddy/lua/runtime.hpp>

#include <lua.hpp>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace paddy {
class PluginManager;
}

namespace paddy::lua {

// One parameter declared by paddy.parameters.
struct ParameterDecl {
  enum class Type { Number, Integer, String, Boolean };
  std::string name;
  Type type = Type::Number;
  std::string unit, description;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  std::vector<std::string> choices;  // allowed values of a string parameter (empty = any)
  nlohmann::json default_value, value;
};

// Totals over every sim:run of the script; the last run's state describes the final state.
struct RunStats {
  double particle_steps = 0.0;
  std::uint64_t steps = 0;
  double run_wall_seconds = 0.0;
  std::size_t particles = 0;
  double simulated_time = 0.0;
  std::string state_hash;  // of the simulation last run (see stateHash)
};

struct RuntimeState {
  ScriptOptions options;
  std::filesystem::path script;   // as given
  std::filesystem::path out_dir;  // created before the script starts (empty with --help)
  int threads = 1;                // resolved --threads
  std::vector<ParameterDecl> parameters;
  bool parameters_declared = false;
  nlohmann::json results = nlohmann::json::object();
  std::set<std::string> models_used;  // "normal:jkr", ...
  RunStats stats;
  int simulations = 0;
  bool contention_checked = false;  // the busy-cores warning was considered (lua_simulation.cpp)
  std::shared_ptr<PluginManager> plugins;  // loaded on first use

  std::shared_ptr<const PluginManager> pluginManager();
};

RuntimeState& runtimeState(lua_State* L);
void setRuntimeState(lua_State* L, RuntimeState* state);

// paddy.parameters and --help (parameters.cpp)
std::string parametersHelp(const RuntimeState& state);
nlohmann::json parameterValues(const RuntimeState& state);
// Pushes the Simulation metatable's methods (lua_simulation.cpp).
void registerSimulationType(lua_State* L);
// Lua value → JSON (result.cpp). Tables with keys 1..n become arrays, others objects.
nlohmann::json toJson(lua_State* L, int idx, int depth = 0);
// JSON → Lua value on the stack (lua_json.cpp): objects → tables, arrays → sequences, null → nil.
void pushJson(lua_State* L, const nlohmann::json& value, int depth = 0);

}  // namespace paddy::lua
