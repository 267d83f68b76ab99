// The candidate physical effects through the whole engine: JKR pull-off of two spheres and of a
// sphere and a plate against 3πγR* (Johnson, Kendall & Roberts 1971, γ the surface energy), the
// liquid bridge's work over its whole range (Willett et al. 2000 force to the Lian et al. 1993
// rupture distance: the neighbour search must reach it), and effects at strength 0 changing no
// bit of a small pile's state.
#include "physics_fixture.hpp"

#include <jkr/jkr.hpp>

#include <paddy/measure/coarse_graining.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

using namespace paddy;

namespace {

const double kR = 1e-3;
const double kPi = std::numbers::pi;

// The overlap at which the JKR force is lowest: t³ = 3/2 in the quartic t⁴ − 2t = δ/ℓ (jkr.hpp).
double jkrMinimumOverlap(double gamma, double r_eff, const MaterialPair& pair) {
  const contact::JkrNormal jkr(pair.e_star, pair.g_star, gamma, false);
  const double t = std::cbrt(1.5);
  return (t * t * t * t - 2.0 * t) * jkr.overlapScale(r_eff);
}

InteractionSpec jkrSpec(double gamma) {
  InteractionSpec spec;
  spec.normal = "jkr";
  spec.damping = "hertz_mindlin";
  spec.tangential = "mindlin";
  spec.params = {{"restitution", 1.0}, {"friction", 0.0}, {"surface_energy", gamma}};
  return spec;
}

// fn of the only contact at the current positions (no step taken).
double onlyContactForce(const Simulation& sim) {
  const auto c = sim.contacts();
  REQUIRE(c.size() == 1);
  return c[0].fn;
}

}  // namespace

TEST_CASE("physics/jkr pull-off: two spheres and a sphere on a plate pull at most 3 pi gamma R*, as coarse graining says",
          "[physics][effects][jkr]") {
  const double gamma = 0.096;
  SECTION("two spheres") {
    const double rs = kR / 2;
    const MaterialPair pair = MaterialPair::of(test::mudMaterial(), test::mudMaterial());
    const double d_min = jkrMinimumOverlap(gamma, rs, pair);
    const double expected = measure::CoarseGraining::jkrPullOffForce(gamma, rs);
    CHECK(expected == Approx(3.0 * kPi * gamma * rs).epsilon(1e-15));
    auto pairForce = [&](double overlap) {
      Simulation sim(test::shippedPlugins());
      const int mud = sim.addMaterial(test::mudMaterial());
      sim.setInteraction(mud, mud, jkrSpec(gamma));
      sim.setGravity(Vec3::Zero());
      sim.addParticle(Vec3(kR - 0.5 * overlap, 0, 0), kR, mud);
      sim.addParticle(Vec3(-kR + 0.5 * overlap, 0, 0), kR, mud);
      return onlyContactForce(sim);
    };
    CHECK(pairForce(d_min) == Approx(-expected).epsilon(1e-9));
    CHECK(pairForce(0.95 * d_min) > pairForce(d_min));  // the neighbours pull less
    CHECK(pairForce(1.05 * d_min) > pairForce(d_min));
  }
  SECTION("sphere on a steel plate (mud_steel_surface_energy)") {
    auto s = test::mudOnSteelFloor(jkrSpec(gamma));
    s.sim->setGravity(Vec3::Zero());
    const MaterialPair pair = MaterialPair::of(test::mudMaterial(), test::steelMaterial());
    const double d_min = jkrMinimumOverlap(gamma, kR, pair);
    s.sim->addParticle(Vec3(0, 0, kR - d_min), kR, s.mud);
    CHECK(onlyContactForce(*s.sim) == Approx(-measure::CoarseGraining::jkrPullOffForce(gamma, kR)).epsilon(1e-9));
  }
}

TEST_CASE("physics/liquid bridge: separating spheres lose Willett's work up to the rupture distance",
          "[physics][effects][liquid_bridge]") {
  const double gamma = 0.072, V = 0.05 * 4.0 / 3.0 * kPi * kR * kR * kR;
  Simulation sim(test::shippedPlugins());
  const int mud = sim.addMaterial(test::mudMaterial());
  InteractionSpec spec;
  spec.normal = "hertz";
  spec.damping = "hertz_mindlin";
  spec.tangential = "";
  spec.extras = {"liquid_bridge"};
  spec.params = {{"restitution", 1.0}, {"bridge_volume", V}, {"surface_tension", gamma}};
  sim.setInteraction(mud, mud, spec);
  sim.setGravity(Vec3::Zero());
  sim.setThreads(1);
  const double v0 = 0.25;  // each sphere; relative speed 0.5 m/s
  sim.addParticle(Vec3(kR, 0, 0), kR, mud, Vec3(v0, 0, 0));    // touching: the bridge forms
  sim.addParticle(Vec3(-kR, 0, 0), kR, mud, Vec3(-v0, 0, 0));
  sim.setTimeStepFraction(0.01);
  const double s_c = std::cbrt(V);  // θ = 0
  // Work of the bridge from s = 0 to s_c (Simpson), Willett's force with R = 2R* = R.
  auto force = [&](double s) {
    const double x = (s / 2.0) * std::sqrt(kR / V);
    return 2.0 * kPi * kR * gamma / (1.0 + 2.1 * x + 10.0 * x * x);
  };
  const int n = 20000;
  double w = force(0.0) + force(s_c);
  for (int k = 1; k < n; ++k) w += (k % 2 ? 4.0 : 2.0) * force(s_c * k / n);
  w *= s_c / (3.0 * n);
  const double ke0 = sim.kineticEnergy();
  double last_attraction_gap = 0.0;
  while (true) {
    sim.step();
    const auto& p = sim.particles();
    const double gap = (p.position[0] - p.position[1]).norm() - 2.0 * kR;
    const auto c = sim.contacts();
    if (!c.empty() && c[0].fn < 0.0) last_attraction_gap = gap;
    if (gap > 1.2 * s_c) break;
    REQUIRE(sim.time() < 0.05);
  }
  CHECK(last_attraction_gap > 0.95 * s_c);  // the pair stayed in the neighbour list to the rupture
  CHECK(last_attraction_gap <= s_c);
  CHECK(ke0 - sim.kineticEnergy() == Approx(w).epsilon(0.01));
}

namespace {
// A 3×3×3 pile of mud spheres dropped on a steel floor: final positions and velocities.
std::vector<Vec3> dropPile(const InteractionSpec& mud_mud, const InteractionSpec& mud_steel) {
  Simulation sim(test::shippedPlugins());
  const int mud = sim.addMaterial(test::mudMaterial());
  const int steel = sim.addMaterial(test::steelMaterial());
  sim.setInteraction(mud, mud, mud_mud);
  sim.setInteraction(mud, steel, mud_steel);
  sim.addWall(std::make_unique<PlaneWall>("floor", steel, Vec3::Zero(), Vec3::UnitZ()));
  sim.setThreads(1);
  unsigned seed = 12345u;
  auto jitter = [&] {
    seed = seed * 1664525u + 1013904223u;
    return (static_cast<double>(seed >> 8) / 16777216.0 - 0.5) * 0.2 * kR;
  };
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        sim.addParticle(Vec3(2.05 * kR * i + jitter(), 2.05 * kR * j + jitter(), kR + 2.05 * kR * k + 0.5 * kR),
                        kR, mud);
  sim.setTimeStepFraction(0.1);
  sim.run(0.03);
  std::vector<Vec3> out;
  const auto& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    out.push_back(p.position[i]);
    out.push_back(p.velocity[i]);
    out.push_back(p.omega[i]);
  }
  return out;
}
}  // namespace

TEST_CASE("physics/effects at strength 0: a pile's state is bit for bit the one without them", "[physics][effects]") {
  InteractionSpec mm = jkrSpec(0.096);
  mm.params = {{"restitution", 0.13}, {"friction", 0.15}, {"surface_energy", 0.096}, {"rolling_friction", 0.1}};
  mm.rolling = "constant_torque";
  InteractionSpec ms;
  ms.normal = "hertz";
  ms.damping = "hertz_mindlin";
  ms.tangential = "mindlin";
  ms.rolling = "constant_torque";
  ms.params = {{"restitution", 0.3}, {"friction", 0.6}, {"rolling_friction", 0.05}};
  const auto base = dropPile(mm, ms);

  InteractionSpec mm0 = mm, ms0 = ms;
  for (InteractionSpec* s : {&mm0, &ms0}) {
    s->extras = {"liquid_bridge", "lubrication", "plastic_adhesion"};
    s->params["bridge_volume"] = 0.0;
    s->params["lubrication_viscosity"] = 0.0;
    s->params["plastic_adhesion"] = 0.0;
  }
  ms0.normal = "jkr";  // mud_steel_surface_energy = 0: JKR with γ = 0 is Hertz
  ms0.params["surface_energy"] = 0.0;
  const auto off = dropPile(mm0, ms0);
  REQUIRE(off.size() == base.size());
  for (std::size_t k = 0; k < base.size(); ++k) REQUIRE((off[k].array() == base[k].array()).all());

  // The comparison notices an effect that is on.
  InteractionSpec mm1 = mm;
  mm1.extras = {"liquid_bridge"};
  mm1.params["bridge_volume"] = 0.05 * 4.0 / 3.0 * kPi * kR * kR * kR;
  const auto on = dropPile(mm1, ms);
  bool differs = false;
  for (std::size_t k = 0; k < base.size(); ++k) differs = differs || !(on[k].array() == base[k].array()).all();
  CHECK(differs);
}
