// Builds simulations of one or two spheres with the shipped plugins, for closed-form checks.
#pragma once

#include <paddy/plane_wall.hpp>
#include <paddy/plugin_manager.hpp>
#include <paddy/simulation.hpp>

#include <memory>

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

}  // namespace paddy::test
