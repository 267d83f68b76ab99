// Slump ↔ yield stress for a cylinder (Pashias et al. 1996) or a truncated cone (Schowalter &
// Christensen 1998). Formulas and assumptions in paddy/measure/slump_yield_stress.hpp.
#include <paddy/errors.hpp>
#include <paddy/measure/slump_yield_stress.hpp>

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>
#include <sstream>

namespace paddy::measure {

namespace {

void checkMould(const SlumpMould& m, double density, double gravity, const char* what) {
  std::ostringstream s;
  if (!(m.height > 0.0) || !std::isfinite(m.height)) s << "mould height = " << m.height << " m must be finite and > 0";
  else if (!(m.top_diameter > 0.0) || !std::isfinite(m.top_diameter)) s << "top_diameter = " << m.top_diameter << " m must be finite and > 0";
  else if (!(m.bottom_diameter >= m.top_diameter) || !std::isfinite(m.bottom_diameter))
    s << "bottom_diameter = " << m.bottom_diameter << " m must be finite and >= top_diameter = " << m.top_diameter << " m";
  else if (!(density > 0.0) || !std::isfinite(density)) s << "density = " << density << " kg/m^3 must be finite and > 0";
  else if (!(gravity > 0.0) || !std::isfinite(gravity)) s << "gravity = " << gravity << " m/s^2 must be finite and > 0";
  if (!s.str().empty()) throw InputError(std::string(what) + ": " + s.str());
}

// V(z)/π: volume above depth z over π; A(z)/π = r(z)².
struct Mould {
  double H, r1, k;  // r(z) = r1 + k z
  double r(double z) const { return r1 + k * z; }
  double volume(double z) const {  // ∫0^z r² dz
    if (k == 0.0) return r1 * r1 * z;
    const double rz = r(z);
    return (rz * rz * rz - r1 * r1 * r1) / (3.0 * k);
  }
  double stressHeight(double z) const { return volume(z) / (r(z) * r(z)); }  // σ/(ρg) = V/A, increasing in z
};

Mould mouldOf(const SlumpMould& m) {
  return {m.height, 0.5 * m.top_diameter, 0.5 * (m.bottom_diameter - m.top_diameter) / m.height};
}

}  // namespace

double slumpYieldLimit(double density, double gravity, const SlumpMould& m) {
  checkMould(m, density, gravity, "slumpYieldLimit");
  const Mould g = mouldOf(m);
  return 0.5 * density * gravity * g.stressHeight(g.H);
}

double slumpFromYieldStress(double tau_y, double density, double gravity, const SlumpMould& m) {
  checkMould(m, density, gravity, "slumpFromYieldStress");
  if (!(tau_y >= 0.0) || !std::isfinite(tau_y))
    throw InputError("slumpFromYieldStress: yield stress = " + std::to_string(tau_y) + " Pa must be finite and >= 0");
  const Mould g = mouldOf(m);
  if (tau_y == 0.0) return g.H;
  const double ell = 2.0 * tau_y / (density * gravity);  // 2τ_y/(ρg) [m]
  if (ell >= g.stressHeight(g.H)) return 0.0;           // nothing yields
  // h0: V(h0)/A(h0) = ell; V/A increases monotonically from 0 at z = 0.
  std::uintmax_t iters = 200;
  const auto root = boost::math::tools::toms748_solve([&](double z) { return g.stressHeight(z) - ell; }, 0.0, g.H,
                                                      boost::math::tools::eps_tolerance<double>(52), iters);
  const double h0 = 0.5 * (root.first + root.second);
  const double h1 = ell * std::log(g.volume(g.H) / g.volume(h0));
  return g.H - h0 - h1;
}

double yieldStressFromSlump(double slump, double density, double gravity, const SlumpMould& m) {
  checkMould(m, density, gravity, "yieldStressFromSlump");
  if (!(slump > 0.0 && slump < m.height)) {
    std::ostringstream s;
    s << "yieldStressFromSlump: slump = " << slump << " m is outside the range the model inverts, 0 < slump < "
      << m.height << " m (the mould height)";
    throw InputError(s.str());
  }
  const double hi = slumpYieldLimit(density, gravity, m);
  std::uintmax_t iters = 200;
  const auto root = boost::math::tools::toms748_solve(
      [&](double t) { return slumpFromYieldStress(t, density, gravity, m) - slump; }, 0.0, hi,
      boost::math::tools::eps_tolerance<double>(50), iters);
  return 0.5 * (root.first + root.second);
}

}  // namespace paddy::measure
