// Coarse-graining scaling laws p_cg = α^k p_ref. The laws, what each holds invariant and the
// sources: paddy/measure/coarse_graining.hpp and docs/measurement.md.
#include <paddy/errors.hpp>
#include <paddy/measure/coarse_graining.hpp>

#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>

namespace paddy::measure {

const std::vector<ScalingLaw>& CoarseGraining::laws() {
  static const std::vector<ScalingLaw> table = {
      {"radius", 1.0, "definition of alpha = d_cg/d_ref"},
      {"diameter", 1.0, "definition of alpha = d_cg/d_ref"},
      {"particle_count", -3.0, "same solid volume"},
      {"density", 0.0, "same material; bulk density and weight per volume kept"},
      {"shear_modulus", 0.0, "same material; Hertz stiffness ~ E* a grows ~ R (Thakur et al. 2016; Feng & Owen 2014)"},
      {"youngs_modulus", 0.0, "same material (as shear_modulus)"},
      {"poisson", 0.0, "dimensionless"},
      {"restitution", 0.0, "dimensionless; fixes the damping ratio (Radl et al. 2011; Sakai & Koshizuka 2009)"},
      {"rolling_damping", 0.0, "dimensionless damping ratio"},
      {"friction", 0.0, "Coulomb ratio, dimensionless (Sakai & Koshizuka 2009)"},
      {"rolling_friction", 0.0, "dimensionless; torque mu_r F_n R scales as force x length"},
      {"jkr_hysteretic", 0.0, "switch"},
      {"surface_energy", 1.0,
       "pull-off force 3 pi gamma R* ~ alpha^2 like contact forces at fixed bulk stress; cohesive stress "
       "F_po/d^2 invariant (Thakur et al. 2016: adhesive force ~ size^2)"},
      {"time_step", 1.0, "Rayleigh time pi R/(0.163 nu + 0.877) sqrt(rho/G) ~ R"},
  };
  return table;
}

const ScalingLaw& CoarseGraining::law(const std::string& name) {
  for (const auto& l : laws())
    if (l.name == name) return l;
  std::string known;
  for (const auto& l : laws()) known += (known.empty() ? "" : ", ") + l.name;
  throw InputError("coarse graining: no scaling law for parameter '" + name + "'; known: " + known +
                   " (pass a ScalingLaw for others)");
}

CoarseGraining::CoarseGraining(double alpha) : alpha_(alpha) {
  if (!(alpha > 0.0) || !std::isfinite(alpha))
    throw InputError("coarse graining: alpha = d_cg/d_ref = " + std::to_string(alpha) + " must be > 0");
}

double CoarseGraining::factor(const std::string& name) const { return std::pow(alpha_, law(name).exponent); }

double CoarseGraining::rayleighTime(double radius, double density, double shear_modulus, double poisson) {
  if (!(radius > 0.0) || !(density > 0.0) || !(shear_modulus > 0.0) || !(poisson > -1.0 && poisson <= 0.5))
    throw InputError("rayleighTime: needs radius, density, shear modulus > 0 and -1 < poisson <= 0.5");
  return std::numbers::pi * radius / (0.163 * poisson + 0.877) * std::sqrt(density / shear_modulus);
}

double CoarseGraining::jkrPullOffForce(double surface_energy, double r_eff) {
  if (!(surface_energy >= 0.0) || !(r_eff > 0.0))
    throw InputError("jkrPullOffForce: needs surface energy >= 0 and effective radius > 0");
  return 3.0 * std::numbers::pi * surface_energy * r_eff;
}

ScaledParameters scaleParameters(const ParamValues& parameters, double alpha,
                                 const std::vector<ScalingLaw>& extra_laws) {
  const CoarseGraining cg(alpha);
  ScaledParameters out;
  for (const auto& [name, value] : parameters) {
    const ScalingLaw* law = nullptr;
    for (const auto& l : extra_laws)
      if (l.name == name) law = &l;
    if (!law) law = &CoarseGraining::law(name);
    ScalingRow row;
    row.name = name;
    row.reference = value;
    row.exponent = law->exponent;
    row.factor = law->exponent == 0.0 ? 1.0 : std::pow(alpha, law->exponent);
    row.scaled = value * row.factor;
    row.reason = law->reason;
    out.values[name] = row.scaled;
    out.table.push_back(row);
  }
  return out;
}

std::string ScaledParameters::text() const {
  std::ostringstream s;
  s << std::left << std::setw(18) << "parameter" << std::setw(14) << "reference" << std::setw(14) << "scaled"
    << std::setw(9) << "exponent" << std::setw(8) << "changed" << "law\n";
  for (const auto& r : table) {
    s << std::left << std::setw(18) << r.name << std::setw(14) << std::setprecision(6) << r.reference
      << std::setw(14) << r.scaled << std::setw(9) << r.exponent << std::setw(8) << (r.factor != 1.0 ? "yes" : "no")
      << r.reason
      << '\n';
  }
  return s.str();
}

}  // namespace paddy::measure
