// Lua binding of the stress across a surface (paddy/measure/surface_stress.hpp, docs/measurement.md):
//
//   sim:measure_stress{surface = "disc", z =, r_max =, r_min = 0, axis = {x, y}, walls = {...}}
//   sim:measure_stress{surface = "cylinder", radius =, z_min =, z_max =, axis = {x, y}, walls = {...}}
//     → {normal = σ_n [Pa] (compression positive), shear = τ along θ̂ [Pa], area = [m²], crossings =}
//
// The contacts are the simulation's particle–particle contacts at its current state
// (Simulation::contacts()); the force of each is the one the law gives. Wall contacts count only
// for the walls listed in `walls` (a wall or a list, by index or name): the wall then stands in for
// the second particle, its branch from the sphere's centre to the contact point
// x_c = x_i − (r_i − δ/2) n̂ (the lever arm the engine applies the force at). A vane's blade tips
// lie on the cylinder its tips sweep: list the vane to count the spheres they push.
#include "lua_util.hpp"
#include "registry.hpp"
#include "sim_handle.hpp"
#include "wall_args.hpp"

#include <paddy/errors.hpp>
#include <paddy/measure/surface_stress.hpp>

#include <algorithm>
#include <string>
#include <unordered_map>
#include <vector>

namespace paddy::lua {

namespace {

namespace pm = paddy::measure;

pm::Vec2 axisOption(lua_State* L, OptionTable& opt) {
  if (!opt.has("axis")) return pm::Vec2::Zero();
  opt.push("axis");
  const std::vector<double> a = toNumberArray(L, -1, opt.context() + " option 'axis'");
  lua_pop(L, 1);
  if (a.size() != 2 && a.size() != 3) throw InputError(opt.context() + " option 'axis' must be {x, y}");
  return {a[0], a[1]};
}

// Walls given as `walls` (one wall or a list), as indices.
std::vector<int> wallsOption(lua_State* L, SimHandle& h, OptionTable& opt) {
  std::vector<int> out;
  if (!opt.has("walls")) return out;
  opt.push("walls");
  const int idx = lua_gettop(L);
  try {
    if (lua_type(L, idx) == LUA_TTABLE) {
      const auto n = static_cast<lua_Integer>(lua_rawlen(L, idx));
      for (lua_Integer k = 1; k <= n; ++k) {
        lua_rawgeti(L, idx, k);
        out.push_back(wallArg(L, h, -1, opt.context() + " option 'walls' entry " + std::to_string(k)));
        lua_pop(L, 1);
      }
    } else {
      out.push_back(wallArg(L, h, idx, opt.context() + " option 'walls'"));
    }
  } catch (...) {
    lua_settop(L, idx - 1);
    throw;
  }
  lua_pop(L, 1);
  return out;
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

int measureStress(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  OptionTable opt(L, 2, "measure_stress");
  const std::string surface = opt.string("surface");
  const std::vector<int> walls = wallsOption(L, h, opt);
  pm::SurfaceStress s;
  if (surface == "disc") {
    pm::DiscSurface d;
    d.axis = axisOption(L, opt);
    d.z = opt.number("z");
    d.r_min = opt.number("r_min", 0.0);
    d.r_max = opt.number("r_max");
    opt.finish();
    s = pm::discStress(contactForces(*h.sim, walls), d);
  } else if (surface == "cylinder") {
    pm::CylinderSurface c;
    c.axis = axisOption(L, opt);
    c.radius = opt.number("radius");
    c.z_min = opt.number("z_min");
    c.z_max = opt.number("z_max");
    opt.finish();
    s = pm::cylinderStress(contactForces(*h.sim, walls), c);
  } else {
    throw InputError("measure_stress: surface '" + surface + "' is not one of disc, cylinder");
  }
  lua_createtable(L, 0, 4);
  setNumber(L, "normal", s.normal);
  setNumber(L, "shear", s.shear);
  setNumber(L, "area", s.area);
  setInteger(L, "crossings", static_cast<long long>(s.crossings));
  return 1;
}

const SimulationMethod reg_measure_stress{"measure_stress", &guarded<measureStress>};

}  // namespace

}  // namespace paddy::lua
