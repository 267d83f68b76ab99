// sim:fill{...}: fills a region with particles (see packing.hpp for the algorithms).
//
//   sim:fill{region = {type="box", min={..}, max={..}}
//                   | {type="cylinder", base={..}, radius=, height=}
//                   | {type="cone", base={..}, radius_bottom=, radius_top=, height=},
//            radius = r | {dist="uniform", min=, max=} | {dist="normal", mean=, std=, min=, max=}
//                       | {dist="lognormal", median=, sigma=, min=, max=},
//            material = m, packing = "random" | "lattice" (hexagonal) | "cubic",
//            count = N, volume_fraction = φ, seed = paddy.seed, spacing = 1.0, jitter = 0,
//            attempts = 500, vel = {..}}  → particles placed, solid fraction of the region
#include "lua_util.hpp"
#include "packing.hpp"
#include "registry.hpp"
#include "runtime_state.hpp"
#include "sim_handle.hpp"

#include <paddy/errors.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace paddy::lua {

namespace {

Region readRegion(lua_State* L, int idx) {
  OptionTable opt(L, idx, "sim:fill region");
  Region r;
  const std::string type = opt.string("type");
  if (type == "box") {
    r.type = Region::Type::Box;
    r.min = opt.vec3("min");
    r.max = opt.vec3("max");
  } else if (type == "cylinder") {
    r.type = Region::Type::Cylinder;
    r.base = opt.vec3("base", Vec3::Zero());
    r.radius = opt.number("radius");
    r.height = opt.number("height");
  } else if (type == "cone") {
    r.type = Region::Type::Cone;
    r.base = opt.vec3("base", Vec3::Zero());
    r.radius = opt.number("radius_bottom");
    r.radius_top = opt.number("radius_top");
    r.height = opt.number("height");
  } else {
    throw InputError("sim:fill: region type '" + type + "' is not one of box, cylinder, cone");
  }
  opt.finish();
  return r;
}

RadiusDistribution readRadius(lua_State* L, int idx) {
  RadiusDistribution d;
  if (lua_type(L, idx) == LUA_TNUMBER) {
    d.a = lua_tonumber(L, idx);
    return d;
  }
  OptionTable opt(L, idx, "sim:fill radius");
  const std::string dist = opt.string("dist");
  if (dist == "uniform") {
    d.type = RadiusDistribution::Type::Uniform;
    d.min = opt.number("min");
    d.max = opt.number("max");
  } else if (dist == "normal") {
    d.type = RadiusDistribution::Type::Normal;
    d.a = opt.number("mean");
    d.b = opt.number("std");
    d.min = opt.number("min", std::max(d.a - 3.0 * d.b, 0.1 * d.a));
    d.max = opt.number("max", d.a + 3.0 * d.b);
  } else if (dist == "lognormal") {
    d.type = RadiusDistribution::Type::LogNormal;
    d.a = opt.number("median");
    d.b = opt.number("sigma");
    d.min = opt.number("min", d.a * std::exp(-3.0 * d.b));
    d.max = opt.number("max", d.a * std::exp(3.0 * d.b));
  } else {
    throw InputError("sim:fill: radius dist '" + dist + "' is not one of uniform, normal, lognormal");
  }
  opt.finish();
  return d;
}

int fill(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  OptionTable opt(L, 2, "sim:fill");
  FillRequest q;
  if (opt.push("region") == LUA_TNIL) throw InputError("sim:fill needs region = {type = ..., ...}");
  q.region = readRegion(L, -1);
  lua_pop(L, 1);
  if (opt.push("radius") == LUA_TNIL) throw InputError("sim:fill needs radius = r or radius = {dist = ..., ...}");
  q.radius = readRadius(L, -1);
  lua_pop(L, 1);
  if (opt.push("material") == LUA_TNIL) throw InputError("sim:fill needs material = (id from sim:material)");
  const int material = materialArg(L, h, -1, "sim:fill: material");
  lua_pop(L, 1);
  const std::string packing = opt.string("packing", "random");
  if (packing == "random") q.packing = FillRequest::Packing::Random;
  else if (packing == "lattice" || packing == "hexagonal") q.packing = FillRequest::Packing::Hexagonal;
  else if (packing == "cubic") q.packing = FillRequest::Packing::Cubic;
  else throw InputError("sim:fill: packing '" + packing + "' is not one of random, lattice, cubic");
  const long long seed = opt.integer("seed", static_cast<long long>(runtimeState(L).options.seed));
  q.seed = static_cast<std::uint64_t>(seed);
  const long long count = opt.integer("count", -1);
  if (count == 0 || count < -1) throw InputError("sim:fill: count must be > 0");
  if (count > 0) q.count = static_cast<std::size_t>(count);
  q.volume_fraction = opt.optNumber("volume_fraction");
  q.spacing = opt.number("spacing", 1.0);
  q.jitter = opt.number("jitter", 0.0);
  q.attempts = static_cast<int>(opt.integer("attempts", q.attempts));
  const Vec3 vel = opt.vec3("vel", Vec3::Zero());
  opt.finish();

  const ParticleArrays& p = h.sim->particles();
  std::vector<Sphere> existing(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) existing[i] = {p.position[i], p.radius[i]};
  const std::vector<Sphere> placed = fillRegion(q, existing);
  double volume = 0.0;
  for (const Sphere& s : placed) {
    h.sim->addParticle(s.x, s.r, material, vel);
    volume += 4.0 / 3.0 * std::numbers::pi * s.r * s.r * s.r;
  }
  if (q.count && placed.size() < *q.count)
    std::fprintf(stderr, "paddy: warning: sim:fill placed %zu of the %zu particles asked for (region full)\n",
                 placed.size(), *q.count);
  lua_pushinteger(L, static_cast<lua_Integer>(placed.size()));
  lua_pushnumber(L, volume / q.region.volume());
  return 2;
}

const SimulationMethod reg_fill{"fill", &guarded<fill>};

}  // namespace

}  // namespace paddy::lua
