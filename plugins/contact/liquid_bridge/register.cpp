// Plugin paddy_liquid_bridge: extra "liquid_bridge" (capillary force of a pendular bridge, Willett
// et al. 2000; rupture distance of Lian et al. 1993). Formula in liquid_bridge.hpp and
// docs/physics.md "Liquid bridges".
#include "liquid_bridge.hpp"

#include <paddy/plugin.hpp>

#include <memory>

using namespace paddy;
using namespace paddy::contact;

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(PluginRegistry* r) {
  r->addSubModel(
      {"liquid_bridge", SubModelKind::Extra,
       "capillary bridge F = 2 pi R gamma_s cos(theta)/(1 + 1.05 s^ + 2.5 s^2), s^ = s sqrt(R/V), R = 2R* "
       "(Willett et al. 2000); formed at touch, ruptures at s_c = (1 + theta/2) V^(1/3) (Lian et al. 1993)",
       {{"bridge_volume", 0.0, 0.0, 1e-3, "m^3", "liquid volume V of one bridge (0: no bridges)", false, 3.0,
         "V ~ d^3: the same liquid fraction of the sphere volume; then s_c ~ alpha and F(alpha s) ~ alpha^2 F(s) "
         "when gamma_s ~ alpha"},
        {"surface_tension", 0.072, 0.0, 10.0, "N/m", "liquid surface tension gamma_s (water 0.072)", false, 1.0,
         "capillary force 2 pi R gamma_s ~ alpha^2 like contact forces at fixed bulk stress, as the JKR surface "
         "energy (Thakur et al. 2016)"},
        {"contact_angle", 0.0, 0.0, 90.0, "deg", "liquid-solid contact angle theta (water on mud 0)", false, 0.0,
         "an angle"}},
       [](const ParamValues& p, const MaterialPair&) -> std::unique_ptr<SubModel> {
         return std::make_unique<LiquidBridge>(param(p, "bridge_volume"), param(p, "surface_tension"),
                                               param(p, "contact_angle"));
       },
       kNormalForce | kCohesiveNormalForce | kRangeBeyondContact});
  return PADDY_PLUGIN_ABI_VERSION;
}
