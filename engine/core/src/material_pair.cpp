#include <paddy/contact_model.hpp>
#include <paddy/errors.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <utility>

namespace paddy {

const char* toString(SubModelKind kind) {
  switch (kind) {
    case SubModelKind::Normal: return "normal";
    case SubModelKind::Damping: return "damping";
    case SubModelKind::Tangential: return "tangential";
    case SubModelKind::Rolling: return "rolling";
    case SubModelKind::Twisting: return "twisting";
    case SubModelKind::Extra: return "extra";
  }
  return "?";
}

std::string capabilityNames(unsigned capabilities) {
  static const std::pair<unsigned, const char*> names[] = {
      {kNormalForce, "normal force"},
      {kContactState, "contact state (active, contact radius, friction load)"},
      {kNormalStiffness, "normal stiffness"},
      {kTangentialStiffness, "tangential stiffness"},
      {kCohesiveNormalForce, "cohesive normal force"},
      {kRangeBeyondContact, "range beyond contact"},
      {kViscousFluidForce, "viscous fluid force"},
  };
  std::string out;
  for (const auto& [bit, name] : names)
    if (capabilities & bit) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

MaterialPair MaterialPair::of(const Material& a, const Material& b) {
  MaterialPair p{a, b, 0.0, 0.0};
  const double inv_e = (1.0 - a.poisson * a.poisson) / a.youngs() + (1.0 - b.poisson * b.poisson) / b.youngs();
  const double inv_g = (2.0 - a.poisson) / a.shear_modulus + (2.0 - b.poisson) / b.shear_modulus;
  p.e_star = 1.0 / inv_e;
  p.g_star = 1.0 / inv_g;
  return p;
}

void checkRange(const std::string& name, double value, double lo, double hi, const std::string& unit) {
  if (std::isnan(value) || value < lo || value > hi) {
    std::ostringstream msg;
    msg << "parameter '" << name << "' = " << value << (unit.empty() ? "" : " " + unit)
        << " is outside the allowed range [" << lo << ", " << hi << "]" << (unit.empty() ? "" : " " + unit);
    throw InputError(msg.str());
  }
}

}  // namespace paddy
