// Private state of Simulation: contact laws, the neighbour list with contact history, wall
// contacts, per-thread force buffers. Split over small files in engine/core/src/ by concern:
//   simulation.cpp (set-up), integrator.cpp (time loop and spatial re-sorting, sortSpatially),
//   neighbour_list.cpp (search + history carry-over), forces.cpp (particle–particle and
//   particle–wall force loops, contact_kernel.hpp their shared helpers), wall_forces.cpp (wall
//   contacts matched to their history), checkpoint.cpp (HDF5 checkpoint / restart).
#pragma once

#include "contact_law.hpp"
#include "neighbour_list.hpp"

#include <paddy/simulation.hpp>

#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace paddy {

// A batch being filled by one thread, and where each of its contacts came from.
struct BatchWork {
  ContactBatch batch;
  std::vector<double> history;            // kCapacity × stride: copies of the history in a dry pass
  std::uint32_t i[ContactBatch::kCapacity];
  std::uint32_t j[ContactBatch::kCapacity];  // particle index, or wall contact index for walls
  std::uint8_t* slot_live[ContactBatch::kCapacity];  // the list slot's live flag (nullptr: a wall)
  Vec3 point[ContactBatch::kCapacity];       // contact point (walls)
  int law = -1;
};

// History of one particle–wall contact, kept sorted by (particle id, wall, key).
struct WallContactState {
  std::uint64_t particle_id = 0;
  std::uint32_t wall = 0;
  std::uint32_t key = 0;
};

// The contact with the largest overlap / radius of a force pass: named in instability messages.
struct WorstOverlap {
  std::uint64_t id_i = 0;    // persistent particle id
  std::uint64_t id_j = 0;    // persistent particle id, or the wall's index when wall
  bool wall = false;
};

struct ThreadBuffers {
  // Per particle; zero outside [touched_lo, touched_hi), the particles this thread's last pass
  // wrote to (it clears only those before its next pass). One thread at a step writes the
  // particle arrays instead.
  std::vector<Vec3> force, torque;
  std::vector<double> resist;        // per particle: resisting-torque magnitudes (same rule)
  std::size_t touched_lo = 0, touched_hi = 0;
  std::vector<ContactRecord> records;
  double max_overlap_ratio = 0.0;
  WorstOverlap worst;                // the contact with max_overlap_ratio
  std::uint64_t active_contacts = 0;
  std::vector<BatchWork> work;       // one per contact law
};

struct Simulation::Impl {
  static constexpr std::size_t kNoIndex = std::numeric_limits<std::size_t>::max();

  std::vector<ContactLaw> laws;
  std::vector<int> law_index;        // [mat_a * n_materials + mat_b] → laws index, -1 = none
  std::size_t history_stride = 0;

  NeighbourList list;
  std::vector<std::size_t> prev_index;  // current index → index at the last list build
  bool list_valid = false;
  bool forces_valid = false;
  double skin_fraction = 0.4;
  double skin = 0.0;
  double list_build_time = 0.0;
  // Wall candidates refreshed on their own (refreshWalls) since the particle list was built:
  // positions and time of that refresh (the skin criterion of the walls counts from it).
  bool walls_refreshed = false;
  std::vector<Vec3> x_at_wall_refresh;
  double wall_refresh_time = 0.0;
  double wall_max_gap = 0.0;  // largest gap any law acts at for the largest particle (walls)
  int sort_interval = 20;

  // walls
  std::vector<WallContactState> wall_state;  // sorted, matches wall_history blocks
  std::vector<double> wall_history;
  std::vector<WallContact> wall_found;       // scratch
  std::vector<std::uint32_t> wall_of_found;
  // Scratch of collectWallContacts and computeForces, kept to avoid allocations every step.
  struct WallContactOrder {
    std::uint64_t sort_key;  // (id rank · walls + wall) · 2^32 + key: ordered as (id, wall, key)
    std::uint64_t particle_id;
    std::uint32_t wall, key, index;  // index into wall_scratch_found
  };
  std::vector<WallContact> wall_scratch_found, wall_scratch_tmp;
  std::vector<WallContactOrder> wall_scratch_order, wall_scratch_order_tmp;
  // Rank of each particle's id among all ids (index → rank), for the wall contacts' order; ranked
  // again at a list build when the ids in storage order changed (wall_forces.cpp).
  std::vector<std::uint32_t> id_rank;
  std::vector<std::uint64_t> id_rank_ids;
  void rankIds(const ParticleArrays& p);
  std::vector<double> wall_scratch_history;  // history of this step's wall contacts
  std::vector<Vec3> wall_scratch_force;      // force on the particle of each wall contact

  std::vector<ThreadBuffers> threads;
  // The owners of the particle–particle loop split among the threads (forces.cpp) by their cost
  // at the step before: kParticleCost + an owner's list slots + kContactCost × its pairs in range
  // (a slot out of range is one distance test, a pair in range a contact law, and every particle
  // goes through the per-particle loops that follow the same split: kicks, drift, packing,
  // prediction, the force reduction). owner_bounds holds threads + 1 owner indices; empty after a
  // list build, until a step has counted (then split by slots).
  static constexpr std::uint64_t kContactCost = 16;
  static constexpr std::uint64_t kParticleCost = 16;
  std::vector<std::size_t> owner_bounds, owner_bounds_used;
  // Thread t's owners [first, second) of nt: by owner_bounds when it holds a split for nt threads,
  // else an even split of the list's slots (an even split of the particles without a list). The
  // per-particle loops (kicks, drift, velocity prediction, the force reduction) use the same
  // range: each thread then moves, predicts and sums the particles whose contacts it evaluates,
  // which stay in its core's cache (with a split of their own, a few thousand particles' data
  // crossed between the cores at every loop). Which thread moves a particle does not change its
  // numbers; which thread sums a contact does (the reduction's order), so the split is kept in
  // checkpoints.
  std::pair<std::size_t, std::size_t> ownerRange(int t, int nt, std::size_t n) const;
  std::vector<std::uint64_t> owner_cost_sum;     // per owner: running cost within its thread's range
  std::vector<std::uint64_t> owner_thread_cost;  // per thread: its range's cost
  void rebalanceOwners(std::size_t n, int nt);
  double dt_fraction = 0.0;   // requested as a fraction of the Rayleigh time (0: explicit dt)
  bool dt_explicit = false;

  // The force pass's copy of each body, written at its start (packBodies, each thread for its own
  // owners, before a barrier): where a partner's position, radius, velocities and mass sit in five
  // arrays, the pair loop would read up to five cache lines per partner; packed it reads one for
  // the distance test of a list slot (BodyShape) and one more for a pair in range (BodyMotion).
  // v and w are the velocities the contact laws see: at a step under velocity Verlet those
  // predicted to the end of the step, v(t+dt) ≈ v(t+dt/2) + dt/2 F(t)/m (predictVelocities,
  // integrator.cpp, beside the kicks it repeats), otherwise the current ones.
  struct alignas(32) BodyShape {
    Vec3 x;
    double r;
  };
  struct alignas(64) BodyMotion {
    Vec3 v, w;
    double m;
  };
  std::vector<BodyShape> body_shape;
  std::vector<BodyMotion> body_motion;
  void packBodies(const Simulation& s, std::size_t lo, std::size_t hi, bool predicted);
  TimeIntegration integration = TimeIntegration::VelocityVerlet;
  // Only velocity Verlet predicts (the Euler scheme's forces see the velocities of the step).
  bool predictsVelocities() const { return integration == TimeIntegration::VelocityVerlet; }
  void predictVelocities(const Simulation& s, std::size_t lo, std::size_t hi);

  std::vector<ContactRecord> last_records;
  std::uint64_t active_contacts = 0;
  double max_overlap_ratio = 0.0;
  WorstOverlap worst_overlap;
  std::string describeWorstOverlap(const Simulation& s) const;  // "particles 3 and 7 ..." (integrator.cpp)

  // Force evaluation (forces.cpp).
  //   Step:    forces at the new positions; history advanced over the step just taken.
  //   Initial: forces of the initial state; history written but not advanced (nothing moved).
  //   Dry:     evaluate at the current state without advancing or writing any history, and
  //            collect ContactRecords instead of updating forces.
  enum class ForcePass { Step, Initial, Dry };
  void computeForces(Simulation& s, ForcePass pass);
  // Wall contacts of the current step, matched to their stored history (wall_forces.cpp).
  void collectWallContacts(Simulation& s, double max_gap, std::vector<double>& history_out);
  void storeWallHistory(const Simulation& s, const std::vector<double>& history_in);
  // Rebuild the neighbour list (and wall candidate lists), re-sorting if due (integrator.cpp).
  void rebuild(Simulation& s);
  // The contact search is due again (a particle or a wall moved too far since the last refresh):
  // rebuild the particle list when it is stale or a re-sort is due, else only the walls'
  // candidate lists (a moving cone or hopper does not make the particle list stale).
  void refresh(Simulation& s, bool list_stale);
  // Whether the particle list may miss a pair, from the displacements since its build: the
  // largest and the box that holds them all (integrator.cpp).
  bool listStale(const Simulation& s, double largest_displacement, const Vec3& box_lo, const Vec3& box_hi) const;
  // One thread's share of a step's drift (integrator.cpp): the largest squared displacements since
  // the list build and since the walls' refresh, the box of the displacements, and whether one
  // was not finite. Combined over the threads after the loop (max, min, or: exact in any order).
  struct DriftExtent {
    double m2 = 0.0, r2 = 0.0;
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());
    bool bad = false;
  };
  std::vector<DriftExtent> drift_extents;
  void refreshWalls(Simulation& s);
  // Candidate lists of all walls for particles at x (current radii), marked built now.
  void buildWallCandidates(Simulation& s, const std::vector<Vec3>& x);
  void sortSpatially(Simulation& s);
  void prepareThreads(std::size_t n_particles, int n_threads);
};

}  // namespace paddy
