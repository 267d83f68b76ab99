// Test helpers for the contact sub-models: reference materials, a one-batch "engine" that runs a
// chain of sub-models in the engine's order, and small integrators for the closed-form checks.
#pragma once

#include <paddy/contact_batch.hpp>
#include <paddy/contact_model.hpp>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

namespace ctest {

using paddy::ContactBatch;
using paddy::Material;
using paddy::MaterialPair;
using paddy::SubModel;
using paddy::Vec3;

inline const double kInf = std::numeric_limits<double>::infinity();
inline const double kPi = std::numbers::pi;
inline const double kG = 9.81;

// Reference study Table 2.
inline Material mud() { return {"mud", 1680.0, 1.0e6, 0.5}; }
inline Material steel() { return {"steel", 7800.0, 7000.0e6, 0.3}; }
inline double sphereMass(const Material& m, double r) { return m.density * 4.0 / 3.0 * kPi * r * r * r; }

// Runs sub-models in order on one batch with its own history, as the engine does.
struct Chain {
  std::vector<std::unique_ptr<SubModel>> models;
  std::vector<std::size_t> offsets;
  std::size_t history_size = 0;
  std::unique_ptr<ContactBatch> batch = std::make_unique<ContactBatch>();
  std::vector<double> history;

  Chain& add(std::unique_ptr<SubModel> m) {
    offsets.push_back(history_size);
    history_size += m->historySize();
    models.push_back(std::move(m));
    return *this;
  }
  ContactBatch& setup(std::size_t n, double dt = 0.0) {
    batch->n = n;
    batch->dt = dt;
    history.assign(std::max<std::size_t>(1, n * history_size), 0.0);
    batch->setContiguousHistory(history.data(), history_size, n);
    for (std::size_t k = 0; k < n; ++k) {
      batch->vn[k] = 0.0;
      batch->vt[k].setZero();
      batch->omega_i[k].setZero();
      batch->omega_j[k].setZero();
      batch->normal[k] = Vec3::UnitZ();
    }
    return *batch;
  }
  ContactBatch& run() {
    batch->resetOutputs();
    for (std::size_t s = 0; s < models.size(); ++s) models[s]->compute(*batch, offsets[s]);
    return *batch;
  }
};

// Geometry of contact k between spheres (or a sphere and a wall: rj = inf, mj = inf).
inline void setPair(ContactBatch& b, std::size_t k, double overlap, double ri, double rj, double mi, double mj) {
  b.overlap[k] = overlap;
  b.radius_i[k] = ri;
  b.radius_j[k] = rj;
  b.r_eff[k] = std::isinf(rj) ? ri : ri * rj / (ri + rj);
  b.m_eff[k] = std::isinf(mj) ? mi : mi * mj / (mi + mj);
}

// Hertz contact time of an undamped collision at approach speed v (Johnson 1985):
// t_c = 2.868 (m*² / (R* E*² v))^{1/5}.
inline double hertzContactTime(double m_eff, double r_eff, double e_star, double v) {
  return 2.868 * std::pow(m_eff * m_eff / (r_eff * e_star * e_star * v), 0.2);
}

// Head-on collision of two equal spheres (radius r, mass m) along x, integrated with velocity
// Verlet (forces evaluated with the half-step velocity). i is on the right, j on the left; the
// normal is +x. Starts at overlap `start_overlap` (< 0, a gap) with relative approach speed v0;
// stops when the overlap is below `end_overlap` and the spheres separate.
struct CollisionResult {
  double v_rebound = 0.0;  // final relative separation speed
  double ke_in = 0.0, ke_out = 0.0;
  long steps = 0;
};
inline CollisionResult collide(Chain& chain, double r, double m, double v0, double dt, double start_overlap,
                               double end_overlap) {
  ContactBatch& b = chain.setup(1, dt);
  double xi = r - 0.5 * start_overlap, xj = -xi;  // centres; overlap = 2r − (xi − xj)
  double vi = -0.5 * v0, vj = 0.5 * v0;
  auto force = [&](double hvi, double hvj) {
    setPair(b, 0, 2.0 * r - (xi - xj), r, r, m, m);
    b.normal[0] = Vec3::UnitX();
    b.vn[0] = hvi - hvj;
    chain.run();
    return b.fn[0];  // on i along +x; j gets −fn
  };
  CollisionResult res;
  res.ke_in = 0.5 * m * (vi * vi + vj * vj);
  double f = force(vi, vj);
  bool touched = false;
  for (long s = 0; s < 100000000; ++s) {
    const double hvi = vi + 0.5 * dt * f / m, hvj = vj - 0.5 * dt * f / m;
    xi += hvi * dt;
    xj += hvj * dt;
    f = force(hvi, hvj);
    vi = hvi + 0.5 * dt * f / m;
    vj = hvj - 0.5 * dt * f / m;
    res.steps = s + 1;
    const double overlap = 2.0 * r - (xi - xj);
    if (overlap > 0.0) touched = true;
    if (touched && overlap < end_overlap && vi - vj > 0.0 && f == 0.0) break;
  }
  res.v_rebound = vi - vj;
  res.ke_out = 0.5 * m * (vi * vi + vj * vj);
  return res;
}

// A sphere on the horizontal wall z = 0 (normal +z) under gravity, integrated with symplectic
// Euler. The contact point is R − δ/2 below the centre, as in the engine.
struct SphereOnWall {
  double r, m, inertia;
  Vec3 x, v, w;
  Chain* chain;
  SphereOnWall(Chain& c, double radius, double mass, double overlap0)
      : r(radius), m(mass), inertia(0.4 * mass * radius * radius), x(0, 0, radius - overlap0),
        v(Vec3::Zero()), w(Vec3::Zero()), chain(&c) {
    c.setup(1);
  }
  void step(double dt) {
    ContactBatch& b = *chain->batch;
    b.dt = dt;
    const double overlap = r - x.z();
    setPair(b, 0, overlap, r, kInf, m, kInf);
    const Vec3 n = Vec3::UnitZ();
    const Vec3 arm = -(r - 0.5 * overlap) * n;
    const Vec3 vc = v + w.cross(arm);
    b.normal[0] = n;
    b.vn[0] = vc.dot(n);
    b.vt[0] = vc - b.vn[0] * n;
    b.omega_i[0] = w;
    b.omega_j[0].setZero();
    chain->run();
    const Vec3 f = b.fn[0] * n + b.ft[0] + Vec3(0, 0, -m * kG);
    const Vec3 tq = arm.cross(b.ft[0]) + b.torque_i[0];
    v += dt / m * f;
    w += dt / inertia * tq;
    // Resisting torque, applied implicitly as the engine does: slows |ω| by R dt/I, stops at 0.
    const double loss = dt / inertia * b.resist_i[0], speed = w.norm();
    w = speed > loss ? Vec3(w * (1.0 - loss / speed)) : Vec3::Zero();
    x += dt * v;
  }
};

// Overlap of a sphere resting on a wall under its weight with Hertz: 4/3 E* sqrt(R) δ^{3/2} = m g.
inline double hertzRestingOverlap(double e_star, double r, double m) {
  return std::pow(m * kG / (4.0 / 3.0 * e_star * std::sqrt(r)), 2.0 / 3.0);
}

}  // namespace ctest
