// The steady-torque criterion of a vane speed step (steady_torque.hpp) on synthetic signals with
// known answers: a ramp is never steady, a noisy constant becomes steady after min_angle, a slow
// drift and a start-up transient are detected.
#include <paddy/errors.hpp>
#include <paddy/measure/steady_torque.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

using namespace paddy::measure;
using paddy::InputError;
using Catch::Matchers::Contains;

namespace {
constexpr double deg = std::numbers::pi / 180.0;

// Samples every dtheta up to theta_max of torque(θ) + seeded Gaussian noise of std sigma.
template <class F>
void signal(std::vector<double>& a, std::vector<double>& t, double theta_max, double dtheta, F torque,
            double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  a.clear();
  t.clear();
  for (double th = 0.0; th <= theta_max + 1e-12; th += dtheta) {
    a.push_back(th);
    t.push_back(torque(th) + (sigma > 0 ? noise(rng) : 0.0));
  }
}

// Smallest angle (checked at every sample) at which the criterion says steady; -1 if never.
double firstSteadyAngle(const std::vector<double>& a, const std::vector<double>& t, const SteadyTorqueOptions& o) {
  std::vector<double> aa, tt;
  for (std::size_t i = 0; i < a.size(); ++i) {
    aa.push_back(a[i]);
    tt.push_back(t[i]);
    if (steadyTorque(aa, tt, o).steady) return a[i];
  }
  return -1.0;
}
}  // namespace

TEST_CASE("measure: steady torque - a linear ramp is never steady", "[measure][steady]") {
  const SteadyTorqueOptions o;  // 10° windows, 6 compared, 60° minimum
  std::vector<double> a, t;
  // Noise-free ramp (elastic start-up) 0.1 N m per radian on top of 0.05 N m, over two turns.
  signal(a, t, 720 * deg, 0.5 * deg, [](double th) { return 0.05 + 0.1 * th; }, 0.0, 1);
  CHECK(firstSteadyAngle(a, t, o) < 0.0);
  const auto r = steadyTorque(a, t, o);
  CHECK_FALSE(r.steady);
  CHECK(r.trend == Approx(0.1).epsilon(1e-9));           // the slope of the ramp
  CHECK(r.trend_p_value < 1e-9);                         // no scatter (but rounding): certain
  CHECK(r.compared_windows == 6);
  // The same ramp in noise: the trend is still found (p < 0.05) at every angle past the minimum.
  signal(a, t, 720 * deg, 0.5 * deg, [](double th) { return 0.05 + 0.1 * th; }, 0.01, 7);
  CHECK(firstSteadyAngle(a, t, o) < 0.0);
}

TEST_CASE("measure: steady torque - a noisy constant becomes steady after the minimum angle", "[measure][steady]") {
  SteadyTorqueOptions o;
  std::vector<double> a, t;
  signal(a, t, 360 * deg, 0.5 * deg, [](double) { return 0.2; }, 0.02, 11);
  const double first = firstSteadyAngle(a, t, o);
  REQUIRE(first > 0.0);
  CHECK(first >= o.min_angle);          // not before the minimum rotation ...
  CHECK(first < o.min_angle + 30 * deg);  // ... but soon after it (a few windows at most)
  const auto r = steadyTorque(a, t, o);
  CHECK(r.mean == Approx(0.2).margin(3 * r.standard_error + 1e-12));
  // Batch means of 20 samples of std 0.02: standard error of the mean of 6 ≈ 0.02/sqrt(120).
  CHECK(r.standard_error == Approx(0.02 / std::sqrt(120.0)).epsilon(0.6));
  // Not before min_angle even though a constant is steady from the first windows on.
  o.min_angle = 120 * deg;
  CHECK(firstSteadyAngle(a, t, o) >= 120 * deg);
}

TEST_CASE("measure: steady torque - a slow drift is detected", "[measure][steady]") {
  const SteadyTorqueOptions o;
  std::vector<double> a, t;
  // +3 % of the torque per 10° window, in noise of 2 %: over 6 windows an 18 % change.
  signal(a, t, 720 * deg, 0.5 * deg, [](double th) { return 0.2 * (1 + 0.03 * th / (10 * deg)); }, 0.004, 5);
  CHECK(firstSteadyAngle(a, t, o) < 0.0);
  // Half a per cent per window (3 % over the windows, within the 5 % tolerance) but resolved:
  // noise 0.1 % → the t test alone finds it.
  signal(a, t, 720 * deg, 0.5 * deg, [](double th) { return 0.2 * (1 + 0.005 * th / (10 * deg)); }, 0.0002, 9);
  const auto r = steadyTorque(a, t, o);
  CHECK(r.drift < o.drift_tolerance);
  CHECK(r.trend_p_value < o.alpha);
  CHECK_FALSE(r.steady);
  CHECK_THAT(r.reason, Contains("trend"));
}

TEST_CASE("measure: steady torque - the start-up transient is left behind", "[measure][steady]") {
  // Saturating start-up T = 0.2 (1 − exp(−θ/θc)), θc = 15°, noise 1 %: steady only once the
  // compared windows are past the rise, and the mean is then the plateau.
  const SteadyTorqueOptions o;
  std::vector<double> a, t;
  const double thc = 15 * deg;
  signal(a, t, 360 * deg, 0.5 * deg, [&](double th) { return 0.2 * (1 - std::exp(-th / thc)); }, 0.002, 3);
  const double first = firstSteadyAngle(a, t, o);
  REQUIRE(first > 0.0);
  CHECK(first > 90 * deg);  // at 60° the windows 0-60° still hold the rise
  std::size_t n = 0;
  while (a[n] < first) ++n;
  std::vector<double> aa(a.begin(), a.begin() + std::ptrdiff_t(n + 1));
  std::vector<double> tt(t.begin(), t.begin() + std::ptrdiff_t(n + 1));
  const auto r = steadyTorque(aa, tt, o);
  REQUIRE(r.steady);
  CHECK(r.mean == Approx(0.2).epsilon(0.05));
}

TEST_CASE("measure: steady torque - bad input is named", "[measure][steady]") {
  SteadyTorqueOptions o;
  o.windows = 2;
  CHECK_THROWS_WITH(steadyTorque({0, 1}, {1, 1}, o), Contains("windows = 2"));
  o = {};
  o.window_angle = 0;
  CHECK_THROWS_WITH(steadyTorque({0, 1}, {1, 1}, o), Contains("window_angle"));
  CHECK_THROWS_WITH(steadyTorque({0, 1}, {1}, {}), Contains("2 angles but 1 torques"));
  CHECK_THROWS_WITH(steadyTorque({0, 0.5, 0.4}, {1, 1, 1}, {}), Contains("decreases"));
  CHECK_THROWS_WITH(steadyTorque({0, NAN}, {1, 1}, {}), Contains("finite"));
  // Sampled every 30° with 10° windows: windows without samples.
  CHECK_THROWS_WITH(steadyTorque({0, 30 * deg, 60 * deg, 90 * deg}, {1, 1, 1, 1}, {}), Contains("no sample"));
  const auto r = steadyTorque({}, {}, {});
  CHECK_FALSE(r.steady);
}
