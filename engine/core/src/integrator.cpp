// Time loop: velocity Verlet (or semi-implicit Euler) for translation and rotation (spheres), with
// the neighbour list rebuilt when two particles may have closed by more than the skin since its
// build, and stability guards.
//
// Velocity Verlet (TimeIntegration::VelocityVerlet, the default; second order):
//   v(t+dt/2) = v(t) + dt/2 · F(t)/m,   x(t+dt) = x(t) + dt · v(t+dt/2),
//   F(t+dt) from x(t+dt) and the velocities predicted to t+dt (predictVelocities),
//   v(t+dt) = v(t+dt/2) + dt/2 · F(t+dt)/m   (same for ω, T/I).
// Semi-implicit (symplectic) Euler (TimeIntegration::SymplecticEuler; first order, e.g. Hairer,
// Lubich & Wanner, Geometric Numerical Integration, 2006, §I.1.2):
//   v(t+dt) = v(t) + dt · F(t)/m,   x(t+dt) = x(t) + dt · v(t+dt),
//   F(t+dt) from x(t+dt), v(t+dt)   (same for ω, T/I; the resisting torque with h = dt).
// Under gravity alone it puts a body at x0 + v0 t − g dt² n(n+1)/2 after n steps (Verlet: the
// exact x0 + v0 t − g t²/2); it is stable for an undamped spring up to ω dt = 2, as Verlet, where
// the forward Euler scheme (positions from the old velocities) gains energy at every step.
//
// Resisting torques (ContactBatch::resist_i, summed per body into R = resisting_torque) are the
// set-valued law T_r = −R ω/|ω| (|T_r| ≤ R at rest). Each rotational half-kick applies it by
// backward Euler, which for this law is exact and has a closed form:
//   ω* = ω + h T/I,   ω ← ω* · max(0, 1 − h R / (I |ω*|))      (h = dt/2)
// The rotation slows by h R/I per half-step and stops at zero instead of reversing, so a body
// whose other torques stay below R stays at rest exactly. The explicit form ω += h(T − R ω̂)/I
// reverses ω every step near rest (chatter of amplitude ~ R dt / I) and lets a loaded body creep
// at a mean rate that grows with dt (docs/physics.md §2.5).
#include "simulation_impl.hpp"

#include <paddy/errors.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace paddy {

namespace {
// A contact overlap beyond this fraction of the smaller radius means the step is too large.
constexpr double kMaxOverlapRatio = 0.5;

// Rotational half-kick with the resisting torque applied implicitly (see the header comment);
// h_over_i = h / I.
inline Vec3 kickRotation(const Vec3& omega, const Vec3& torque, double resist, double h_over_i) {
  Vec3 w = omega + h_over_i * torque;
  if (resist > 0.0) {
    const double speed = w.norm(), loss = h_over_i * resist;
    w = speed > loss ? Vec3(w * (1.0 - loss / speed)) : Vec3::Zero();
  }
  return w;
}

double maxRadius(const ParticleArrays& p) {
  double r = 0.0;
  for (double x : p.radius) r = std::max(r, x);
  return r;
}
}  // namespace

void Simulation::Impl::rebuild(Simulation& s) {
  ParticleArrays& p = s.p_;
  const double rmax = maxRadius(p);
  skin = skin_fraction * rmax;
  if (sort_interval > 0 && s.list_builds_ % static_cast<std::size_t>(sort_interval) == 0) sortSpatially(s);
  rankIds(p);  // the wall contacts' order (wall_forces.cpp); ranks again only if the ids moved
  list.build(p, prev_index, skin, history_stride, laws, law_index, s.materials_, s.threads_);
  owner_bounds.clear();  // the owners' costs were of the old list
  std::iota(prev_index.begin(), prev_index.end(), std::size_t{0});
  wall_max_gap = 0.0;
  for (const auto& law : laws) wall_max_gap = std::max(wall_max_gap, law.maxSeparation(rmax));
  buildWallCandidates(s, p.position);
  walls_refreshed = false;
  x_at_wall_refresh.clear();
  list_valid = true;
  list_build_time = s.time_;
  ++s.list_builds_;
}

void Simulation::Impl::buildWallCandidates(Simulation& s, const std::vector<Vec3>& x) {
  if (s.walls_.empty()) return;
  const ParticleArrays& p = s.p_;
  ParticleView view{x.size(), x.data(), p.radius.data(), s.threads_};
  // A wall contact acts within radius + wall_max_gap. Until the next refresh a particle and a wall
  // together move less than one skin (the refresh rule in step()), so a triangle or plane within
  // radius + wall_max_gap + skin now holds every contact until then. 1 % of the largest radius on
  // top is room for the rounding of the distances (orders of magnitude more than it).
  const double range = wall_max_gap + skin + 0.01 * maxRadius(p);
  for (auto& w : s.walls_) {
    w->buildCandidates(view, range);
    w->markListBuilt();
  }
}

void Simulation::Impl::refreshWalls(Simulation& s) {
  buildWallCandidates(s, s.p_.position);
  walls_refreshed = true;
  x_at_wall_refresh = s.p_.position;
  wall_refresh_time = s.time_;
  ++s.list_builds_;  // counts refreshes of the contact search: the re-sort schedule counts them
}

void Simulation::Impl::refresh(Simulation& s, bool list_stale) {
  // A full rebuild here would give the same forces (the list still holds every pair within
  // reach, in the same order); it is skipped unless the list is stale or the spatial re-sort,
  // every sort_interval-th refresh, is due, so the re-sort comes at the same steps as before.
  // Without walls the step calls this only for a stale list.
  const bool sort_due = sort_interval > 0 && s.list_builds_ % static_cast<std::size_t>(sort_interval) == 0;
  if (sort_due || list_stale) rebuild(s);
  else refreshWalls(s);
}

bool Simulation::Impl::listStale(const Simulation& s, double largest_displacement, const Vec3& box_lo,
                                  const Vec3& box_hi) const {
  // A pair left out of the list was farther apart than its range + skin at the build. It can have
  // come into range only if |Δx_i − Δx_j| > skin, Δx the displacements since the build. Three
  // bounds of that difference, each enough, the cheaper first: |Δx_i| + |Δx_j| ≤ 2 max_k |Δx_k|;
  // the diagonal of the box that holds every Δx_k (both lie in it); and, for c the box's centre,
  // |Δx_i − c| + |Δx_j − c| ≤ 2 max_k |Δx_k − c| (one more pass over the particles, only when
  // the other two cannot clear the list). The last two stay small while the particles move
  // together (a falling pour, a drifting packing).
  if (2.0 * largest_displacement <= skin) return false;
  if ((box_hi - box_lo).norm() <= skin) return false;
  const ParticleArrays& p = s.p_;
  const std::size_t n = p.size();
  const Vec3 c = 0.5 * (box_lo + box_hi);
  const Vec3* x_build = list.x_at_build.data();
  double e2 = 0.0;
#pragma omp parallel num_threads(s.threads_) reduction(max : e2)
  {
    const auto range = ownerRange(omp_get_thread_num(), omp_get_num_threads(), n);
    for (std::size_t i = range.first; i < range.second; ++i)
      e2 = std::max(e2, (p.position[i] - x_build[i] - c).squaredNorm());
  }
  return 2.0 * std::sqrt(e2) > skin;
}

void Simulation::Impl::sortSpatially(Simulation& s) {
  ParticleArrays& p = s.p_;
  const std::size_t n = p.size();
  if (n < 2) return;
  CellGrid grid;
  grid.build(p.position, std::max(list.cell_size, 2.0 * maxRadius(p)));
  const std::vector<std::uint32_t>& perm = grid.order;  // new index k ← old index perm[k]
  auto permute = [&](auto& v) {
    using V = std::decay_t<decltype(v)>;
    V out(v.size());
    for (std::size_t k = 0; k < n; ++k) out[k] = v[perm[k]];
    v.swap(out);
  };
  permute(p.id);
  permute(p.material);
  permute(p.radius);
  permute(p.mass);
  permute(p.inertia);
  permute(p.position);
  permute(p.velocity);
  permute(p.omega);
  permute(p.force);
  permute(p.torque);
  permute(p.resisting_torque);
  permute(prev_index);
}

void Simulation::Impl::predictVelocities(const Simulation& s, std::size_t lo, std::size_t hi) {
  const ParticleArrays& p = s.p_;
  const double half = 0.5 * s.dt_;
  for (std::size_t i = lo; i < hi; ++i) {
    body_motion[i] = {p.velocity[i] + (half / p.mass[i]) * p.force[i],
                      kickRotation(p.omega[i], p.torque[i], p.resisting_torque[i], half / p.inertia[i]), p.mass[i]};
  }
}

namespace {
void checkTimeStep(Simulation& s, double dt, bool explicit_dt) {
  if (s.particles().size() == 0) return;
  if (explicit_dt && dt > s.maxStableTimeStep()) {
    std::ostringstream msg;
    msg << "time step " << dt << " s is above the stable limit " << s.maxStableTimeStep()
        << " s for the particles now present (smaller particles were added after the step was set)";
    throw InputError(msg.str());
  }
}
}  // namespace

// Names the contact of the largest overlap for an instability message: the particles' persistent
// ids, where they are and how fast they move (or the wall's name).
std::string Simulation::Impl::describeWorstOverlap(const Simulation& s) const {
  const auto& p = s.particles();
  auto particle = [&](std::uint64_t id) {
    std::ostringstream o;
    o << "particle " << id;
    for (std::size_t k = 0; k < p.size(); ++k) {
      if (p.id[k] != id) continue;
      o << " at (" << p.position[k].x() << ", " << p.position[k].y() << ", " << p.position[k].z() << ") m, speed "
        << p.velocity[k].norm() << " m/s, radius " << p.radius[k] << " m";
      break;
    }
    return o.str();
  };
  const WorstOverlap& w = worst_overlap;
  std::ostringstream msg;
  msg << particle(w.id_i) << " and ";
  if (w.wall) {
    msg << "wall " << w.id_j;
    if (w.id_j < s.walls_.size()) msg << " '" << s.walls_[w.id_j]->name() << "'";
  } else {
    msg << particle(w.id_j);
  }
  return msg.str();
}

void Simulation::step(std::uint64_t n) {
  if (!impl_->dt_explicit) {
    if (p_.size() == 0 && dt_ <= 0.0) throw InputError("no time step: add particles or set the time step explicitly");
    if (p_.size() > 0) dt_ = impl_->dt_fraction * rayleighTime();
  }
  checkTimeStep(*this, dt_, impl_->dt_explicit);
  Impl& m = *impl_;
  if (!m.list_valid) m.rebuild(*this);
  if (!m.forces_valid) {
    for (auto& w : walls_) w->moveTo(time_);
    m.computeForces(*this, Impl::ForcePass::Initial);
    if (m.max_overlap_ratio > kMaxOverlapRatio) {
      std::ostringstream msg;
      msg << "particles overlap by " << 100.0 * m.max_overlap_ratio
          << " % of their radius (" << m.describeWorstOverlap(*this) << ") before the step at t = " << time_
          << " s; they were created overlapping (check the packing or the radii)";
      throw InstabilityError(msg.str());
    }
  }
  const double dt = dt_;
  const double half = 0.5 * dt;
  const bool euler = m.integration == TimeIntegration::SymplecticEuler;
  const double kick = euler ? dt : half;  // the kick before the drift: all of Euler's, half of Verlet's
  const std::size_t np = p_.size();
  // One parallel loop per step moves the particles: the closing half-kick of the previous step
  // (deferred to here: nothing reads the velocities in between), the opening half-kick, the drift,
  // and the largest displacements since the list build and since the last refresh of the contact
  // search (the same unless the walls were refreshed on their own since the build). The same
  // operations in the same order per particle as separate loops, so the same numbers.
  bool closing_kick_due = false;
  for (std::uint64_t s = 0; s < n; ++s) {
    const bool closing = closing_kick_due;
    const bool two_refs = m.walls_refreshed;
    const Vec3* x_build = m.list.x_at_build.size() == np ? m.list.x_at_build.data() : nullptr;
    const Vec3* x_refresh = two_refs && m.x_at_wall_refresh.size() == np ? m.x_at_wall_refresh.data() : nullptr;
    // Each thread moves its own owners (ownerRange) and bounds their displacements.
    m.drift_extents.assign(static_cast<std::size_t>(std::max(threads_, 1)), Impl::DriftExtent{});
#pragma omp parallel num_threads(threads_)
    {
      const int t = omp_get_thread_num();
      const auto range = m.ownerRange(t, omp_get_num_threads(), np);
      Impl::DriftExtent e;
      for (std::size_t i = range.first; i < range.second; ++i) {
        const double k_over_m = kick / p_.mass[i], k_over_i = kick / p_.inertia[i];
        if (closing) {  // Verlet only: kick = dt/2
          p_.velocity[i] += k_over_m * p_.force[i];
          p_.omega[i] = kickRotation(p_.omega[i], p_.torque[i], p_.resisting_torque[i], k_over_i);
        }
        p_.velocity[i] += k_over_m * p_.force[i];
        p_.omega[i] = kickRotation(p_.omega[i], p_.torque[i], p_.resisting_torque[i], k_over_i);
        p_.position[i] += dt * p_.velocity[i];
        if (x_build) {
          const Vec3 dx = p_.position[i] - x_build[i];
          const double d2 = dx.squaredNorm();
          if (!std::isfinite(d2)) e.bad = true;
          e.m2 = std::max(e.m2, d2);
          e.lo = e.lo.cwiseMin(dx);
          e.hi = e.hi.cwiseMax(dx);
          if (x_refresh) {
            const double e2 = (p_.position[i] - x_refresh[i]).squaredNorm();
            if (!std::isfinite(e2)) e.bad = true;
            e.r2 = std::max(e.r2, e2);
          }
        }
      }
      m.drift_extents[static_cast<std::size_t>(t)] = e;
    }
    double m2 = 0.0, r2 = 0.0;
    Vec3 box_lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 box_hi = -box_lo;
    bool bad = x_build == nullptr || (two_refs && x_refresh == nullptr);
    for (const Impl::DriftExtent& e : m.drift_extents) {
      m2 = std::max(m2, e.m2), r2 = std::max(r2, e.r2);
      box_lo = box_lo.cwiseMin(e.lo), box_hi = box_hi.cwiseMax(e.hi);
      bad = bad || e.bad;
    }
    closing_kick_due = false;
    time_ += dt;
    ++steps_;
    for (auto& w : walls_) w->moveTo(time_);

    const double disp = bad ? std::numeric_limits<double>::infinity() : std::sqrt(m2);
    const double disp_refresh = two_refs ? (bad ? disp : std::sqrt(r2)) : disp;
    if (!std::isfinite(disp)) {
      std::ostringstream msg;
      msg << "a particle position became NaN or infinite at t = " << time_ << " s (step " << steps_ << ")";
      for (std::size_t i = 0; i < p_.size(); ++i) {
        if (p_.position[i].allFinite()) continue;
        msg << ": particle " << p_.id[i] << " (radius " << p_.radius[i] << " m, force " << p_.force[i].norm() << " N)";
        break;
      }
      msg << "; the time step " << dt << " s is too large or a contact parameter is unphysical";
      throw InstabilityError(msg.str());
    }
    // The particle list goes stale with the particles' displacements since its build; the walls'
    // candidate lists with a particle's and a wall's together since their last refresh (which
    // may be later than the build: refreshWalls).
    const bool list_stale = np > 0 && m.listStale(*this, disp, box_lo, box_hi);
    double wall_disp = 0.0;
    for (const auto& w : walls_) wall_disp = std::max(wall_disp, w->displacementSinceListBuild());
    const bool walls_stale = !walls_.empty() && disp_refresh + wall_disp > m.skin;
    if (list_stale || walls_stale) m.refresh(*this, list_stale);

    m.computeForces(*this, Impl::ForcePass::Step);  // predicts the velocities it uses first
    if (m.max_overlap_ratio > kMaxOverlapRatio) {
      std::ostringstream msg;
      msg << "contact overlap reached " << 100.0 * m.max_overlap_ratio << " % of the particle radius ("
          << m.describeWorstOverlap(*this) << ") at t = " << time_ << " s (step " << steps_ << "): the time step " << dt << " s ("
          << dt / rayleighTime() << " x Rayleigh time) is too large for these velocities; reduce it";
      throw InstabilityError(msg.str());
    }
    closing_kick_due = !euler;
  }
  if (closing_kick_due) {
#pragma omp parallel num_threads(threads_)
    {
      const auto range = m.ownerRange(omp_get_thread_num(), omp_get_num_threads(), np);
      for (std::size_t i = range.first; i < range.second; ++i) {
        p_.velocity[i] += (half / p_.mass[i]) * p_.force[i];
        p_.omega[i] = kickRotation(p_.omega[i], p_.torque[i], p_.resisting_torque[i], half / p_.inertia[i]);
      }
    }
  }
}

std::uint64_t Simulation::run(double duration, const std::function<bool(Simulation&)>& callback, double interval) {
  if (!(duration >= 0.0) || !std::isfinite(duration)) throw InputError("run: duration must be >= 0 seconds");
  step(0);  // resolves the time step and initial forces
  const auto total = static_cast<std::uint64_t>(std::ceil(duration / dt_ - 1e-9));
  std::uint64_t every = total;
  if (callback && interval > 0.0) every = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(interval / dt_)));
  if (every == 0) every = 1;
  std::uint64_t done = 0;
  while (done < total) {
    const std::uint64_t chunk = std::min(every, total - done);
    step(chunk);
    done += chunk;
    if (callback && !callback(*this)) break;
  }
  return done;
}

}  // namespace paddy
