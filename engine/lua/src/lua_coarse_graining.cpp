// Lua bindings of coarse graining (paddy::measure::CoarseGraining, docs/measurement.md):
//   paddy.coarse_grain{alpha=, params={...}, laws={name = exponent | {exponent=, reason=} |
//                      "law name"}} → scaled params, rows (one per parameter). Every parameter
//                      needs its law in `laws` (no law is guessed from its name). A law name is
//                      first looked up among the registered contact sub-models' parameters (the
//                      law each declares in its ParamSpec), then among the built-in laws.
//   require("paddy.measure").coarse_grain, .scaling_laws (measure_module.hpp).
#include "lua_util.hpp"
#include "measure_module.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"

#include <paddy/errors.hpp>
#include <paddy/lua/runtime.hpp>
#include <paddy/measure/measure.hpp>
#include <paddy/plugin_manager.hpp>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace paddy::lua {

namespace {

namespace pm = paddy::measure;

// ---- coarse graining ----------------------------------------------------------------------------

// The coarse-graining law a registered contact sub-model declares for its parameter `param`
// (ParamSpec::coarse_graining_exponent, beside the model that defines the parameter).
std::optional<pm::ScalingLaw> declaredContactLaw(lua_State* L, const std::string& param) {
  const auto plugins = runtimeState(L).pluginManager();
  for (SubModelKind kind : {SubModelKind::Normal, SubModelKind::Damping, SubModelKind::Tangential,
                            SubModelKind::Rolling, SubModelKind::Twisting, SubModelKind::Extra})
    for (const SubModelInfo* info : plugins->subModels(kind))
      for (const ParamSpec& p : info->params)
        if (p.name == param)
          return pm::ScalingLaw{param, p.coarse_graining_exponent,
                                std::string(toString(kind)) + " '" + info->name + "': " + p.coarse_graining_reason};
  return std::nullopt;
}

// paddy.coarse_grain{alpha=, params={name=value,...}, laws={name = exponent | "law" |
//                    {exponent=, reason=}}} → scaled {name=value}, rows {{name, law, reference,
//                    scaled, factor, exponent, changed, reason}, ...} (rows in name order)
int coarseGrain(lua_State* L) {
  OptionTable opt(L, 1, "coarse_grain");
  const double alpha = opt.number("alpha");
  // The laws the script declares (every parameter needs one).
  std::map<std::string, pm::ScalingLaw> explicit_laws;
  std::map<std::string, std::string> law_names;  // parameter → law name given as a string
  if (opt.push("laws") != LUA_TNIL) {
    if (!lua_istable(L, -1)) throw InputError("coarse_grain option 'laws' must be a table");
    const int t = lua_gettop(L);
    lua_pushnil(L);
    while (lua_next(L, t) != 0) {
      if (lua_type(L, -2) != LUA_TSTRING) throw InputError("coarse_grain: laws keys must be parameter names");
      const std::string name = lua_tostring(L, -2);
      pm::ScalingLaw law{name, 0.0, "given by the script"};
      if (lua_type(L, -1) == LUA_TNUMBER) {
        law.exponent = lua_tonumber(L, -1);
      } else if (lua_type(L, -1) == LUA_TSTRING) {
        // A contact sub-model's parameter name (its declared law) first, then a built-in law.
        const std::string law_name = lua_tostring(L, -1);
        if (const auto declared = declaredContactLaw(L, law_name)) {
          law.exponent = declared->exponent;
          law.reason = law_name + " (" + declared->reason + ")";
        } else {
          const pm::ScalingLaw& known = pm::CoarseGraining::law(law_name);
          law.exponent = known.exponent;
          law.reason = known.name + ": " + known.reason;
        }
        law_names[name] = law_name;
      } else if (lua_istable(L, -1)) {
        OptionTable lt(L, -1, "coarse_grain laws." + name);
        law.exponent = lt.number("exponent");
        law.reason = lt.string("reason", law.reason);
        lt.finish();
      } else {
        throw InputError("coarse_grain: laws." + name + " must be an exponent, a law name or {exponent=, reason=}");
      }
      explicit_laws[name] = law;
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
  ParamValues params;
  if (opt.push("params") != LUA_TTABLE) throw InputError("coarse_grain needs option 'params' (a table name = value)");
  const int t = lua_gettop(L);
  lua_pushnil(L);
  while (lua_next(L, t) != 0) {
    if (lua_type(L, -2) != LUA_TSTRING || lua_type(L, -1) != LUA_TNUMBER)
      throw InputError("coarse_grain: params must map names to numbers");
    params[lua_tostring(L, -2)] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  opt.finish();

  std::vector<pm::ScalingLaw> extra;
  std::map<std::string, std::string> law_of;  // parameter → law it follows
  for (const auto& [name, value] : params) {
    (void)value;
    const auto it = explicit_laws.find(name);
    if (it == explicit_laws.end()) {
      std::string known;
      for (const auto& l : pm::CoarseGraining::laws()) known += (known.empty() ? "" : ", ") + l.name;
      throw InputError("coarse_grain: parameter '" + name + "' has no scaling law; declare it in laws = {" + name +
                       " = ...}: an exponent k (p_cg = alpha^k p_ref), {exponent =, reason =}, the name of a "
                       "contact sub-model parameter whose declared law it follows, or a built-in law (" +
                       known + ")");
    }
    extra.push_back(it->second);
    law_of[name] = law_names.count(name) ? law_names[name] : "given";
  }
  const pm::ScaledParameters s = pm::scaleParameters(params, alpha, extra);
  lua_createtable(L, 0, static_cast<int>(s.values.size()));
  for (const auto& [name, value] : s.values) setNumber(L, name.c_str(), value);
  lua_createtable(L, static_cast<int>(s.table.size()), 0);
  for (std::size_t k = 0; k < s.table.size(); ++k) {
    const pm::ScalingRow& row = s.table[k];
    lua_createtable(L, 0, 8);
    lua_pushstring(L, row.name.c_str());
    lua_setfield(L, -2, "name");
    lua_pushstring(L, law_of[row.name].c_str());
    lua_setfield(L, -2, "law");
    setNumber(L, "reference", row.reference);
    setNumber(L, "scaled", row.scaled);
    setNumber(L, "factor", row.factor);
    setNumber(L, "exponent", row.exponent);
    lua_pushboolean(L, row.scaled != row.reference);
    lua_setfield(L, -2, "changed");
    lua_pushstring(L, row.reason.c_str());
    lua_setfield(L, -2, "reason");
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 2;
}

// scaling_laws() → {{name=, exponent=, reason=}, ...}
int scalingLaws(lua_State* L) {
  const auto& laws = pm::CoarseGraining::laws();
  lua_createtable(L, static_cast<int>(laws.size()), 0);
  for (std::size_t k = 0; k < laws.size(); ++k) {
    lua_createtable(L, 0, 3);
    lua_pushstring(L, laws[k].name.c_str());
    lua_setfield(L, -2, "name");
    setNumber(L, "exponent", laws[k].exponent);
    lua_pushstring(L, laws[k].reason.c_str());
    lua_setfield(L, -2, "reason");
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 1;
}

const ModuleFunction reg_coarse_grain{"coarse_grain", &guarded<coarseGrain>};

}  // namespace

const luaL_Reg kCoarseGrainingFunctions[] = {
    {"coarse_grain", &guarded<coarseGrain>},
    {"scaling_laws", &guarded<scalingLaws>},
    {nullptr, nullptr},
};

}  // namespace paddy::lua
