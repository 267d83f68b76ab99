// Relative error of a simulated response against its measurement, as the reference study defines
// it: δ = |Y_measured − Y_sim| / Y_sim (the simulated value is the denominator).
#pragma once

#include <vector>

namespace paddy::measure {

// Throws InputError for non-finite values or Y_sim = 0.
double relativeError(double measured, double simulated);

struct RelativeErrors {
  std::vector<double> per_point;  // δ_i for each speed / response
  double mean = 0.0;
  double max = 0.0;
};

// Throws InputError when the vectors are empty or differ in size, or any δ_i is undefined.
RelativeErrors relativeErrors(const std::vector<double>& measured, const std::vector<double>& simulated);

}  // namespace paddy::measure
