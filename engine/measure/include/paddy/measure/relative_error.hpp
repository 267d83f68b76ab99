// Relative error of a simulated response against its measurement: δ = |Y_measured − Y_sim| /
// Y_measured. The reference's README writes Y_sim in the denominator, but every percentage of its
// Table 6 is reproduced only with the measured value there (27/231 = 11.69 %, not 27/258), so
// Paddy follows the table; tests/measure checks all eight Table 6 percentages.
#pragma once

#include <vector>

namespace paddy::measure {

// Throws InputError for non-finite values or Y_measured = 0.
double relativeError(double measured, double simulated);

struct RelativeErrors {
  std::vector<double> per_point;  // δ_i for each speed / response
  double mean = 0.0;
  double max = 0.0;
};

// Throws InputError when the vectors are empty or differ in size, or any δ_i is undefined.
RelativeErrors relativeErrors(const std::vector<double>& measured, const std::vector<double>& simulated);

}  // namespace paddy::measure
