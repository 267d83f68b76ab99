// Plugin paddy_plastic_adhesion: extra "plastic_adhesion" (adhesion growing with the largest load,
// after Luding 2008 and the EEPA model of Thakur et al. 2014). Formula in plastic_adhesion.hpp and
// docs/physics.md "Plastic adhesion".
#include "plastic_adhesion.hpp"

#include <paddy/plugin.hpp>

#include <memory>

using namespace paddy;
using namespace paddy::contact;

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(PluginRegistry* r) {
  r->addSubModel(
      {"plastic_adhesion", SubModelKind::Extra,
       "adhesion A = lambda F_max (largest load carried), F_ad = A in contact, A (1 + d/s_c) across the bonded gap, "
       "s_c = min(d_max, kappa R*); friction load += F_ad (Luding 2008; Thakur et al. 2014 EEPA)",
       {{"plastic_adhesion", 0.0, 0.0, 0.9, "", "pull-off / largest load carried, lambda (0: off)", false, 0.0,
         "a ratio of forces: the pull-off follows the loads, ~ alpha^2 at fixed bulk stress"},
        {"plastic_adhesion_range", 0.05, 1e-6, 0.5, "R*", "largest bonded gap kappa R* (the range is min(d_max, kappa R*))",
         false, 0.0, "a ratio of lengths"}},
       [](const ParamValues& p, const MaterialPair&) -> std::unique_ptr<SubModel> {
         return std::make_unique<PlasticAdhesion>(param(p, "plastic_adhesion"), param(p, "plastic_adhesion_range"));
       },
       kNormalForce | kCohesiveNormalForce | kRangeBeyondContact | kContactState, kContactState});
  return PADDY_PLUGIN_ABI_VERSION;
}
