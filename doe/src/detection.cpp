#include "paddy/doe/detection.hpp"

#include "paddy/doe/error.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>

namespace paddy::doe {

double signatureNoise(const std::vector<Eigen::VectorXd>& projectedDeviations) {
  const auto K = static_cast<double>(projectedDeviations.size());
  if (K < 2) return 0.0;
  double sum = 0.0;
  for (const auto& d : projectedDeviations) sum += d.squaredNorm();
  return sum / (K * (K - 1.0));
}

Detectability detectability(double a, double b, double aNoise, double zStar, double power, double relevant) {
  if (!(power > 0 && power < 1)) throw DoeError("detection_power: must be in (0, 1), got " + std::to_string(power));
  if (!(a >= 0) || !(aNoise >= 0) || !std::isfinite(b) || !std::isfinite(zStar) || !std::isfinite(relevant))
    throw DoeError("detectability: a, a_noise must be >= 0 and b, z*, relevant finite");
  const boost::math::normal unit;
  Detectability d;
  d.aNoise = aNoise;
  d.aSignal = a - aNoise;
  if (!(d.aSignal > 0) || !(a > 0)) return d;  // the signature is within its own noise: nothing is bounded
  const double root = std::sqrt(a);
  const double zPower = boost::math::quantile(unit, power);
  d.detectionLimit = (zStar + zPower + relevant * root) * root / d.aSignal;
  d.strength = b / d.aSignal;
  d.strengthSe = root / d.aSignal;
  d.upperLimit = std::max(d.strength, 0.0) + boost::math::quantile(unit, 0.95) * d.strengthSe;
  return d;
}

}  // namespace paddy::doe
