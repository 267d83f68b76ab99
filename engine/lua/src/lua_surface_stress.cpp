// Lua binding of the stress across a surface (paddy/measure/surface_stress.hpp, docs/measurement.md):
//
//   sim:measure_stress{surface = "disc", z =, r_max =, r_min = 0, axis = {x, y}, walls = {...}}
//   sim:measure_stress{surface = "cylinder", radius =, z_min =, z_max =, axis = {x, y}, walls = {...}}
//     → {normal = σ_n [Pa] (compression positive), shear = τ along θ̂ [Pa], area = [m²], crossings =}
//   sim:measure_stress{surfaces = {{surface = ..., ...}, ...}, walls = {...}}
//     → an array of such tables, one per surface, from one reading of the contacts
//
// The contacts are the simulation's particle–particle contacts at its current state
// (Simulation::contacts()); the force of each is the one the law gives. Wall contacts count only
// for the walls listed in `walls` (a wall or a list, by index or name): the wall then stands in for
// the second particle, its branch from the sphere's centre to the contact point
// x_c = x_i − (r_i − δ/2) n̂ (the lever arm the engine applies the force at). A vane's blade tips
// lie on the cylinder its tips sweep: list the vane to count the spheres they push.
#include "lua_util.hpp"
#include "measure_module.hpp"
#include "registry.hpp"
#include "sim_handle.hpp"
#include "wall_args.hpp"

#include <paddy/errors.hpp>
#include <paddy/measure/surface_stress.hpp>

#include <algorithm>
#include <string>
#include <unordered_map>
#include <variant>
#include <vector>

namespace paddy::lua {

namespace {

namespace pm = paddy::measure;

using Surface = std::variant<pm::DiscSurface, pm::CylinderSurface>;

// One surface from the option table at `idx` (its `surface`, axis and dimensions); `extra`
// names a key the table may hold besides them (the single form's `walls`), or nullptr.
Surface readSurface(lua_State* L, int idx, const std::string& context, const char* extra) {
  OptionTable opt(L, idx, context);
  if (extra) opt.accept(extra);
  const std::string surface = opt.string("surface");
  if (surface == "disc") {
    pm::DiscSurface d;
    d.axis = readAxis(L, opt);
    d.z = opt.number("z");
    d.r_min = opt.number("r_min", 0.0);
    d.r_max = opt.number("r_max");
    opt.finish();
    return d;
  }
  if (surface == "cylinder") {
    pm::CylinderSurface c;
    c.axis = readAxis(L, opt);
    c.radius = opt.number("radius");
    c.z_min = opt.number("z_min");
    c.z_max = opt.number("z_max");
    opt.finish();
    return c;
  }
  throw InputError(context + ": surface '" + surface + "' is not one of disc, cylinder");
}

// The particle–particle contacts (both centres, the force on the first particle) and the contacts
// with the walls listed (the sphere's centre, the contact point, the force on the sphere).
std::vector<pm::ContactForce> contactForces(const Simulation& sim, const std::vector<int>& walls) {
  const ParticleArrays& p = sim.particles();
  std::unordered_map<std::uint64_t, std::size_t> index;
  index.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) index.emplace(p.id[i], i);
  std::vector<pm::ContactForce> out;
  for (const ContactRecord& c : sim.contacts()) {
    const auto a = index.find(c.id_i);
    if (a == index.end()) continue;
    const Vec3& xi = p.position[a->second];
    const Vec3 f = c.fn * c.normal + c.ft;
    if (c.wall) {
      if (std::find(walls.begin(), walls.end(), static_cast<int>(c.id_j)) == walls.end()) continue;
      out.push_back({xi, Vec3(xi - (p.radius[a->second] - 0.5 * c.overlap) * c.normal), f});
    } else {
      const auto b = index.find(c.id_j);
      if (b == index.end()) continue;
      out.push_back({xi, p.position[b->second], f});
    }
  }
  return out;
}

void pushStress(lua_State* L, const pm::SurfaceStress& s) {
  lua_createtable(L, 0, 4);
  setNumber(L, "normal", s.normal);
  setNumber(L, "shear", s.shear);
  setNumber(L, "area", s.area);
  setInteger(L, "crossings", static_cast<long long>(s.crossings));
}

pm::SurfaceStress stressAcross(const std::vector<pm::ContactForce>& contacts, const Surface& surface) {
  if (const auto* d = std::get_if<pm::DiscSurface>(&surface)) return pm::discStress(contacts, *d);
  return pm::cylinderStress(contacts, std::get<pm::CylinderSurface>(surface));
}

int measureStress(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  const std::string ctx = "measure_stress";
  if (lua_type(L, 2) != LUA_TTABLE) throw InputError(ctx + " expects a table of options");
  // Walls whose contacts count: one wall or a list ({} or absent: none).
  std::vector<int> walls;
  lua_getfield(L, 2, "walls");
  if (!lua_isnil(L, -1) && !(lua_type(L, -1) == LUA_TTABLE && lua_rawlen(L, -1) == 0)) {
    try {
      walls = wallList(L, h, -1, ctx + " option 'walls'");
    } catch (...) {
      lua_pop(L, 1);
      throw;
    }
  }
  lua_pop(L, 1);
  // The surfaces: the list `surfaces` (with nothing else but walls), or the table itself.
  std::vector<Surface> surfaces;
  lua_getfield(L, 2, "surfaces");
  const bool many = !lua_isnil(L, -1);
  lua_pop(L, 1);
  if (many) {
    OptionTable opt(L, 2, ctx);
    opt.accept("walls");
    opt.push("surfaces");
    const int list = lua_gettop(L);
    const auto n = lua_type(L, list) == LUA_TTABLE ? static_cast<lua_Integer>(lua_rawlen(L, list)) : 0;
    try {
      if (n == 0) throw InputError(ctx + " option 'surfaces' must be a non-empty list of surfaces");
      for (lua_Integer k = 1; k <= n; ++k) {
        lua_rawgeti(L, list, k);
        surfaces.push_back(readSurface(L, -1, ctx + " surface " + std::to_string(k), nullptr));
        lua_pop(L, 1);
      }
    } catch (...) {
      lua_settop(L, list - 1);
      throw;
    }
    lua_pop(L, 1);
    opt.finish();
  } else {
    surfaces.push_back(readSurface(L, 2, ctx, "walls"));
  }
  const std::vector<pm::ContactForce> contacts = contactForces(*h.sim, walls);
  if (!many) {
    pushStress(L, stressAcross(contacts, surfaces[0]));
    return 1;
  }
  lua_createtable(L, static_cast<int>(surfaces.size()), 0);
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    pushStress(L, stressAcross(contacts, surfaces[k]));
    lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
  }
  return 1;
}

const SimulationMethod reg_measure_stress{"measure_stress", &guarded<measureStress>};

}  // namespace

}  // namespace paddy::lua
