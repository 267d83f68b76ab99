// MeshWall: see mesh_wall.hpp for the contact algorithm, the region keys and the candidate grid.
#include <paddy/util/union_find.hpp>
#include <paddy/errors.hpp>
#include <paddy/geometry/closest_point.hpp>
#include <paddy/geometry/mesh_check.hpp>
#include <paddy/geometry/mesh_wall.hpp>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace paddy {
using geometry::TriFeature;

struct MeshWall::Hit {
  std::uint32_t tri = 0;
  std::uint32_t region = 0;
  TriFeature feature = TriFeature::Face;
  double d = 0.0;        // |centre − q|
  double overlap = 0.0;  // radius − d (radius + d for a centre inside a solid)
  Vec3 q = Vec3::Zero(), n = Vec3::Zero();  // closest point, normal (wall → centre), body frame
  std::uint32_t key = 0;
};

struct MeshWall::Grid {
  Vec3 lo = Vec3::Zero();
  double h = 0.0;
  int nx = 0, ny = 0, nz = 0;
  double built_for = 0.0;  // query radius the cell size was chosen for
  std::vector<std::uint32_t> start, items;
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(ny) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(nx) + static_cast<std::size_t>(i);
  }
};

namespace {
constexpr double kPi = 3.14159265358979323846;
// Below this many particles (candidate search) or candidates (contacts) a wall's search runs on
// one thread: a parallel region costs a few µs, about as much as ~100 candidates.
constexpr long kParallelMin = 256;
double cosDeg(double deg) { return std::cos(deg * kPi / 180.0); }

using DisjointSets = paddy::UnionFind<std::uint32_t>;
}  // namespace

MeshWall::MeshWall(std::string name, int material, TriangleMesh body_mesh, const geometry::Pose& placement,
                   geometry::Kinematics kinematics, const MeshWallOptions& options)
    : name_(std::move(name)), material_(material), mesh_(std::move(body_mesh)), opt_(options),
      motion_(placement, std::move(kinematics)) {
  geometry::MeshCheckOptions check;
  check.source = "mesh wall '" + name_ + "'";
  geometry::validateMesh(mesh_, check);
  if (!placement.x.allFinite() || !placement.R.allFinite() ||
      (placement.R * placement.R.transpose() - Eigen::Matrix3d::Identity()).norm() > 1e-9 ||
      placement.R.determinant() < 0.0)
    throw InputError(check.source + ": the placement must be a finite proper rotation and translation");
  checkRange(check.source + " region_angle_deg", opt_.region_angle_deg, 0.0, 90.0, "deg");
  checkRange(check.source + " cluster_angle_deg", opt_.cluster_angle_deg, 0.0, 180.0, "deg");
  checkRange(check.source + " merge_angle_deg", opt_.merge_angle_deg, 0.0, 90.0, "deg");
  buildTopology();
  moveTo(0.0);
  pose_at_build_ = state_.pose;
}

MeshWall::~MeshWall() = default;

// ---- topology ---------------------------------------------------------------------------------
void MeshWall::buildTopology() {
  const std::size_t nt = mesh_.triangles.size(), nv = mesh_.vertices.size();
  tri_normal_.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) tri_normal_[t] = geometry::triangleNormal(mesh_, t);

  // Edge records (key, triangle, local edge), sorted so equal edges are adjacent.
  struct Rec { std::uint64_t key; std::uint32_t tri; std::uint8_t k; };
  std::vector<Rec> recs;
  recs.reserve(3 * nt);
  for (std::size_t t = 0; t < nt; ++t)
    for (std::uint8_t k = 0; k < 3; ++k) {
      std::uint32_t a = mesh_.triangles[t][k], b = mesh_.triangles[t][(k + 1) % 3];
      if (a > b) std::swap(a, b);
      recs.push_back({(static_cast<std::uint64_t>(a) << 32) | b, static_cast<std::uint32_t>(t), k});
    }
  std::sort(recs.begin(), recs.end(), [](const Rec& x, const Rec& y) {
    return x.key < y.key || (x.key == y.key && x.tri < y.tri);
  });
  std::vector<std::uint32_t> count(3 * nt, 0);
  std::vector<std::uint8_t> comp_open;
  std::size_t ncomp = 0;
  const auto comp = geometry::connectedComponents(mesh_, &ncomp);
  comp_open.assign(ncomp, 0);
  DisjointSets regions(nt);
  const double cos_region = cosDeg(opt_.region_angle_deg);
  for (std::size_t i = 0; i < recs.size();) {
    std::size_t j = i;
    while (j < recs.size() && recs[j].key == recs[i].key) ++j;
    const std::size_t n = j - i;
    if (n != 2) comp_open[comp[recs[i].tri]] = 1;  // boundary or non-manifold: not a solid
    for (std::size_t a = i; a < j; ++a) count[3 * recs[a].tri + recs[a].k] = static_cast<std::uint32_t>(n - 1);
    if (n == 2) {
      const Rec &r1 = recs[i], &r2 = recs[i + 1];
      // Consistently oriented neighbours traverse the shared edge in opposite directions.
      const bool consistent = mesh_.triangles[r1.tri][r1.k] != mesh_.triangles[r2.tri][r2.k];
      const Vec3 n2 = consistent ? tri_normal_[r2.tri] : Vec3(-tri_normal_[r2.tri]);
      if (tri_normal_[r1.tri].dot(n2) >= cos_region) regions.unite(r1.tri, r2.tri);
    }
    i = j;
  }
  edge_nb_off_.assign(3 * nt + 1, 0);
  for (std::size_t e = 0; e < 3 * nt; ++e) edge_nb_off_[e + 1] = edge_nb_off_[e] + count[e];
  edge_nb_.assign(edge_nb_off_.back(), 0);
  {
    std::vector<std::uint32_t> fill(edge_nb_off_.begin(), edge_nb_off_.end() - 1);
    for (std::size_t i = 0; i < recs.size();) {
      std::size_t j = i;
      while (j < recs.size() && recs[j].key == recs[i].key) ++j;
      for (std::size_t a = i; a < j; ++a)
        for (std::size_t b = i; b < j; ++b)
          if (a != b) edge_nb_[fill[3 * recs[a].tri + recs[a].k]++] = recs[b].tri;
      i = j;
    }
  }
  // Regions: union-find roots → dense ids in order of first triangle.
  region_.assign(nt, 0);
  std::vector<std::uint32_t> label(nt, UINT32_MAX);
  region_count_ = 0;
  for (std::size_t t = 0; t < nt; ++t) {
    const std::uint32_t r = regions.find(static_cast<std::uint32_t>(t));
    if (label[r] == UINT32_MAX) label[r] = static_cast<std::uint32_t>(region_count_++);
    region_[t] = label[r];
  }
  tri_closed_.assign(nt, 0);
  for (std::size_t t = 0; t < nt; ++t) tri_closed_[t] = comp_open[comp[t]] ? 0 : 1;

  // Vertex → triangles.
  vert_tri_off_.assign(nv + 1, 0);
  for (const auto& tri : mesh_.triangles)
    for (auto v : tri) ++vert_tri_off_[v + 1];
  for (std::size_t v = 0; v < nv; ++v) vert_tri_off_[v + 1] += vert_tri_off_[v];
  vert_tri_.assign(vert_tri_off_.back(), 0);
  {
    std::vector<std::uint32_t> fill(vert_tri_off_.begin(), vert_tri_off_.end() - 1);
    for (std::size_t t = 0; t < nt; ++t)
      for (auto v : mesh_.triangles[t]) vert_tri_[fill[v]++] = static_cast<std::uint32_t>(t);
  }
  // Pseudo-normals (Bærentzen & Aanæs 2005): edge = sum of the two face normals; vertex = sum of
  // the incident face normals weighted by the corner angle. Used for closed components only.
  edge_pseudo_.assign(3 * nt, Vec3::Zero());
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      Vec3 s = tri_normal_[t];
      for (std::uint32_t e = edge_nb_off_[3 * t + k]; e < edge_nb_off_[3 * t + k + 1]; ++e) s += tri_normal_[edge_nb_[e]];
      edge_pseudo_[3 * t + k] = s;
    }
  vert_pseudo_.assign(nv, Vec3::Zero());
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh_.vertices[mesh_.triangles[t][k]];
      const Vec3 a = (mesh_.vertices[mesh_.triangles[t][(k + 1) % 3]] - p).normalized();
      const Vec3 b = (mesh_.vertices[mesh_.triangles[t][(k + 2) % 3]] - p).normalized();
      const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
      vert_pseudo_[mesh_.triangles[t][k]] += angle * tri_normal_[t];
    }
  // Bounding sphere about the box centre (for the displacement bound).
  const geometry::Bounds b = geometry::bounds(mesh_);
  bcentre_ = 0.5 * (b.lo + b.hi);
  bradius_ = 0.0;
  for (const Vec3& v : mesh_.vertices) bradius_ = std::max(bradius_, (v - bcentre_).norm());
}

// ---- kinematics -------------------------------------------------------------------------------
void MeshWall::moveTo(double t) {
  time_ = t;
  state_ = motion_.at(t);
}

void MeshWall::setKinematics(geometry::Kinematics k) {
  motion_.reset(std::move(k));
  moveTo(time_);
}

void MeshWall::changeKinematics(double t_switch, geometry::Kinematics k) {
  motion_.change(t_switch, std::move(k));
  moveTo(time_);
}

Vec3 MeshWall::velocityAt(const Vec3& p) const { return state_.velocity + state_.omega.cross(p - state_.axis_point); }
Vec3 MeshWall::angularVelocity() const { return state_.omega; }
Vec3 MeshWall::torqueOrigin() const { return state_.axis_point; }

double MeshWall::displacementSinceListBuild() const {
  // A body point X moves by Δ(X) = (R − R0)X + (x − x0): affine in X, so |Δ| is convex and its
  // maximum over the mesh is at a vertex. Exact for meshes up to 200k vertices; above, the
  // bounding-sphere bound |Δ(c)| + ‖R − R0‖₂ ρ with ‖R − R0‖₂ = sqrt(3 − tr(R R0ᵀ)).
  const Eigen::Matrix3d dR = state_.pose.R - pose_at_build_.R;
  const Vec3 dx = state_.pose.x - pose_at_build_.x;
  // Not turned since the build (a fixed or translating wall): every point moved by dx exactly.
  if ((dR.array() == 0.0).all()) return std::sqrt(dx.squaredNorm());
  if (mesh_.vertices.size() <= 200000) {
    double m2 = 0.0;
    for (const Vec3& v : mesh_.vertices) m2 = std::max(m2, (dR * v + dx).squaredNorm());
    return std::sqrt(m2);
  }
  const double tr = (state_.pose.R * pose_at_build_.R.transpose()).trace();
  return (dR * bcentre_ + dx).norm() + std::sqrt(std::max(0.0, 3.0 - tr)) * bradius_;
}

void MeshWall::markListBuilt() { pose_at_build_ = state_.pose; }

TriangleMesh MeshWall::worldMesh() const {
  TriangleMesh m = mesh_;
  for (Vec3& v : m.vertices) v = state_.pose.apply(v);
  return m;
}

// ---- candidate grid ---------------------------------------------------------------------------
void MeshWall::buildGrid(double query) {
  auto g = std::make_unique<Grid>();
  const geometry::Bounds b = geometry::bounds(mesh_);
  double h = std::max(2.0 * query, 1e-9 * std::max(1.0, b.size().maxCoeff()));
  const Vec3 size = b.size();
  auto dims = [&](double cell) {
    return Eigen::Vector3i(static_cast<int>(std::floor(size.x() / cell)) + 1, static_cast<int>(std::floor(size.y() / cell)) + 1,
                           static_cast<int>(std::floor(size.z() / cell)) + 1);
  };
  while (true) {
    const Eigen::Vector3i d = dims(h);
    if (static_cast<double>(d.x()) * d.y() * d.z() <= 4.0e6) break;
    h *= 1.25;
  }
  const Eigen::Vector3i d = dims(h);
  g->h = h;
  g->nx = d.x();
  g->ny = d.y();
  g->nz = d.z();
  g->lo = b.lo;
  g->built_for = query;
  const double reach = 0.5 * std::sqrt(3.0) * h;  // circumradius of a cell
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (cell, triangle)
  for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
    const auto& tri = mesh_.triangles[t];
    const Vec3 &a = mesh_.vertices[tri[0]], &bb = mesh_.vertices[tri[1]], &c = mesh_.vertices[tri[2]];
    const Vec3 tlo = a.cwiseMin(bb).cwiseMin(c), thi = a.cwiseMax(bb).cwiseMax(c);
    Eigen::Vector3i i0, i1;
    for (int k = 0; k < 3; ++k) {
      i0[k] = std::clamp(static_cast<int>(std::floor((tlo[k] - g->lo[k]) / h)), 0, d[k] - 1);
      i1[k] = std::clamp(static_cast<int>(std::floor((thi[k] - g->lo[k]) / h)), 0, d[k] - 1);
    }
    for (int k = i0.z(); k <= i1.z(); ++k)
      for (int j = i0.y(); j <= i1.y(); ++j)
        for (int i = i0.x(); i <= i1.x(); ++i) {
          const Vec3 centre = g->lo + h * Vec3(i + 0.5, j + 0.5, k + 0.5);
          if (std::abs(tri_normal_[t].dot(centre - a)) > reach) continue;
          if ((geometry::closestPointOnTriangle(centre, a, bb, c).point - centre).norm() > reach) continue;
          pairs.emplace_back(static_cast<std::uint32_t>(g->index(i, j, k)), static_cast<std::uint32_t>(t));
        }
  }
  const std::size_t ncell = static_cast<std::size_t>(d.x()) * d.y() * d.z();
  g->start.assign(ncell + 1, 0);
  for (const auto& p : pairs) ++g->start[p.first + 1];
  for (std::size_t i = 0; i < ncell; ++i) g->start[i + 1] += g->start[i];
  g->items.assign(pairs.size(), 0);
  std::vector<std::uint32_t> fill(g->start.begin(), g->start.end() - 1);
  for (const auto& p : pairs) g->items[fill[p.first]++] = p.second;
  grid_ = std::move(g);
}

void MeshWall::gatherTriangles(const Vec3& xb, double reach, std::vector<std::uint32_t>& tris) const {
  tris.clear();
  if (!grid_) {
    tris.resize(mesh_.triangles.size());
    std::iota(tris.begin(), tris.end(), 0u);
    return;
  }
  const Grid& g = *grid_;
  int lo[3], hi[3];
  const int n[3] = {g.nx, g.ny, g.nz};
  for (int k = 0; k < 3; ++k) {
    const double a = (xb[k] - reach - g.lo[k]) / g.h, b = (xb[k] + reach - g.lo[k]) / g.h;
    if (b < 0.0 || a >= n[k]) return;  // query box outside the grid
    lo[k] = std::max(0, static_cast<int>(std::floor(a)));
    hi[k] = std::min(n[k] - 1, static_cast<int>(std::floor(b)));
  }
  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        const std::size_t c = g.index(i, j, k);
        tris.insert(tris.end(), g.items.begin() + g.start[c], g.items.begin() + g.start[c + 1]);
      }
  std::sort(tris.begin(), tris.end());
  tris.erase(std::unique(tris.begin(), tris.end()), tris.end());
}

void MeshWall::buildCandidates(const ParticleView& p, double range) {
  double rmax = 0.0;
  for (std::size_t i = 0; i < p.n; ++i) rmax = std::max(rmax, p.radius[i]);
  const double query = rmax + std::max(range, 0.0);
  if (!grid_ || query > 2.0 * grid_->built_for || query < 0.25 * grid_->built_for) buildGrid(query);

  const int nthreads = std::max(1, p.threads);
  std::vector<std::vector<std::uint32_t>> lpart(static_cast<std::size_t>(nthreads)), lcount(static_cast<std::size_t>(nthreads)),
      ltri(static_cast<std::size_t>(nthreads));
  const long n = static_cast<long>(p.n);
  // The simulation's threads, static chunks in thread order: the lists come out in particle order
  // whatever the thread count.
#pragma omp parallel num_threads(nthreads) if (n >= kParallelMin)
  {
    const auto tid = static_cast<std::size_t>(omp_get_thread_num());
    std::vector<std::uint32_t> tris;
#pragma omp for schedule(static)
    for (long i = 0; i < n; ++i) {
      const Vec3 xb = state_.pose.toBody(p.position[i]);
      const double reach = p.radius[i] + range;
      gatherTriangles(xb, reach, tris);
      std::uint32_t kept = 0;
      for (std::uint32_t t : tris) {
        const auto& tri = mesh_.triangles[t];
        const auto cp = geometry::closestPointOnTriangle(xb, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]);
        if ((cp.point - xb).squaredNorm() <= reach * reach) {
          ltri[tid].push_back(t);
          ++kept;
        }
      }
      if (kept) {
        lpart[tid].push_back(static_cast<std::uint32_t>(i));
        lcount[tid].push_back(kept);
      }
    }
  }
  cand_particle_.clear();
  cand_off_.assign(1, 0);
  cand_tri_.clear();
  for (std::size_t t = 0; t < lpart.size(); ++t) {
    cand_particle_.insert(cand_particle_.end(), lpart[t].begin(), lpart[t].end());
    for (auto c : lcount[t]) cand_off_.push_back(cand_off_.back() + c);
    cand_tri_.insert(cand_tri_.end(), ltri[t].begin(), ltri[t].end());
  }
}

// ---- contacts ---------------------------------------------------------------------------------
bool MeshWall::isLocalMinimum(const Hit& h, const Vec3& xb) const {
  if (h.feature == TriFeature::Face) return true;
  const double eps = 1e-9 * h.d + 1e-15;
  auto closer = [&](std::uint32_t o) {
    if (o == h.tri) return false;
    const auto& tri = mesh_.triangles[o];
    const auto cp = geometry::closestPointOnTriangle(xb, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]);
    return (cp.point - xb).norm() < h.d - eps;
  };
  if (geometry::isEdge(h.feature)) {
    const std::size_t e = 3 * h.tri + static_cast<std::size_t>(geometry::edgeIndex(h.feature));
    for (std::uint32_t k = edge_nb_off_[e]; k < edge_nb_off_[e + 1]; ++k)
      if (closer(edge_nb_[k])) return false;
  } else {
    const std::uint32_t v = mesh_.triangles[h.tri][static_cast<std::size_t>(geometry::vertexIndex(h.feature))];
    for (std::uint32_t k = vert_tri_off_[v]; k < vert_tri_off_[v + 1]; ++k)
      if (closer(vert_tri_[k])) return false;
  }
  return true;
}

void MeshWall::reduce(const Vec3& xb, double radius, std::uint32_t particle, std::vector<Hit>& hits,
                      std::vector<WallContact>& out) const {
  if (hits.empty()) return;
  // Normals and overlaps.
  for (Hit& h : hits) {
    const Vec3 diff = xb - h.q;
    const Vec3& fn = tri_normal_[h.tri];
    const bool closed = tri_closed_[h.tri] != 0;
    if (h.feature == TriFeature::Face) {
      const double s = fn.dot(diff);
      if (closed) {
        h.n = fn;
        h.overlap = radius - s;
      } else {
        h.n = s >= 0.0 ? fn : Vec3(-fn);
        h.overlap = radius - std::abs(s);
      }
    } else {
      Vec3 pseudo = geometry::isEdge(h.feature)
                        ? edge_pseudo_[3 * h.tri + static_cast<std::size_t>(geometry::edgeIndex(h.feature))]
                        : vert_pseudo_[mesh_.triangles[h.tri][static_cast<std::size_t>(geometry::vertexIndex(h.feature))]];
      if (h.d > 1e-12 * radius) {
        h.n = diff / h.d;
        h.overlap = radius - h.d;
        if (closed && diff.dot(pseudo) < 0.0) {
          h.n = -h.n;
          h.overlap = radius + h.d;
        }
      } else {
        h.n = closed && pseudo.norm() > 0.0 ? Vec3(pseudo.normalized()) : fn;
        h.overlap = radius;
      }
    }
  }
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
    return a.region < b.region || (a.region == b.region && (a.d < b.d || (a.d == b.d && a.tri < b.tri)));
  });
  const double cos_cluster = cosDeg(opt_.cluster_angle_deg), cos_merge = cosDeg(opt_.merge_angle_deg);
  // Accepted contacts, compacted to the front of `hits`.
  std::size_t accepted = 0, region_begin = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    if (i == 0 || hits[i].region != hits[i - 1].region) region_begin = accepted;
    Hit& h = hits[i];
    bool absorbed = false;
    for (std::size_t a = region_begin; a < accepted && !absorbed; ++a) absorbed = hits[a].n.dot(h.n) >= cos_cluster;
    if (absorbed || !isLocalMinimum(h, xb)) continue;
    h.key = accepted == region_begin ? h.region : static_cast<std::uint32_t>(region_count_ + h.tri);
    hits[accepted++] = h;
  }
  hits.resize(accepted);
  // Merge across regions: deepest first; a contact within merge angle of a kept one joins it.
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
    return a.overlap > b.overlap || (a.overlap == b.overlap && a.key < b.key);
  });
  std::size_t kept = 0;
  for (std::size_t i = 0; i < hits.size(); ++i) {
    bool merged = false;
    for (std::size_t k = 0; k < kept && !merged; ++k)
      if (hits[k].n.dot(hits[i].n) >= cos_merge) {
        hits[k].key = std::min(hits[k].key, hits[i].key);
        merged = true;
      }
    if (!merged) hits[kept++] = hits[i];
  }
  for (std::size_t k = 0; k < kept; ++k) {
    const Hit& h = hits[k];
    out.push_back({particle, h.key, h.overlap, state_.pose.R * h.n, state_.pose.apply(h.q)});
  }
}

void MeshWall::closestHits(const Vec3& xb, double reach, const std::uint32_t* first, const std::uint32_t* last,
                           std::vector<Hit>& hits) const {
  for (const std::uint32_t* it = first; it != last; ++it) {
    const std::uint32_t t = *it;
    const auto& tri = mesh_.triangles[t];
    const auto cp = geometry::closestPointOnTriangle(xb, mesh_.vertices[tri[0]], mesh_.vertices[tri[1]], mesh_.vertices[tri[2]]);
    const double d = (cp.point - xb).norm();
    if (d >= reach) continue;
    Hit h;
    h.tri = t;
    h.region = region_[t];
    h.feature = cp.feature;
    h.d = d;
    h.q = cp.point;
    hits.push_back(h);
  }
}

void MeshWall::findContacts(const ParticleView& p, double max_gap, std::vector<WallContact>& out) const {
  const long nc = static_cast<long>(cand_particle_.size());
  const int nthreads = std::max(1, p.threads);
  std::vector<std::vector<WallContact>>& local = contacts_per_thread_;
  local.resize(static_cast<std::size_t>(nthreads));
  for (auto& l : local) l.clear();
  // Static chunks in thread order: concatenated, the contacts are in candidate order whatever the
  // thread count.
#pragma omp parallel num_threads(nthreads) if (nc >= kParallelMin)
  {
    const auto tid = static_cast<std::size_t>(omp_get_thread_num());
    std::vector<Hit> hits;
#pragma omp for schedule(static)
    for (long c = 0; c < nc; ++c) {
      const std::uint32_t i = cand_particle_[static_cast<std::size_t>(c)];
      if (i >= p.n) continue;
      const Vec3 xb = state_.pose.toBody(p.position[i]);
      const double r = p.radius[i], reach = r + max_gap;
      hits.clear();
      const std::uint32_t* tris = cand_tri_.data();
      closestHits(xb, reach, tris + cand_off_[static_cast<std::size_t>(c)], tris + cand_off_[static_cast<std::size_t>(c) + 1], hits);
      if (!hits.empty()) reduce(xb, r, i, hits, local[tid]);
    }
  }
  for (auto& l : local)
    for (const WallContact& c : l)
      if (c.overlap > -max_gap) out.push_back(c);
}

void MeshWall::contactsOfSphere(const Vec3& centre, double radius, double max_gap, std::uint32_t particle,
                                std::vector<WallContact>& out) const {
  const Vec3 xb = state_.pose.toBody(centre);
  std::vector<std::uint32_t> tris;
  gatherTriangles(xb, radius + max_gap, tris);
  std::vector<Hit> hits;
  closestHits(xb, radius + max_gap, tris.data(), tris.data() + tris.size(), hits);
  std::vector<WallContact> found;
  reduce(xb, radius, particle, hits, found);
  for (const WallContact& c : found)
    if (c.overlap > -max_gap) out.push_back(c);
}

// ---- loads ------------------------------------------------------------------------------------
void MeshWall::recordLoads(double t) {
  geometry::LoadSample s;
  s.t = t;
  s.force = force();
  s.torque = torque();
  s.axial_torque = axialTorque();
  const geometry::Motion::State m = t == time_ ? state_ : motion_.at(t);
  s.distance = m.distance;
  s.angle = m.angle;
  history_.push_back(s);
}

void MeshWall::writeLoadHistoryCsv(const std::string& path) const { geometry::writeLoadHistoryCsv(path, history_, name_); }

void MeshWall::writeLoadHistoryH5(const std::string& path) const {
  geometry::writeLoadHistoryH5(path, {{name_, &history_}});
}

}  // namespace paddy
