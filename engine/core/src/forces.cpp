// Force evaluation: particle–particle contacts from the half neighbour list, particle–wall
// contacts from the walls, both in batches per contact law; per-thread force buffers reduced in
// a fixed order (deterministic for a given thread count).
#include "contact_kernel.hpp"

#include <paddy/errors.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace paddy {

namespace {
// List slots per chunk of the pair loop's distance tests (an owner with more slots takes several).
constexpr std::size_t kSlotChunk = 64;
}  // namespace

void Simulation::Impl::prepareThreads(std::size_t n, int n_threads) {
  // The buffers keep their size between steps: re-initialise only when something changed (the
  // history scratch of a dry pass is overwritten contact by contact before every use).
  const std::size_t hist_size = ContactBatch::kCapacity * std::max<std::size_t>(history_stride, 1);
  bool same = threads.size() == static_cast<std::size_t>(n_threads);
  for (std::size_t t = 0; same && t < threads.size(); ++t) {
    const ThreadBuffers& tb = threads[t];
    same = tb.force.size() == n && tb.work.size() == laws.size() &&
           (tb.work.empty() || tb.work[0].history.size() == hist_size);
  }
  if (same) return;
  threads.resize(static_cast<std::size_t>(n_threads));
  for (auto& tb : threads) {
    tb.force.assign(n, Vec3::Zero());
    tb.torque.assign(n, Vec3::Zero());
    tb.resist.assign(n, 0.0);
    tb.touched_lo = tb.touched_hi = 0;
    tb.work.resize(laws.size());
    for (std::size_t l = 0; l < laws.size(); ++l) {
      tb.work[l].law = static_cast<int>(l);
      tb.work[l].history.assign(hist_size, 0.0);
    }
  }
}

void Simulation::Impl::computeForces(Simulation& s, ForcePass pass) {
  const bool dry = pass == ForcePass::Dry;
  ParticleArrays& p = s.p_;
  const std::size_t n = p.size();
  const int nthreads = s.threads_;
  const std::size_t stride = history_stride;
  const int nmat = static_cast<int>(s.materials_.size());
  prepareThreads(n, nthreads);

  // Wall contacts are found serially (each wall may parallelise its own search).
  std::vector<double>& wall_hist = wall_scratch_history;
  wall_hist.clear();
  if (!s.walls_.empty()) {
    const double max_gap = wall_max_gap;  // set at the list build, when radii last changed
    if (!dry)
      for (auto& w : s.walls_) w->resetLoads();
    collectWallContacts(s, max_gap, wall_hist);
  }
  const std::size_t n_wall = wall_found.size();
  std::vector<Vec3>& wall_force = wall_scratch_force;
  wall_force.assign(n_wall, Vec3::Zero());
  // The bodies as the pair loop reads them (packBodies), with the velocities the contact laws see:
  // at a step predicted to the end of the step (see predictVelocities), otherwise the current ones.
  const bool predicted = pass == ForcePass::Step && predictsVelocities();
  body_shape.resize(n);
  body_motion.resize(n);
  const BodyShape* S = body_shape.data();
  const BodyMotion* M = body_motion.data();
  // Count the owners' costs for the next pass's split (more than one thread, forces kept).
  const bool balance = !dry && nthreads > 1;
  if (balance) {
    owner_cost_sum.resize(n);
    owner_thread_cost.assign(static_cast<std::size_t>(nthreads), 0);
    owner_bounds_used.assign(static_cast<std::size_t>(nthreads) + 1, n);
  }

#pragma omp parallel num_threads(nthreads)
  {
    const int t = omp_get_thread_num();
    const int nt = omp_get_num_threads();
    // This thread's owners (see ownerRange), read before thread 0 rebalances them below: the
    // pair loop and the reduction both use them.
    const std::pair<std::size_t, std::size_t> range = ownerRange(t, nt, n);
    const std::size_t lo = range.first, hi = range.second;
    // Every thread's bodies packed before any reads a partner's, and before one thread at a step
    // writes the force arrays the prediction reads.
    packBodies(s, lo, hi, predicted);
#pragma omp barrier
    ThreadBuffers& tb = threads[static_cast<std::size_t>(t)];
    // One thread at a step sums straight into the particle arrays. Otherwise each thread sums
    // into its own buffers, clearing first only what its last pass wrote: its owners and their
    // partners, a band of the spatially sorted particles (not all n every step), and the
    // reduction below adds a buffer only over that band.
    const bool direct = !dry && nt == 1;
    Vec3* F = direct ? p.force.data() : tb.force.data();
    Vec3* Tq = direct ? p.torque.data() : tb.torque.data();
    double* Rs = direct ? p.resisting_torque.data() : tb.resist.data();
    const std::size_t clear_lo = direct ? 0 : tb.touched_lo, clear_hi = direct ? n : std::min(tb.touched_hi, n);
    if (clear_lo < clear_hi) {
      std::fill(F + clear_lo, F + clear_hi, Vec3::Zero());
      std::fill(Tq + clear_lo, Tq + clear_hi, Vec3::Zero());
      std::fill(Rs + clear_lo, Rs + clear_hi, 0.0);
    }
    std::size_t touched_lo = n, touched_hi = 0;
    tb.records.clear();
    tb.max_overlap_ratio = 0.0;
    tb.worst = {};
    tb.active_contacts = 0;
    for (auto& w : tb.work) {
      w.batch.n = 0;
      w.batch.dt = pass == ForcePass::Step ? s.dt_ : 0.0;
      w.batch.time = s.time_;
    }

    // Where contact m of a batch keeps its history while the laws run: the stored block itself
    // (the laws update it in place), or in a dry pass a copy in the batch's scratch, so that the
    // stored history stays as it was.
    auto historySlot = [&](BatchWork& w, std::size_t m, double* stored) -> double* {
      if (!dry) return stored;
      double* copy = w.history.data() + m * stride;
      std::copy_n(stored, stride, copy);
      return copy;
    };

    auto flush = [&](BatchWork& w, bool is_wall) {
      ContactBatch& b = w.batch;
      if (b.n == 0) return;
      laws[static_cast<std::size_t>(w.law)].compute(b);
      for (std::size_t m = 0; m < b.n; ++m) {
        const std::uint32_t i = w.i[m];
        const kernel::Applied a = kernel::applied(b, m, b.radius_i[m], is_wall ? 0.0 : b.radius_j[m]);
        F[i] += a.force_i;
        Tq[i] += a.torque_i;
        Rs[i] += b.resist_i[m];
        touched_lo = std::min<std::size_t>(touched_lo, i);
        touched_hi = std::max<std::size_t>(touched_hi, i + 1);
        if (is_wall) {
          wall_force[w.j[m]] = a.force_i;
        } else {
          const std::uint32_t j = w.j[m];
          F[j] -= a.force_i;
          Tq[j] += a.torque_j;
          Rs[j] += b.resist_j[m];
          touched_lo = std::min<std::size_t>(touched_lo, j);
          touched_hi = std::max<std::size_t>(touched_hi, j + 1);
        }
        // Largest overlap / smaller radius: the division only for a candidate (the pre-test is
        // looser than the exact comparison by far more than its rounding).
        const double r_min = std::min(b.radius_i[m], b.radius_j[m]);
        if (b.overlap[m] > tb.max_overlap_ratio * r_min * (1.0 - 1e-12)) {
          const double ratio = b.overlap[m] / r_min;
          if (ratio > tb.max_overlap_ratio) {
            tb.max_overlap_ratio = ratio;
            tb.worst = {p.id[i], is_wall ? static_cast<std::uint64_t>(wall_of_found[w.j[m]]) : p.id[w.j[m]], is_wall};
          }
        }
        if (b.active[m]) ++tb.active_contacts;
        if (dry) {
          if (b.active[m] || b.fn[m] != 0.0 || b.ft[m].squaredNorm() > 0.0) {
            ContactRecord r;
            r.id_i = p.id[i];
            r.wall = is_wall;
            r.id_j = is_wall ? wall_of_found[w.j[m]] : p.id[w.j[m]];
            r.overlap = b.overlap[m];
            r.normal = b.normal[m];
            r.fn = b.fn[m];
            r.ft = b.ft[m];
            if (stride > 0) r.history.assign(b.history_at[m], b.history_at[m] + stride);
            tb.records.push_back(std::move(r));
          }
        } else if (stride > 0 && w.slot_live[m]) {
          *w.slot_live[m] = 1;
        }
      }
      b.n = 0;
    };

    // ---- particle–particle ----------------------------------------------------------------
    // Owners split so that each thread gets about the same work (ownerRange): the split decides
    // only which thread's buffer a contact's force goes to; the same state gives the same split,
    // so the same results.
    std::uint64_t running = 0;
    if (balance) owner_bounds_used[static_cast<std::size_t>(t)] = lo;
    for (std::size_t i = lo; i < hi; ++i) {
      const Vec3 xi = S[i].x;
      const double ri = S[i].r;
      std::uint64_t in_range = 0;
      // Whether listed pair k is within its interaction range: one test for both passes below.
      const auto inRange = [&](std::size_t k) { return (xi - S[list.partner[k]].x).squaredNorm() < list.range2[k]; };
      // The owner's slots in chunks of kSlotChunk: first the distance test of every slot, noting
      // the pairs in range without a branch (whether a listed pair touches is close to random, and
      // a branch on it is mispredicted often), then the contacts of the pairs noted, in slot order.
      for (std::size_t k0 = list.start[i], k_end = list.start[i + 1]; k0 < k_end; k0 += kSlotChunk) {
        const std::size_t k1 = std::min(k_end, k0 + kSlotChunk);
        std::uint32_t hit[kSlotChunk];
        std::size_t n_hit = 0;
        bool separated = false;  // a pair with history out of range
        for (std::size_t k = k0; k < k1; ++k) {
          const bool in = inRange(k);
          hit[n_hit] = static_cast<std::uint32_t>(k - k0);
          n_hit += in ? 1 : 0;
          separated |= !in & (list.live[k] != 0);
        }
        if (separated && !dry) {
          // A pair that has separated forgets its history (the same test again: the same answer).
          for (std::size_t k = k0; k < k1; ++k) {
            if (list.live[k] && !inRange(k)) {
              std::fill_n(&list.history[k * stride], stride, 0.0);
              list.live[k] = 0;
            }
          }
        }
        in_range += n_hit;
        for (std::size_t h = 0; h < n_hit; ++h) {
          const std::size_t k = k0 + hit[h];
          const std::uint32_t j = list.partner[k];
          const Vec3 d = xi - S[j].x;
          BatchWork& w = tb.work[static_cast<std::size_t>(list.law[k])];
          ContactBatch& b = w.batch;
          const std::size_t m = b.n;
          const double dist = std::sqrt(d.squaredNorm());
          const Vec3 nrm = dist > 0.0 ? Vec3(d / dist) : Vec3(0.0, 0.0, 1.0);
          const double rj = S[j].r;
          const double overlap = ri + rj - dist;
          const Vec3 cj = (rj - 0.5 * overlap) * nrm;
          const Vec3 vj_contact = M[j].v + M[j].w.cross(cj);
          kernel::fill(b, m, nrm, overlap, ri, rj, M[i].m, M[j].m, M[i].v, M[i].w, vj_contact, M[j].w);
          if (stride > 0) b.history_at[m] = historySlot(w, m, &list.history[k * stride]);
          w.i[m] = static_cast<std::uint32_t>(i);
          w.j[m] = j;
          w.slot_live[m] = &list.live[k];
          b.n = m + 1;
          if (b.n == ContactBatch::kCapacity) flush(w, false);
        }
      }
      if (balance) {
        running += kParticleCost + (list.start[i + 1] - list.start[i]) + kContactCost * in_range;
        owner_cost_sum[i] = running;
      }
    }
    if (balance) owner_thread_cost[static_cast<std::size_t>(t)] = running;
    for (auto& w : tb.work) flush(w, false);

    // ---- particle–wall ----------------------------------------------------------------------
    const std::size_t clo = n_wall * t / nt, chi = n_wall * (t + 1) / nt;
    for (std::size_t c = clo; c < chi; ++c) {
      const WallContact& wc = wall_found[c];
      const Wall& wall = *s.walls_[wall_of_found[c]];
      const std::uint32_t i = wc.particle;
      const int law = law_index[static_cast<std::size_t>(p.material[i] * nmat + wall.material())];
      BatchWork& w = tb.work[static_cast<std::size_t>(law)];
      ContactBatch& b = w.batch;
      const std::size_t m = b.n;
      const double inf = std::numeric_limits<double>::infinity();
      kernel::fill(b, m, wc.normal, wc.overlap, S[i].r, inf, M[i].m, inf, M[i].v, M[i].w,
                   wall.velocityAt(wc.point), wall.angularVelocity());
      if (stride > 0) b.history_at[m] = historySlot(w, m, &wall_hist[c * stride]);
      w.i[m] = i;
      w.j[m] = static_cast<std::uint32_t>(c);
      w.slot_live[m] = nullptr;
      w.point[m] = wc.point;
      b.n = m + 1;
      if (b.n == ContactBatch::kCapacity) flush(w, true);
    }
    for (auto& w : tb.work) flush(w, true);
    if (!direct) tb.touched_lo = touched_lo, tb.touched_hi = touched_hi;

    // ---- reduction in a fixed order -----------------------------------------------------------
    // Thread 0's sum first, then thread 1's, ...: a buffer outside its band holds zeros, which
    // the sum skips (x + 0 = x), so the order and the result are those of adding every buffer.
    if (!dry) {
#pragma omp barrier
      if (balance && t == 0) rebalanceOwners(n, nt);  // nothing reads the bounds until the next pass
      if (direct) {
        for (std::size_t i = 0; i < n; ++i) p.force[i] += p.mass[i] * s.gravity_;
      } else {
        // Each thread sums its own owners (the particles it moves at the next step); the
        // barrier at the end of the parallel region ends the reduction.
        for (std::size_t i = lo; i < hi; ++i) {
          Vec3 f = Vec3::Zero(), tq = Vec3::Zero();
          double rs = 0.0;
          bool first = true;
          for (int u = 0; u < nt; ++u) {
            const ThreadBuffers& b = threads[static_cast<std::size_t>(u)];
            if (i < b.touched_lo || i >= b.touched_hi) continue;
            if (first) {
              f = b.force[i], tq = b.torque[i], rs = b.resist[i];
              first = false;
            } else {
              f += b.force[i];
              tq += b.torque[i];
              rs += b.resist[i];
            }
          }
          p.force[i] = f + p.mass[i] * s.gravity_;
          p.torque[i] = tq;
          p.resisting_torque[i] = rs;
        }
      }
    }
  }

  double ratio = 0.0;
  WorstOverlap worst;
  std::uint64_t active = 0;
  for (const auto& tb : threads) {  // in thread order: the same contact for the same run
    if (tb.max_overlap_ratio > ratio) {
      ratio = tb.max_overlap_ratio;
      worst = tb.worst;
    }
    active += tb.active_contacts;
  }
  if (dry) {
    last_records.clear();
    for (const auto& tb : threads) last_records.insert(last_records.end(), tb.records.begin(), tb.records.end());
    return;
  }
  max_overlap_ratio = ratio;
  worst_overlap = worst;
  active_contacts = active;
  for (std::size_t c = 0; c < n_wall; ++c) s.walls_[wall_of_found[c]]->addLoad(-wall_force[c], wall_found[c].point);
  if (!s.walls_.empty()) storeWallHistory(s, wall_hist);
  forces_valid = true;
}

void Simulation::Impl::packBodies(const Simulation& s, std::size_t lo, std::size_t hi, bool predicted) {
  const ParticleArrays& p = s.p_;
  for (std::size_t i = lo; i < hi; ++i) body_shape[i] = {p.position[i], p.radius[i]};
  if (predicted) {
    predictVelocities(s, lo, hi);
    return;
  }
  for (std::size_t i = lo; i < hi; ++i) body_motion[i] = {p.velocity[i], p.omega[i], p.mass[i]};
}

// Thread t's owners: by the costs of the pass before (owner_bounds, rebalanceOwners), else by
// list slots (the half list puts more slots on some owners than on others; where the packing is
// loose most slots are out of range and cheap, where it is dense most are contacts: an even split
// by slots can leave one thread with twice the contacts of the other), else by particles.
std::pair<std::size_t, std::size_t> Simulation::Impl::ownerRange(int t, int nt, std::size_t n) const {
  if (nt <= 1) return {0, n};
  const auto ts = static_cast<std::size_t>(t), nts = static_cast<std::size_t>(nt);
  if (owner_bounds.size() == nts + 1 && owner_bounds.back() == n) return {owner_bounds[ts], owner_bounds[ts + 1]};
  if (list.start.size() != n + 1) return {n * ts / nts, n * (ts + 1) / nts};
  const auto split = [&](std::size_t u) -> std::size_t {
    if (u == 0) return 0;
    if (u >= nts) return n;
    const std::size_t target = list.start[n] / nts * u;
    return static_cast<std::size_t>(std::lower_bound(list.start.begin(), list.start.begin() + static_cast<std::ptrdiff_t>(n), target) -
                                    list.start.begin());
  };
  return {split(ts), split(ts + 1)};
}

// The owners' split for the next pass: boundary u where the running cost of this pass reaches
// u / nt of the total (owner_cost_sum holds each thread's running cost over its own range, from
// owner_bounds_used). Deterministic: the costs are counts of the state's pairs.
void Simulation::Impl::rebalanceOwners(std::size_t n, int nt) {
  const auto nts = static_cast<std::size_t>(nt);
  if (owner_thread_cost.size() < nts || owner_bounds_used.size() < nts + 1) return;
  owner_bounds_used[nts] = n;
  std::uint64_t total = 0;
  for (std::size_t u = 0; u < nts; ++u) total += owner_thread_cost[u];
  std::vector<std::size_t>& b = owner_bounds;
  b.assign(nts + 1, n);
  b[0] = 0;
  std::size_t s = 0;
  std::uint64_t before = 0;  // cost of the ranges of threads < s
  for (std::size_t u = 1; u < nts; ++u) {
    const std::uint64_t target = total / nts * u;
    while (s + 1 < nts && before + owner_thread_cost[s] <= target) before += owner_thread_cost[s++];
    const std::size_t r_lo = owner_bounds_used[s], r_hi = owner_bounds_used[s + 1];
    // first owner of s's range whose running cost passes the target: it starts thread u's range
    const auto first = owner_cost_sum.begin() + static_cast<std::ptrdiff_t>(r_lo);
    const auto last = owner_cost_sum.begin() + static_cast<std::ptrdiff_t>(r_hi);
    const std::size_t at = static_cast<std::size_t>(std::upper_bound(first, last, target - before) - owner_cost_sum.begin());
    b[u] = std::max(b[u - 1], std::min(at, n));
  }
}

std::vector<std::uint64_t> Simulation::pairWorkPerThread() const {
  if (threads_ <= 1) return {};
  return impl_->owner_thread_cost;
}

std::vector<ContactRecord> Simulation::contacts() const {
  auto* self = const_cast<Simulation*>(this);
  if (!impl_->list_valid) self->impl_->rebuild(*self);
  self->impl_->computeForces(*self, Impl::ForcePass::Dry);
  return impl_->last_records;
}

}  // namespace paddy
