// Wall arguments of the Lua bindings (private to engine/lua/src): a wall is given by the index
// sim:add_wall / sim:add_mesh_wall returned or by its name.
#pragma once

#include "sim_handle.hpp"

#include <paddy/geometry/mesh_wall.hpp>

#include <string>
#include <vector>

namespace paddy::lua {

// Index of the wall at stack index `idx`; throws InputError naming `fn` and the valid indices.
int wallArg(lua_State* L, SimHandle& h, int idx, const std::string& fn);
// The mesh wall at `idx`; throws InputError if it is another kind of wall.
MeshWall& meshWallArg(lua_State* L, SimHandle& h, int idx, const std::string& fn);
// Indices of the walls at `idx`: one wall or a non-empty list {w1, w2, ...} (entries named in
// errors); mesh_only: each must be a mesh wall.
std::vector<int> wallList(lua_State* L, SimHandle& h, int idx, const std::string& fn, bool mesh_only = false);
// Indices of the mesh walls at `idx` (wallList with mesh_only).
std::vector<int> meshWallList(lua_State* L, SimHandle& h, int idx, const std::string& fn);
// Indices of all mesh walls, in order.
std::vector<int> allMeshWalls(Simulation& sim);

}  // namespace paddy::lua
