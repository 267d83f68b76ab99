// paddy.parameters{...}: declared script parameters, --set overrides and the --help listing.
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"

#include <paddy/errors.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace paddy::lua {

namespace {

using Type = ParameterDecl::Type;

std::string joinNames(const std::vector<ParameterDecl>& decls) {
  std::string s;
  for (const auto& d : decls) s += (s.empty() ? "" : ", ") + d.name;
  return s.empty() ? "(none)" : s;
}

std::string rangeText(const ParameterDecl& d) {
  if (!d.choices.empty()) {
    std::string s;
    for (const auto& c : d.choices) s += (s.empty() ? "" : "|") + c;
    return s;
  }
  if (d.type == Type::Boolean) return "true|false";
  if (d.type == Type::String) return "";
  if (std::isinf(d.min) && std::isinf(d.max)) return "";
  std::ostringstream s;
  s << '[' << d.min << ", " << d.max << ']';
  return s.str();
}

std::string valueText(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// Checks a value against the declaration; `origin` says where it came from.
void validate(const ParameterDecl& d, const nlohmann::json& v, const std::string& origin) {
  if (d.type == Type::Number || d.type == Type::Integer) {
    try {
      checkRange(d.name, v.get<double>(), d.min, d.max, d.unit);
    } catch (const InputError& e) {
      throw InputError(origin + e.what());
    }
  }
  if (d.type == Type::String && !d.choices.empty() &&
      std::find(d.choices.begin(), d.choices.end(), v.get<std::string>()) == d.choices.end())
    throw InputError(origin + "parameter '" + d.name + "' = '" + v.get<std::string>() +
                     "' is not one of the allowed values " + rangeText(d));
}

// Parses --set text for a declared parameter.
nlohmann::json parseValue(const ParameterDecl& d, const std::string& text) {
  const std::string origin = "--set " + d.name + "=" + text + ": ";
  switch (d.type) {
    case Type::Number: {
      char* end = nullptr;
      errno = 0;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
        throw InputError(origin + "parameter '" + d.name + "' needs a number");
      return v;
    }
    case Type::Integer: {
      char* end = nullptr;
      errno = 0;
      const long long v = std::strtoll(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || errno == ERANGE)
        throw InputError(origin + "parameter '" + d.name + "' needs an integer");
      return v;
    }
    case Type::Boolean: {
      std::string t = text;
      std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return std::tolower(c); });
      if (t == "true" || t == "1" || t == "yes" || t == "on") return true;
      if (t == "false" || t == "0" || t == "no" || t == "off") return false;
      throw InputError(origin + "parameter '" + d.name + "' needs true or false");
    }
    case Type::String: return text;
  }
  return text;
}

ParameterDecl parseDecl(lua_State* L, const std::string& name, int spec_idx) {
  OptionTable spec(L, spec_idx, "paddy.parameters: parameter '" + name + "'");
  ParameterDecl d;
  d.name = name;
  spec.accept("name");
  const std::string type = spec.string("type", "");
  const int t = spec.type("default");
  if (t == LUA_TNIL) throw InputError(spec.context() + " needs a default value");
  spec.push("default");
  if (t == LUA_TNUMBER) {
    d.type = (type == "integer") ? Type::Integer : Type::Number;
    if (d.type == Type::Integer) {
      if (!lua_isinteger(L, -1)) {
        lua_pop(L, 1);
        throw InputError(spec.context() + ": the default of an integer parameter must be an integer");
      }
      d.default_value = static_cast<long long>(lua_tointeger(L, -1));
    } else {
      d.default_value = static_cast<double>(lua_tonumber(L, -1));
    }
  } else if (t == LUA_TSTRING) {
    d.type = Type::String;
    d.default_value = std::string(lua_tostring(L, -1));
  } else if (t == LUA_TBOOLEAN) {
    d.type = Type::Boolean;
    d.default_value = static_cast<bool>(lua_toboolean(L, -1));
  } else {
    lua_pop(L, 1);
    throw InputError(spec.context() + ": the default must be a number, string or boolean");
  }
  lua_pop(L, 1);
  if (!type.empty() && type != "integer" && type != "number" && type != "string" && type != "boolean")
    throw InputError(spec.context() + ": type must be number, integer, string or boolean");
  d.unit = spec.string("unit", "");
  d.description = spec.string("description", "");
  d.min = spec.number("min", d.min);
  d.max = spec.number("max", d.max);
  if (d.min > d.max) throw InputError(spec.context() + ": min > max");
  if (spec.push("choices") == LUA_TTABLE) {
    const int n = static_cast<int>(lua_rawlen(L, -1));
    for (int k = 1; k <= n; ++k) {
      lua_rawgeti(L, -1, k);
      if (lua_type(L, -1) == LUA_TSTRING) d.choices.emplace_back(lua_tostring(L, -1));
      lua_pop(L, 1);
    }
    if (static_cast<int>(d.choices.size()) != n || d.type != Type::String) {
      lua_pop(L, 1);
      throw InputError(spec.context() + ": choices must be a list of strings, for a string parameter");
    }
  }
  lua_pop(L, 1);
  spec.finish();
  validate(d, d.default_value, "paddy.parameters: the default of ");
  d.value = d.default_value;
  return d;
}

void pushValue(lua_State* L, const ParameterDecl& d) {
  switch (d.type) {
    case Type::Number: lua_pushnumber(L, d.value.get<double>()); break;
    case Type::Integer: lua_pushinteger(L, d.value.get<long long>()); break;
    case Type::Boolean: lua_pushboolean(L, d.value.get<bool>()); break;
    case Type::String: {
      const auto& s = d.value.get_ref<const std::string&>();
      lua_pushlstring(L, s.data(), s.size());
      break;
    }
  }
}

// The parameter table is an empty proxy: reads go to the values (upvalue 1) and fail for
// unknown names (typos); writes fail. pairs(P) iterates the values.
int parameterIndex(lua_State* L) {
  lua_pushvalue(L, 2);
  if (lua_rawget(L, lua_upvalueindex(1)) != LUA_TNIL) return 1;
  const char* key = lua_tostring(L, 2);
  throw InputError(std::string("unknown parameter '") + (key ? key : "?") +
                   "' (declared: " + joinNames(runtimeState(L).parameters) + ")");
}

int parameterNewIndex(lua_State*) { throw InputError("script parameters are read-only"); }

int parameterPairs(lua_State* L) {
  lua_getglobal(L, "next");
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_pushnil(L);
  return 3;
}

int parameters(lua_State* L) {
  RuntimeState& st = runtimeState(L);
  if (st.parameters_declared) throw InputError("paddy.parameters may be called only once");
  if (lua_type(L, 1) != LUA_TTABLE) throw InputError("paddy.parameters expects a table of declarations");
  std::vector<std::pair<lua_Integer, ParameterDecl>> listed;
  std::vector<ParameterDecl> named;
  lua_pushnil(L);
  while (lua_next(L, 1) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING) {
      named.push_back(parseDecl(L, lua_tostring(L, -2), -1));
    } else if (lua_isinteger(L, -2) && lua_type(L, -1) == LUA_TTABLE) {
      lua_getfield(L, -1, "name");
      const bool ok = lua_type(L, -1) == LUA_TSTRING;
      const std::string name = ok ? lua_tostring(L, -1) : "";
      lua_pop(L, 1);
      if (!ok) throw InputError("paddy.parameters: a listed declaration needs name = \"...\"");
      const lua_Integer position = lua_tointeger(L, -2);
      listed.emplace_back(position, parseDecl(L, name, -1));
    } else {
      throw InputError("paddy.parameters: entries are name = {default = ...} or {name = ..., default = ...}");
    }
    lua_pop(L, 1);
  }
  std::sort(named.begin(), named.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  std::sort(listed.begin(), listed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  st.parameters.clear();
  for (auto& entry : listed) st.parameters.push_back(std::move(entry.second));
  for (auto& d : named) {
    for (const auto& e : st.parameters)
      if (e.name == d.name) throw InputError("paddy.parameters: parameter '" + d.name + "' is declared twice");
    st.parameters.push_back(std::move(d));
  }
  st.parameters_declared = true;
  if (st.options.help) throw HelpRequested{};

  for (const auto& [name, text] : st.options.sets) {
    // (no structured binding in the capture: clang 14, used by the sanitizer builds, refuses it)
    auto it = std::find_if(st.parameters.begin(), st.parameters.end(), [&n = name](const auto& d) { return d.name == n; });
    if (it == st.parameters.end())
      throw ScriptError("--set " + name + "=" + text + ": unknown parameter '" + name +
                            "'; the script declares: " + joinNames(st.parameters),
                        ErrorKind::Input);
    try {
      nlohmann::json v = parseValue(*it, text);
      validate(*it, v, "--set " + name + "=" + text + ": ");
      it->value = std::move(v);
    } catch (const InputError& e) {
      throw ScriptError(e.what(), ErrorKind::Input);
    }
  }

  lua_newtable(L);  // the proxy returned to the script
  lua_createtable(L, 0, static_cast<int>(st.parameters.size()));  // the values
  for (const auto& d : st.parameters) {
    pushValue(L, d);
    lua_setfield(L, -2, d.name.c_str());
  }
  lua_createtable(L, 0, 3);  // metatable
  lua_pushvalue(L, -2);
  lua_pushcclosure(L, &guarded<parameterIndex>, 1);
  lua_setfield(L, -2, "__index");
  lua_pushvalue(L, -2);
  lua_pushcclosure(L, &guarded<parameterPairs>, 1);
  lua_setfield(L, -2, "__pairs");
  lua_pushcfunction(L, &guarded<parameterNewIndex>);
  lua_setfield(L, -2, "__newindex");
  lua_remove(L, -2);  // the values stay reachable through the closures
  lua_setmetatable(L, -2);
  return 1;
}

const ModuleFunction reg_parameters{"parameters", &guarded<parameters>};

}  // namespace

std::string parametersHelp(const RuntimeState& st) {
  std::ostringstream out;
  out << "Parameters of " << st.script.string() << " (override with --set name=value):\n";
  if (st.parameters.empty()) {
    out << "  (the script declares no parameters)\n";
    return out.str();
  }
  std::size_t w_name = 4, w_def = 7, w_unit = 4, w_range = 7;
  for (const auto& d : st.parameters) {
    w_name = std::max(w_name, d.name.size());
    w_def = std::max(w_def, valueText(d.default_value).size());
    w_unit = std::max(w_unit, d.unit.size());
    w_range = std::max(w_range, rangeText(d).size());
  }
  auto row = [&](const std::string& a, const std::string& b, const std::string& c, const std::string& d,
                 const std::string& e) {
    std::ostringstream line;
    line << "  " << std::left << std::setw(int(w_name)) << a << "  " << std::setw(int(w_def)) << b << "  "
         << std::setw(int(w_unit)) << c << "  " << std::setw(int(w_range)) << d << "  " << e;
    std::string text = line.str();
    while (!text.empty() && text.back() == ' ') text.pop_back();
    out << text << '\n';
  };
  row("name", "default", "unit", "allowed", "description");
  for (const auto& d : st.parameters) row(d.name, valueText(d.default_value), d.unit, rangeText(d), d.description);
  return out.str();
}

nlohmann::json parameterValues(const RuntimeState& st) {
  nlohmann::json values = nlohmann::json::object();
  for (const auto& d : st.parameters) values[d.name] = d.value;
  return values;
}

}  // namespace paddy::lua
