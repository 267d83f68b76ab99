// Plugin paddy_lubrication: extra "lubrication" (squeeze-film force of the interstitial fluid,
// Reynolds normal term and Goldman, Cox & Brenner 1967 tangential log term). Formula in
// lubrication.hpp and docs/physics.md "Lubrication".
#include "lubrication.hpp"

#include <paddy/errors.hpp>
#include <paddy/plugin.hpp>

#include <memory>

using namespace paddy;
using namespace paddy::contact;

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(PluginRegistry* r) {
  r->addSubModel(
      {"lubrication", SubModelKind::Extra,
       "squeeze film F_n = -6 pi mu R*^2 v_n/h, F_t = -6 pi mu R* (8/15) ln(R*/h) v_t, h = max(gap, h_min), "
       "gap < h_cut; coefficients capped at m*/(12 dt) (Reynolds; Goldman, Cox & Brenner 1967)",
       {{"lubrication_viscosity", 0.0, 0.0, 1e4, "Pa s", "viscosity mu of the interstitial fluid (0: off)", false, 1.0,
         "force 6 pi mu R*^2 v/h ~ mu alpha at the same velocity and gap ratio; mu ~ alpha makes it ~ alpha^2 like "
         "contact forces at fixed bulk stress (as the JKR surface energy)"},
        {"lubrication_min_gap", 0.01, 1e-6, 1.0, "R*", "minimum film thickness h_min / R* (regularisation)", false, 0.0,
         "a ratio of lengths"},
        {"lubrication_cutoff", 0.1, 1e-6, 1.0, "R*", "gap h_cut / R* beyond which the film force is 0", false, 0.0,
         "a ratio of lengths"}},
       [](const ParamValues& p, const MaterialPair&) -> std::unique_ptr<SubModel> {
         const double h_min = param(p, "lubrication_min_gap"), h_cut = param(p, "lubrication_cutoff");
         if (!(h_cut > h_min))
           throw InputError("parameter 'lubrication_cutoff' = " + std::to_string(h_cut) +
                            " must be larger than 'lubrication_min_gap' = " + std::to_string(h_min));
         return std::make_unique<Lubrication>(param(p, "lubrication_viscosity"), h_min, h_cut);
       },
       kNormalForce | kRangeBeyondContact | kViscousFluidForce, 0, kViscousFluidForce});
  return PADDY_PLUGIN_ABI_VERSION;
}
