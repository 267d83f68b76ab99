// A Lua state with require("paddy.doe") preloaded, for the tests of the Lua binding
// (engine/lua/src/lua_doe.cpp).
#pragma once
#include <paddy/lua/doe.hpp>

#include <lua.hpp>
#include <string>

namespace doe_test {

struct LuaState {
  lua_State* L = luaL_newstate();
  LuaState() {
    luaL_openlibs(L);
    luaL_requiref(L, "paddy.doe", luaopen_paddy_doe, 0);
    lua_pop(L, 1);
  }
  ~LuaState() { lua_close(L); }
  LuaState(const LuaState&) = delete;
  LuaState& operator=(const LuaState&) = delete;
  std::string run(const std::string& code) {  // returns "" or the error message
    if (luaL_dostring(L, code.c_str()) != LUA_OK) {
      std::string e = lua_tostring(L, -1);
      lua_pop(L, 1);
      return e;
    }
    return "";
  }
};

}  // namespace doe_test
