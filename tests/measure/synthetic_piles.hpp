// Synthetic piles with known answers for the measurement tests: spheres of diameter d on a simple
// cubic lattice (spacing d, touching neighbours) inside a cone, a disc or an elliptic slab.
#pragma once

#include <paddy/measure/common.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace paddy::measure::test {

struct Pile {
  std::vector<Vec3> x;
  std::vector<double> r;
  void add(const Vec3& p, double radius) {
    x.push_back(p);
    r.push_back(radius);
  }
};

// Cone of height H and base radius R on z = 0, axis at `c`: a sphere is kept when it rests on or
// above the plate (z ≥ r) and its centre is at least r below the cone surface (perpendicular).
inline Pile conePile(double H, double R, double d, const Vec2& c = Vec2::Zero()) {
  Pile p;
  const double r = d / 2, s = std::sqrt(1.0 + (H / R) * (H / R));
  const int n = static_cast<int>(R / d) + 1;
  for (int k = 0; r + k * d < H; ++k)
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i) {
        const double z = r + k * d, rho = std::hypot(i * d, j * d);
        if ((H * (1.0 - rho / R) - z) / s >= r) p.add(Vec3(c.x() + i * d, c.y() + j * d, z), r);
      }
  return p;
}

// Elliptic slab: centres with (x/a)² + (y/b)² ≤ 1 in the frame rotated by `angle`, `layers` high.
inline Pile ellipsePile(double a, double b, double d, int layers, const Vec2& c = Vec2::Zero(),
                        double angle = 0.0) {
  Pile p;
  const double r = d / 2, ca = std::cos(angle), sa = std::sin(angle);
  const int n = static_cast<int>(std::max(a, b) / d) + 1;
  for (int k = 0; k < layers; ++k)
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i) {
        const double u = i * d, v = j * d;
        if ((u / a) * (u / a) + (v / b) * (v / b) <= 1.0)
          p.add(Vec3(c.x() + ca * u - sa * v, c.y() + sa * u + ca * v, r + k * d), r);
      }
  return p;
}

inline Pile discPile(double R, double d, int layers, const Vec2& c = Vec2::Zero()) {
  return ellipsePile(R, R, d, layers, c);
}

// n loose particles scattered in the annulus [rho_min, rho_max] about c, at random heights.
inline void addNoise(Pile& p, int n, double rho_min, double rho_max, double radius, const Vec2& c,
                     unsigned seed = 42) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int k = 0; k < n; ++k) {
    const double rho = rho_min + (rho_max - rho_min) * U(rng), phi = 2.0 * std::numbers::pi * U(rng);
    p.add(Vec3(c.x() + rho * std::cos(phi), c.y() + rho * std::sin(phi), radius + 0.05 * U(rng)), radius);
  }
}

}  // namespace paddy::measure::test
