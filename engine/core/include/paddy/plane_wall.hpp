// PlaneWall: an infinite flat wall {x : (x − origin)·n = 0}, particles on the side n points to.
// Optionally translating at a constant velocity. The simplest Wall; meshes are in plugins/geometry.
#pragma once

#include <paddy/wall.hpp>

namespace paddy {

class PlaneWall final : public Wall {
 public:
  PlaneWall(std::string name, int material, const Vec3& origin, const Vec3& normal,
            const Vec3& velocity = Vec3::Zero());

  std::string name() const override { return name_; }
  int material() const override { return material_; }
  void moveTo(double t) override { time_ = t; }
  Vec3 velocityAt(const Vec3&) const override { return velocity_; }
  Vec3 angularVelocity() const override { return Vec3::Zero(); }
  double displacementSinceListBuild() const override { return velocity_.norm() * std::abs(time_ - build_time_); }
  void buildCandidates(const ParticleView& particles, double range) override;
  void markListBuilt() override { build_time_ = time_; }
  void findContacts(const ParticleView& particles, double max_gap, std::vector<WallContact>& out) const override;
  Vec3 torqueOrigin() const override { return origin(); }

  Vec3 origin() const { return origin0_ + velocity_ * time_; }
  const Vec3& normal() const { return normal_; }

 private:
  std::string name_;
  int material_;
  Vec3 origin0_, normal_, velocity_;
  double time_ = 0.0, build_time_ = 0.0;
  std::vector<std::uint32_t> candidates_;
};

}  // namespace paddy
