// Region filling for sim:fill: random sequential insertion and lattices, see packing.hpp.
#include "packing.hpp"

#include <paddy/errors.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace paddy::lua {

// ---- regions ----------------------------------------------------------------------------------

void Region::validate() const {
  switch (type) {
    case Type::Box:
      if (!(max.array() > min.array()).all()) throw InputError("sim:fill: box region needs max > min in x, y and z");
      break;
    case Type::Cylinder:
      if (!(radius > 0 && height > 0)) throw InputError("sim:fill: cylinder region needs radius > 0 and height > 0");
      break;
    case Type::Cone:
      if (!(radius >= 0 && radius_top >= 0 && std::max(radius, radius_top) > 0 && height > 0))
        throw InputError("sim:fill: cone region needs radius_bottom, radius_top >= 0 (one > 0) and height > 0");
      break;
  }
}

bool Region::containsSphere(const Vec3& x, double r_in) const {
  // A relative tolerance keeps lattice sites that touch the boundary exactly (rounding).
  const double r = r_in * (1.0 - 1e-9);
  switch (type) {
    case Type::Box:
      return ((x.array() - r) >= min.array()).all() && ((x.array() + r) <= max.array()).all();
    case Type::Cylinder: {
      const double z = x.z() - base.z();
      const double rho = std::hypot(x.x() - base.x(), x.y() - base.y());
      return z >= r && z <= height - r && rho <= radius - r;
    }
    case Type::Cone: {
      const double z = x.z() - base.z();
      if (z < r || z > height - r) return false;
      const double slope = (radius_top - radius) / height;  // dR/dz
      const double rho = std::hypot(x.x() - base.x(), x.y() - base.y());
      // Distance from the axis-plane point to the slanted side, measured normal to it.
      return rho <= radius + slope * z - r * std::sqrt(1.0 + slope * slope);
    }
  }
  return false;
}

double Region::volume() const {
  switch (type) {
    case Type::Box: return (max - min).prod();
    case Type::Cylinder: return std::numbers::pi * radius * radius * height;
    case Type::Cone:
      return std::numbers::pi * height / 3.0 * (radius * radius + radius * radius_top + radius_top * radius_top);
  }
  return 0.0;
}

void Region::bounds(Vec3& lo, Vec3& hi) const {
  if (type == Type::Box) {
    lo = min;
    hi = max;
    return;
  }
  const double r = std::max(radius, radius_top);
  lo = base - Vec3(r, r, 0.0);
  hi = base + Vec3(r, r, height);
}

// ---- random numbers and radii -----------------------------------------------------------------

double Rng::normal() {
  if (spare_) {
    const double v = *spare_;
    spare_.reset();
    return v;
  }
  double u1 = 0.0;
  while (u1 <= 0.0) u1 = uniform();
  const double u2 = uniform();
  const double m = std::sqrt(-2.0 * std::log(u1));
  spare_ = m * std::sin(2.0 * std::numbers::pi * u2);
  return m * std::cos(2.0 * std::numbers::pi * u2);
}

void RadiusDistribution::validate() const {
  if (type == Type::Fixed) {
    if (!(a > 0)) throw InputError("sim:fill: radius must be > 0");
    return;
  }
  if (!(min > 0 && max >= min)) throw InputError("sim:fill: radius distribution needs 0 < min <= max");
  if (type == Type::Normal && !(b >= 0)) throw InputError("sim:fill: normal radius needs std >= 0");
  if (type == Type::LogNormal && !(a > 0 && b >= 0)) throw InputError("sim:fill: lognormal radius needs median > 0, sigma >= 0");
}

double RadiusDistribution::sample(Rng& rng) const {
  switch (type) {
    case Type::Fixed: return a;
    case Type::Uniform: return rng.uniform(min, max);
    case Type::Normal:
    case Type::LogNormal:
      for (int tries = 0; tries < 1000; ++tries) {
        const double z = rng.normal();
        const double r = type == Type::Normal ? a + b * z : a * std::exp(b * z);
        if (r >= min && r <= max) return r;
      }
      return std::clamp(a, min, max);  // truncation window far in the tail
  }
  return a;
}

// ---- the cell grid ----------------------------------------------------------------------------

namespace {

class Grid {
 public:
  explicit Grid(double cell) : cell_(cell) {}
  void insert(const Sphere& s) {
    const std::size_t index = spheres_.size();
    spheres_.push_back(s);
    cells_[key(cellOf(s.x))].push_back(index);
  }
  bool overlaps(const Vec3& x, double r) const {
    const auto c = cellOf(x);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
          if (it == cells_.end()) continue;
          for (std::size_t j : it->second) {
            const double reach = (r + spheres_[j].r) * (1.0 - 1e-9);  // touching is not overlapping
            if ((spheres_[j].x - x).squaredNorm() < reach * reach) return true;
          }
        }
    return false;
  }

 private:
  std::array<long, 3> cellOf(const Vec3& x) const {
    return {static_cast<long>(std::floor(x.x() / cell_)), static_cast<long>(std::floor(x.y() / cell_)),
            static_cast<long>(std::floor(x.z() / cell_))};
  }
  static std::uint64_t key(const std::array<long, 3>& c) {
    auto part = [](long v) { return static_cast<std::uint64_t>(v + (1l << 20)) & ((1ull << 21) - 1); };
    return part(c[0]) | (part(c[1]) << 21) | (part(c[2]) << 42);
  }
  double cell_;
  std::vector<Sphere> spheres_;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

// Existing particles near the region go into the grid; returns the largest radius seen.
double seedGrid(Grid& grid, const std::vector<Sphere>& existing, const Vec3& lo, const Vec3& hi, double margin) {
  double largest = 0.0;
  for (const Sphere& s : existing) {
    if (((s.x.array() + margin + s.r) < lo.array()).any() || ((s.x.array() - margin - s.r) > hi.array()).any()) continue;
    grid.insert(s);
    largest = std::max(largest, s.r);
  }
  return largest;
}

double largestExisting(const std::vector<Sphere>& existing) {
  double r = 0.0;
  for (const Sphere& s : existing) r = std::max(r, s.r);
  return r;
}

std::vector<Sphere> randomFill(const FillRequest& q, const std::vector<Sphere>& existing) {
  Rng rng(q.seed);
  std::size_t target = 0;
  if (q.count) {
    target = *q.count;
  } else {
    // Expected sphere volume from a fixed sample of the distribution (its own seeded stream).
    Rng probe(q.seed ^ 0x9e3779b97f4a7c15ull);
    double mean_volume = 0.0;
    const int n = q.radius.type == RadiusDistribution::Type::Fixed ? 1 : 4096;
    for (int k = 0; k < n; ++k) mean_volume += std::pow(q.radius.sample(probe), 3);
    mean_volume *= 4.0 / 3.0 * std::numbers::pi / n;
    target = static_cast<std::size_t>(std::floor(*q.volume_fraction * q.region.volume() / mean_volume));
  }
  std::vector<double> radii(target);
  for (double& r : radii) r = q.radius.sample(rng);
  std::sort(radii.begin(), radii.end(), std::greater<>());

  Vec3 lo, hi;
  q.region.bounds(lo, hi);
  const double r_new = q.radius.largest();
  Grid grid(2.0 * std::max(r_new, largestExisting(existing)));
  seedGrid(grid, existing, lo, hi, 2.0 * r_new);

  std::vector<Sphere> placed;
  placed.reserve(target);
  int failures_in_a_row = 0;
  for (double r : radii) {
    bool ok = false;
    for (int a = 0; a < q.attempts && !ok; ++a) {
      const Vec3 x(rng.uniform(lo.x() + r, hi.x() - r), rng.uniform(lo.y() + r, hi.y() - r),
                   rng.uniform(lo.z() + r, hi.z() - r));
      if (!q.region.containsSphere(x, r) || grid.overlaps(x, r)) continue;
      grid.insert({x, r});
      placed.push_back({x, r});
      ok = true;
    }
    failures_in_a_row = ok ? 0 : failures_in_a_row + 1;
    if (failures_in_a_row >= 20) break;  // the region is jammed
  }
  return placed;
}

std::vector<Sphere> latticeFill(const FillRequest& q, const std::vector<Sphere>& existing) {
  Rng rng(q.seed);
  const double r_max = q.radius.largest();
  const double d = 2.0 * r_max * q.spacing;
  const bool hex = q.packing == FillRequest::Packing::Hexagonal;
  const double dy = hex ? d * std::sqrt(3.0) / 2.0 : d;
  const double dz = hex ? d * std::sqrt(2.0 / 3.0) : d;
  Vec3 lo, hi;
  q.region.bounds(lo, hi);
  const Vec3 inner = (hi - lo).array() - 2.0 * r_max;
  if ((inner.array() < 0).any()) return {};
  // Whole lattice steps that fit (a little slack against rounding: 0.028 / 0.002 = 13.999...).
  const auto fit = [](double length, double step) { return std::floor(length / step + 1e-9); };
  // Centre the lattice across x and y; start at the bottom in z.
  const double sx = 0.5 * std::max(0.0, inner.x() - fit(inner.x(), d) * d);
  const double sy = 0.5 * std::max(0.0, inner.y() - fit(inner.y(), dy) * dy);
  const Vec3 origin = lo + Vec3(r_max + sx, r_max + sy, r_max);
  const long nx = static_cast<long>(fit(inner.x(), d)) + 1;
  const long ny = static_cast<long>(fit(inner.y(), dy)) + 1;
  const long nz = static_cast<long>(fit(inner.z(), dz)) + 1;

  Grid grid(2.0 * std::max(r_max, largestExisting(existing)));
  seedGrid(grid, existing, lo, hi, 2.0 * r_max);
  std::vector<Sphere> placed;
  const double jitter = std::clamp(q.jitter, 0.0, 1.0);
  for (long k = 0; k < nz; ++k)
    for (long j = 0; j < ny; ++j)
      for (long i = -1; i < nx; ++i) {  // i = -1 lets shifted rows use the left slack
        if (q.count && placed.size() >= *q.count) return placed;
        Vec3 x = origin + Vec3(i * d, j * dy, k * dz);
        if (hex) {
          const int layer = static_cast<int>(k % 3);
          x.x() += 0.5 * d * ((j % 2) + layer);  // ABC stacking: shift by (d/2, d/(2√3)) per layer
          x.y() += layer * d / (2.0 * std::sqrt(3.0));
        }
        const double r = q.radius.sample(rng);
        if (jitter > 0) {
          const double amplitude = jitter * std::max(0.0, 0.5 * d - r) / std::sqrt(3.0);
          x += Vec3(rng.uniform(-amplitude, amplitude), rng.uniform(-amplitude, amplitude),
                    rng.uniform(-amplitude, amplitude));
        }
        if (!q.region.containsSphere(x, r) || grid.overlaps(x, r)) continue;
        grid.insert({x, r});
        placed.push_back({x, r});
      }
  return placed;
}

}  // namespace

std::vector<Sphere> fillRegion(const FillRequest& q, const std::vector<Sphere>& existing) {
  q.region.validate();
  q.radius.validate();
  if (q.spacing < 1.0) throw InputError("sim:fill: spacing must be >= 1 (a multiple of the largest diameter)");
  if (q.packing == FillRequest::Packing::Random) {
    if (!q.count && !q.volume_fraction) throw InputError("sim:fill: random packing needs count or volume_fraction");
    if (q.volume_fraction && !(*q.volume_fraction > 0 && *q.volume_fraction < 0.74))
      throw InputError("sim:fill: volume_fraction must be in (0, 0.74)");
    return randomFill(q, existing);
  }
  return latticeFill(q, existing);
}

}  // namespace paddy::lua
