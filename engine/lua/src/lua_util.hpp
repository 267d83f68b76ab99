// Helpers shared by the Lua bindings (private to engine/lua/src).
//
// Error discipline: Lua reports errors with longjmp, which must never cross a C++ frame that
// owns objects. Every binding therefore (1) reads its arguments with the throwing helpers below
// instead of luaL_check*, (2) calls Lua callbacks with lua_pcall and turns their errors into a
// ScriptError, and (3) is wrapped in guarded<>, which converts any C++ exception into a Lua
// error object *after* all C++ objects of the binding are gone. C++ errors get the calling
// script's "file:line:" in front (luaL_where(L, 1)).
#pragma once

#include <paddy/contact_batch.hpp>

#include <lua.hpp>

#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace paddy::lua {

// What kind of failure a Lua error object carries; decides the exit code.
enum class ErrorKind { Input, Instability, Runtime, Help };

// A Lua error caught in C++ (from a callback): the message already names file and line.
struct ScriptError : std::runtime_error {
  ScriptError(const std::string& message, ErrorKind k) : std::runtime_error(message), kind(k) {}
  ErrorKind kind;
};

// Thrown by paddy.parameters (and paddy.simulation) when the script runs only for --help.
struct HelpRequested {};

// Pushes a paddy error object: a table {kind=..., message=...} whose tostring is the message.
void pushErrorObject(lua_State* L, ErrorKind kind, const std::string& message);
// Converts the exception being handled into an error object on the stack. Never throws.
void pushCurrentException(lua_State* L) noexcept;
// Kind and text of the error value at `idx` (any Lua value; plain strings are Input errors).
ErrorKind errorKind(lua_State* L, int idx);
std::string errorMessage(lua_State* L, int idx);
// Calls the function below its `nargs` arguments with lua_pcall; on error throws ScriptError.
void protectedCall(lua_State* L, int nargs, int nresults);

template <int (*F)(lua_State*)>
int guarded(lua_State* L) {
  int results = -1;
  try {
    results = F(L);
  } catch (...) {
    pushCurrentException(L);
  }
  if (results >= 0) return results;
  return lua_error(L);  // no C++ object of this frame is alive here
}

// ---- argument reading (throw InputError naming the function and argument) ------------------
double toNumber(lua_State* L, int idx, const std::string& what);
std::string toString(lua_State* L, int idx, const std::string& what);
Vec3 toVec3(lua_State* L, int idx, const std::string& what);  // {x, y, z}

// Read-only view of an option table (raw access: metatables are ignored). Records which keys
// were read; finish() rejects the others, listing the accepted ones.
class OptionTable {
 public:
  OptionTable(lua_State* L, int idx, std::string context);
  bool has(const char* key);
  int type(const char* key);  // LUA_T* of the field (LUA_TNIL if absent)
  double number(const char* key);
  double number(const char* key, double fallback);
  std::optional<double> optNumber(const char* key);
  long long integer(const char* key, long long fallback);
  std::string string(const char* key);
  std::string string(const char* key, const std::string& fallback);
  bool boolean(const char* key, bool fallback);
  Vec3 vec3(const char* key);
  Vec3 vec3(const char* key, const Vec3& fallback);
  // Pushes the raw field onto the stack (nil if absent) and marks it used.
  int push(const char* key);
  void accept(const char* key) { used_.insert(key); }
  void finish() const;
  int index() const { return idx_; }
  const std::string& context() const { return ctx_; }

 private:
  std::string field(const char* key) const { return ctx_ + " option '" + key + "'"; }
  lua_State* L_;
  int idx_;
  std::string ctx_;
  std::set<std::string> used_;
};

// Pushes a Lua array of numbers.
void pushNumberArray(lua_State* L, const std::vector<double>& values);
// A Lua array of numbers at idx → vector (InputError naming `what`).
std::vector<double> toNumberArray(lua_State* L, int idx, const std::string& what);
// t[key] = v on the table at the top of the stack.
void setNumber(lua_State* L, const char* key, double v);
void setInteger(lua_State* L, const char* key, long long v);

}  // namespace paddy::lua
