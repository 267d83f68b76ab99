// Input checks and the sample quantile of the measurement layer.
#include <paddy/errors.hpp>
#include <paddy/measure/common.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace paddy::measure {

void checkParticles(const std::vector<Vec3>& positions, const std::vector<double>& radii,
                    const std::string& what) {
  if (positions.empty()) throw InputError(what + ": no particles");
  if (positions.size() != radii.size()) {
    std::ostringstream s;
    s << what << ": " << positions.size() << " positions but " << radii.size() << " radii";
    throw InputError(s.str());
  }
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!positions[i].allFinite() || !std::isfinite(radii[i]) || radii[i] <= 0.0) {
      std::ostringstream s;
      s << what << ": particle " << i << " has position (" << positions[i].transpose()
        << ") and radius " << radii[i] << "; positions must be finite and radii > 0";
      throw InputError(s.str());
    }
  }
}

double quantile(std::vector<double> values, double q) {
  if (values.empty()) throw InputError("quantile of an empty sample");
  if (!(q >= 0.0 && q <= 1.0))
    throw InputError("quantile q = " + std::to_string(q) + " is outside [0, 1]");
  const double h = q * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(lo), values.end());
  const double a = values[lo];
  if (lo + 1 >= values.size()) return a;
  const double b = *std::min_element(values.begin() + static_cast<std::ptrdiff_t>(lo) + 1, values.end());
  return a + (h - static_cast<double>(lo)) * (b - a);
}

double meanRadius(const std::vector<double>& radii) {
  if (radii.empty()) throw InputError("mean radius of no particles");
  double s = 0.0;
  for (double r : radii) s += r;
  return s / static_cast<double>(radii.size());
}

}  // namespace paddy::measure
