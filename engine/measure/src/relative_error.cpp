// Relative errors δ = |Y_measured − Y_sim| / Y_measured (see relative_error.hpp).
#include <paddy/errors.hpp>
#include <paddy/measure/relative_error.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace paddy::measure {

double relativeError(double measured, double simulated) {
  if (!std::isfinite(measured) || !std::isfinite(simulated)) {
    std::ostringstream s;
    s << "relativeError: measured " << measured << " and simulated " << simulated << " must be finite";
    throw InputError(s.str());
  }
  if (measured == 0.0) throw InputError("relativeError: the measured value is 0, so delta = |Ym - Ys|/Ym is undefined");
  return std::abs(measured - simulated) / std::abs(measured);
}

RelativeErrors relativeErrors(const std::vector<double>& measured, const std::vector<double>& simulated) {
  if (measured.size() != simulated.size())
    throw InputError("relativeErrors: " + std::to_string(measured.size()) + " measured values but " +
                     std::to_string(simulated.size()) + " simulated values");
  if (measured.empty()) throw InputError("relativeErrors: no values");
  RelativeErrors r;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    try {
      r.per_point.push_back(relativeError(measured[i], simulated[i]));
    } catch (const InputError& e) {
      throw InputError("relativeErrors: point " + std::to_string(i) + ": " + e.what());
    }
    r.mean += r.per_point.back();
    r.max = std::max(r.max, r.per_point.back());
  }
  r.mean /= static_cast<double>(measured.size());
  return r;
}

}  // namespace paddy::measure
