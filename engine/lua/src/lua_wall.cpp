// sim:add_wall{...}: walls. For now the engine's PlaneWall (e.g. the floor of a column
// collapse); meshes and moving geometry (paddy.mesh, the slump cone lifted at a speed) come with
// the geometry module — as another self-registering binding file, see registry.hpp.
//
//   sim:add_wall{type = "plane", point = {0,0,0}, normal = {0,0,1}, material = steel,
//                velocity = {0,0,0}, name = "floor"} → wall index
#include "lua_util.hpp"
#include "registry.hpp"
#include "sim_handle.hpp"

#include <paddy/errors.hpp>
#include <paddy/plane_wall.hpp>

namespace paddy::lua {

namespace {

int addWall(lua_State* L) {
  SimHandle& h = checkSim(L, 1);
  OptionTable opt(L, 2, "sim:add_wall");
  const std::string type = opt.string("type");
  if (type != "plane")
    throw InputError("sim:add_wall: type '" + type + "' is not available (available: plane; meshes come with paddy.mesh)");
  const Vec3 point = opt.vec3("point", Vec3::Zero());
  const Vec3 normal = opt.vec3("normal", Vec3(0.0, 0.0, 1.0));
  if (!(normal.norm() > 0.0)) throw InputError("sim:add_wall: normal must not be zero");
  opt.push("material");
  const int material = materialArg(L, h, -1, "sim:add_wall: material");
  lua_pop(L, 1);
  const Vec3 velocity = opt.vec3("velocity", Vec3::Zero());
  const std::string name = opt.string("name", "plane");
  opt.finish();
  lua_pushinteger(L, h.sim->addWall(std::make_unique<PlaneWall>(name, material, point, normal.normalized(), velocity)));
  return 1;
}

const SimulationMethod reg_wall{"add_wall", &guarded<addWall>};

}  // namespace

}  // namespace paddy::lua
