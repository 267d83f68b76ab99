// Minimal sub-models used to test the engine's mechanics independently of the physics plugins:
// a linear spring normal law, and an "age" extra that accumulates time in contact in history.
#pragma once

#include <paddy/plugin_manager.hpp>
#include <paddy/simulation.hpp>

#include <memory>

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

}  // namespace paddy::test
