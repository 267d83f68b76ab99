// Builds simulations of one or two spheres with the shipped plugins, for closed-form checks.
#pragma once

#include <paddy/plane_wall.hpp>
#include <paddy/plugin_manager.hpp>
#include <paddy/simulation.hpp>

#include <cmath>
#include <memory>
#include <string>

namespace paddy::test {

inline std::shared_ptr<PluginManager> shippedPlugins() {
  static auto pm = [] {
    auto m = std::make_shared<PluginManager>();
    m->loadDefault();
    return m;
  }();
  return pm;
}

inline Material mudMaterial() { return {"mud", 1680.0, 1e6, 0.5}; }
inline Material steelMaterial() { return {"steel", 7800.0, 7e9, 0.3}; }

// Hertz + Hertz-Mindlin damping + Mindlin with restitution e and friction mu.
inline InteractionSpec hertzMindlin(double e, double mu) {
  InteractionSpec s;
  s.normal = "hertz";
  s.damping = "hertz_mindlin";
  s.tangential = "mindlin";
  s.params = {{"restitution", e}, {"friction", mu}};
  return s;
}

// A simulation with mud particles and a steel floor at z = 0 (normal +z).
struct FloorSetup {
  std::unique_ptr<Simulation> sim;
  int mud = -1, steel = -1;
};

inline FloorSetup mudOnSteelFloor(const InteractionSpec& mud_steel) {
  FloorSetup s;
  s.sim = std::make_unique<Simulation>(shippedPlugins());
  s.mud = s.sim->addMaterial(mudMaterial());
  s.steel = s.sim->addMaterial(steelMaterial());
  s.sim->setInteraction(s.mud, s.steel, mud_steel);
  InteractionSpec mm = mud_steel;
  s.sim->setInteraction(s.mud, s.mud, mm);
  s.sim->addWall(std::make_unique<PlaneWall>("floor", s.steel, Vec3::Zero(), Vec3::UnitZ()));
  return s;
}

// A sphere of radius 1 mm on a steel plane inclined by θ (gravity tilted): Hertz + Hertz-Mindlin
// damping (e = 0.3) + Mindlin (μ_s = 0.9, sticking) + the rolling sub-model `rolling` with μ_r.
// Settles on the level plane, tilts, and returns the distance rolled down the slope in
// `duration` (half_way: after duration / 2); omega_out: the final angular velocity.
inline double rollDownIncline(const std::string& rolling, double tan_theta, double mu_r, double dt_fraction,
                              double duration, Vec3* omega_out, double* half_way = nullptr) {
  const double R = 1e-3, g = 9.81;
  InteractionSpec spec = hertzMindlin(0.3, 0.9);
  spec.rolling = rolling;
  spec.params["rolling_friction"] = mu_r;
  auto s = mudOnSteelFloor(spec);
  auto& sim = *s.sim;
  sim.addParticle(Vec3(0, 0, R), R, s.mud);
  sim.setTimeStepFraction(dt_fraction);
  sim.run(0.3);  // settle on the level plane
  const double c = 1.0 / std::sqrt(1.0 + tan_theta * tan_theta);
  sim.setGravity(Vec3(g * tan_theta * c, 0.0, -g * c));
  sim.particles().velocity[0].setZero();
  sim.particles().omega[0].setZero();
  const double x0 = sim.particles().position[0].x();
  sim.run(0.5 * duration);
  if (half_way) *half_way = sim.particles().position[0].x() - x0;
  sim.run(0.5 * duration);
  *omega_out = sim.particles().omega[0];
  return sim.particles().position[0].x() - x0;
}

}  // namespace paddy::test
