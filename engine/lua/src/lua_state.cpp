// Reading the particle state from Lua, removing particles, and the state digest.
//
//   sim:positions() → { {x,y,z}, ... }       sim:xyz() → xs, ys, zs (three arrays, faster)
//   sim:velocities() → { {vx,vy,vz}, ... }   sim:radii() → { r, ... }   sim:ids() → { id, ... }
//   sim:remove_if(function(i, x, y, z, r) return <bool> end) → removed count
//   sim:state_hash() → hex digest of positions and velocities ordered by particle id
#include "lua_util.hpp"
#include "registry.hpp"
#include "sim_handle.hpp"

#include <paddy/errors.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <numeric>

namespace paddy::lua {

std::string stateHash(const ParticleArrays& p) {
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a, 64 bit
  auto mix = [&h](const void* data, std::size_t n) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < n; ++k) h = (h ^ bytes[k]) * 1099511628211ull;
  };
  for (std::size_t i : order) {
    mix(&p.id[i], sizeof(std::uint64_t));
    const double values[6] = {p.position[i].x(), p.position[i].y(), p.position[i].z(),
                              p.velocity[i].x(), p.velocity[i].y(), p.velocity[i].z()};
    mix(values, sizeof values);
  }
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

namespace {

void pushVec3List(lua_State* L, const std::vector<Vec3>& values) {
  lua_createtable(L, static_cast<int>(values.size()), 0);
  for (std::size_t i = 0; i < values.size(); ++i) {
    lua_createtable(L, 3, 0);
    for (int k = 0; k < 3; ++k) {
      lua_pushnumber(L, values[i][k]);
      lua_rawseti(L, -2, k + 1);
    }
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

int positions(lua_State* L) {
  pushVec3List(L, checkSim(L, 1).sim->particles().position);
  return 1;
}

int velocities(lua_State* L) {
  pushVec3List(L, checkSim(L, 1).sim->particles().velocity);
  return 1;
}

int xyz(lua_State* L) {
  const auto& pos = checkSim(L, 1).sim->particles().position;
  for (int k = 0; k < 3; ++k) {
    lua_createtable(L, static_cast<int>(pos.size()), 0);
    for (std::size_t i = 0; i < pos.size(); ++i) {
      lua_pushnumber(L, pos[i][k]);
      lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
    }
  }
  return 3;
}

int radii(lua_State* L) {
  pushNumberArray(L, checkSim(L, 1).sim->particles().radius);
  return 1;
}

int ids(lua_State* L) {
  const auto& id = checkSim(L, 1).sim->particles().id;
  lua_createtable(L, static_cast<int>(id.size()), 0);
  for (std::size_t i = 0; i < id.size(); ++i) {
    lua_pushinteger(L, static_cast<lua_Integer>(id[i]));
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

int removeIf(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  if (lua_type(L, 2) != LUA_TFUNCTION) throw InputError("sim:remove_if expects a function(i, x, y, z, r)");
  const ParticleArrays& p = h.sim->particles();
  // Ask the script first, then remove: no Lua runs inside the engine's loop.
  std::vector<char> remove(p.size(), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    lua_pushvalue(L, 2);
    lua_pushinteger(L, static_cast<lua_Integer>(i + 1));
    for (int k = 0; k < 3; ++k) lua_pushnumber(L, p.position[i][k]);
    lua_pushnumber(L, p.radius[i]);
    protectedCall(L, 5, 1);
    remove[i] = lua_toboolean(L, -1) ? 1 : 0;
    lua_pop(L, 1);
  }
  const auto removed = std::count(remove.begin(), remove.end(), 1);
  if (removed) h.sim->removeParticles([&](std::size_t i) { return remove[i] != 0; });
  lua_pushinteger(L, static_cast<lua_Integer>(removed));
  return 1;
}

int hash(lua_State* L) {
  lua_pushstring(L, stateHash(checkSim(L, 1).sim->particles()).c_str());
  return 1;
}

const SimulationMethod reg_state[] = {
    {"positions", &guarded<positions>}, {"velocities", &guarded<velocities>},
    {"xyz", &guarded<xyz>},             {"radii", &guarded<radii>},
    {"ids", &guarded<ids>},             {"remove_if", &guarded<removeIf>},
    {"state_hash", &guarded<hash>},
};

}  // namespace

}  // namespace paddy::lua
