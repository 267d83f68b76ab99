// Plugin paddy_jkr: normal sub-model "jkr" (Hertz-Mindlin with JKR cohesion, EDEM 2018 form, with
// an optional hysteretic LAMMPS-like variant). Formulas in jkr.hpp and docs/physics.md.
#include "jkr.hpp"

#include <paddy/errors.hpp>
#include <paddy/plugin.hpp>

#include <memory>

using namespace paddy;
using namespace paddy::contact;

extern "C" PADDY_PLUGIN_EXPORT int paddy_register_plugin(PluginRegistry* r) {
  r->addSubModel(
      {"jkr", SubModelKind::Normal,
       "JKR cohesion F = -4 sqrt(pi gamma E*) a^1.5 + 4E* a^3/(3R*), d = a^2/R* - sqrt(4 pi gamma a/E*), "
       "attraction down to d_c (Johnson, Kendall & Roberts 1971; EDEM 2018)",
       {{"surface_energy", 0.0, 0.0, 100.0, "J/m^2", "surface energy gamma (work of adhesion 2 gamma)", true, 1.0,
         "pull-off force 3 pi gamma R* ~ alpha^2 like contact forces at fixed bulk stress; cohesive stress "
         "F_po/d^2 invariant (Thakur et al. 2016: adhesive force ~ size^2)"},
        {"jkr_hysteretic", 0.0, 0.0, 1.0, "",
         "0: EDEM (attraction from d_c on approach too); 1: snap-in at touch, release at d_c", false, 0.0, "switch"},
        {"jkr_overlap_stiffness", 0.0, 0.0, 1.0, "",
         "0: damping and tangential stiffness from the JKR contact radius a (Paddy); 1: from sqrt(R* d), "
         "zero in a gap, as Hertz-Mindlin (EDEM)", false, 0.0, "switch"}},
       [](const ParamValues& p, const MaterialPair& m) -> std::unique_ptr<SubModel> {
         const double h = param(p, "jkr_hysteretic");
         if (h != 0.0 && h != 1.0)
           throw InputError("parameter 'jkr_hysteretic' = " + std::to_string(h) + " must be 0 or 1");
         const double o = param(p, "jkr_overlap_stiffness");
         if (o != 0.0 && o != 1.0)
           throw InputError("parameter 'jkr_overlap_stiffness' = " + std::to_string(o) + " must be 0 or 1");
         return std::make_unique<JkrNormal>(m.e_star, m.g_star, param(p, "surface_energy"), h == 1.0, o == 1.0);
       },
       kNormalForce | kContactState | kNormalStiffness | kTangentialStiffness | kCohesiveNormalForce |
           kRangeBeyondContact});
  return PADDY_PLUGIN_ABI_VERSION;
}
