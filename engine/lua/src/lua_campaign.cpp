// Lua binding of the campaign runner (self-registering, see lua/registry.hpp):
//
//   local c = paddy.campaign{dir = "calib", executor = "local" | "slurm", max_parallel = 2,
//                            threads_per_job = 1, max_attempts = 2, progress = true,
//                            paddy_executable = ..., code_version = ...,
//                            slurm = {partition = "debug", time = "00:30:00", cpus_per_task = 2,
//                                     extra_args = {"--mem=4G"}, poll_interval = 5}}
//   local key = c:submit{script = "slump.lua", params = {restitution = 0.13}, seed = 1, threads = 2}
//   local runs = c:run()      -- in submission order: {key=, status="done"|"failed",
//                             --   result={...results...}, metadata={...}, error="..."}
//   c:run{k1, k2}             -- runs everything queued, reports only these jobs, in this order
//   c:result(key) → the job's results table (nil, message if it is not done)
//   c:status(key) → "queued" | "running" | "done" | "failed";   c:keys() → keys in order
//
// dir defaults to <paddy.out_dir>/campaign; a relative script is looked up in the working
// directory, then beside the calling script. See docs/campaign.md.
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"

#include <paddy/campaign/campaign.hpp>
#include <paddy/errors.hpp>

#include <memory>

namespace paddy::lua {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using paddy::campaign::Campaign;
using paddy::campaign::CampaignOptions;
using paddy::campaign::JobSpec;
using paddy::campaign::JobStatus;

const char* kCampaignMeta = "paddy.Campaign";

struct CampaignHandle {
  Campaign* campaign;
  std::vector<std::string>* submitted;  // keys in submission order, repeats included
};

CampaignHandle& checkCampaign(lua_State* L, int idx) {
  auto* h = static_cast<CampaignHandle*>(luaL_testudata(L, idx, kCampaignMeta));
  if (!h || !h->campaign) throw InputError("expected a campaign (from paddy.campaign{...}) as the receiver; use c:method()");
  return *h;
}

// Directories of package.path's "<dir>/?.lua" entries: where require() finds modules.
std::vector<fs::path> luaModuleDirs(lua_State* L) {
  std::vector<fs::path> dirs;
  lua_getglobal(L, "package");
  if (lua_type(L, -1) == LUA_TTABLE) {
    lua_getfield(L, -1, "path");
    if (lua_type(L, -1) == LUA_TSTRING) {
      std::string path = lua_tostring(L, -1);
      std::size_t start = 0;
      while (start <= path.size()) {
        const auto end = std::min(path.find(';', start), path.size());
        const std::string entry = path.substr(start, end - start);
        const std::string suffix = "/?.lua";
        if (entry.size() > suffix.size() && entry.compare(entry.size() - suffix.size(), suffix.size(), suffix) == 0)
          dirs.emplace_back(entry.substr(0, entry.size() - suffix.size()));
        start = end + 1;
      }
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return dirs;
}

int gcCampaign(lua_State* L) {
  auto* h = static_cast<CampaignHandle*>(luaL_testudata(L, 1, kCampaignMeta));
  if (h) {
    delete h->campaign;
    delete h->submitted;
    h->campaign = nullptr;
    h->submitted = nullptr;
  }
  return 0;
}

int submit(lua_State* L) {
  CampaignHandle& h = checkCampaign(L, 1);
  OptionTable opt(L, 2, "c:submit");
  JobSpec spec;
  std::string script = opt.string("script");
  std::error_code ec;
  if (fs::path(script).is_relative() && !fs::is_regular_file(script, ec)) {
    try {
      const fs::path beside = fs::absolute(runtimeState(L).script).parent_path() / script;
      if (fs::is_regular_file(beside, ec)) script = beside.string();
    } catch (const std::exception&) {
    }
  }
  if (!fs::is_regular_file(script, ec)) throw InputError("c:submit: cannot find script '" + script + "'");
  spec.script = script;
  lua_getglobal(L, "paddy");
  lua_getfield(L, -1, "seed");
  const long long default_seed = lua_isinteger(L, -1) ? lua_tointeger(L, -1) : 1;
  lua_pop(L, 2);
  const long long seed = opt.integer("seed", default_seed);
  if (seed < 0) throw InputError("c:submit: seed must not be negative");
  spec.seed = static_cast<std::uint64_t>(seed);
  if (opt.has("threads")) spec.threads = static_cast<int>(opt.integer("threads", 1));
  if (opt.push("params") == LUA_TTABLE) {
    const int t = lua_gettop(L);
    lua_pushnil(L);
    while (lua_next(L, t) != 0) {
      if (lua_type(L, -2) != LUA_TSTRING) throw InputError("c:submit: params must be a table name = value");
      const std::string name = lua_tostring(L, -2);
      switch (lua_type(L, -1)) {
        case LUA_TNUMBER:
          if (lua_isinteger(L, -1))
            spec.set(name, static_cast<long long>(lua_tointeger(L, -1)));
          else
            spec.set(name, lua_tonumber(L, -1));
          break;
        case LUA_TBOOLEAN: spec.set(name, lua_toboolean(L, -1) != 0); break;
        case LUA_TSTRING: spec.set(name, std::string(lua_tostring(L, -1))); break;
        default: throw InputError("c:submit: parameter '" + name + "' must be a number, string or boolean");
      }
      lua_pop(L, 1);
    }
  } else if (lua_type(L, -1) != LUA_TNIL) {
    throw InputError("c:submit: params must be a table");
  }
  lua_pop(L, 1);
  opt.finish();
  const std::string key = h.campaign->submit(spec);
  h.submitted->push_back(key);
  lua_pushstring(L, key.c_str());
  return 1;
}

void pushRun(lua_State* L, const Campaign& c, const std::string& key) {
  const auto& rec = c.record(key);
  lua_createtable(L, 0, 6);
  lua_pushstring(L, key.c_str());
  lua_setfield(L, -2, "key");
  lua_pushstring(L, paddy::campaign::statusName(rec.status));
  lua_setfield(L, -2, "status");
  lua_pushstring(L, rec.dir.string().c_str());
  lua_setfield(L, -2, "dir");
  if (rec.status == JobStatus::Done) {
    const json doc = c.result(key);
    pushJson(L, doc.value("results", json::object()));
    lua_setfield(L, -2, "result");
    pushJson(L, doc.value("metadata", json::object()));
    lua_setfield(L, -2, "metadata");
  } else if (!rec.error.empty()) {
    lua_pushstring(L, rec.error.c_str());
    lua_setfield(L, -2, "error");
  }
}

int run(lua_State* L) {
  CampaignHandle& h = checkCampaign(L, 1);
  // c:run(keys): report only these jobs (in this order), so a script that submits in rounds
  // does not read every earlier result again each round.
  std::vector<std::string> only;
  const bool subset = !lua_isnoneornil(L, 2);
  if (subset) {
    if (!lua_istable(L, 2)) throw InputError("c:run: the argument must be a list of job keys (from c:submit)");
    const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, 2));
    for (lua_Integer k = 1; k <= n; ++k) {
      lua_rawgeti(L, 2, k);
      only.push_back(toString(L, -1, "c:run keys[" + std::to_string(k) + "]"));
      lua_pop(L, 1);
      h.campaign->record(only.back());  // unknown key: an error naming it, before anything runs
    }
  }
  h.campaign->runAll();
  const auto& keys = subset ? only : *h.submitted;
  lua_createtable(L, static_cast<int>(keys.size()), 0);
  lua_Integer i = 1;
  for (const auto& key : keys) {
    pushRun(L, *h.campaign, key);
    lua_rawseti(L, -2, i++);
  }
  return 1;
}

int result(lua_State* L) {
  CampaignHandle& h = checkCampaign(L, 1);
  const std::string key = toString(L, 2, "c:result key");
  const auto& rec = h.campaign->record(key);
  if (rec.status != JobStatus::Done) {
    lua_pushnil(L);
    lua_pushstring(L, ("job " + key + " is " + paddy::campaign::statusName(rec.status) +
                       (rec.error.empty() ? "" : ": " + rec.error)).c_str());
    return 2;
  }
  pushJson(L, h.campaign->result(key).value("results", json::object()));
  return 1;
}

int status(lua_State* L) {
  CampaignHandle& h = checkCampaign(L, 1);
  lua_pushstring(L, paddy::campaign::statusName(h.campaign->status(toString(L, 2, "c:status key"))));
  return 1;
}

int keys(lua_State* L) {
  CampaignHandle& h = checkCampaign(L, 1);
  const auto k = h.campaign->keys();
  lua_createtable(L, static_cast<int>(k.size()), 0);
  for (std::size_t i = 0; i < k.size(); ++i) {
    lua_pushstring(L, k[i].c_str());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  return 1;
}

std::vector<std::string> stringList(lua_State* L, int idx, const std::string& what) {
  std::vector<std::string> out;
  if (lua_type(L, idx) == LUA_TNIL) return out;
  if (lua_type(L, idx) != LUA_TTABLE) throw InputError(what + " must be a list of strings");
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, idx));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, idx, i);
    out.push_back(toString(L, -1, what));
    lua_pop(L, 1);
  }
  return out;
}

int newCampaign(lua_State* L) {
  OptionTable opt(L, 1, "paddy.campaign");
  CampaignOptions o;
  std::string default_dir = "campaign";
  try {
    const auto& st = runtimeState(L);
    if (!st.out_dir.empty()) default_dir = (st.out_dir / "campaign").string();
  } catch (const std::exception&) {
  }
  o.dir = opt.string("dir", default_dir);
  o.executor = opt.string("executor", "local");
  o.max_parallel = static_cast<int>(opt.integer("max_parallel", 0));
  o.threads_per_job = static_cast<int>(opt.integer("threads_per_job", 0));
  o.max_attempts = static_cast<int>(opt.integer("max_attempts", 2));
  o.paddy_executable = opt.string("paddy_executable", "");
  o.code_version = opt.string("code_version", "");
  o.progress = opt.boolean("progress", true);
  o.progress_interval = opt.number("progress_interval", 10.0);
  o.module_path = luaModuleDirs(L);
  if (opt.push("slurm") == LUA_TTABLE) {
    OptionTable s(L, -1, "paddy.campaign slurm");
    o.slurm.partition = s.string("partition", "");
    o.slurm.time = s.string("time", "");
    o.slurm.cpus_per_task = static_cast<int>(s.integer("cpus_per_task", 0));
    o.slurm.poll_interval = s.number("poll_interval", 5.0);
    s.push("extra_args");
    o.slurm.extra_args = stringList(L, lua_gettop(L), "paddy.campaign slurm.extra_args");
    lua_pop(L, 1);
    s.finish();
  } else if (lua_type(L, -1) != LUA_TNIL) {
    throw InputError("paddy.campaign option 'slurm' must be a table");
  }
  lua_pop(L, 1);
  opt.finish();

  auto campaign = std::make_unique<Campaign>(o);
  auto submitted = std::make_unique<std::vector<std::string>>();
  auto* h = static_cast<CampaignHandle*>(lua_newuserdatauv(L, sizeof(CampaignHandle), 0));
  h->campaign = nullptr;
  h->submitted = nullptr;
  if (luaL_newmetatable(L, kCampaignMeta)) {
    lua_pushcfunction(L, gcCampaign);
    lua_setfield(L, -2, "__gc");
    static const luaL_Reg methods[] = {{"submit", &guarded<submit>}, {"run", &guarded<run>},
                                       {"result", &guarded<result>}, {"status", &guarded<status>},
                                       {"keys", &guarded<keys>},     {nullptr, nullptr}};
    lua_newtable(L);
    luaL_setfuncs(L, methods, 0);
    lua_setfield(L, -2, "__index");
  }
  lua_setmetatable(L, -2);
  h->campaign = campaign.release();
  h->submitted = submitted.release();
  return 1;
}

const ModuleFunction reg_campaign{"campaign", &guarded<newCampaign>};

}  // namespace

}  // namespace paddy::lua
