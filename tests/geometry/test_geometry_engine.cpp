// Engine-level wall tests (need the lead's Simulation and the hertz_mindlin plugin): a sphere
// resting on a meshed plate carries its weight (Hertz overlap), rolls down a meshed incline with
// a = 5/7 g sin θ across triangle edges and a 6-triangle vertex, bounces off a meshed plate as off
// the analytic PlaneWall, and a slump cone holds a pile of particles until it is lifted.
#include "../physics/physics_fixture.hpp"

#include <paddy/geometry/mesh_wall.hpp>
#include <paddy/geometry/parts.hpp>
#include <paddy/plane_wall.hpp>
#include <paddy/plugin_manager.hpp>
#include <paddy/simulation.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <random>

using namespace paddy;
using namespace paddy::geometry;

namespace {
constexpr double kPi = 3.14159265358979323846;

std::shared_ptr<PluginManager> plugins() {
  static std::shared_ptr<PluginManager> pm = [] {
    auto m = std::make_shared<PluginManager>();
    const char* dir = std::getenv("PADDY_PLUGIN_PATH");
    m->loadLibrary(std::string(dir ? dir : PADDY_TEST_PLUGIN_DIR) + "/libpaddy_hertz_mindlin.so");
    return m;
  }();
  return pm;
}

using test::hertzMindlin;  // Hertz + Hertz-Mindlin damping + Mindlin, as in the physics tests

const Material kMud = test::mudMaterial();
const Material kSteel = test::steelMaterial();

double eStar() {
  const double e_mud = kMud.youngs(), e_steel = kSteel.youngs();
  return 1.0 / ((1 - 0.25) / e_mud + (1 - 0.09) / e_steel);
}
}  // namespace

TEST_CASE("geometry engine: sphere resting on a meshed plate carries its weight with the Hertz overlap") {
  Simulation sim(plugins());
  const int mud = sim.addMaterial(kMud), steel = sim.addMaterial(kSteel);
  sim.setInteraction(mud, steel, hertzMindlin(0.3, 0.5));
  sim.setInteraction(mud, mud, hertzMindlin(0.3, 0.5));
  PlateParams pp;
  pp.side = 0.02;
  pp.divisions = 4;
  const int w = sim.addWall(std::make_unique<MeshWall>("plate", steel, buildPlate(pp)));
  const double R = 0.001;
  sim.addParticle(Vec3(0.0, 0.0, R), R, mud);  // on the 6-triangle vertex
  sim.setTimeStepFraction(0.2);
  sim.run(0.05);
  const double m = sim.particles().mass[0], g = 9.81;
  const double delta = std::pow(m * g / (4.0 / 3.0 * eStar() * std::sqrt(R)), 2.0 / 3.0);
  CHECK(sim.wall(w).force().z() == Approx(-m * g).epsilon(1e-3));
  CHECK(std::abs(sim.wall(w).force().x()) < 1e-9 * m * g);
  CHECK(sim.particles().position[0].z() == Approx(R - delta).epsilon(1e-6));
  CHECK(R - sim.particles().position[0].z() == Approx(delta).epsilon(0.01));
}

TEST_CASE("geometry engine: sphere rolls down a meshed incline with a = 5/7 g sin(theta)") {
  const double theta = 20.0 * kPi / 180.0, R = 0.001, g = 9.81;
  Simulation sim(plugins());
  const int mud = sim.addMaterial(kMud), steel = sim.addMaterial(kSteel);
  sim.setInteraction(mud, steel, hertzMindlin(0.3, 0.8));
  sim.setInteraction(mud, mud, hertzMindlin(0.3, 0.8));
  Pose place;
  place.R = Eigen::AngleAxisd(theta, Vec3::UnitX()).toRotationMatrix();  // body +y goes uphill
  PlateParams pp;
  pp.side = 0.2;
  pp.divisions = 32;  // 6.25 mm squares: the path crosses edges and the vertex at the origin
  sim.addWall(std::make_unique<MeshWall>("incline", steel, buildPlate(pp), place));
  const Vec3 n = place.R * Vec3::UnitZ(), down = -(place.R * Vec3::UnitY());
  sim.addParticle(place.R * Vec3(0.0, 0.003, 0.0) + R * n, R, mud);
  sim.setTimeStepFraction(0.2);
  const double T = 0.1;
  sim.run(T);
  const double v = sim.particles().velocity[0].dot(down);
  const double a = 5.0 / 7.0 * g * std::sin(theta);
  CHECK(v == Approx(a * T).epsilon(0.02));
  CHECK(std::abs(sim.particles().velocity[0].dot(n)) < 1e-3 * v);
  // Rolling without slip: ω R = v about the axis n × down.
  CHECK(sim.particles().omega[0].dot(n.cross(down)) * R == Approx(v).epsilon(0.02));
  const double s = (sim.particles().position[0] - place.R * Vec3(0.0, 0.003, 0.0)).dot(down);
  CHECK(s == Approx(0.5 * a * T * T).epsilon(0.03));
  CHECK(s > 0.003);  // it went over the vertex at the origin
}

TEST_CASE("geometry engine: bounce on a meshed plate equals the analytic plane wall (restitution)") {
  const double R = 0.001, v0 = 0.5, e = 0.5;
  double rebound[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    Simulation sim(plugins());
    const int mud = sim.addMaterial(kMud), steel = sim.addMaterial(kSteel);
    sim.setInteraction(mud, steel, hertzMindlin(e, 0.5));
    sim.setInteraction(mud, mud, hertzMindlin(e, 0.5));
    sim.setGravity(Vec3::Zero());
    if (k == 0) {
      PlateParams pp;
      pp.side = 0.02;
      pp.divisions = 4;
      sim.addWall(std::make_unique<MeshWall>("plate", steel, buildPlate(pp)));
    } else {
      sim.addWall(std::make_unique<PlaneWall>("plane", steel, Vec3::Zero(), Vec3::UnitZ()));
    }
    sim.addParticle(Vec3(0.0013, 0.0021, R + 1e-5), R, mud, Vec3(0, 0, -v0));
    sim.setTimeStepFraction(0.1);
    sim.run(0.005);
    rebound[k] = sim.particles().velocity[0].z();
  }
  CHECK(rebound[0] == Approx(rebound[1]).epsilon(1e-9));
  CHECK(rebound[0] / v0 == Approx(e).epsilon(0.05));
}

TEST_CASE("geometry engine: the slump cone holds a pile and releases it when lifted at 0.05 m/s") {
  Simulation sim(plugins());
  const int mud = sim.addMaterial(kMud), steel = sim.addMaterial(kSteel);
  sim.setInteraction(mud, steel, hertzMindlin(0.3, 0.5));
  sim.setInteraction(mud, mud, hertzMindlin(0.3, 0.5));
  sim.addWall(std::make_unique<MeshWall>("plate", steel, buildPlate()));
  const int cone_index = sim.addWall(std::make_unique<MeshWall>("cone", steel, buildSlumpCone()));
  const double R = 0.004, h = 0.3, rb = 0.1, rt = 0.05;
  auto coneRadius = [&](double z) { return rb + (rt - rb) * z / h; };
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.05 * R, 0.05 * R);
  for (double z = R * 1.2; z < 0.04; z += 2.2 * R)
    for (double x = -rb; x <= rb; x += 2.2 * R)
      for (double y = -rb; y <= rb; y += 2.2 * R)
        if (std::hypot(x, y) < coneRadius(z) - 1.5 * R) sim.addParticle(Vec3(x + jitter(rng), y + jitter(rng), z), R, mud);
  const std::size_t n = sim.particles().size();
  INFO(n << " particles");
  sim.setTimeStepFraction(0.2);
  sim.run(0.2);
  double max_out = -1e9, min_z = 1e9;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = sim.particles().position[i];
    max_out = std::max(max_out, std::hypot(x.x(), x.y()) + R - coneRadius(x.z()));
    min_z = std::min(min_z, x.z() - R);
  }
  CHECK(max_out < 0.1 * R);   // nobody passed through the cone wall
  CHECK(min_z > -0.1 * R);    // nor through the plate
  // Weight is carried by plate + cone (the pile is quasi-static).
  double weight = 0.0;
  for (double m : sim.particles().mass) weight += m * 9.81;
  const double carried = -(sim.wall(0).force().z() + sim.wall(cone_index).force().z());
  CHECK(carried == Approx(weight).epsilon(0.02));

  double max_r0 = 0.0;
  for (const Vec3& x : sim.particles().position) max_r0 = std::max(max_r0, std::hypot(x.x(), x.y()));

  // Lift the cone: particles flow out under its rim.
  auto& cone = dynamic_cast<MeshWall&>(sim.wall(cone_index));
  const double t_lift = sim.time();
  cone.setKinematics(Kinematics::translation(Vec3(0, 0, 0.05), t_lift));
  sim.run(0.25, [&](Simulation& s) {
    cone.recordLoads(s.time());
    return true;
  }, 0.01);
  CHECK(cone.pose().x.z() == Approx(0.05 * (sim.time() - t_lift)).epsilon(1e-12));
  double max_r = 0.0;
  for (const Vec3& x : sim.particles().position) max_r = std::max(max_r, std::hypot(x.x(), x.y()));
  INFO("pile radius before the lift " << max_r0 << " m, after " << max_r << " m");
  CHECK(max_r > max_r0 + R);
  CHECK(cone.loadHistory().size() >= 25);
}

TEST_CASE("geometry engine: PluginManager loads the geometry plugin and builds its parts") {
  PluginManager pm;
  const char* dir = std::getenv("PADDY_PLUGIN_PATH");
  pm.loadLibrary(std::string(dir ? dir : PADDY_TEST_PLUGIN_DIR) + "/libpaddy_geometry.so");
  const auto names = pm.geometryNames();
  for (const char* n : {"slump_cone", "plate", "cup", "vane"})
    CHECK(std::find(names.begin(), names.end(), std::string(n)) != names.end());
  const GeometryInfo& cone = pm.geometry("slump_cone");
  ParamValues v;
  for (const auto& p : cone.params) v[p.name] = p.default_value;
  v["segments"] = 48;
  const TriangleMesh m = cone.build(v);
  CHECK(m.triangles.size() == 96);
  MeshWall wall("cone", 0, m);
  CHECK(wall.regionCount() == 1);
}
