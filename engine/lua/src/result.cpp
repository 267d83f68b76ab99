// paddy.result{...}: results the script reports, merged into DIR/result.json at the end.
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"

#include <paddy/errors.hpp>

#include <cmath>

namespace paddy::lua {

namespace {

constexpr int kMaxDepth = 32;

bool isArray(lua_State* L, int idx, lua_Integer& length) {
  length = static_cast<lua_Integer>(lua_rawlen(L, idx));
  lua_Integer count = 0;
  lua_pushnil(L);
  while (lua_next(L, idx) != 0) {
    lua_pop(L, 1);
    ++count;
    if (!lua_isinteger(L, -1)) {
      lua_pop(L, 1);
      return false;
    }
    const lua_Integer k = lua_tointeger(L, -1);
    if (k < 1 || k > length) {
      lua_pop(L, 1);
      return false;
    }
  }
  return count == length;
}

std::string keyText(lua_State* L, int idx) {
  if (lua_type(L, idx) == LUA_TSTRING) return lua_tostring(L, idx);
  if (lua_isinteger(L, idx)) return std::to_string(lua_tointeger(L, idx));
  if (lua_type(L, idx) == LUA_TNUMBER) return nlohmann::json(lua_tonumber(L, idx)).dump();
  if (lua_type(L, idx) == LUA_TBOOLEAN) return lua_toboolean(L, idx) ? "true" : "false";
  throw InputError(std::string("paddy.result: a table key of type ") + luaL_typename(L, idx) +
                   " cannot be written to JSON");
}

}  // namespace

nlohmann::json toJson(lua_State* L, int idx, int depth) {
  idx = lua_absindex(L, idx);
  if (depth > kMaxDepth) throw InputError("paddy.result: tables nested too deeply (a cycle?)");
  switch (lua_type(L, idx)) {
    case LUA_TNIL: return nullptr;
    case LUA_TBOOLEAN: return static_cast<bool>(lua_toboolean(L, idx));
    case LUA_TNUMBER:
      if (lua_isinteger(L, idx)) return static_cast<long long>(lua_tointeger(L, idx));
      return static_cast<double>(lua_tonumber(L, idx));  // NaN/inf are written as null
    case LUA_TSTRING: {
      std::size_t len = 0;
      const char* s = lua_tolstring(L, idx, &len);
      return std::string(s, len);
    }
    case LUA_TTABLE: {
      lua_Integer length = 0;
      if (isArray(L, idx, length) && length > 0) {
        nlohmann::json array = nlohmann::json::array();
        for (lua_Integer k = 1; k <= length; ++k) {
          lua_rawgeti(L, idx, k);
          array.push_back(toJson(L, -1, depth + 1));
          lua_pop(L, 1);
        }
        return array;
      }
      nlohmann::json object = nlohmann::json::object();
      lua_pushnil(L);
      while (lua_next(L, idx) != 0) {
        object[keyText(L, -2)] = toJson(L, -1, depth + 1);
        lua_pop(L, 1);
      }
      return object;
    }
    default:
      throw InputError(std::string("paddy.result: a value of type ") + luaL_typename(L, idx) +
                       " cannot be written to JSON");
  }
}

namespace {

// paddy.result{key = value, ...}: later calls add keys and overwrite earlier ones.
int result(lua_State* L) {
  if (lua_type(L, 1) != LUA_TTABLE) throw InputError("paddy.result expects a table {name = value, ...}");
  nlohmann::json values = toJson(L, 1);
  if (!values.is_object()) throw InputError("paddy.result expects named values {name = value, ...}");
  RuntimeState& st = runtimeState(L);
  for (auto& [key, value] : values.items()) st.results[key] = std::move(value);
  return 0;
}

const ModuleFunction reg_result{"result", &guarded<result>};

}  // namespace

}  // namespace paddy::lua
