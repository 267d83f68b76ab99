// The functions of require("paddy.measure"), in three files by subject: particle measures and
// scalars (lua_measure.cpp, which opens the module), the rheometer and slump yield-stress relations
// (lua_rheometer.cpp) and coarse graining (lua_coarse_graining.cpp). Private to engine/lua/src.
#pragma once

#include <lua.hpp>

namespace paddy::lua {

extern const luaL_Reg kRheometerFunctions[];       // nullptr-terminated
extern const luaL_Reg kCoarseGrainingFunctions[];  // nullptr-terminated

}  // namespace paddy::lua
