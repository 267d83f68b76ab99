// Simulation: owns particles, walls, contact laws and the time loop (velocity Verlet, or the
// semi-implicit Euler scheme on request: TimeIntegration).
//
// Particles are stored as structure-of-arrays (one array per field). The neighbour search is a
// cell list feeding a half Verlet list with a skin; per-contact history lives beside the list and
// is carried over at every rebuild and every spatial re-sort, keyed by persistent particle ids.
// Forces are computed in batches of contacts of one material pair (ContactBatch); each batch is
// passed through the pair's sub-model chain (one virtual call per sub-model per batch).
#pragma once

#include <paddy/contact_model.hpp>
#include <paddy/wall.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace paddy {

class PluginManager;
class ContactLaw;
class NeighbourList;

// Which sub-models make up a material pair's contact law, and their parameters.
struct InteractionSpec {
  std::string normal = "hertz";
  std::string damping = "hertz_mindlin";
  std::string tangential = "mindlin";
  std::string rolling;   // "" = none
  std::string twisting;  // "" = none
  std::vector<std::string> extras;
  ParamValues params;    // flat: each sub-model takes the names it declares
};

struct ParticleArrays {
  std::vector<std::uint64_t> id;  // persistent id (survives re-sorting)
  std::vector<int> material;
  std::vector<double> radius, mass, inertia;  // inertia = 2/5 m R²
  std::vector<Vec3> position, velocity, omega, force, torque;
  // Sum of the magnitudes of the torques opposing the body's own rotation (ContactBatch::resist_i),
  // applied implicitly by the integrator; not part of `torque` [N m].
  std::vector<double> resisting_torque;
  std::size_t size() const { return id.size(); }
};

// One contact as exported for output (snapshots) and inspection.
struct ContactRecord {
  std::uint64_t id_i = 0, id_j = 0;  // id_j = wall index for wall contacts
  bool wall = false;
  double overlap = 0.0;
  Vec3 normal = Vec3::Zero();
  double fn = 0.0;
  Vec3 ft = Vec3::Zero();
  std::vector<double> history;  // the contact's history block (all sub-models, in chain order)
};

struct TimeStepPolicy {
  // The step is refused above this fraction of the Rayleigh time (stability limit).
  static constexpr double kMaxRayleighFraction = 0.5;
  static constexpr double kDefaultRayleighFraction = 0.2;
};

// The time integration scheme (integrator.cpp gives the formulas).
//   VelocityVerlet:      second order; half-kick, drift, forces at the new positions with the
//                        velocities predicted to the end of the step, half-kick (the default).
//   SymplecticEuler:     first order (semi-implicit Euler): v(t+dt) = v(t) + dt F(t)/m, then
//                        x(t+dt) = x(t) + dt v(t+dt); forces with the velocities of the step, no
//                        prediction. EDEM's default scheme is a first-order "Euler"
//                        (docs/physics.md §6).
enum class TimeIntegration { VelocityVerlet, SymplecticEuler };
const char* timeIntegrationName(TimeIntegration scheme);  // "velocity_verlet", "euler"
// The scheme of that name; throws InputError naming the choices for any other name.
TimeIntegration timeIntegrationFromName(const std::string& name);

class Simulation {
 public:
  explicit Simulation(std::shared_ptr<const PluginManager> plugins);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  const PluginManager& plugins() const { return *plugins_; }

  // ---- set-up ---------------------------------------------------------------------------------
  int addMaterial(const Material& m);  // validates; returns material id
  int materialId(const std::string& name) const;  // throws if unknown
  const std::vector<Material>& materials() const { return materials_; }
  // Validates sub-model names (unknown ones list what is available) and parameters (names and
  // ranges). The pair is symmetric.
  void setInteraction(int mat_a, int mat_b, const InteractionSpec& spec);
  void setGravity(const Vec3& g) { gravity_ = g; }
  const Vec3& gravity() const { return gravity_; }
  std::size_t addParticle(const Vec3& x, double radius, int material,
                          const Vec3& v = Vec3::Zero(), const Vec3& omega = Vec3::Zero());
  void removeParticles(const std::function<bool(std::size_t index)>& predicate);
  int addWall(std::unique_ptr<Wall> wall);  // returns wall index
  Wall& wall(int index) { return *walls_.at(index); }
  std::size_t wallCount() const { return walls_.size(); }
  void setThreads(int n);
  int threads() const { return threads_; }
  // Neighbour-list skin as a fraction of the largest particle radius (default 0.4).
  void setSkinFraction(double f);
  // Re-sort particles along a space-filling order every n rebuilds (0 = never; default 20).
  void setSortInterval(int rebuilds);

  // ---- time step ------------------------------------------------------------------------------
  // Rayleigh time of the smallest particle: T_R = π R / (0.163 ν + 0.877) · sqrt(ρ / G).
  double rayleighTime() const;
  double maxStableTimeStep() const { return TimeStepPolicy::kMaxRayleighFraction * rayleighTime(); }
  // Throws InputError giving the limit if dt > maxStableTimeStep().
  void setTimeStep(double dt);
  void setTimeStepFraction(double fraction_of_rayleigh);
  double timeStep() const { return dt_; }
  // May change between calls of step(): each leaves positions, velocities and forces consistent.
  void setTimeIntegration(TimeIntegration scheme);
  TimeIntegration timeIntegration() const;

  // ---- running --------------------------------------------------------------------------------
  void step(std::uint64_t n = 1);
  // Runs for `duration` seconds; calls `callback` every `interval` seconds of simulated time
  // (and at the end); the callback returns false to stop early. Returns steps taken.
  std::uint64_t run(double duration, const std::function<bool(Simulation&)>& callback = {},
                    double interval = 0.0);
  double time() const { return time_; }
  std::uint64_t stepCount() const { return steps_; }

  // ---- state ----------------------------------------------------------------------------------
  ParticleArrays& particles() { return p_; }
  const ParticleArrays& particles() const { return p_; }
  double kineticEnergy() const;  // translational + rotational [J]
  double maxSpeed() const;
  std::vector<ContactRecord> contacts() const;  // contacts active at the last force evaluation
  std::size_t neighbourListBuilds() const { return list_builds_; }
  // Work of each thread in the particle–particle loop of the last force pass, in thread order:
  // its owners' list slots + 16 × their pairs in range (the cost the owners' split balances,
  // forces.cpp). Empty on one thread.
  std::vector<std::uint64_t> pairWorkPerThread() const;

  // ---- checkpoint / restart (HDF5): full state incl. contact history ------------------------
  void saveCheckpoint(const std::string& path) const;
  void loadCheckpoint(const std::string& path);

 private:
  struct Impl;
  // Declared first so it is destroyed last: the contact laws in impl_ hold code from the plugin
  // libraries the manager unloads when it goes.
  std::shared_ptr<const PluginManager> plugins_;
  std::unique_ptr<Impl> impl_;
  std::vector<Material> materials_;
  std::vector<std::unique_ptr<Wall>> walls_;
  ParticleArrays p_;
  Vec3 gravity_ = Vec3(0.0, 0.0, -9.81);
  double dt_ = 0.0;
  double time_ = 0.0;
  std::uint64_t steps_ = 0;
  std::uint64_t next_id_ = 0;
  std::size_t list_builds_ = 0;
  int threads_ = 1;
};

}  // namespace paddy
