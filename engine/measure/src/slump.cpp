// Slump (cone height − pile height) and the pile profile h(r).
// Definitions in paddy/measure/slump.hpp and docs/measurement.md.
#include <paddy/errors.hpp>
#include <paddy/measure/clusters.hpp>
#include <paddy/measure/slump.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <utility>

namespace paddy::measure {

namespace {

// Indices of the particles that count: the largest connected cluster, or all of them.
std::vector<std::size_t> pileMembers(const std::vector<Vec3>& x, const std::vector<double>& r,
                                     bool largest_cluster, double gap) {
  std::vector<std::size_t> idx;
  idx.reserve(x.size());
  if (!largest_cluster) {
    for (std::size_t i = 0; i < x.size(); ++i) idx.push_back(i);
    return idx;
  }
  if (gap < 0.0) gap = 0.1 * meanRadius(r);
  const Clusters c = connectedClusters(x, r, gap);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (c.label[i] == c.largest) idx.push_back(i);
  return idx;
}

void checkFinite(const std::string& what, double v) {
  if (!std::isfinite(v)) throw InputError(what + " = " + std::to_string(v) + " must be finite");
}

}  // namespace

SlumpHeightResult slumpHeight(const std::vector<Vec3>& x, const std::vector<double>& r,
                              const SlumpHeightOptions& o) {
  checkParticles(x, r, "slumpHeight");
  if (!o.axis.allFinite()) throw InputError("slumpHeight: axis point must be finite");
  checkFinite("slumpHeight: base_z", o.base_z);
  if (!(o.r_axis >= 0.0) || !std::isfinite(o.r_axis))
    throw InputError("slumpHeight: r_axis = " + std::to_string(o.r_axis) + " must be >= 0 (0 = automatic)");
  if (!(o.quantile > 0.0 && o.quantile <= 1.0))
    throw InputError("slumpHeight: quantile = " + std::to_string(o.quantile) + " is outside (0, 1]");
  if (o.min_particles == 0) throw InputError("slumpHeight: min_particles must be at least 1");

  const std::vector<std::size_t> pile = pileMembers(x, r, o.largest_cluster, o.contact_gap);
  SlumpHeightResult res;
  res.cluster = pile.size();
  res.ignored = x.size() - pile.size();

  // Horizontal distance of each pile particle from the axis.
  std::vector<double> rho(pile.size());
  double rho_max = 0.0;
  for (std::size_t k = 0; k < pile.size(); ++k) {
    rho[k] = (x[pile[k]].head<2>() - o.axis).norm();
    rho_max = std::max(rho_max, rho[k]);
  }
  double r_axis = o.r_axis > 0.0 ? o.r_axis : 6.0 * meanRadius(r);
  const std::size_t want = std::min(o.min_particles, pile.size());
  std::vector<double> tops;
  for (;;) {
    tops.clear();
    for (std::size_t k = 0; k < pile.size(); ++k)
      if (rho[k] <= r_axis) tops.push_back(x[pile[k]].z() + r[pile[k]] - o.base_z);
    if (tops.size() >= want || r_axis > rho_max) break;
    r_axis *= 1.5;
  }
  res.r_axis = r_axis;
  res.column = tops.size();
  res.height = quantile(tops, o.quantile);
  return res;
}

double slump(double cone_height, double pile_height) {
  checkFinite("slump: cone_height", cone_height);
  checkFinite("slump: pile_height", pile_height);
  return cone_height - pile_height;
}

std::vector<ProfileBin> pileProfile(const std::vector<Vec3>& x, const std::vector<double>& r,
                                    const ProfileOptions& o) {
  checkParticles(x, r, "pileProfile");
  if (!o.axis.allFinite()) throw InputError("pileProfile: axis point must be finite");
  checkFinite("pileProfile: base_z", o.base_z);
  for (const auto& [name, v] : std::initializer_list<std::pair<const char*, double>>{
           {"bin_width", o.bin_width}, {"r_max", o.r_max}, {"cell_arc", o.cell_arc}})
    if (!(v >= 0.0) || !std::isfinite(v))
      throw InputError(std::string("pileProfile: ") + name + " = " + std::to_string(v) +
                       " must be >= 0 (0 = automatic)");
  if (!(o.cell_quantile >= 0.0 && o.cell_quantile <= 1.0))
    throw InputError("pileProfile: cell_quantile = " + std::to_string(o.cell_quantile) + " is outside [0, 1]");

  const double rm = meanRadius(r);
  const double dr = o.bin_width > 0.0 ? o.bin_width : 2.0 * rm;
  const double arc = o.cell_arc > 0.0 ? o.cell_arc : 4.0 * rm;
  const std::vector<std::size_t> pile = pileMembers(x, r, o.largest_cluster, o.contact_gap);

  double r_end = o.r_max;
  if (r_end <= 0.0)
    for (std::size_t i : pile) r_end = std::max(r_end, (x[i].head<2>() - o.axis).norm() + r[i]);
  const auto nbins = static_cast<std::size_t>(std::max(1.0, std::ceil(r_end / dr)));
  if (nbins > 10'000'000) throw InputError("pileProfile: more than 10^7 bins; increase bin_width");

  std::vector<ProfileBin> bins(nbins);
  std::vector<std::vector<double>> cell_top(nbins);  // highest top per cell; −inf = empty
  for (std::size_t b = 0; b < nbins; ++b) {
    auto& bin = bins[b];
    bin.r_inner = static_cast<double>(b) * dr;
    bin.r_outer = bin.r_inner + dr;
    bin.r_centre = bin.r_inner + 0.5 * dr;
    bin.cells = static_cast<std::size_t>(std::max(1.0, std::round(2.0 * std::numbers::pi * bin.r_centre / arc)));
    cell_top[b].assign(bin.cells, -std::numeric_limits<double>::infinity());
  }
  for (std::size_t i : pile) {
    const Vec2 d = x[i].head<2>() - o.axis;
    const double rho = d.norm();
    const auto b = static_cast<std::size_t>(rho / dr);
    if (b >= nbins) continue;
    const double phi = std::atan2(d.y(), d.x()) + std::numbers::pi;  // [0, 2π]
    auto c = static_cast<std::size_t>(phi / (2.0 * std::numbers::pi) * static_cast<double>(bins[b].cells));
    c = std::min(c, bins[b].cells - 1);
    cell_top[b][c] = std::max(cell_top[b][c], x[i].z() + r[i] - o.base_z);
    ++bins[b].particles;
  }
  for (std::size_t b = 0; b < nbins; ++b) {
    std::size_t filled = 0;
    double sum = 0.0;
    for (double& t : cell_top[b]) {
      if (std::isinf(t)) t = 0.0; else ++filled;
      sum += t;
    }
    bins[b].mean_height = sum / static_cast<double>(bins[b].cells);
    bins[b].coverage = static_cast<double>(filled) / static_cast<double>(bins[b].cells);
    bins[b].height = quantile(cell_top[b], o.cell_quantile);
  }
  return bins;
}

}  // namespace paddy::measure
