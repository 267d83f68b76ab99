// Loads the out-of-tree example plugin from a directory and checks that its sub-model is
// registered, validated and computes F_n = k δ.
#include <paddy/errors.hpp>
#include <paddy/plugin_manager.hpp>

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  paddy::PluginManager pm;
  pm.loadDirectories({argv[1]});
  if (pm.loaded().size() != 1 || pm.loaded()[0].provides.at(0) != "normal:linear_spring") {
    std::fprintf(stderr, "example plugin not found in %s\n", argv[1]);
    return 1;
  }
  const auto& info = pm.subModel("linear_spring", paddy::SubModelKind::Normal);
  const paddy::Material mud{"mud", 1680.0, 1e6, 0.5};
  auto model = info.create({{"stiffness", 250.0}}, paddy::MaterialPair::of(mud, mud));
  paddy::ContactBatch b;
  b.n = 2;
  b.overlap[0] = 2e-5;
  b.overlap[1] = -1e-5;
  b.r_eff[0] = b.r_eff[1] = 5e-4;
  b.resetOutputs();
  model->compute(b, 0);
  if (std::abs(b.fn[0] - 250.0 * 2e-5) > 1e-15 || b.fn[1] != 0.0 || !b.active[0] || b.active[1]) {
    std::fprintf(stderr, "example plugin computed a wrong force: %g %g\n", b.fn[0], b.fn[1]);
    return 1;
  }
  std::printf("loaded %s\n", pm.loaded()[0].path.c_str());
  return 0;
}
