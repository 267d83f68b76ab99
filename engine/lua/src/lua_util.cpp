// Error objects, protected calls and argument readers for the Lua bindings.
#include "lua_util.hpp"

#include <paddy/errors.hpp>

#include <cmath>
#include <sstream>

namespace paddy::lua {

namespace {

const char* kErrorMeta = "paddy.error";

const char* kindName(ErrorKind k) {
  switch (k) {
    case ErrorKind::Input: return "input";
    case ErrorKind::Instability: return "instability";
    case ErrorKind::Runtime: return "runtime";
    case ErrorKind::Help: return "help";
  }
  return "runtime";
}

int errorToString(lua_State* L) {
  lua_getfield(L, 1, "message");
  return 1;
}

std::string where(lua_State* L) {
  luaL_where(L, 1);
  std::string w = lua_tostring(L, -1);
  lua_pop(L, 1);
  return w;
}

}  // namespace

void pushErrorObject(lua_State* L, ErrorKind kind, const std::string& message) {
  lua_createtable(L, 0, 2);
  lua_pushstring(L, kindName(kind));
  lua_setfield(L, -2, "kind");
  lua_pushlstring(L, message.data(), message.size());
  lua_setfield(L, -2, "message");
  if (luaL_newmetatable(L, kErrorMeta)) {
    lua_pushcfunction(L, errorToString);
    lua_setfield(L, -2, "__tostring");
  }
  lua_setmetatable(L, -2);
}

void pushCurrentException(lua_State* L) noexcept {
  try {
    try {
      throw;
    } catch (const HelpRequested&) {
      pushErrorObject(L, ErrorKind::Help, "help requested");
    } catch (const ScriptError& e) {
      pushErrorObject(L, e.kind, e.what());
    } catch (const InputError& e) {
      pushErrorObject(L, ErrorKind::Input, where(L) + " " + e.what());
    } catch (const InstabilityError& e) {
      pushErrorObject(L, ErrorKind::Instability, where(L) + " " + e.what());
    } catch (const std::exception& e) {
      pushErrorObject(L, ErrorKind::Runtime, where(L) + " " + e.what());
    } catch (...) {
      pushErrorObject(L, ErrorKind::Runtime, where(L) + " unknown error");
    }
  } catch (...) {
    lua_pushstring(L, "out of memory while reporting an error");
  }
}

ErrorKind errorKind(lua_State* L, int idx) {
  if (lua_type(L, idx) != LUA_TTABLE) return ErrorKind::Input;
  lua_getfield(L, idx, "kind");
  const char* k = lua_tostring(L, -1);
  ErrorKind kind = ErrorKind::Input;
  if (k) {
    const std::string s = k;
    if (s == "instability") kind = ErrorKind::Instability;
    else if (s == "runtime") kind = ErrorKind::Runtime;
    else if (s == "help") kind = ErrorKind::Help;
  }
  lua_pop(L, 1);
  return kind;
}

std::string errorMessage(lua_State* L, int idx) {
  idx = lua_absindex(L, idx);
  if (lua_type(L, idx) == LUA_TTABLE) {
    lua_getfield(L, idx, "message");
    std::string m = lua_isstring(L, -1) ? lua_tostring(L, -1) : "(error object without message)";
    lua_pop(L, 1);
    return m;
  }
  if (lua_isstring(L, idx)) return lua_tostring(L, idx);
  return std::string("(error object is a ") + luaL_typename(L, idx) + ")";
}

void protectedCall(lua_State* L, int nargs, int nresults) {
  if (lua_pcall(L, nargs, nresults, 0) != LUA_OK) {
    const ErrorKind kind = errorKind(L, -1);
    std::string message = errorMessage(L, -1);
    lua_pop(L, 1);
    if (kind == ErrorKind::Help) throw HelpRequested{};
    throw ScriptError(message, kind);
  }
}

// ---- argument readers -------------------------------------------------------------------------

double toNumber(lua_State* L, int idx, const std::string& what) {
  if (lua_type(L, idx) != LUA_TNUMBER)
    throw InputError(what + " must be a number (got " + luaL_typename(L, idx) + ")");
  return lua_tonumber(L, idx);
}

std::string toString(lua_State* L, int idx, const std::string& what) {
  if (lua_type(L, idx) != LUA_TSTRING)
    throw InputError(what + " must be a string (got " + luaL_typename(L, idx) + ")");
  std::size_t len = 0;
  const char* s = lua_tolstring(L, idx, &len);
  return std::string(s, len);
}

Vec3 toVec3(lua_State* L, int idx, const std::string& what) {
  idx = lua_absindex(L, idx);
  if (lua_type(L, idx) != LUA_TTABLE || lua_rawlen(L, idx) != 3)
    throw InputError(what + " must be a table of 3 numbers {x, y, z}");
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    lua_rawgeti(L, idx, k + 1);
    const bool ok = lua_type(L, -1) == LUA_TNUMBER;
    v[k] = lua_tonumber(L, -1);
    lua_pop(L, 1);
    if (!ok) throw InputError(what + " must be a table of 3 numbers {x, y, z}");
  }
  return v;
}

void pushNumberArray(lua_State* L, const std::vector<double>& values) {
  lua_createtable(L, static_cast<int>(values.size()), 0);
  for (std::size_t i = 0; i < values.size(); ++i) {
    lua_pushnumber(L, values[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
}

// ---- OptionTable ------------------------------------------------------------------------------

OptionTable::OptionTable(lua_State* L, int idx, std::string context)
    : L_(L), idx_(lua_absindex(L, idx)), ctx_(std::move(context)) {
  if (lua_type(L, idx_) != LUA_TTABLE)
    throw InputError(ctx_ + " expects a table of options (got " + luaL_typename(L, idx_) + ")");
}

int OptionTable::push(const char* key) {
  used_.insert(key);
  lua_pushstring(L_, key);
  return lua_rawget(L_, idx_);
}

int OptionTable::type(const char* key) {
  const int t = push(key);
  lua_pop(L_, 1);
  return t;
}

bool OptionTable::has(const char* key) { return type(key) != LUA_TNIL; }

std::optional<double> OptionTable::optNumber(const char* key) {
  const int t = push(key);
  if (t == LUA_TNIL) {
    lua_pop(L_, 1);
    return std::nullopt;
  }
  const double v = lua_tonumber(L_, -1);
  lua_pop(L_, 1);
  if (t != LUA_TNUMBER) throw InputError(field(key) + " must be a number");
  if (std::isnan(v)) throw InputError(field(key) + " is NaN");
  return v;
}

double OptionTable::number(const char* key) {
  const auto v = optNumber(key);
  if (!v) throw InputError(ctx_ + " needs option '" + key + "'");
  return *v;
}

double OptionTable::number(const char* key, double fallback) { return optNumber(key).value_or(fallback); }

long long OptionTable::integer(const char* key, long long fallback) {
  const auto v = optNumber(key);
  if (!v) return fallback;
  if (std::floor(*v) != *v || std::fabs(*v) > 9.0e15) throw InputError(field(key) + " must be an integer");
  return static_cast<long long>(*v);
}

std::string OptionTable::string(const char* key) {
  const int t = push(key);
  if (t == LUA_TNIL) {
    lua_pop(L_, 1);
    throw InputError(ctx_ + " needs option '" + key + "'");
  }
  if (t != LUA_TSTRING) {
    lua_pop(L_, 1);
    throw InputError(field(key) + " must be a string");
  }
  std::string s = lua_tostring(L_, -1);
  lua_pop(L_, 1);
  return s;
}

std::string OptionTable::string(const char* key, const std::string& fallback) {
  return has(key) ? string(key) : fallback;
}

bool OptionTable::boolean(const char* key, bool fallback) {
  const int t = push(key);
  const bool v = lua_toboolean(L_, -1);
  lua_pop(L_, 1);
  if (t == LUA_TNIL) return fallback;
  if (t != LUA_TBOOLEAN) throw InputError(field(key) + " must be true or false");
  return v;
}

Vec3 OptionTable::vec3(const char* key) {
  push(key);
  if (lua_isnil(L_, -1)) {
    lua_pop(L_, 1);
    throw InputError(ctx_ + " needs option '" + key + "'");
  }
  try {
    const Vec3 v = toVec3(L_, -1, field(key));
    lua_pop(L_, 1);
    return v;
  } catch (...) {
    lua_pop(L_, 1);
    throw;
  }
}

Vec3 OptionTable::vec3(const char* key, const Vec3& fallback) { return has(key) ? vec3(key) : fallback; }

void OptionTable::finish() const {
  std::vector<std::string> unknown;
  lua_pushnil(L_);
  while (lua_next(L_, idx_) != 0) {
    lua_pop(L_, 1);  // value
    if (lua_type(L_, -1) != LUA_TSTRING) {
      unknown.push_back(lua_type(L_, -1) == LUA_TNUMBER ? "[" + std::to_string(lua_tointeger(L_, -1)) + "]"
                                                        : std::string("<") + luaL_typename(L_, -1) + ">");
    } else if (!used_.count(lua_tostring(L_, -1))) {
      unknown.push_back(lua_tostring(L_, -1));
    }
  }
  if (unknown.empty()) return;
  std::ostringstream msg;
  msg << ctx_ << ": unknown option" << (unknown.size() > 1 ? "s " : " ");
  for (std::size_t k = 0; k < unknown.size(); ++k) msg << (k ? ", '" : "'") << unknown[k] << "'";
  msg << " (accepted:";
  for (const auto& name : used_) msg << ' ' << name;
  msg << ")";
  throw InputError(msg.str());
}

// A Lua array of numbers at idx → vector (InputError naming `what`).
std::vector<double> toNumberArray(lua_State* L, int idx, const std::string& what) {
  idx = lua_absindex(L, idx);
  if (lua_type(L, idx) != LUA_TTABLE) throw InputError(what + " must be an array of numbers");
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, idx));
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(n));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, idx, i);
    const bool ok = lua_type(L, -1) == LUA_TNUMBER;
    const double v = lua_tonumber(L, -1);
    lua_pop(L, 1);
    if (!ok) throw InputError(what + "[" + std::to_string(i) + "] is not a number");
    out.push_back(v);
  }
  return out;
}

void setNumber(lua_State* L, const char* key, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, key);
}
void setInteger(lua_State* L, const char* key, long long v) {
  lua_pushinteger(L, static_cast<lua_Integer>(v));
  lua_setfield(L, -2, key);
}

}  // namespace paddy::lua
