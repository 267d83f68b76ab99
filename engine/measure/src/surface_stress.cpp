// Stress across a disc or a cylinder from the contact forces whose branch segments cross it
// (method of planes; formulas and sources in paddy/measure/surface_stress.hpp).
#include <paddy/errors.hpp>
#include <paddy/measure/surface_stress.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace paddy::measure {

namespace {

void requireFinite(double v, const std::string& what) {
  if (!std::isfinite(v)) throw InputError(what + " must be finite, got " + std::to_string(v));
}

// The force on the particle on the near side, from the one on the far side.
Vec3 forceOnNear(const ContactForce& c, bool i_near) { return i_near ? c.force_on_i : Vec3(-c.force_on_i); }

// Azimuthal unit vector at horizontal offset (dx, dy) from the axis (zero on the axis).
Vec3 azimuthal(double dx, double dy) {
  const double r = std::hypot(dx, dy);
  return r > 0.0 ? Vec3(-dy / r, dx / r, 0.0) : Vec3::Zero();
}

void checkContacts(const std::vector<ContactForce>& contacts, const std::string& what) {
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const ContactForce& c = contacts[k];
    if (!c.x_i.allFinite() || !c.x_j.allFinite() || !c.force_on_i.allFinite()) {
      std::ostringstream s;
      s << what << ": contact " << k << " has a non-finite position or force";
      throw InputError(s.str());
    }
  }
}

}  // namespace

SurfaceStress discStress(const std::vector<ContactForce>& contacts, const DiscSurface& disc) {
  requireFinite(disc.z, "disc stress: z");
  requireFinite(disc.r_min, "disc stress: r_min");
  requireFinite(disc.r_max, "disc stress: r_max");
  if (!disc.axis.allFinite()) throw InputError("disc stress: axis must be finite");
  if (disc.r_min < 0.0 || !(disc.r_max > disc.r_min)) {
    std::ostringstream s;
    s << "disc stress: radii r_min = " << disc.r_min << " m, r_max = " << disc.r_max
      << " m; allowed: 0 <= r_min < r_max";
    throw InputError(s.str());
  }
  checkContacts(contacts, "disc stress");
  SurfaceStress out;
  out.area = std::numbers::pi * (disc.r_max * disc.r_max - disc.r_min * disc.r_min);
  Vec3 traction = Vec3::Zero();
  double shear = 0.0;
  for (const ContactForce& c : contacts) {
    const bool i_above = c.x_i.z() >= disc.z, j_above = c.x_j.z() >= disc.z;
    if (i_above == j_above) continue;
    const double t = (disc.z - c.x_j.z()) / (c.x_i.z() - c.x_j.z());
    const Vec3 p = c.x_j + t * (c.x_i - c.x_j);
    const double dx = p.x() - disc.axis.x(), dy = p.y() - disc.axis.y();
    const double r = std::hypot(dx, dy);
    if (r < disc.r_min || r >= disc.r_max) continue;
    const Vec3 f = forceOnNear(c, !i_above);  // the near side is below the plane
    traction += f;
    shear += f.dot(azimuthal(dx, dy));
    ++out.crossings;
  }
  out.normal = -traction.z() / out.area + 0.0;  // + 0.0: no "-0" when nothing crosses
  out.shear = shear / out.area;
  return out;
}

SurfaceStress cylinderStress(const std::vector<ContactForce>& contacts, const CylinderSurface& cyl) {
  requireFinite(cyl.radius, "cylinder stress: radius");
  requireFinite(cyl.z_min, "cylinder stress: z_min");
  requireFinite(cyl.z_max, "cylinder stress: z_max");
  if (!cyl.axis.allFinite()) throw InputError("cylinder stress: axis must be finite");
  if (!(cyl.radius > 0.0) || !(cyl.z_max > cyl.z_min)) {
    std::ostringstream s;
    s << "cylinder stress: radius = " << cyl.radius << " m, z_min = " << cyl.z_min << " m, z_max = " << cyl.z_max
      << " m; allowed: radius > 0 and z_max > z_min";
    throw InputError(s.str());
  }
  checkContacts(contacts, "cylinder stress");
  const double R = cyl.radius, R2 = R * R;
  SurfaceStress out;
  out.area = 2.0 * std::numbers::pi * R * (cyl.z_max - cyl.z_min);
  double normal = 0.0, shear = 0.0;
  for (const ContactForce& c : contacts) {
    const Vec2 qi = c.x_i.head<2>() - cyl.axis, qj = c.x_j.head<2>() - cyl.axis;
    const bool i_in = qi.squaredNorm() < R2, j_in = qj.squaredNorm() < R2;
    if (i_in == j_in) continue;
    // |qj + t u| = R with u = qi − qj: a t² + 2 b t + (|qj|² − R²) = 0, one root in [0, 1].
    const Vec2 u = qi - qj;
    const double a = u.squaredNorm(), b = qj.dot(u), cc = qj.squaredNorm() - R2;
    const double sq = std::sqrt(std::max(0.0, b * b - a * cc));
    double t = (-b + sq) / a;
    if (t < 0.0 || t > 1.0) t = (-b - sq) / a;
    t = std::clamp(t, 0.0, 1.0);
    const Vec3 p = c.x_j + t * (c.x_i - c.x_j);
    if (p.z() < cyl.z_min || p.z() >= cyl.z_max) continue;
    const double dx = p.x() - cyl.axis.x(), dy = p.y() - cyl.axis.y();
    const double r = std::hypot(dx, dy);
    const Vec3 rhat = r > 0.0 ? Vec3(dx / r, dy / r, 0.0) : Vec3::Zero();
    const Vec3 f = forceOnNear(c, i_in);  // the near side is inside the cylinder
    normal -= f.dot(rhat);
    shear += f.dot(azimuthal(dx, dy));
    ++out.crossings;
  }
  out.normal = normal / out.area + 0.0;
  out.shear = shear / out.area;
  return out;
}

}  // namespace paddy::measure
