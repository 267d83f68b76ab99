// Filling a region with non-overlapping spheres (private to engine/lua/src; used by sim:fill).
//
// Random packing is seeded random sequential insertion: radii are drawn first and placed from
// the largest down; each sphere tries random centres inside the region until it overlaps
// neither a placed sphere nor an existing particle (a hashed cell grid makes each test O(1)).
// Lattice packing puts spheres on a hexagonal close-packed (ABC) or simple cubic lattice, from
// the bottom up. Everything is deterministic for a given seed (std::mt19937_64 and our own
// transforms of its output, not the implementation-defined std distributions).
#pragma once

#include <paddy/contact_batch.hpp>

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace paddy::lua {

// A region whose axis, for cylinders and cones, is +z from `base` (the centre of the bottom).
struct Region {
  enum class Type { Box, Cylinder, Cone };
  Type type = Type::Box;
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();  // box
  Vec3 base = Vec3::Zero();                     // cylinder, cone
  double radius = 0.0;       // cylinder radius / cone bottom radius [m]
  double radius_top = 0.0;   // cone top radius [m]
  double height = 0.0;

  bool containsSphere(const Vec3& x, double r) const;  // the whole sphere lies inside
  double volume() const;
  void bounds(Vec3& lo, Vec3& hi) const;
  void validate() const;  // throws InputError for degenerate regions
};

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  double normal();  // standard normal (Box-Muller)

 private:
  std::mt19937_64 engine_;
  std::optional<double> spare_;
};

// Radius distribution: a fixed value, or uniform / normal / lognormal truncated to [min, max].
struct RadiusDistribution {
  enum class Type { Fixed, Uniform, Normal, LogNormal };
  Type type = Type::Fixed;
  double a = 0.0, b = 0.0;  // fixed: a; uniform: [a,b]; normal: mean a, std b; lognormal: median a, sigma b
  double min = 0.0, max = 0.0;
  double sample(Rng& rng) const;
  double largest() const { return type == Type::Fixed ? a : max; }
  void validate() const;
};

struct FillRequest {
  enum class Packing { Random, Hexagonal, Cubic };
  Region region;
  RadiusDistribution radius;
  Packing packing = Packing::Random;
  std::uint64_t seed = 1;
  std::optional<std::size_t> count;        // at most this many
  std::optional<double> volume_fraction;   // random packing: target solid fraction
  double spacing = 1.0;  // lattice pitch as a multiple of the largest diameter (>= 1)
  double jitter = 0.0;   // lattice: random shift, as a fraction (0..1) of the free gap
  int attempts = 500;    // random packing: tries per sphere
};

struct Sphere {
  Vec3 x;
  double r;
};

// Spheres to add; `existing` are the simulation's particles (never overlapped).
std::vector<Sphere> fillRegion(const FillRequest& request, const std::vector<Sphere>& existing);

}  // namespace paddy::lua
