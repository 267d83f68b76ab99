// Coarse graining: scaling laws for the contact parameters when the particles are enlarged by the
// size ratio α = d_cg / d_ref (α > 1: fewer, larger particles; the pile, cone and plate keep their
// size, gravity is unchanged). Each law is a power: p_cg = α^k · p_ref.
//
//   radius, diameter                     k = 1   by definition
//   particle_count                       k = −3  same solid volume
//   density, shear_modulus,
//   youngs_modulus, poisson              k = 0   same material: Hertz contact stiffness then grows
//                                                ∝ R, which is the linear size scaling of contact
//                                                stiffness found by Thakur et al. 2016 and the
//                                                exact-scaling choice of Feng & Owen 2014
//   restitution, rolling_damping         k = 0   dimensionless damping; restitution fixes the
//                                                damping ratio (Radl et al. 2011; Sakai & Koshizuka
//                                                2009 keep e, μ unchanged)
//   friction, rolling_friction           k = 0   Coulomb ratios; the rolling torque μ_r F_n R then
//                                                scales as force × length
//   jkr_hysteretic                       k = 0   a switch
//   surface_energy (JKR γ)               k = 1   the pull-off force F_po = 3π γ R* scales as α²,
//                                                like every contact force at a given bulk stress
//                                                (F ~ σ d²); held invariant: the cohesive stress
//                                                F_po/d² ∝ γ/R and the stress Bond number
//                                                F_po/(σ d²). Thakur et al. 2016 found the adhesive
//                                                force must scale with the square of the particle
//                                                size for scale-independent bulk response. With E
//                                                and ν fixed the whole JKR force–overlap curve is then
//                                                self-similar: F_cg(α δ) = α² F(δ).
//   time_step                            k = 1   Rayleigh time T_R = πR/(0.163ν + 0.877)·sqrt(ρ/G) ∝ R
// Not invariant (documented bias): the particle Bond number F_po/(m g) ∝ γ/(ρ g R²) falls as 1/α,
// so single grains on the free surface are relatively less sticky; the number of particles across
// the pile falls as 1/α. Sources in docs/measurement.md.
// The contact parameters' laws are also declared beside the sub-models that define them
// (ParamSpec::coarse_graining_exponent; paddy.coarse_grain uses those for a law given by name);
// the rows here for restitution, friction, rolling friction, rolling damping, jkr_hysteretic and
// surface_energy must agree with them (tests/contact/test_effects_interface.cpp checks it).
#pragma once

#include <paddy/contact_model.hpp>

#include <string>
#include <vector>

namespace paddy::measure {

struct ScalingLaw {
  std::string name;       // parameter name, as the contact sub-models declare it
  double exponent = 0.0;  // p_cg = α^exponent · p_ref
  std::string reason;     // what is held invariant, and the source
};

struct ScalingRow {
  std::string name;
  double reference = 0.0;
  double scaled = 0.0;
  double factor = 1.0;  // α^exponent
  double exponent = 0.0;
  std::string reason;
};

struct ScaledParameters {
  ParamValues values;             // the scaled parameters (same names)
  std::vector<ScalingRow> table;  // one row per parameter, in name order
  std::string text() const;       // the table as aligned text, with a yes/no "changed" column
};

class CoarseGraining {
 public:
  // α = d_cg / d_ref > 0 (InputError otherwise).
  explicit CoarseGraining(double alpha);
  double alpha() const { return alpha_; }

  // The built-in laws (see the header comment).
  static const std::vector<ScalingLaw>& laws();
  // The law for a parameter name; InputError naming the known names if there is none.
  static const ScalingLaw& law(const std::string& name);

  double factor(const std::string& name) const;  // α^k for that parameter
  double radius(double r) const { return alpha_ * r; }
  double surfaceEnergy(double gamma) const { return alpha_ * gamma; }
  double timeStep(double dt) const { return alpha_ * dt; }
  double particleCount(double n) const { return n / (alpha_ * alpha_ * alpha_); }

  // Physical quantities used to check the laws.
  // T_R = π R / (0.163 ν + 0.877) · sqrt(ρ / G)  (reference README; the usual DEM Rayleigh-wave time)
  static double rayleighTime(double radius, double density, double shear_modulus, double poisson);
  // JKR pull-off force 3π γ R* = (3/2) π W R* with the work of adhesion W = 2γ (Johnson, Kendall &
  // Roberts 1971); γ is the surface energy of the "jkr" sub-model (plugins/contact/jkr/jkr.hpp),
  // whose force πγR* (4/3 t⁶ − 4 t³) has this minimum at t³ = 3/2.
  static double jkrPullOffForce(double surface_energy, double r_eff);

 private:
  double alpha_;
};

// Scales every parameter by its law. Unknown names throw InputError (listing the known ones)
// unless a law for them is passed in `extra_laws`. α = 1 returns the input unchanged.
ScaledParameters scaleParameters(const ParamValues& parameters, double alpha,
                                 const std::vector<ScalingLaw>& extra_laws = {});

}  // namespace paddy::measure
