// Top-view image of a pile: rendering, binary morphology, components, holes, boundary tracing.
// Methods and sources in paddy/measure/top_view.hpp.
#include <paddy/errors.hpp>
#include <paddy/measure/top_view.hpp>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <set>

namespace paddy::measure {

namespace {

using Mask = std::vector<std::uint8_t>;

void checkMask(const Mask& m, int nx, int ny, const char* what) {
  if (nx < 0 || ny < 0 || m.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny))
    throw InputError(std::string(what) + ": mask size does not match " + std::to_string(nx) + " x " +
                     std::to_string(ny));
}

// 1-D squared distance transform of a sampled function (Felzenszwalb & Huttenlocher 2012).
void distance1d(const std::vector<double>& f, int n, std::vector<double>& d, std::vector<int>& v,
                std::vector<double>& z) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  int k = 0;
  v[0] = 0;
  z[0] = -inf;
  z[1] = inf;
  auto cross = [&](int q, int p) {
    return ((f[static_cast<std::size_t>(q)] + double(q) * q) - (f[static_cast<std::size_t>(p)] + double(p) * p)) /
           (2.0 * (q - p));
  };
  for (int q = 1; q < n; ++q) {
    double s = cross(q, v[static_cast<std::size_t>(k)]);
    while (s <= z[static_cast<std::size_t>(k)]) {  // z[0] = -inf stops the loop at k = 0
      --k;
      s = cross(q, v[static_cast<std::size_t>(k)]);
    }
    ++k;
    v[static_cast<std::size_t>(k)] = q;
    z[static_cast<std::size_t>(k)] = s;
    z[static_cast<std::size_t>(k) + 1] = inf;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[static_cast<std::size_t>(k) + 1] < q) ++k;
    const int p = v[static_cast<std::size_t>(k)];
    d[static_cast<std::size_t>(q)] = double(q - p) * (q - p) + f[static_cast<std::size_t>(p)];
  }
}

// Squared Euclidean distance (in pixels²) of every pixel to the nearest pixel with value `feature`.
std::vector<double> squaredDistance(const Mask& m, int nx, int ny, std::uint8_t feature) {
  constexpr double big = 1e20;
  std::vector<double> g(m.size());
  for (std::size_t k = 0; k < m.size(); ++k) g[k] = (m[k] == feature) ? 0.0 : big;
  const int n = std::max(nx, ny);
  std::vector<double> f(static_cast<std::size_t>(n)), d(static_cast<std::size_t>(n)), z(static_cast<std::size_t>(n) + 1);
  std::vector<int> v(static_cast<std::size_t>(n));
  for (int j = 0; j < ny; ++j) {  // rows
    for (int i = 0; i < nx; ++i) f[static_cast<std::size_t>(i)] = g[static_cast<std::size_t>(j) * nx + i];
    distance1d(f, nx, d, v, z);
    for (int i = 0; i < nx; ++i) g[static_cast<std::size_t>(j) * nx + i] = std::min(d[static_cast<std::size_t>(i)], big);
  }
  for (int i = 0; i < nx; ++i) {  // columns
    for (int j = 0; j < ny; ++j) f[static_cast<std::size_t>(j)] = g[static_cast<std::size_t>(j) * nx + i];
    distance1d(f, ny, d, v, z);
    for (int j = 0; j < ny; ++j) g[static_cast<std::size_t>(j) * nx + i] = std::min(d[static_cast<std::size_t>(j)], big);
  }
  return g;
}

bool inside(int i, int j, int nx, int ny) { return i >= 0 && j >= 0 && i < nx && j < ny; }

}  // namespace

TopViewImage renderTopView(const std::vector<Vec3>& x, const std::vector<double>& r,
                           const TopViewOptions& o) {
  checkParticles(x, r, "renderTopView");
  if (!(o.pixel > 0.0) || !std::isfinite(o.pixel))
    throw InputError("renderTopView: pixel = " + std::to_string(o.pixel) + " m must be > 0");
  if (!o.axis.allFinite() || !std::isfinite(o.base_z) || !std::isfinite(o.min_thickness))
    throw InputError("renderTopView: axis, base_z and min_thickness must be finite");
  if (!(o.window_half_width >= 0.0) || !std::isfinite(o.window_half_width))
    throw InputError("renderTopView: window_half_width must be >= 0 (0 = bounding box)");
  if (o.margin_pixels < 0) throw InputError("renderTopView: margin_pixels must be >= 0");

  const double p = o.pixel;
  double i_lo, i_hi, j_lo, j_hi;  // pixel-edge indices relative to the axis
  if (o.window_half_width > 0.0) {
    const double h = std::ceil(o.window_half_width / p);
    i_lo = j_lo = -h;
    i_hi = j_hi = h;
  } else {
    Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (std::size_t k = 0; k < x.size(); ++k) {
      lo = lo.cwiseMin(Vec2(x[k].x() - r[k], x[k].y() - r[k]));
      hi = hi.cwiseMax(Vec2(x[k].x() + r[k], x[k].y() + r[k]));
    }
    i_lo = std::floor((lo.x() - o.axis.x()) / p);
    i_hi = std::ceil((hi.x() - o.axis.x()) / p);
    j_lo = std::floor((lo.y() - o.axis.y()) / p);
    j_hi = std::ceil((hi.y() - o.axis.y()) / p);
  }
  i_lo -= o.margin_pixels;
  j_lo -= o.margin_pixels;
  i_hi += o.margin_pixels;
  j_hi += o.margin_pixels;
  const double count = (i_hi - i_lo) * (j_hi - j_lo);
  if (count > static_cast<double>(o.max_pixels))
    throw InputError("renderTopView: the image would have " + std::to_string(count) + " pixels (limit " +
                     std::to_string(o.max_pixels) + "); use a larger pixel or a window_half_width");

  TopViewImage img;
  img.pixel = p;
  img.nx = static_cast<int>(i_hi - i_lo);
  img.ny = static_cast<int>(j_hi - j_lo);
  img.x0 = o.axis.x() + i_lo * p;
  img.y0 = o.axis.y() + j_lo * p;
  const std::size_t n = static_cast<std::size_t>(img.nx) * static_cast<std::size_t>(img.ny);
  img.height.assign(n, -std::numeric_limits<float>::infinity());
  img.covered.assign(n, 0);

  for (std::size_t k = 0; k < x.size(); ++k) {
    const double rk = r[k];
    const int ia = std::max(0, static_cast<int>(std::floor((x[k].x() - rk - img.x0) / p - 0.5)));
    const int ib = std::min(img.nx - 1, static_cast<int>(std::ceil((x[k].x() + rk - img.x0) / p - 0.5)));
    const int ja = std::max(0, static_cast<int>(std::floor((x[k].y() - rk - img.y0) / p - 0.5)));
    const int jb = std::min(img.ny - 1, static_cast<int>(std::ceil((x[k].y() + rk - img.y0) / p - 0.5)));
    for (int j = ja; j <= jb; ++j) {
      const double dy = img.y0 + (j + 0.5) * p - x[k].y();
      for (int i = ia; i <= ib; ++i) {
        const double dx = img.x0 + (i + 0.5) * p - x[k].x();
        const double rho2 = dx * dx + dy * dy;
        if (rho2 > rk * rk) continue;
        const std::size_t idx = img.index(i, j);
        const auto top = static_cast<float>(x[k].z() - o.base_z + std::sqrt(rk * rk - rho2));
        img.covered[idx] = 1;
        img.height[idx] = std::max(img.height[idx], top);
      }
    }
  }
  img.mask.assign(n, 0);
  for (std::size_t idx = 0; idx < n; ++idx) {
    if (!img.covered[idx]) {
      img.height[idx] = 0.0f;
      continue;
    }
    img.mask[idx] = img.height[idx] >= static_cast<float>(o.min_thickness) ? 1 : 0;
  }
  return img;
}

std::vector<std::uint8_t> dilation(const Mask& m, int nx, int ny, double radius) {
  checkMask(m, nx, ny, "dilation");
  if (radius <= 0.0) return m;
  const auto d2 = squaredDistance(m, nx, ny, 1);
  Mask out(m.size());
  for (std::size_t k = 0; k < m.size(); ++k) out[k] = d2[k] <= radius * radius ? 1 : 0;
  return out;
}

std::vector<std::uint8_t> erosion(const Mask& m, int nx, int ny, double radius) {
  checkMask(m, nx, ny, "erosion");
  if (radius <= 0.0) return m;
  // Pad with background so that the outside of the image counts as background.
  const int pad = static_cast<int>(std::ceil(radius)) + 1;
  const int px = nx + 2 * pad, py = ny + 2 * pad;
  Mask padded(static_cast<std::size_t>(px) * static_cast<std::size_t>(py), 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      padded[static_cast<std::size_t>(j + pad) * px + (i + pad)] = m[static_cast<std::size_t>(j) * nx + i];
  const auto d2 = squaredDistance(padded, px, py, 0);
  Mask out(m.size());
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      out[static_cast<std::size_t>(j) * nx + i] =
          d2[static_cast<std::size_t>(j + pad) * px + (i + pad)] > radius * radius ? 1 : 0;
  return out;
}

std::vector<std::uint8_t> closing(const Mask& m, int nx, int ny, double radius) {
  return erosion(dilation(m, nx, ny, radius), nx, ny, radius);
}

std::vector<std::uint8_t> largestComponent(const Mask& m, int nx, int ny, std::size_t* pixels) {
  checkMask(m, nx, ny, "largestComponent");
  std::vector<int> label(m.size(), -1);
  std::vector<std::size_t> sizes;
  std::vector<std::size_t> stack;
  for (std::size_t start = 0; start < m.size(); ++start) {
    if (!m[start] || label[start] >= 0) continue;
    const int id = static_cast<int>(sizes.size());
    std::size_t count = 0;
    label[start] = id;
    stack.push_back(start);
    while (!stack.empty()) {
      const std::size_t k = stack.back();
      stack.pop_back();
      ++count;
      const int i = static_cast<int>(k % static_cast<std::size_t>(nx)), j = static_cast<int>(k / static_cast<std::size_t>(nx));
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int a = i + di, b = j + dj;
          if (!inside(a, b, nx, ny)) continue;
          const std::size_t q = static_cast<std::size_t>(b) * nx + a;
          if (m[q] && label[q] < 0) {
            label[q] = id;
            stack.push_back(q);
          }
        }
    }
    sizes.push_back(count);
  }
  Mask out(m.size(), 0);
  if (sizes.empty()) {
    if (pixels) *pixels = 0;
    return out;
  }
  const int best = static_cast<int>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  for (std::size_t k = 0; k < m.size(); ++k) out[k] = label[k] == best ? 1 : 0;
  if (pixels) *pixels = sizes[static_cast<std::size_t>(best)];
  return out;
}

std::vector<std::uint8_t> fillHoles(const Mask& m, int nx, int ny) {
  checkMask(m, nx, ny, "fillHoles");
  Mask outside(m.size(), 0);
  std::deque<std::size_t> queue;
  auto seed = [&](int i, int j) {
    const std::size_t k = static_cast<std::size_t>(j) * nx + i;
    if (!m[k] && !outside[k]) {
      outside[k] = 1;
      queue.push_back(k);
    }
  };
  for (int i = 0; i < nx; ++i) {
    seed(i, 0);
    seed(i, ny - 1);
  }
  for (int j = 0; j < ny; ++j) {
    seed(0, j);
    seed(nx - 1, j);
  }
  const int di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
  while (!queue.empty()) {
    const std::size_t k = queue.front();
    queue.pop_front();
    const int i = static_cast<int>(k % static_cast<std::size_t>(nx)), j = static_cast<int>(k / static_cast<std::size_t>(nx));
    for (int d = 0; d < 4; ++d)
      if (inside(i + di[d], j + dj[d], nx, ny)) seed(i + di[d], j + dj[d]);
  }
  Mask out(m.size());
  for (std::size_t k = 0; k < m.size(); ++k) out[k] = outside[k] ? 0 : 1;
  return out;
}

std::vector<Eigen::Vector2i> traceBoundary(const Mask& m, int nx, int ny) {
  checkMask(m, nx, ny, "traceBoundary");
  // The 8 neighbours in cyclic (clockwise for y up) order, starting west.
  static const int ox[8] = {-1, -1, 0, 1, 1, 1, 0, -1};
  static const int oy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
  auto fg = [&](int i, int j) { return inside(i, j, nx, ny) && m[static_cast<std::size_t>(j) * nx + i]; };
  auto dir = [&](int dx, int dy) {
    for (int k = 0; k < 8; ++k)
      if (ox[k] == dx && oy[k] == dy) return k;
    return 0;
  };

  std::vector<Eigen::Vector2i> out;
  std::size_t first = m.size();
  for (std::size_t k = 0; k < m.size(); ++k)
    if (m[k]) {
      first = k;
      break;
    }
  if (first == m.size()) return out;
  const Eigen::Vector2i start(static_cast<int>(first % static_cast<std::size_t>(nx)),
                              static_cast<int>(first / static_cast<std::size_t>(nx)));
  const Eigen::Vector2i start_back(start.x() - 1, start.y());
  Eigen::Vector2i p = start, b = start_back, second(-1, -1);
  out.push_back(p);
  const std::size_t cap = 4 * m.size() + 16;
  for (std::size_t step = 0; step < cap; ++step) {
    const int k0 = dir(b.x() - p.x(), b.y() - p.y());
    int found = -1;
    for (int t = 1; t <= 8; ++t) {
      const int k = (k0 + t) % 8;
      if (fg(p.x() + ox[k], p.y() + oy[k])) {
        found = k;
        break;
      }
    }
    if (found < 0) break;  // isolated pixel
    const Eigen::Vector2i c(p.x() + ox[found], p.y() + oy[found]);
    // Stop when the first move (start → second pixel) would be repeated: the contour is closed.
    if (p == start && step > 0 && c == second) break;
    if (step == 0) second = c;
    const int kb = (found + 7) % 8;
    b = Eigen::Vector2i(p.x() + ox[kb], p.y() + oy[kb]);
    p = c;
    if (p == start) continue;  // back at the start: decide on the next move
    out.push_back(p);
  }
  return out;
}

std::vector<Vec2> boundaryEdgePoints(const TopViewImage& g, const Mask& m,
                                     const std::vector<Eigen::Vector2i>& boundary) {
  checkMask(m, g.nx, g.ny, "boundaryEdgePoints");
  static const int di[4] = {-1, 0, 1, 0}, dj[4] = {0, 1, 0, -1};  // W, N, E, S
  std::set<std::size_t> seen;
  std::vector<Vec2> pts;
  for (const auto& q : boundary) {
    for (int d = 0; d < 4; ++d) {
      const int a = q.x() + di[d], b = q.y() + dj[d];
      if (inside(a, b, g.nx, g.ny) && m[static_cast<std::size_t>(b) * g.nx + a]) continue;
      const std::size_t key = g.index(q.x(), q.y()) * 4 + static_cast<std::size_t>(d);
      if (!seen.insert(key).second) continue;
      pts.push_back(g.pixelCentre(q.x(), q.y()) + 0.5 * g.pixel * Vec2(di[d], dj[d]));
    }
  }
  return pts;
}

}  // namespace paddy::measure
