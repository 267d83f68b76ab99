// Plugin paddy_hertz_mindlin: EDEM-style Hertz-Mindlin (no slip) — normal "hertz",
// damping "hertz_mindlin", tangential "mindlin". Formulas in the headers and docs/physics.md.
#include "hertz.hpp"
#include "hertz_mindlin_damping.hpp"
#include "mindlin.hpp"

#include <paddy/plugin.hpp>

#include <memory>

using namespace paddy;
using namespace paddy::contact;

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(PluginRegistry* r) {
  r->addSubModel({"hertz", SubModelKind::Normal,
                  "Hertz: F_n = 4/3 E* sqrt(R*) d^1.5, S_n = 2E*a, S_t = 8G*a, a = sqrt(R* d) (Hertz 1882; EDEM)",
                  {},
                  [](const ParamValues&, const MaterialPair& m) -> std::unique_ptr<SubModel> {
                    return std::make_unique<HertzNormal>(m.e_star, m.g_star);
                  },
                  kNormalForce | kContactState | kNormalStiffness | kTangentialStiffness});
  r->addSubModel({"hertz_mindlin", SubModelKind::Damping,
                  "normal damping -2 sqrt(5/6) beta sqrt(S_n m*) v_n, beta = ln e/sqrt(ln^2 e + pi^2) "
                  "(EDEM Hertz-Mindlin; Tsuji et al. 1992)",
                  {restitutionParam()},
                  [](const ParamValues& p, const MaterialPair&) -> std::unique_ptr<SubModel> {
                    return std::make_unique<HertzMindlinDamping>(param(p, "restitution"));
                  },
                  kNormalForce, kContactState | kNormalStiffness});
  r->addSubModel({"mindlin", SubModelKind::Tangential,
                  "Mindlin no-slip spring F_t = -S_t xi - 2 sqrt(5/6) beta sqrt(S_t m*) v_t, total capped at "
                  "mu_s F_n (Mindlin & Deresiewicz 1953; EDEM)",
                  {frictionParam(), restitutionParam()},
                  [](const ParamValues& p, const MaterialPair&) -> std::unique_ptr<SubModel> {
                    return std::make_unique<MindlinTangential>(param(p, "friction"), param(p, "restitution"));
                  },
                  0, kContactState | kTangentialStiffness});
  return PADDY_PLUGIN_ABI_VERSION;
}
