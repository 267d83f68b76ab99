// Self-registration of Lua bindings. A binding file adds functions to the `paddy` module or
// methods to the Simulation userdata with one static object, so a new group of bindings (e.g.
// walls and meshes) is one new .cpp file and nothing else:
//
//   static const paddy::lua::SimulationMethod reg_add_wall{"add_wall", &guarded<addWall>};
//   static const paddy::lua::ModuleFunction reg_mesh{"mesh", &guarded<mesh>};
#pragma once

#include <lua.hpp>

#include <string>
#include <vector>

namespace paddy::lua {

struct Binding {
  std::string name;
  lua_CFunction function;
};

std::vector<Binding>& moduleFunctions();      // paddy.<name>
std::vector<Binding>& simulationMethods();    // sim:<name>()

struct ModuleFunction {
  ModuleFunction(const char* name, lua_CFunction f) { moduleFunctions().push_back({name, f}); }
};
struct SimulationMethod {
  SimulationMethod(const char* name, lua_CFunction f) { simulationMethods().push_back({name, f}); }
};

}  // namespace paddy::lua
