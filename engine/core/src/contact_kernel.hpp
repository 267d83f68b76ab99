// Helpers shared by the particle–particle and particle–wall force loops: fill one contact of a
// batch from body states, and apply a computed batch to the bodies.
#pragma once

#include "simulation_impl.hpp"

#include <algorithm>
#include <cmath>

namespace paddy::kernel {

// Geometry and kinematics of contact slot k for bodies i and j, normal n (j → i), overlap δ.
// Contact points: c_i = −(R_i − δ/2) n from i's centre, c_j = +(R_j − δ/2) n from j's centre
// (for a wall, c_j is the wall point itself and v_j the wall's velocity there).
inline void fill(ContactBatch& b, std::size_t k, const Vec3& n, double overlap, double ri, double rj,
                 double mi, double mj, const Vec3& vi, const Vec3& wi, const Vec3& vj_contact, const Vec3& wj) {
  b.overlap[k] = overlap;
  b.radius_i[k] = ri;
  b.radius_j[k] = rj;
  b.r_eff[k] = std::isinf(rj) ? ri : ri * rj / (ri + rj);
  b.m_eff[k] = std::isinf(mj) ? mi : mi * mj / (mi + mj);
  b.normal[k] = n;
  const Vec3 ci = -(ri - 0.5 * overlap) * n;
  const Vec3 v_rel = vi + wi.cross(ci) - vj_contact;
  const double vn = v_rel.dot(n);
  b.vn[k] = vn;
  b.vt[k] = v_rel - vn * n;
  b.omega_i[k] = wi;
  b.omega_j[k] = wj;
}

// Total force on i of contact k, and the torques on i and j (j's lever arm c_j given).
struct Applied {
  Vec3 force_i, torque_i, torque_j;
};
inline Applied applied(const ContactBatch& b, std::size_t k, double ri, double rj_arm) {
  const Vec3& n = b.normal[k];
  const Vec3 f = b.fn[k] * n + b.ft[k];
  const Vec3 ci = -(ri - 0.5 * b.overlap[k]) * n;
  const Vec3 cj = (rj_arm - 0.5 * b.overlap[k]) * n;
  return {f, ci.cross(b.ft[k]) + b.torque_i[k], cj.cross(-b.ft[k]) + b.torque_j[k]};
}

}  // namespace paddy::kernel
