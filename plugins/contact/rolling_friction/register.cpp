// Plugin paddy_rolling_friction: rolling sub-models "constant_torque" (EDEM type A / Ai et al. 2011
// model A, integrated implicitly), "constant_torque_explicit" (the same law applied explicitly, as
// EDEM integrates it) and "elastic_plastic" (EDEM type C / Ai et al. 2011 model C).
#include "constant_torque.hpp"
#include "constant_torque_explicit.hpp"
#include "elastic_plastic.hpp"

#include <paddy/plugin.hpp>

#include <memory>

using namespace paddy;
using namespace paddy::contact;

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(PluginRegistry* r) {
  r->addSubModel({"constant_torque", SubModelKind::Rolling,
                  "constant rolling torque tau_i = -mu_r F_n R_i w_i/|w_i| (Ai et al. 2011 model A; EDEM type A)",
                  {rollingFrictionParam()},
                  [](const ParamValues& p, const MaterialPair&) -> std::unique_ptr<SubModel> {
                    return std::make_unique<ConstantTorqueRolling>(param(p, "rolling_friction"));
                  },
                  0, kContactState});
  r->addSubModel({"constant_torque_explicit", SubModelKind::Rolling,
                  "constant rolling torque tau_i = -mu_r F_n R_i w_i/|w_i| applied explicitly from the step's w "
                  "(EDEM standard rolling friction, type A, as EDEM integrates it)",
                  {rollingFrictionParam()},
                  [](const ParamValues& p, const MaterialPair&) -> std::unique_ptr<SubModel> {
                    return std::make_unique<ConstantTorqueExplicitRolling>(param(p, "rolling_friction"));
                  },
                  0, kContactState});
  r->addSubModel({"elastic_plastic", SubModelKind::Rolling,
                  "elastic-plastic rolling spring k_r = 2.25 S_n mu_r^2 R*^2, limit mu_r R* F_n, damping "
                  "2 zeta sqrt(I_r k_r) (Ai et al. 2011 model C; EDEM type C)",
                  {rollingFrictionParam(),
                   {"rolling_damping", 0.3, 0.0, 10.0, "", "rolling viscous damping ratio zeta (Ai et al. eta_r)", false, 0.0,
                    "dimensionless damping ratio"}},
                  [](const ParamValues& p, const MaterialPair&) -> std::unique_ptr<SubModel> {
                    return std::make_unique<ElasticPlasticRolling>(param(p, "rolling_friction"),
                                                                   param(p, "rolling_damping"));
                  },
                  0, kContactState});
  return PADDY_PLUGIN_ABI_VERSION;
}
