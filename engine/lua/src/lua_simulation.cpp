// paddy.simulation{...} and the basic Simulation methods: materials, interactions, particles,
// time step and scalar queries. Further method groups register themselves (see registry.hpp):
// lua_run.cpp, lua_fill.cpp, lua_state.cpp, lua_output.cpp, lua_wall.cpp.
#include "lua_util.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"
#include "sim_handle.hpp"
#include "thread_contention.hpp"

#include <paddy/errors.hpp>
#include <paddy/plugin_manager.hpp>

#include <algorithm>
#include <cstdio>

namespace paddy::lua {

SimHandle& checkSim(lua_State* L, int idx) {
  auto** slot = static_cast<SimHandle**>(luaL_testudata(L, idx, kSimulationMeta));
  if (!slot) throw InputError("expected a simulation (call methods with ':', e.g. sim:run{...})");
  if (!*slot) throw InputError("the simulation has been closed");
  return **slot;
}

int materialArg(lua_State* L, SimHandle& h, int idx, const std::string& what) {
  if (lua_type(L, idx) == LUA_TSTRING) return h.sim->materialId(lua_tostring(L, idx));
  if (!lua_isinteger(L, idx)) throw InputError(what + " must be a material id (from sim:material) or name");
  const lua_Integer id = lua_tointeger(L, idx);
  if (id < 0 || id >= static_cast<lua_Integer>(h.sim->materials().size()))
    throw InputError(what + " = " + std::to_string(id) + " is not a material of this simulation");
  return static_cast<int>(id);
}

double ensureTimeStep(Simulation& sim) {
  if (sim.timeStep() <= 0.0) sim.setTimeStepFraction(TimeStepPolicy::kDefaultRayleighFraction);
  return sim.timeStep();
}

namespace {

// paddy.simulation{gravity = {0,0,-9.81}, threads = paddy.threads, skin = 0.4, sort_interval = 20}
int newSimulation(lua_State* L) {
  RuntimeState& st = runtimeState(L);
  if (st.options.help) throw HelpRequested{};
  if (!st.parameters_declared && !st.options.sets.empty())
    throw InputError("--set was given but the script declares no parameters (paddy.parameters)");
  if (lua_isnone(L, 1)) lua_newtable(L);
  OptionTable opt(L, 1, "paddy.simulation");
  auto handle = std::make_unique<SimHandle>();
  handle->sim = std::make_unique<Simulation>(st.pluginManager());
  Simulation& sim = *handle->sim;
  sim.setGravity(opt.vec3("gravity", Vec3(0.0, 0.0, -9.81)));
  const long long threads = opt.integer("threads", st.threads);
  if (threads < 1) throw InputError("paddy.simulation: threads must be >= 1");
  sim.setThreads(static_cast<int>(threads));
  if (threads > 1 && !st.contention_checked) {  // once per run, at the first parallel simulation
    st.contention_checked = true;
    if (const auto load = currentCpuLoad()) {
      const std::string warning = contentionWarning(static_cast<int>(threads), *load, passiveWaitPolicy());
      if (!warning.empty()) std::fprintf(stderr, "%s\n", warning.c_str());
    }
  }
  if (auto skin = opt.optNumber("skin")) sim.setSkinFraction(*skin);
  if (opt.has("sort_interval")) sim.setSortInterval(static_cast<int>(opt.integer("sort_interval", 20)));
  ++st.simulations;
  const std::string dir = st.simulations == 1 ? "snapshots" : "snapshots_" + std::to_string(st.simulations);
  handle->snapshot_dir = st.out_dir / opt.string("snapshot_dir", dir);
  opt.finish();

  auto** slot = static_cast<SimHandle**>(lua_newuserdatauv(L, sizeof(SimHandle*), 0));
  *slot = handle.release();
  luaL_setmetatable(L, kSimulationMeta);
  return 1;
}

int gc(lua_State* L) {
  auto** slot = static_cast<SimHandle**>(luaL_testudata(L, 1, kSimulationMeta));
  if (slot && *slot) {
    delete *slot;
    *slot = nullptr;
  }
  return 0;
}

int simToString(lua_State* L) {
  const SimHandle& h = checkSim(L, 1);
  char buf[128];
  std::snprintf(buf, sizeof buf, "paddy.simulation(%zu particles, t = %g s)", h.sim->particles().size(),
                h.sim->time());
  lua_pushstring(L, buf);
  return 1;
}

// sim:material{name=, density=, shear_modulus=, poisson=} → material id
int material(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  OptionTable opt(L, 2, "sim:material");
  Material m;
  m.name = opt.string("name");
  m.density = opt.number("density");
  m.shear_modulus = opt.number("shear_modulus");
  m.poisson = opt.number("poisson");
  opt.finish();
  lua_pushinteger(L, h.sim->addMaterial(m));
  return 1;
}

// sim:interaction(m1, m2, {normal=, damping=, tangential=, rolling=, twisting=, extras={...},
//                          <parameter> = number, ...})
int interaction(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  const int a = materialArg(L, h, 2, "sim:interaction: first material");
  const int b = materialArg(L, h, 3, "sim:interaction: second material");
  if (lua_type(L, 4) != LUA_TTABLE) throw InputError("sim:interaction(m1, m2, {...}) needs a table of sub-models and parameters");
  InteractionSpec spec;
  std::vector<std::string> used;
  lua_pushnil(L);
  while (lua_next(L, 4) != 0) {
    if (lua_type(L, -2) != LUA_TSTRING) throw InputError("sim:interaction: keys must be names");
    const std::string key = lua_tostring(L, -2);
    std::string* slot = key == "normal" ? &spec.normal
                        : key == "damping" ? &spec.damping
                        : key == "tangential" ? &spec.tangential
                        : key == "rolling" ? &spec.rolling
                        : key == "twisting" ? &spec.twisting
                                            : nullptr;
    if (slot) {
      if (lua_type(L, -1) == LUA_TBOOLEAN && !lua_toboolean(L, -1)) *slot = "";  // rolling = false
      else *slot = toString(L, -1, "sim:interaction: " + key);
    } else if (key == "extras") {
      if (lua_type(L, -1) != LUA_TTABLE) throw InputError("sim:interaction: extras must be a list of names");
      const auto n = lua_rawlen(L, -1);
      for (lua_Unsigned k = 1; k <= n; ++k) {
        lua_rawgeti(L, -1, static_cast<lua_Integer>(k));
        spec.extras.push_back(toString(L, -1, "sim:interaction: extras[" + std::to_string(k) + "]"));
        lua_pop(L, 1);
      }
    } else {
      spec.params[key] = toNumber(L, -1, "sim:interaction: parameter '" + key + "'");
    }
    lua_pop(L, 1);
  }
  h.sim->setInteraction(a, b, spec);
  RuntimeState& st = runtimeState(L);
  const std::pair<const char*, const std::string*> slots[] = {{"normal", &spec.normal},   {"damping", &spec.damping},
                                                              {"tangential", &spec.tangential},
                                                              {"rolling", &spec.rolling}, {"twisting", &spec.twisting}};
  for (const auto& [kind, name] : slots)
    if (!name->empty()) st.models_used.insert(std::string(kind) + ":" + *name);
  for (const auto& e : spec.extras) st.models_used.insert("extra:" + e);
  return 0;
}

// sim:add_particle{pos={x,y,z}, radius=r, material=m, vel={...}, omega={...}} → index (1-based)
int addParticle(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  OptionTable opt(L, 2, "sim:add_particle");
  const Vec3 x = opt.vec3("pos");
  const double r = opt.number("radius");
  opt.push("material");
  const int m = materialArg(L, h, -1, "sim:add_particle: material");
  lua_pop(L, 1);
  const Vec3 v = opt.vec3("vel", Vec3::Zero());
  const Vec3 w = opt.vec3("omega", Vec3::Zero());
  opt.finish();
  if (!(r > 0.0)) throw InputError("sim:add_particle: radius must be > 0");
  lua_pushinteger(L, static_cast<lua_Integer>(h.sim->addParticle(x, r, m, v, w)) + 1);
  return 1;
}

// sim:timestep{fraction=0.2} | sim:timestep{dt=1e-6} | sim:timestep() → dt [s]
int timestep(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  if (!lua_isnoneornil(L, 2)) {
    OptionTable opt(L, 2, "sim:timestep");
    const auto fraction = opt.optNumber("fraction");
    const auto dt = opt.optNumber("dt");
    opt.finish();
    if (fraction && dt) throw InputError("sim:timestep: give either fraction or dt, not both");
    if (dt) h.sim->setTimeStep(*dt);
    else if (fraction) h.sim->setTimeStepFraction(*fraction);
    else throw InputError("sim:timestep needs fraction = (of the Rayleigh time) or dt = (seconds)");
  }
  lua_pushnumber(L, ensureTimeStep(*h.sim));
  return 1;
}

// sim:integration("velocity_verlet" | "euler") | sim:integration() → the scheme's name
int integration(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  if (!lua_isnoneornil(L, 2)) {
    try {
      h.sim->setTimeIntegration(timeIntegrationFromName(luaL_checkstring(L, 2)));
    } catch (const InputError& e) {
      throw InputError(std::string("sim:integration: ") + e.what());
    }
  }
  lua_pushstring(L, timeIntegrationName(h.sim->timeIntegration()));
  return 1;
}

int rayleighTime(lua_State* L) {
  lua_pushnumber(L, checkSim(L, 1).sim->rayleighTime());
  return 1;
}
int time(lua_State* L) {
  lua_pushnumber(L, checkSim(L, 1).sim->time());
  return 1;
}
int steps(lua_State* L) {
  lua_pushinteger(L, static_cast<lua_Integer>(checkSim(L, 1).sim->stepCount()));
  return 1;
}
int count(lua_State* L) {
  lua_pushinteger(L, static_cast<lua_Integer>(checkSim(L, 1).sim->particles().size()));
  return 1;
}
int kineticEnergy(lua_State* L) {
  lua_pushnumber(L, checkSim(L, 1).sim->kineticEnergy());
  return 1;
}
int maxSpeed(lua_State* L) {
  lua_pushnumber(L, checkSim(L, 1).sim->maxSpeed());
  return 1;
}
int contactCount(lua_State* L) {
  lua_pushinteger(L, static_cast<lua_Integer>(checkSim(L, 1).sim->contacts().size()));
  return 1;
}

const ModuleFunction reg_simulation{"simulation", &guarded<newSimulation>};
const SimulationMethod reg_methods[] = {
    {"material", &guarded<material>},
    {"interaction", &guarded<interaction>},
    {"add_particle", &guarded<addParticle>},
    {"timestep", &guarded<timestep>},
    {"integration", &guarded<integration>},
    {"rayleigh_time", &guarded<rayleighTime>},
    {"time", &guarded<time>},
    {"steps", &guarded<steps>},
    {"count", &guarded<count>},
    {"kinetic_energy", &guarded<kineticEnergy>},
    {"max_speed", &guarded<maxSpeed>},
    {"contact_count", &guarded<contactCount>},
};

}  // namespace

void registerSimulationType(lua_State* L) {
  luaL_newmetatable(L, kSimulationMeta);
  lua_newtable(L);
  for (const Binding& b : simulationMethods()) {
    lua_pushcfunction(L, b.function);
    lua_setfield(L, -2, b.name.c_str());
  }
  lua_setfield(L, -2, "__index");
  lua_pushcfunction(L, gc);
  lua_setfield(L, -2, "__gc");
  lua_pushcfunction(L, &guarded<simToString>);
  lua_setfield(L, -2, "__tostring");
  lua_pop(L, 1);
}

}  // namespace paddy::lua
