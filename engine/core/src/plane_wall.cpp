#include <paddy/errors.hpp>
#include <paddy/plane_wall.hpp>

namespace paddy {

PlaneWall::PlaneWall(std::string name, int material, const Vec3& origin, const Vec3& normal, const Vec3& velocity)
    : name_(std::move(name)), material_(material), origin0_(origin), velocity_(velocity) {
  if (!(normal.norm() > 0.0) || !normal.allFinite()) throw InputError("plane wall '" + name_ + "': normal must be non-zero");
  if (!origin.allFinite() || !velocity.allFinite()) throw InputError("plane wall '" + name_ + "': origin and velocity must be finite");
  normal_ = normal.normalized();
}

void PlaneWall::buildCandidates(const ParticleView& p, double range) {
  candidates_.clear();
  const Vec3 o = origin();
  for (std::size_t i = 0; i < p.n; ++i)
    if ((p.position[i] - o).dot(normal_) - p.radius[i] < range) candidates_.push_back(static_cast<std::uint32_t>(i));
}

void PlaneWall::findContacts(const ParticleView& p, double max_gap, std::vector<WallContact>& out) const {
  const Vec3 o = origin();
  for (std::uint32_t i : candidates_) {
    if (i >= p.n) continue;
    const double dist = (p.position[i] - o).dot(normal_);
    const double overlap = p.radius[i] - dist;
    if (overlap <= -max_gap) continue;
    out.push_back({i, 0u, overlap, normal_, p.position[i] - dist * normal_});
  }
}

}  // namespace paddy
