// Wall: a rigid body (triangle mesh, analytic plane, ...) that particles touch.
// The engine owns the time loop; a wall reports contacts with particles, moves by its prescribed
// kinematics and accumulates the force and torque the particles exert on it.
#pragma once

#include <paddy/contact_batch.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace paddy {

// One sphere–wall contact found by a wall. `key` identifies the contact on that wall across
// steps (e.g. a patch/cluster id), so its history survives; (particle id, wall index, key) is
// the history key.
struct WallContact {
  std::uint32_t particle = 0;  // particle index (current storage order)
  std::uint32_t key = 0;       // per-wall contact key, stable while the contact lasts
  double overlap = 0.0;        // radius − distance to the wall surface [m] (< 0: a gap)
  Vec3 normal = Vec3::Zero();  // unit normal from the wall towards the particle centre
  Vec3 point = Vec3::Zero();   // closest point on the wall surface [m]
};

// Read-only view of the particle arrays passed to walls.
struct ParticleView {
  std::size_t n = 0;
  const Vec3* position = nullptr;
  const double* radius = nullptr;
  int threads = 1;  // threads a wall may use for its search (the simulation's)
};

class Wall {
 public:
  virtual ~Wall() = default;
  virtual std::string name() const = 0;
  virtual int material() const = 0;

  // Advance the prescribed kinematics to time t (called once per step before forces).
  virtual void moveTo(double t) = 0;
  // Velocity of the wall's material point at p, and its angular velocity, at the current time.
  virtual Vec3 velocityAt(const Vec3& p) const = 0;
  virtual Vec3 angularVelocity() const = 0;
  // How far the wall has moved (max displacement of any of its points) since the last call to
  // markListBuilt(); the engine refreshes the candidate lists when this plus the largest particle
  // displacement since then exceeds the skin.
  virtual double displacementSinceListBuild() const = 0;

  // Candidate search, at a neighbour-list rebuild: remember which particles lie within `range`
  // of the wall (range already includes the skin).
  virtual void buildCandidates(const ParticleView& particles, double range) = 0;
  virtual void markListBuilt() = 0;
  // Exact contacts among the candidates for the current positions: all contacts with
  // overlap > -max_gap, at most one per flat region (no double counting at shared edges).
  virtual void findContacts(const ParticleView& particles, double max_gap,
                            std::vector<WallContact>& out) const = 0;

  // Loads exerted by the particles on the wall during the current step.
  void resetLoads() { force_.setZero(); torque_.setZero(); }
  void addLoad(const Vec3& f, const Vec3& point) {
    force_ += f;
    torque_ += (point - torqueOrigin()).cross(f);
  }
  const Vec3& force() const { return force_; }
  const Vec3& torque() const { return torque_; }  // about torqueOrigin()
  virtual Vec3 torqueOrigin() const { return Vec3::Zero(); }

 private:
  Vec3 force_ = Vec3::Zero();
  Vec3 torque_ = Vec3::Zero();
};

}  // namespace paddy
