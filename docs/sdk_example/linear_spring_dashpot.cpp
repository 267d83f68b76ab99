// Example plugin: a linear spring normal contact, F_n = k δ (δ > 0), with the contact radius of
// Hertz, a = sqrt(R* δ), so the standard damping and tangential models can be stacked on it.
// Cundall & Strack (1979), Géotechnique 29(1):47–65.
#include <paddy/plugin.hpp>

#include <cmath>
#include <memory>

namespace {

class LinearSpring final : public paddy::SubModel {
 public:
  explicit LinearSpring(double k) : k_(k) {}
  void compute(paddy::ContactBatch& b, std::size_t) const override {
    for (std::size_t m = 0; m < b.n; ++m) {
      const double d = b.overlap[m];
      if (d <= 0.0) continue;
      b.active[m] = 1;
      b.fn[m] = k_ * d;
      b.fn_friction[m] = b.fn[m];
      b.contact_radius[m] = std::sqrt(b.r_eff[m] * d);
      b.stiffness_n[m] = k_;
      b.stiffness_t[m] = k_;
    }
  }

 private:
  double k_;
};

}  // namespace

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(paddy::PluginRegistry* registry) {
  paddy::SubModelInfo info;
  info.name = "linear_spring";
  info.kind = paddy::SubModelKind::Normal;
  info.description = "F_n = k delta (Cundall & Strack 1979)";
  info.params = {{"stiffness", 1e3, 0.0, 1e12, "N/m", "normal spring constant k", false}};
  info.create = [](const paddy::ParamValues& p, const paddy::MaterialPair&) {
    return std::make_unique<LinearSpring>(p.at("stiffness"));
  };
  registry->addSubModel(std::move(info));
  return PADDY_PLUGIN_ABI_VERSION;
}
