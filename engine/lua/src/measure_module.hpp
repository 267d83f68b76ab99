// The functions of require("paddy.measure"), in three files by subject: particle measures and
// scalars (lua_measure.cpp, which opens the module), the rheometer and slump yield-stress relations
// (lua_rheometer.cpp) and coarse graining (lua_coarse_graining.cpp), and their shared option
// reader; the stress across a surface (lua_surface_stress.cpp) reads the axis the same way.
// Private to engine/lua/src.
#pragma once

#include "lua_util.hpp"

#include <Eigen/Core>
#include <lua.hpp>

namespace paddy::lua {

// Option `axis` of a measure: {x, y} or {x, y, z} (z ignored); absent: (0, 0). lua_measure.cpp.
Eigen::Vector2d readAxis(lua_State* L, OptionTable& opt);

extern const luaL_Reg kRheometerFunctions[];       // nullptr-terminated
extern const luaL_Reg kCoarseGrainingFunctions[];  // nullptr-terminated

}  // namespace paddy::lua
