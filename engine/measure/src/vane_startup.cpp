// Vane start-up (stress-growth) test: smoothed peak torque and the yield stress from it.
// Formulas, criterion and sources in paddy/measure/vane_startup.hpp.
#include <paddy/errors.hpp>
#include <paddy/measure/vane_startup.hpp>

#include <cmath>
#include <sstream>

namespace paddy::measure {

VaneStartupResult vaneStartup(const std::vector<double>& angle, const std::vector<double>& torque,
                              const VaneGeometry& vane, const VaneStartupOptions& o) {
  {
    std::ostringstream s;
    if (!(o.smoothing_angle >= 0.0) || !std::isfinite(o.smoothing_angle))
      s << "smoothing_angle = " << o.smoothing_angle << " rad must be finite and >= 0";
    else if (!(o.drop_fraction > 0.0 && o.drop_fraction < 1.0)) s << "drop_fraction = " << o.drop_fraction << " must be in (0, 1)";
    else if (!(o.plateau_angle > 0.0) || !std::isfinite(o.plateau_angle))
      s << "plateau_angle = " << o.plateau_angle << " rad must be finite and > 0";
    else if (angle.size() != torque.size())
      s << angle.size() << " angles but " << torque.size() << " torques";
    else if (angle.size() < 3)
      s << "needs at least 3 samples, got " << angle.size();
    if (!s.str().empty()) throw InputError("vane start-up: " + s.str());
  }
  const std::size_t n = angle.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(angle[i]) || !std::isfinite(torque[i]) || angle[i] < 0.0 || (i > 0 && angle[i] < angle[i - 1])) {
      std::ostringstream s;
      s << "vane start-up: sample " << i << " (angle " << angle[i] << " rad, torque " << torque[i]
        << " N m): angles must be finite, >= 0 and non-decreasing, torques finite";
      throw InputError(s.str());
    }
  }
  VaneStartupResult r;
  r.smoothed.resize(n);
  const double half = 0.5 * o.smoothing_angle;
  std::size_t lo = 0, hi = 0;  // window [lo, hi) of samples within ±half of angle[i]
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    while (hi < n && angle[hi] <= angle[i] + half) sum += torque[hi++];
    while (angle[lo] < angle[i] - half) sum -= torque[lo++];
    r.smoothed[i] = sum / double(hi - lo);
  }
  std::size_t im = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (r.smoothed[i] > r.smoothed[im]) im = i;
  r.peak_torque = r.smoothed[im];
  r.peak_angle = angle[im];
  r.final_torque = r.smoothed.back();
  for (std::size_t i = im; i < n && !r.peak_reached; ++i) {
    if (r.smoothed[i] <= (1.0 - o.drop_fraction) * r.peak_torque) r.peak_reached = true;
    if (angle[i] - r.peak_angle >= o.plateau_angle) r.peak_reached = true;
  }
  r.yield_stress = vaneShearStress(r.peak_torque, vane);
  return r;
}

}  // namespace paddy::measure
