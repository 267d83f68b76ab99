// Shared helpers of the measurement layer (paddy::measure): the particle-data types the
// measures take, input checks that name the problem, and the sample quantile.
//
// Every measure is a pure function of particle data: positions (std::vector<Eigen::Vector3d>,
// metres) and radii (std::vector<double>, metres). Results are in SI units; the Lua layer
// converts to millimetres where the laboratory reports millimetres. See docs/measurement.md.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

namespace paddy::measure {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

// Throws paddy::InputError "<what>: ..." unless positions and radii are non-empty, of equal size,
// finite, and every radius is > 0.
void checkParticles(const std::vector<Vec3>& positions, const std::vector<double>& radii,
                    const std::string& what);

// Sample quantile with linear interpolation between order statistics (Hyndman & Fan 1996,
// definition 7, the default of R and NumPy): q = 0 gives the minimum, q = 1 the maximum.
// Throws InputError for an empty sample or q outside [0, 1].
double quantile(std::vector<double> values, double q);

// Arithmetic mean of the radii (the "particle radius" used for default lengths).
double meanRadius(const std::vector<double>& radii);

}  // namespace paddy::measure
