// Minimal sub-models used to test the engine's mechanics independently of the physics plugins:
// a linear spring normal law, an "age" extra that accumulates time in contact in history, and an
// extra that counts in history how often the chain ran on a contact.
#pragma once

#include <paddy/plugin_manager.hpp>
#include <paddy/simulation.hpp>

#include <memory>
#include <utility>

namespace paddy::test {

// F_n = k δ for δ > 0; a = sqrt(R* δ).
class LinearSpring final : public SubModel {
 public:
  explicit LinearSpring(double k) : k_(k) {}
  void compute(ContactBatch& b, std::size_t) const override {
    for (std::size_t m = 0; m < b.n; ++m) {
      if (b.overlap[m] <= 0.0) continue;
      b.active[m] = 1;
      b.fn[m] = k_ * b.overlap[m];
      b.fn_friction[m] = b.fn[m];
      b.stiffness_n[m] = k_;
    }
  }

 private:
  double k_;
};

// history[0] += dt while the contact is active; history[1] = 1 marks a contact seen once.
class ContactAge final : public SubModel {
 public:
  std::size_t historySize() const override { return 2; }
  void compute(ContactBatch& b, std::size_t off) const override {
    for (std::size_t m = 0; m < b.n; ++m) {
      double* h = b.historyOf(m, off);
      if (b.active[m]) {
        h[0] += b.dt;
        h[1] = 1.0;
      }
    }
  }
};

// history[0] += 1 every time the chain runs on an active contact, whatever the pass (dt = 0 too):
// shows whether a pass wrote the stored history.
class EvaluationCount final : public SubModel {
 public:
  std::size_t historySize() const override { return 1; }
  void compute(ContactBatch& b, std::size_t off) const override {
    for (std::size_t m = 0; m < b.n; ++m)
      if (b.active[m]) b.historyOf(m, off)[0] += 1.0;
  }
};

inline std::shared_ptr<PluginManager> testPlugins() {
  auto pm = std::make_shared<PluginManager>();
  SubModelInfo lin;
  lin.name = "linear_spring";
  lin.kind = SubModelKind::Normal;
  lin.params = {{"stiffness", 1000.0, 0.0, 1e12, "N/m", "spring constant", false, 0.0, "not coarse grained in these tests"}};
  lin.create = [](const ParamValues& p, const MaterialPair&) { return std::make_unique<LinearSpring>(p.at("stiffness")); };
  pm->addSubModel(lin);
  SubModelInfo age;
  age.name = "contact_age";
  age.kind = SubModelKind::Extra;
  age.create = [](const ParamValues&, const MaterialPair&) { return std::make_unique<ContactAge>(); };
  pm->addSubModel(age);
  SubModelInfo count;
  count.name = "evaluation_count";
  count.kind = SubModelKind::Extra;
  count.create = [](const ParamValues&, const MaterialPair&) { return std::make_unique<EvaluationCount>(); };
  pm->addSubModel(count);
  return pm;
}

inline Material mud() { return Material{"mud", 1680.0, 1e6, 0.5}; }

// An interaction made of the linear spring alone (no damping, no tangential model).
inline InteractionSpec linearSpring(double stiffness = 1000.0) {
  InteractionSpec spec;
  spec.normal = "linear_spring";
  spec.damping = spec.tangential = "";
  spec.params["stiffness"] = stiffness;
  return spec;
}

// Mud spheres and a steel wall material, both pairs linear springs, no gravity: the set-up of the
// contact-search tests. Returns {mud, steel} material indices.
inline std::pair<int, int> mudAndSteelSprings(Simulation& sim) {
  const int mud_id = sim.addMaterial(mud());
  const int steel = sim.addMaterial(Material{"steel", 7800.0, 7e9, 0.3});
  sim.setInteraction(mud_id, mud_id, linearSpring());
  sim.setInteraction(mud_id, steel, linearSpring());
  sim.setGravity(Vec3::Zero());
  return {mud_id, steel};
}

}  // namespace paddy::test
