// Wall arguments of the Lua bindings, see wall_args.hpp.
#include "wall_args.hpp"
#include "lua_util.hpp"

#include <paddy/errors.hpp>

#include <cmath>
#include <sstream>

namespace paddy::lua {

int wallArg(lua_State* L, SimHandle& h, int idx, const std::string& fn) {
  const int n = static_cast<int>(h.sim->wallCount());
  if (lua_type(L, idx) == LUA_TSTRING) {
    const std::string name = lua_tostring(L, idx);
    for (int w = 0; w < n; ++w)
      if (h.sim->wall(w).name() == name) return w;
    throw InputError(fn + ": no wall named '" + name + "'");
  }
  const double x = toNumber(L, idx, fn + ": wall");
  if (x != std::floor(x) || x < 0 || x >= n) {
    std::ostringstream m;
    m << fn << ": wall " << x << " does not exist (" << n << " walls";
    if (n > 0) m << ", indices 0.." << n - 1 << " or their names";
    m << ")";
    throw InputError(m.str());
  }
  return static_cast<int>(x);
}

MeshWall& meshWallArg(lua_State* L, SimHandle& h, int idx, const std::string& fn) {
  Wall& w = h.sim->wall(wallArg(L, h, idx, fn));
  auto* m = dynamic_cast<MeshWall*>(&w);
  if (!m) throw InputError(fn + ": wall '" + w.name() + "' is not a mesh wall (sim:add_mesh_wall)");
  return *m;
}

std::vector<int> wallList(lua_State* L, SimHandle& h, int idx, const std::string& fn, bool mesh_only) {
  idx = lua_absindex(L, idx);
  std::vector<int> out;
  if (lua_type(L, idx) != LUA_TTABLE) {
    if (mesh_only) meshWallArg(L, h, idx, fn);
    out.push_back(wallArg(L, h, idx, fn));
    return out;
  }
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, idx));
  if (n == 0) throw InputError(fn + " is an empty list (give walls by index or name)");
  for (lua_Integer k = 1; k <= n; ++k) {
    lua_rawgeti(L, idx, k);
    const std::string entry = fn + " entry " + std::to_string(k);
    try {
      if (mesh_only) meshWallArg(L, h, -1, entry);
      out.push_back(wallArg(L, h, -1, entry));
    } catch (...) {
      lua_pop(L, 1);
      throw;
    }
    lua_pop(L, 1);
  }
  return out;
}

std::vector<int> meshWallList(lua_State* L, SimHandle& h, int idx, const std::string& fn) {
  return wallList(L, h, idx, fn, true);
}

std::vector<int> allMeshWalls(Simulation& sim) {
  std::vector<int> out;
  for (std::size_t k = 0; k < sim.wallCount(); ++k)
    if (dynamic_cast<MeshWall*>(&sim.wall(static_cast<int>(k)))) out.push_back(static_cast<int>(k));
  return out;
}

}  // namespace paddy::lua
