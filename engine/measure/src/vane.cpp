// Vane-in-cup conversions: Dzuy & Boger vane equation, Couette-analogy shear rate with the
// power-law (Krieger) correction, the iterative flow curve and the Herschel–Bulkley forward model.
// Formulas and sources in paddy/measure/vane.hpp.
#include <paddy/errors.hpp>
#include <paddy/measure/vane.hpp>

#include <Eigen/Dense>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <sstream>
#include <utility>

namespace paddy::measure {

namespace {

void checkVane(const VaneGeometry& v) {
  std::ostringstream s;
  if (!(v.diameter > 0.0) || !std::isfinite(v.diameter)) s << "vane diameter = " << v.diameter << " m must be > 0";
  else if (!(v.height > 0.0) || !std::isfinite(v.height)) s << "vane height = " << v.height << " m must be > 0";
  else if (!(v.cup_diameter > v.diameter)) s << "cup diameter = " << v.cup_diameter << " m must exceed the vane diameter " << v.diameter << " m";
  else if (v.sheared_ends < 0 || v.sheared_ends > 2) s << "sheared_ends = " << v.sheared_ends << " must be 0, 1 or 2";
  if (!s.str().empty()) throw InputError("vane: " + s.str());
}

double gapRatio(const VaneGeometry& v) { return std::isinf(v.cup_diameter) ? 0.0 : v.diameter / v.cup_diameter; }

}  // namespace

double vaneTorqueFactor(const VaneGeometry& v) {
  checkVane(v);
  const double D = v.diameter;
  return 0.5 * std::numbers::pi * D * D * D * (v.height / D + v.sheared_ends / 6.0);
}

double vaneShearStress(double torque, const VaneGeometry& v) {
  if (!std::isfinite(torque)) throw InputError("vaneShearStress: torque must be finite");
  return torque / vaneTorqueFactor(v);
}

double vaneTorque(double stress, const VaneGeometry& v) {
  if (!std::isfinite(stress)) throw InputError("vaneTorque: shear stress must be finite");
  return stress * vaneTorqueFactor(v);
}

double vaneShearRate(double omega, const VaneGeometry& v, double n) {
  checkVane(v);
  if (!std::isfinite(omega)) throw InputError("vaneShearRate: angular speed must be finite");
  if (!(n > 0.0) || !std::isfinite(n))
    throw InputError("vaneShearRate: flow index n = " + std::to_string(n) + " must be > 0");
  const double kappa = gapRatio(v);
  return 2.0 * omega / (n * (1.0 - std::pow(kappa, 2.0 / n)));
}

double rpmToRadPerSecond(double rpm) { return 2.0 * std::numbers::pi * rpm / 60.0; }

VaneFlowCurve vaneFlowCurve(const std::vector<double>& omega, const std::vector<double>& torque,
                            const VaneGeometry& v) {
  checkVane(v);
  if (omega.size() != torque.size())
    throw InputError("vaneFlowCurve: " + std::to_string(omega.size()) + " speeds but " +
                     std::to_string(torque.size()) + " torques");
  VaneFlowCurve c;
  const std::size_t m = omega.size();
  c.shear_stress.resize(m);
  for (std::size_t i = 0; i < m; ++i) c.shear_stress[i] = vaneShearStress(torque[i], v);
  if (m < 3) throw InputError("vaneFlowCurve: needs at least 3 (speed, torque) points; got " + std::to_string(m));
  std::vector<std::pair<double, double>> lw(m);  // (ln Ω, ln T)
  for (std::size_t i = 0; i < m; ++i) {
    if (!(omega[i] > 0.0) || !std::isfinite(omega[i]) || !(torque[i] > 0.0) || !std::isfinite(torque[i])) {
      std::ostringstream s;
      s << "vaneFlowCurve: point " << i << " has speed " << omega[i] << " rad/s and torque " << torque[i]
        << " N m; both must be finite and > 0";
      throw InputError(s.str());
    }
    if (i > 0 && !(omega[i] > omega[i - 1]))
      throw InputError("vaneFlowCurve: speeds must increase strictly (point " + std::to_string(i) + ")");
    lw[i] = {std::log(omega[i]), std::log(torque[i])};
  }
  // Local index n_i = d ln T / d ln Ω: slope at ln Ω_i of a least-squares quadratic through the
  // (up to) 5 nearest points (second-order accurate, also at the ends).
  const HerschelBulkleyOptions bounds;
  c.n_local.resize(m);
  c.shear_rate.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t w = std::min<std::size_t>(5, m);
    std::size_t lo = i >= 2 ? i - 2 : 0;
    lo = std::min(lo, m - w);
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    Eigen::Vector3d y = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < w; ++k) {
      const double u = lw[lo + k].first - lw[i].first;
      const Eigen::Vector3d a(1.0, u, u * u);
      A += a * a.transpose();
      y += a * lw[lo + k].second;
    }
    const Eigen::Vector3d q = A.inverse() * y;  // closed-form 3x3 inverse (distinct speeds)
    c.n_local[i] = std::clamp(q(1), bounds.n_min, bounds.n_max);
    c.shear_rate[i] = vaneShearRate(omega[i], v, c.n_local[i]);
  }
  c.fit = fitHerschelBulkley(c.shear_rate, c.shear_stress);
  return c;
}

double vaneTorqueHerschelBulkley(double omega, const HerschelBulkley& h, const VaneGeometry& v) {
  checkVane(v);
  if (!std::isfinite(omega) || omega < 0.0) throw InputError("vaneTorqueHerschelBulkley: omega must be >= 0");
  if (!(h.tau0 >= 0.0) || !(h.K > 0.0) || !(h.n > 0.0) || !std::isfinite(h.tau0) || !std::isfinite(h.K) ||
      !std::isfinite(h.n))
    throw InputError("vaneTorqueHerschelBulkley: needs tau0 >= 0, K > 0, n > 0");
  if (omega == 0.0) return vaneTorque(h.tau0, v);
  const double k2 = gapRatio(v) * gapRatio(v);
  boost::math::quadrature::tanh_sinh<double> integrator;
  // Ω(τ_v) = ½ ∫ γ̇(τ)/τ dτ over [max(κ²τ_v, τ0), τ_v].
  auto speed = [&](double tau_v) {
    const double lo = std::max(k2 * tau_v, h.tau0);
    if (tau_v <= lo) return 0.0;
    auto f = [&](double t) { return t > h.tau0 ? std::pow((t - h.tau0) / h.K, 1.0 / h.n) / t : 0.0; };
    return 0.5 * integrator.integrate(f, lo, tau_v);
  };
  double lo = h.tau0, hi = h.tau0 + h.K * std::pow(2.0 * omega, h.n) + 1e-12;
  for (int k = 0; k < 200 && speed(hi) < omega; ++k) hi *= 2.0;
  std::uintmax_t iters = 200;
  const auto r = boost::math::tools::toms748_solve([&](double t) { return speed(t) - omega; }, lo, hi,
                                                   boost::math::tools::eps_tolerance<double>(50), iters);
  return vaneTorque(0.5 * (r.first + r.second), v);
}

}  // namespace paddy::measure
