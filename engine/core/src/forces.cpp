// Force evaluation: particle–particle contacts from the half neighbour list, particle–wall
// contacts from the walls, both in batches per contact law; per-thread force buffers reduced in
// a fixed order (deterministic for a given thread count).
#include "contact_kernel.hpp"

#include <paddy/errors.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace paddy {

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
    tb.force.resize(n);
    tb.torque.resize(n);
    tb.resist.resize(n);
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
  // Velocities the contact laws see: at a step, predicted to the end of the step (see
  // predictVelocities); otherwise the current ones.
  const bool predicted = pass == ForcePass::Step && predict_velocities;
  if (predicted) {
    v_eval.resize(n);
    w_eval.resize(n);
  } else {
    v_eval.clear();
    w_eval.clear();
  }
  const Vec3* vel = predicted ? v_eval.data() : p.velocity.data();
  const Vec3* omg = predicted ? w_eval.data() : p.omega.data();

#pragma omp parallel num_threads(nthreads)
  {
    if (predicted) {
      // Before any thread clears the force arrays the prediction reads (implicit barrier).
      predictVelocities(s);  // an `omp for` over the particles, with its implicit barrier
    }
    const int t = omp_get_thread_num();
    const int nt = omp_get_num_threads();
    ThreadBuffers& tb = threads[static_cast<std::size_t>(t)];
    Vec3* F = (t == 0 && !dry) ? p.force.data() : tb.force.data();
    Vec3* Tq = (t == 0 && !dry) ? p.torque.data() : tb.torque.data();
    double* Rs = (t == 0 && !dry) ? p.resisting_torque.data() : tb.resist.data();
    std::fill(F, F + n, Vec3::Zero());
    std::fill(Tq, Tq + n, Vec3::Zero());
    std::fill(Rs, Rs + n, 0.0);
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
        if (is_wall) {
          wall_force[w.j[m]] = a.force_i;
        } else {
          F[w.j[m]] -= a.force_i;
          Tq[w.j[m]] += a.torque_j;
          Rs[w.j[m]] += b.resist_j[m];
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
    // Owners split so that each thread gets about the same number of list slots (the half list
    // puts more slots on some owners than on others: an even split by particle count leaves one
    // thread waiting for the other).
    const auto owner_split = [&](int u) -> std::size_t {
      if (u <= 0) return 0;
      if (u >= nt) return n;
      const std::size_t target = list.start[n] / static_cast<std::size_t>(nt) * static_cast<std::size_t>(u);
      return static_cast<std::size_t>(std::lower_bound(list.start.begin(), list.start.begin() + static_cast<std::ptrdiff_t>(n), target) -
                                      list.start.begin());
    };
    const std::size_t lo = owner_split(t), hi = owner_split(t + 1);
    for (std::size_t i = lo; i < hi; ++i) {
      const Vec3 xi = p.position[i];
      const double ri = p.radius[i];
      for (std::size_t k = list.start[i]; k < list.start[i + 1]; ++k) {
        const std::uint32_t j = list.partner[k];
        const Vec3 d = xi - p.position[j];
        const double d2 = d.squaredNorm();
        if (d2 >= list.range2[k]) {
          if (!dry && list.live[k]) {
            std::fill_n(&list.history[k * stride], stride, 0.0);
            list.live[k] = 0;
          }
          continue;
        }
        BatchWork& w = tb.work[static_cast<std::size_t>(list.law[k])];
        ContactBatch& b = w.batch;
        const std::size_t m = b.n;
        const double dist = std::sqrt(d2);
        const Vec3 nrm = dist > 0.0 ? Vec3(d / dist) : Vec3(0.0, 0.0, 1.0);
        const double rj = p.radius[j];
        const double overlap = ri + rj - dist;
        const Vec3 cj = (rj - 0.5 * overlap) * nrm;
        const Vec3 vj_contact = vel[j] + omg[j].cross(cj);
        kernel::fill(b, m, nrm, overlap, ri, rj, p.mass[i], p.mass[j], vel[i], omg[i], vj_contact, omg[j]);
        if (stride > 0) b.history_at[m] = historySlot(w, m, &list.history[k * stride]);
        w.i[m] = static_cast<std::uint32_t>(i);
        w.j[m] = j;
        w.slot_live[m] = &list.live[k];
        b.n = m + 1;
        if (b.n == ContactBatch::kCapacity) flush(w, false);
      }
    }
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
      kernel::fill(b, m, wc.normal, wc.overlap, p.radius[i], inf, p.mass[i], inf, vel[i], omg[i],
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

    // ---- reduction in a fixed order -----------------------------------------------------------
    if (!dry) {
#pragma omp barrier
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        Vec3 f = p.force[i], tq = p.torque[i];
        double rs = p.resisting_torque[i];
        for (int u = 1; u < nt; ++u) {
          f += threads[static_cast<std::size_t>(u)].force[i];
          tq += threads[static_cast<std::size_t>(u)].torque[i];
          rs += threads[static_cast<std::size_t>(u)].resist[i];
        }
        p.force[i] = f + p.mass[i] * s.gravity_;
        p.torque[i] = tq;
        p.resisting_torque[i] = rs;
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

std::vector<ContactRecord> Simulation::contacts() const {
  auto* self = const_cast<Simulation*>(this);
  if (!impl_->list_valid) self->impl_->rebuild(*self);
  self->impl_->computeForces(*self, Impl::ForcePass::Dry);
  return impl_->last_records;
}

}  // namespace paddy
