// The three contact plugins load through their C entry point, register the expected sub-models
// and parameters, and the sub-models they create compute the same as the header classes.
#include "contact_test_util.hpp"

#include <hertz_mindlin/hertz.hpp>
#include <jkr/jkr.hpp>

#include <paddy/errors.hpp>
#include <paddy/plugin.hpp>
#include <paddy/plugin_manager.hpp>

#include <catch2/catch.hpp>

#include <dlfcn.h>

#include <cstdlib>
#include <map>
#include <sstream>
#include <string>

using namespace ctest;
using paddy::ParamValues;
using paddy::SubModelInfo;
using paddy::SubModelKind;

namespace {

struct Registry final : paddy::PluginRegistry {
  std::map<std::string, SubModelInfo> models;
  void addSubModel(SubModelInfo info) override { models[info.name] = std::move(info); }
  void addGeometry(const paddy::GeometryInfo&) override {}
};

// Loads lib<name>.so from $PADDY_PLUGIN_PATH and registers it into `r`; returns the ABI version.
int loadPlugin(const std::string& name, Registry& r) {
  const char* env = std::getenv("PADDY_PLUGIN_PATH");
  REQUIRE(env != nullptr);
  std::stringstream dirs(env);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string path = dir + "/lib" + name + ".so";
    void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!h) continue;
    auto fn = reinterpret_cast<paddy_register_plugin_fn>(dlsym(h, "paddy_register_plugin"));
    REQUIRE(fn != nullptr);
    return fn(&r);  // libraries stay loaded: the registered create() functions live there
  }
  FAIL("plugin " << name << " not found on PADDY_PLUGIN_PATH=" << env);
  return -1;
}

ParamValues withDefaults(const SubModelInfo& info, ParamValues given) {
  for (const auto& p : info.params)
    if (!given.count(p.name)) given[p.name] = p.default_value;
  return given;
}

const paddy::ParamSpec& spec(const SubModelInfo& info, const std::string& name) {
  for (const auto& p : info.params)
    if (p.name == name) return p;
  FAIL("no parameter " << name << " in " << info.name);
  throw;
}

}  // namespace

TEST_CASE("contact plugins: registration, kinds, parameters", "[contact][plugin]") {
  Registry r;
  CHECK(loadPlugin("paddy_hertz_mindlin", r) == PADDY_PLUGIN_ABI_VERSION);
  CHECK(loadPlugin("paddy_jkr", r) == PADDY_PLUGIN_ABI_VERSION);
  CHECK(loadPlugin("paddy_rolling_friction", r) == PADDY_PLUGIN_ABI_VERSION);
  const std::map<std::string, SubModelKind> expected{{"hertz", SubModelKind::Normal},
                                                     {"hertz_mindlin", SubModelKind::Damping},
                                                     {"mindlin", SubModelKind::Tangential},
                                                     {"jkr", SubModelKind::Normal},
                                                     {"constant_torque", SubModelKind::Rolling},
                                                     {"constant_torque_explicit", SubModelKind::Rolling},
                                                     {"elastic_plastic", SubModelKind::Rolling}};
  REQUIRE(r.models.size() == expected.size());
  for (const auto& [name, kind] : expected) {
    INFO(name);
    REQUIRE(r.models.count(name) == 1);
    CHECK(r.models[name].kind == kind);
    CHECK(!r.models[name].description.empty());
    CHECK(r.models[name].create);
  }
  // Shared names are declared identically wherever they appear.
  const auto& e1 = spec(r.models["hertz_mindlin"], "restitution");
  const auto& e2 = spec(r.models["mindlin"], "restitution");
  CHECK((e1.min == e2.min && e1.max == e2.max && e1.required == e2.required && e1.default_value == e2.default_value));
  CHECK(e1.min > 0.0);
  CHECK(e1.max == 1.0);
  const auto& r1 = spec(r.models["constant_torque"], "rolling_friction");
  const auto& r2 = spec(r.models["elastic_plastic"], "rolling_friction");
  CHECK((r1.min == r2.min && r1.max == r2.max && r1.required == r2.required));
  const auto& r3 = spec(r.models["constant_torque_explicit"], "rolling_friction");
  CHECK((r1.min == r3.min && r1.max == r3.max && r1.required == r3.required));
  CHECK((r1.min == 0.0 && r1.max == 10.0));
  const auto& mu = spec(r.models["mindlin"], "friction");
  CHECK((mu.min == 0.0 && mu.max == 10.0));
  const auto& gam = spec(r.models["jkr"], "surface_energy");
  CHECK((gam.min == 0.0 && gam.max == 100.0 && gam.unit == "J/m^2"));
  const auto& hy = spec(r.models["jkr"], "jkr_hysteretic");
  CHECK((hy.min == 0.0 && hy.max == 1.0 && hy.default_value == 0.0 && !hy.required));
  const auto& os = spec(r.models["jkr"], "jkr_overlap_stiffness");
  CHECK((os.min == 0.0 && os.max == 1.0 && os.default_value == 0.0 && !os.required));
  const auto& zeta = spec(r.models["elastic_plastic"], "rolling_damping");
  CHECK((zeta.min == 0.0 && zeta.max == 10.0 && zeta.default_value == 0.3));
  CHECK(r.models["hertz"].params.empty());

  // Created models: history sizes, separation, and the same numbers as the header classes.
  const MaterialPair p = MaterialPair::of(mud(), mud());
  auto make = [&](const std::string& n, ParamValues v) { return r.models[n].create(withDefaults(r.models[n], v), p); };
  CHECK(make("hertz", {})->historySize() == 0);
  CHECK(make("hertz_mindlin", {{"restitution", 0.5}})->historySize() == 0);
  CHECK(make("mindlin", {{"restitution", 0.5}, {"friction", 0.3}})->historySize() == 3);
  CHECK(make("constant_torque", {{"rolling_friction", 0.1}})->historySize() == 0);
  CHECK(make("elastic_plastic", {{"rolling_friction", 0.1}})->historySize() == 3);
  CHECK(make("jkr", {{"surface_energy", 0.1}})->historySize() == 0);
  CHECK(make("jkr", {{"surface_energy", 0.1}, {"jkr_hysteretic", 1.0}})->historySize() == 1);
  const paddy::contact::JkrNormal direct(p.e_star, p.g_star, 0.1, false);
  CHECK(make("jkr", {{"surface_energy", 0.1}})->maxSeparation(0.5e-3) == direct.maxSeparation(0.5e-3));
  CHECK(make("jkr", {{"surface_energy", 0.1}})->maxSeparation(0.5e-3) > 0.0);
  CHECK_THROWS_AS(make("jkr", {{"surface_energy", 0.1}, {"jkr_hysteretic", 0.5}}), paddy::InputError);
  CHECK_THROWS_AS(make("jkr", {{"surface_energy", 0.1}, {"jkr_overlap_stiffness", 0.5}}), paddy::InputError);

  Chain plug, hdr;
  plug.add(make("jkr", {{"surface_energy", 0.1}}));
  hdr.add(std::make_unique<paddy::contact::JkrNormal>(p.e_star, p.g_star, 0.1, false));
  ContactBatch& bp = plug.setup(3);
  ContactBatch& bh = hdr.setup(3);
  for (int k = 0; k < 3; ++k) {
    setPair(bp, k, (k - 1) * 1e-6, 1e-3, 1e-3, 1e-5, 1e-5);
    setPair(bh, k, (k - 1) * 1e-6, 1e-3, 1e-3, 1e-5, 1e-5);
  }
  plug.run();
  hdr.run();
  // Same formula; the plugin may be compiled with other flags (FMA contraction), so allow ulps.
  for (int k = 0; k < 3; ++k) CHECK(bp.fn[k] == Approx(bh.fn[k]).epsilon(1e-13));
  CHECK(bp.fn[0] < 0.0);  // a 1 µm gap is inside the cut-off (δ_c ≈ −2.8 µm): attraction

}

TEST_CASE("contact plugins: load through the engine's PluginManager", "[contact][plugin]") {
  const char* env = std::getenv("PADDY_PLUGIN_PATH");
  REQUIRE(env != nullptr);
  const std::string dir = std::string(env).substr(0, std::string(env).find(':'));
  paddy::PluginManager pm;
  for (const char* lib : {"libpaddy_hertz_mindlin.so", "libpaddy_jkr.so", "libpaddy_rolling_friction.so"})
    pm.loadLibrary(dir + "/" + lib);
  CHECK(pm.subModels(SubModelKind::Normal).size() >= 2);
  const MaterialPair p = MaterialPair::of(mud(), mud());
  const SubModelInfo& jkr = pm.subModel("jkr", SubModelKind::Normal);
  CHECK(jkr.create(withDefaults(jkr, {{"surface_energy", 0.096}}), p)->maxSeparation(0.5e-3) > 0.0);
  // An exception thrown in a plugin is caught by type in the host.
  CHECK_THROWS_AS(jkr.create(withDefaults(jkr, {{"surface_energy", 0.096}, {"jkr_hysteretic", 0.5}}), p),
                  paddy::InputError);
  CHECK(pm.subModel("elastic_plastic", SubModelKind::Rolling).params.size() == 2);
  CHECK_THROWS_AS(pm.subModel("jkr", SubModelKind::Tangential), paddy::InputError);
}
