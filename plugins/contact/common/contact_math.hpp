// Small helpers shared by the contact sub-models (header-only, no state).
//
//  * restitutionBeta(e): β = ln e / sqrt(ln²e + π²), the damping factor of the EDEM Hertz-Mindlin
//    model (Tsuji et al. 1992 form; β ∈ [−1, 0], β = 0 for e = 1).
//  * rotateIntoPlane(v, n): turns a history vector (tangential spring, rolling spring) into the
//    plane normal to the current contact normal n, keeping its length.
//  * contactLever(R, δ): distance from a centre to the contact point, R − δ/2, the same contact
//    point the engine uses for the moments of ft (engine/core/src/contact_kernel.hpp).
#pragma once

#include <paddy/contact_batch.hpp>
#include <paddy/contact_model.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace paddy::contact {

inline double restitutionBeta(double e) {
  if (e >= 1.0) return 0.0;
  const double l = std::log(e);
  return l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

// Removes v's component along n and rescales the rest to |v| (zero if v is parallel to n).
inline void rotateIntoPlane(Vec3& v, const Vec3& n) {
  const double len2 = v.squaredNorm();
  if (len2 == 0.0) return;
  Vec3 p = v - v.dot(n) * n;
  const double p2 = p.squaredNorm();
  if (p2 == 0.0) {
    v.setZero();
    return;
  }
  v = p * std::sqrt(len2 / p2);
}

inline double contactLever(double radius, double overlap) { return radius - 0.5 * overlap; }

inline Vec3 loadVec(const double* h) { return Vec3(h[0], h[1], h[2]); }
inline void storeVec(double* h, const Vec3& v) {
  h[0] = v.x();
  h[1] = v.y();
  h[2] = v.z();
}

// ---- parameter declarations shared by several sub-models (one definition → same range,
// default and wording wherever a name appears) ---------------------------------------------------
inline ParamSpec restitutionParam() {
  // The range is (0, 1]; ParamSpec ranges are closed, so the lower bound is the smallest
  // positive normal double.
  return {"restitution", 0.0, std::numeric_limits<double>::min(), 1.0, "",
          "coefficient of restitution e in (0, 1]; 1 = no damping", true, 0.0,
          "dimensionless; fixes the damping ratio (Radl et al. 2011; Sakai & Koshizuka 2009)"};
}
inline ParamSpec frictionParam() {
  return {"friction", 0.0, 0.0, 10.0, "", "static (Coulomb) friction coefficient mu_s", true, 0.0,
          "Coulomb ratio, dimensionless (Sakai & Koshizuka 2009)"};
}
inline ParamSpec rollingFrictionParam() {
  return {"rolling_friction", 0.0, 0.0, 10.0, "", "rolling friction coefficient mu_r", true, 0.0,
          "dimensionless; torque mu_r F_n R scales as force x length"};
}

inline double param(const ParamValues& p, const std::string& name) { return p.at(name); }

}  // namespace paddy::contact
