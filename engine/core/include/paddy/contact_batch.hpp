// ContactBatch: the data a contact sub-model sees — a block of up to kCapacity contacts of one
// material pair, stored as structure-of-arrays so each sub-model runs one tight loop per batch.
//
// Conventions (all SI units):
//   * contact k is between body i and body j; for a wall contact, j is the wall
//     (radius_j = +inf, so r_eff = radius_i, and m_eff = mass_i);
//   * normal[k] is the unit vector from j towards i;
//   * overlap[k] = radius_i + radius_j − |x_i − x_j|  (> 0 in contact, < 0 a gap);
//   * v_rel[k] is the velocity of i's contact point relative to j's, vn[k] = v_rel·n
//     (> 0 separating, < 0 approaching), vt[k] = v_rel − vn·n;
//   * fn[k] is the scalar normal force on i along normal[k] (> 0 repulsive);
//     ft[k] the tangential force on i; j receives −(fn·n + ft).
//   * torque_i / torque_j are extra torques (rolling, twisting) on i and j; the engine adds the
//     moments of ft about each centre itself.
//   * resist_i / resist_j are magnitudes R ≥ 0 of torques that oppose the body's OWN rotation,
//     −R ω/|ω| (a set-valued, Coulomb-like law such as EDEM's rolling friction "type A"). The
//     engine sums them per body and applies them implicitly in the integrator: within a step they
//     slow the rotation by at most R dt / I and can stop it, but never reverse it (see
//     engine/core/src/integrator.cpp). A model writing its torque explicitly into torque_i instead
//     would make a body at rest chatter, and the result depend on dt.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>

namespace paddy {

using Vec3 = Eigen::Vector3d;

struct ContactBatch {
  static constexpr std::size_t kCapacity = 128;

  std::size_t n = 0;   // contacts in this batch
  double dt = 0.0;     // time step [s]
  double time = 0.0;   // simulated time [s]

  // ---- geometry and kinematics, written by the engine -------------------------------------
  double overlap[kCapacity];    // δ [m]
  double r_eff[kCapacity];      // R* = (1/R_i + 1/R_j)^-1 [m]
  double m_eff[kCapacity];      // m* = (1/m_i + 1/m_j)^-1 [kg]
  double radius_i[kCapacity];   // R_i [m]
  double radius_j[kCapacity];   // R_j [m] (+inf for walls)
  double vn[kCapacity];         // normal relative velocity [m/s]
  Vec3 normal[kCapacity];       // unit normal, j → i
  Vec3 vt[kCapacity];           // tangential relative velocity at the contact point [m/s]
  Vec3 omega_i[kCapacity];      // angular velocity of i [rad/s]
  Vec3 omega_j[kCapacity];      // angular velocity of j [rad/s] (a wall's, for wall contacts)

  // ---- per-contact history, persistent across steps and neighbour-list rebuilds -------------
  // Contact k's block starts at history_at[k]; a sub-model owns `historySize()` doubles from the
  // offset it is given. New contacts start with zeros. The engine points history_at[k] at the
  // contact's own stored block, so a sub-model reads and writes the history in place (no copy
  // into the batch and back); setContiguousHistory lays the blocks of contacts 0 .. count − 1 out
  // one after another in one array of count × stride doubles instead (tests, tools).
  double* history_at[kCapacity] = {};
  double* historyOf(std::size_t k, std::size_t offset) { return history_at[k] + offset; }
  void setContiguousHistory(double* history, std::size_t stride, std::size_t count) {
    for (std::size_t k = 0; k < count && k < kCapacity; ++k) history_at[k] = history + k * stride;
  }

  // ---- shared state: written by the normal model, read by the others ------------------------
  std::uint8_t active[kCapacity];  // 1: bodies interact through the contact patch this step
  double contact_radius[kCapacity];// a [m]
  double fn_friction[kCapacity];   // normal load that sets Coulomb/rolling limits (>= 0) [N]
  double stiffness_n[kCapacity];   // S_n = dF_n/dδ used by damping [N/m]
  double stiffness_t[kCapacity];   // S_t tangential stiffness [N/m]

  // ---- outputs ------------------------------------------------------------------------------
  double fn[kCapacity];            // normal force on i along normal [N]
  Vec3 ft[kCapacity];              // tangential force on i [N]
  Vec3 torque_i[kCapacity];        // extra torque on i [N m]
  Vec3 torque_j[kCapacity];        // extra torque on j [N m]
  double resist_i[kCapacity];      // magnitude of a torque opposing i's rotation [N m]
  double resist_j[kCapacity];      // magnitude of a torque opposing j's rotation [N m]

  // Clears shared state and outputs before the sub-models run.
  void resetOutputs() {
    for (std::size_t k = 0; k < n; ++k) {
      active[k] = 0;
      contact_radius[k] = 0.0;
      fn_friction[k] = 0.0;
      stiffness_n[k] = 0.0;
      stiffness_t[k] = 0.0;
      fn[k] = 0.0;
      ft[k].setZero();
      torque_i[k].setZero();
      torque_j[k].setZero();
      resist_i[k] = 0.0;
      resist_j[k] = 0.0;
    }
  }
};

}  // namespace paddy
