// Simulation set-up: materials, interactions, particles, walls, time step.
#include "simulation_impl.hpp"

#include <paddy/errors.hpp>
#include <paddy/plugin_manager.hpp>

#include <omp.h>

#include <cmath>
#include <numbers>
#include <sstream>

namespace paddy {

Simulation::Simulation(std::shared_ptr<const PluginManager> plugins)
    : plugins_(std::move(plugins)), impl_(std::make_unique<Impl>()) {
  if (!plugins_) throw InputError("Simulation needs a PluginManager");
  impl_->dt_fraction = TimeStepPolicy::kDefaultRayleighFraction;
}

Simulation::~Simulation() = default;

int Simulation::addMaterial(const Material& m) {
  if (m.name.empty()) throw InputError("a material needs a name");
  for (const auto& other : materials_)
    if (other.name == m.name) throw InputError("material '" + m.name + "' is defined twice");
  checkRange(m.name + ".density", m.density, 1e-6, 1e6, "kg/m^3");
  checkRange(m.name + ".shear_modulus", m.shear_modulus, 1.0, 1e13, "Pa");
  checkRange(m.name + ".poisson", m.poisson, -0.999, 0.5);
  materials_.push_back(m);
  const std::size_t n = materials_.size();
  // Grow the pair table, keeping existing entries.
  std::vector<int> table(n * n, -1);
  for (std::size_t a = 0; a + 1 < n; ++a)
    for (std::size_t b = 0; b + 1 < n; ++b) table[a * n + b] = impl_->law_index[a * (n - 1) + b];
  impl_->law_index = std::move(table);
  return static_cast<int>(n - 1);
}

int Simulation::materialId(const std::string& name) const {
  for (std::size_t k = 0; k < materials_.size(); ++k)
    if (materials_[k].name == name) return static_cast<int>(k);
  std::string known;
  for (const auto& m : materials_) known += (known.empty() ? "" : ", ") + m.name;
  throw InputError("unknown material '" + name + "'; defined: " + (known.empty() ? "(none)" : known));
}

void Simulation::setInteraction(int a, int b, const InteractionSpec& spec) {
  const int n = static_cast<int>(materials_.size());
  if (a < 0 || a >= n || b < 0 || b >= n) throw InputError("interaction between unknown material ids");
  ContactLaw law(*plugins_, spec, MaterialPair::of(materials_[a], materials_[b]));
  int index = impl_->law_index[a * n + b];
  if (index >= 0) {
    impl_->laws[index] = std::move(law);
  } else {
    index = static_cast<int>(impl_->laws.size());
    impl_->laws.push_back(std::move(law));
  }
  impl_->law_index[a * n + b] = impl_->law_index[b * n + a] = index;
  std::size_t stride = 0;
  for (const auto& l : impl_->laws) stride = std::max(stride, l.historySize());
  if (stride != impl_->history_stride) {
    impl_->history_stride = stride;
    impl_->wall_state.clear();
    impl_->wall_history.clear();
  }
  impl_->list_valid = false;
  impl_->forces_valid = false;
}

std::size_t Simulation::addParticle(const Vec3& x, double radius, int material, const Vec3& v, const Vec3& omega) {
  if (material < 0 || material >= static_cast<int>(materials_.size()))
    throw InputError("addParticle: unknown material id " + std::to_string(material));
  checkRange("radius", radius, 1e-9, 1e3, "m");
  if (!x.allFinite() || !v.allFinite() || !omega.allFinite())
    throw InputError("addParticle: position and velocity must be finite numbers");
  const Material& m = materials_[material];
  const double mass = m.density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  p_.id.push_back(next_id_++);
  p_.material.push_back(material);
  p_.radius.push_back(radius);
  p_.mass.push_back(mass);
  p_.inertia.push_back(0.4 * mass * radius * radius);
  p_.position.push_back(x);
  p_.velocity.push_back(v);
  p_.omega.push_back(omega);
  p_.force.push_back(Vec3::Zero());
  p_.torque.push_back(Vec3::Zero());
  p_.resisting_torque.push_back(0.0);
  impl_->prev_index.push_back(Impl::kNoIndex);
  impl_->list_valid = false;
  impl_->forces_valid = false;
  return p_.size() - 1;
}

void Simulation::removeParticles(const std::function<bool(std::size_t)>& predicate) {
  std::size_t w = 0;
  const std::size_t n = p_.size();
  for (std::size_t r = 0; r < n; ++r) {
    if (predicate(r)) continue;
    if (w != r) {
      p_.id[w] = p_.id[r];
      p_.material[w] = p_.material[r];
      p_.radius[w] = p_.radius[r];
      p_.mass[w] = p_.mass[r];
      p_.inertia[w] = p_.inertia[r];
      p_.position[w] = p_.position[r];
      p_.velocity[w] = p_.velocity[r];
      p_.omega[w] = p_.omega[r];
      p_.force[w] = p_.force[r];
      p_.torque[w] = p_.torque[r];
      p_.resisting_torque[w] = p_.resisting_torque[r];
      impl_->prev_index[w] = impl_->prev_index[r];
    }
    ++w;
  }
  p_.id.resize(w);
  p_.material.resize(w);
  p_.radius.resize(w);
  p_.mass.resize(w);
  p_.inertia.resize(w);
  p_.position.resize(w);
  p_.velocity.resize(w);
  p_.omega.resize(w);
  p_.force.resize(w);
  p_.torque.resize(w);
  p_.resisting_torque.resize(w);
  impl_->prev_index.resize(w);
  impl_->list_valid = false;
  impl_->forces_valid = false;
}

int Simulation::addWall(std::unique_ptr<Wall> wall) {
  if (!wall) throw InputError("addWall: no wall");
  const int mat = wall->material();
  if (mat < 0 || mat >= static_cast<int>(materials_.size()))
    throw InputError("wall '" + wall->name() + "' has unknown material id " + std::to_string(mat));
  walls_.push_back(std::move(wall));
  impl_->list_valid = false;
  impl_->forces_valid = false;
  return static_cast<int>(walls_.size() - 1);
}

void Simulation::setThreads(int n) {
  checkRange("threads", n, 1, 1024);
  threads_ = n;
}

void Simulation::setSkinFraction(double f) {
  checkRange("skin_fraction", f, 0.01, 5.0);
  impl_->skin_fraction = f;
  impl_->list_valid = false;
}

void Simulation::setSortInterval(int rebuilds) {
  checkRange("sort_interval", rebuilds, 0, 1e9);
  impl_->sort_interval = rebuilds;
}

double Simulation::rayleighTime() const {
  if (p_.size() == 0) throw InputError("the Rayleigh time step needs particles: add particles first");
  double t = std::numeric_limits<double>::infinity();
  // Per material, the smallest particle decides.
  std::vector<double> rmin(materials_.size(), std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < p_.size(); ++i) rmin[p_.material[i]] = std::min(rmin[p_.material[i]], p_.radius[i]);
  for (std::size_t m = 0; m < materials_.size(); ++m) {
    if (!std::isfinite(rmin[m])) continue;
    const Material& mat = materials_[m];
    t = std::min(t, std::numbers::pi * rmin[m] / (0.163 * mat.poisson + 0.877) * std::sqrt(mat.density / mat.shear_modulus));
  }
  return t;
}

void Simulation::setTimeStep(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError("time step must be a positive number of seconds");
  const double limit = maxStableTimeStep();
  if (dt > limit) {
    std::ostringstream msg;
    msg << "time step " << dt << " s is above the stable limit " << limit << " s ("
        << TimeStepPolicy::kMaxRayleighFraction << " x the Rayleigh time " << rayleighTime()
        << " s of the smallest particle); use at most " << limit << " s";
    throw InputError(msg.str());
  }
  dt_ = dt;
  impl_->dt_explicit = true;
}

void Simulation::setTimeStepFraction(double f) {
  checkRange("timestep fraction of the Rayleigh time", f, 1e-6, TimeStepPolicy::kMaxRayleighFraction);
  impl_->dt_fraction = f;
  impl_->dt_explicit = false;
  if (p_.size() > 0) dt_ = f * rayleighTime();
}

const char* timeIntegrationName(TimeIntegration scheme) {
  return scheme == TimeIntegration::SymplecticEuler ? "euler" : "velocity_verlet";
}

TimeIntegration timeIntegrationFromName(const std::string& name) {
  for (TimeIntegration scheme : {TimeIntegration::VelocityVerlet, TimeIntegration::SymplecticEuler})
    if (name == timeIntegrationName(scheme)) return scheme;
  throw InputError("'" + name + "' is not a scheme; choose velocity_verlet or euler");
}

void Simulation::setTimeIntegration(TimeIntegration scheme) { impl_->integration = scheme; }
TimeIntegration Simulation::timeIntegration() const { return impl_->integration; }

double Simulation::kineticEnergy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < p_.size(); ++i)
    e += 0.5 * p_.mass[i] * p_.velocity[i].squaredNorm() + 0.5 * p_.inertia[i] * p_.omega[i].squaredNorm();
  return e;
}

double Simulation::maxSpeed() const {
  double v2 = 0.0;
  for (const auto& v : p_.velocity) v2 = std::max(v2, v.squaredNorm());
  return std::sqrt(v2);
}

}  // namespace paddy
