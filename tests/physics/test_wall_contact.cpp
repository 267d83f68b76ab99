// A sphere on a steel plane: restitution, Coulomb sliding to rolling, rolling resistance.
#include "physics_fixture.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

using namespace paddy;

namespace {
// Settles a sphere of radius R on the floor (no gravity needed later) and returns its set-up.
test::FloorSetup restingSphere(const InteractionSpec& spec, double R, const Vec3& v, const Vec3& w) {
  auto s = test::mudOnSteelFloor(spec);
  s.sim->addParticle(Vec3(0, 0, R), R, s.mud);
  s.sim->setTimeStepFraction(0.05);
  // Settle under gravity until the bounce has died out.
  s.sim->run(0.3);
  auto& p = s.sim->particles();
  p.velocity[0] = v;
  p.omega[0] = w;
  return s;
}
}  // namespace

TEST_CASE("restitution against a wall matches the setting within 1 %", "[physics][restitution]") {
  for (double e : {0.1, 0.5, 0.9}) {
    auto s = test::mudOnSteelFloor(test::hertzMindlin(e, 0.0));
    const double R = 1e-3, v0 = 0.5;
    s.sim->setGravity(Vec3::Zero());
    s.sim->setTimeStepFraction(0.02);  // see docs/physics.md for the error at larger steps
    s.sim->addParticle(Vec3(0, 0, R + 1e-5), R, s.mud, Vec3(0, 0, -v0));
    s.sim->run(2e-3);
    const double v1 = s.sim->particles().velocity[0].z();
    INFO("target e = " << e << ", measured " << v1 / v0);
    REQUIRE(s.sim->contacts().empty());
    REQUIRE(v1 / v0 == Approx(e).epsilon(0.01));
  }
}

TEST_CASE("a sliding sphere decelerates at mu g and ends rolling at 5/7 v0", "[physics][coulomb]") {
  const double R = 1e-3, mu = 0.3, v0 = 0.2, g = 9.81;
  auto s = restingSphere(test::hertzMindlin(0.3, mu), R, Vec3(v0, 0, 0), Vec3::Zero());
  auto& sim = *s.sim;
  // Pure sliding phase lasts t* = 2 v0 / (7 mu g); check the deceleration before it ends.
  const double t_star = 2.0 * v0 / (7.0 * mu * g);
  const double t0 = sim.time();
  sim.run(0.5 * t_star);
  const double t = sim.time() - t0;
  const double v = sim.particles().velocity[0].x();
  REQUIRE(v == Approx(v0 - mu * g * t).epsilon(0.01));
  // Angular velocity grows at 5 mu g / (2 R) about +y (rolling in +x).
  REQUIRE(sim.particles().omega[0].y() == Approx(5.0 * mu * g * t / (2.0 * R)).epsilon(0.02));
  sim.run(2.0 * t_star);
  REQUIRE(sim.particles().velocity[0].x() == Approx(5.0 / 7.0 * v0).epsilon(0.01));
  REQUIRE(sim.particles().omega[0].y() * R == Approx(5.0 / 7.0 * v0).epsilon(0.01));
}

TEST_CASE("rolling resistance stops a rolling sphere at the closed-form distance", "[physics][rolling]") {
  // Constant torque mu_r F_n R opposing the rotation: a = 5/7 mu_r g, distance v0^2 / (2 a).
  const double R = 1e-3, mu_r = 0.1, v0 = 0.05, g = 9.81;
  for (const char* model : {"constant_torque", "elastic_plastic"}) {
    auto spec = test::hertzMindlin(0.3, 0.5);
    spec.rolling = model;
    spec.params["rolling_friction"] = mu_r;
    auto s = restingSphere(spec, R, Vec3(v0, 0, 0), Vec3(0, v0 / R, 0));
    auto& sim = *s.sim;
    const double x0 = sim.particles().position[0].x();
    const double a = 5.0 / 7.0 * mu_r * g;
    const double t_stop = v0 / a;
    sim.run(1.5 * t_stop);
    const double dist = sim.particles().position[0].x() - x0;
    INFO(model << ": distance " << dist << " expected " << v0 * v0 / (2 * a));
    REQUIRE(dist == Approx(v0 * v0 / (2.0 * a)).epsilon(0.03));
    REQUIRE(std::abs(sim.particles().velocity[0].x()) < 0.01 * v0);
    if (std::string(model) == "constant_torque") {
      // Once stopped, the type A torque holds the sphere: no rotation at all (an explicit
      // −R ω/|ω| would flip ω every step), and it does not creep.
      sim.run(0.2);
      REQUIRE(sim.particles().omega[0].norm() == 0.0);
      const double x1 = sim.particles().position[0].x();
      sim.run(0.2);
      REQUIRE(std::abs(sim.particles().position[0].x() - x1) < 1e-9 * R);
    }
  }
}

namespace {
double rollDownIncline(double tan_theta, double mu_r, double dt_fraction, double duration, Vec3* omega_out,
                       double* half_way = nullptr) {
  return test::rollDownIncline("constant_torque", tan_theta, mu_r, dt_fraction, duration, omega_out, half_way);
}
}  // namespace

TEST_CASE("type A rolling friction on an incline: holds below tan θ = μ_r, closed-form roll above, "
          "independent of the time step", "[physics][rolling]") {
  const double R = 1e-3, mu_r = 0.1, g = 9.81;
  Vec3 w;
  // Below the limit: torque balance about the contact, m g sinθ r_c < μ_r m g cosθ r_c.
  for (double frac : {0.2, 0.05}) {
    double half = 0.0;
    const double dist = rollDownIncline(0.5 * mu_r, mu_r, frac, 0.5, &w, &half);
    INFO("dt = " << frac << " T_R: moved " << half << " m in 0.25 s, " << dist << " m in 0.5 s");
    std::printf("[physics] type A on an incline tan = mu_r/2, dt = %.2f T_R: moved %.3e m by 0.25 s, %.3e m by 0.5 s, |w| = %g\n",
                frac, half, dist, w.norm());
    REQUIRE(w.norm() == 0.0);
    // Only the elastic shift of the tangential spring when the slope is applied (F_t / S_t ≈
    // m g sinθ / (8 G* a) ~ 1e-8 m), then no creep at all.
    REQUIRE(std::abs(dist) < 1e-4 * R);
    REQUIRE(std::abs(dist - half) < 1e-12 * R);
  }
  // Above: rolling without slip with the resisting torque, a = g (sinθ − μ_r cosθ) / (1 + I/(m r_c²))
  // (r_c = R − δ/2 ≈ R: 1 + I/(m R²) = 7/5).
  const double tan_theta = 2.0 * mu_r, c = 1.0 / std::sqrt(1.0 + tan_theta * tan_theta);
  const double a = g * (tan_theta * c - mu_r * c) / 1.4, t = 0.1;
  double prev = 0.0;
  for (double frac : {0.2, 0.05}) {
    const double dist = rollDownIncline(tan_theta, mu_r, frac, t, &w);
    INFO("dt = " << frac << " T_R: rolled " << dist << " m, closed form " << 0.5 * a * t * t);
    std::printf("[physics] type A on an incline tan = 2 mu_r, dt = %.2f T_R: %.6e m in %.1f s, closed form %.6e m (%+.2e)\n",
                frac, dist, t, 0.5 * a * t * t, dist / (0.5 * a * t * t) - 1.0);
    REQUIRE(dist == Approx(0.5 * a * t * t).epsilon(0.01));
    REQUIRE(w.y() * R == Approx(a * t).epsilon(0.01));
    if (prev != 0.0) REQUIRE(dist == Approx(prev).epsilon(2e-3));
    prev = dist;
  }
}
