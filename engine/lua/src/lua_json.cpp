// JSON files from Lua, for input data (calibration targets, measured curves) and reports:
//   paddy.read_json(path)           → the document as Lua values (objects → tables with string
//                                     keys, arrays → sequences, null → nil); errors name the file
//                                     and the position of a syntax error
//   paddy.write_json(path, value)   → path; written atomically (temporary file + rename),
//                                     a relative path inside paddy.out_dir
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"

#include <paddy/errors.hpp>
#include <paddy/io/atomic_file.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace paddy::lua {

void pushJson(lua_State* L, const nlohmann::json& v, int depth) {
  using json = nlohmann::json;
  if (depth > 100) throw InputError("JSON value nested too deeply");
  luaL_checkstack(L, 4, "JSON value");
  switch (v.type()) {
    case json::value_t::null: lua_pushnil(L); break;
    case json::value_t::boolean: lua_pushboolean(L, v.get<bool>()); break;
    case json::value_t::number_integer: lua_pushinteger(L, v.get<lua_Integer>()); break;
    case json::value_t::number_unsigned: lua_pushinteger(L, static_cast<lua_Integer>(v.get<std::uint64_t>())); break;
    case json::value_t::number_float: lua_pushnumber(L, v.get<double>()); break;
    case json::value_t::string: lua_pushstring(L, v.get_ref<const std::string&>().c_str()); break;
    case json::value_t::array: {
      lua_createtable(L, static_cast<int>(v.size()), 0);
      lua_Integer i = 1;
      for (const auto& e : v) {
        pushJson(L, e, depth + 1);
        lua_rawseti(L, -2, i++);
      }
      break;
    }
    case json::value_t::object: {
      lua_createtable(L, 0, static_cast<int>(v.size()));
      for (const auto& [k, e] : v.items()) {
        pushJson(L, e, depth + 1);
        lua_setfield(L, -2, k.c_str());
      }
      break;
    }
    default: lua_pushnil(L); break;
  }
}

namespace {

namespace fs = std::filesystem;

int readJson(lua_State* L) {
  const std::string path = luaL_checkstring(L, 1);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("paddy.read_json: cannot open '" + path + "'");
  std::ostringstream text;
  text << in.rdbuf();
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {
    // parse_error, and out_of_range for a number beyond a double (1e309): both the file's fault.
    throw InputError("paddy.read_json: '" + path + "' is not valid JSON: " + e.what());
  }
  try {
    pushJson(L, doc);
  } catch (const InputError& e) {
    throw InputError("paddy.read_json: '" + path + "': " + e.what());
  }
  return 1;
}

int writeJson(lua_State* L) {
  fs::path path = luaL_checkstring(L, 1);
  if (lua_isnone(L, 2)) throw InputError("paddy.write_json(path, value): value is missing");
  if (path.is_relative()) {
    const fs::path& out = runtimeState(L).out_dir;
    if (out.empty()) throw InputError("paddy.write_json: no output directory for the relative path '" + path.string() + "'");
    path = out / path;
  }
  io::writeFileAtomic(path, toJson(L, 2).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  lua_pushstring(L, path.string().c_str());
  return 1;
}

const ModuleFunction reg_read{"read_json", &guarded<readJson>};
const ModuleFunction reg_write{"write_json", &guarded<writeJson>};

}  // namespace

}  // namespace paddy::lua
