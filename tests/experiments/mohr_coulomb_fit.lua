-- lib/mohr_coulomb.lua's Mohr–Coulomb fit τ = c + σ tanφ (the vane depth series of
-- validation/yield_stress.lua) and the overburden σ_v = ρ_p φ g z, on torques with known answers.
local mohr_coulomb = require("lib.mohr_coulomb")
local measure = require("paddy.measure")
local check = require("checks").check
local function near(a, b, tol) return math.abs(a - b) <= tol end

-- The overburden: 1680 kg/m³ particles at φ = 0.5, 60 mm deep → 1680·0.5·9.81·0.06 Pa.
local sv = mohr_coulomb.overburden{particle_density = 1680, solid_fraction = 0.5, depth = 0.06}
check(near(sv, 494.424, 1e-9), "overburden %.17g", sv)
for _, bad in ipairs({{particle_density = 1680, solid_fraction = 0.5, depth = 0},
                      {particle_density = 1680, solid_fraction = 0.5, depth = -0.01},
                      {particle_density = 1680, solid_fraction = 1.2, depth = 0.06},
                      {particle_density = 0, solid_fraction = 0.5, depth = 0.06}}) do
  check(not pcall(mohr_coulomb.overburden, bad), "overburden accepted a non-positive or impossible input")
end

-- Janssen: λ = R/(2Kμ) = 0.05/(2·0.5·0.6) m; σ = ρ_b g λ (1 − e^(−z/λ)); K μ = 0 is hydrostatic;
-- a short depth (z ≪ λ) is nearly hydrostatic, a deep one tends to ρ_b g λ.
local jan = {lateral_ratio = 0.5, wall_friction = 0.6, radius = 0.05}
local lambda = 0.05 / 0.6
local sj = mohr_coulomb.overburden{particle_density = 1680, solid_fraction = 0.5, depth = 0.06, janssen = jan}
check(near(sj, 1680 * 0.5 * 9.81 * lambda * (1 - math.exp(-0.06 / lambda)), 1e-9), "Janssen %.17g", sj)
check(sj < sv, "Janssen %.6g below hydrostatic %.6g", sj, sv)
sj = mohr_coulomb.overburden{particle_density = 1680, solid_fraction = 0.5, depth = 0.06,
                         janssen = {lateral_ratio = 0, wall_friction = 0.6, radius = 0.05}}
check(sj == sv, "K = 0: hydrostatic, got %.17g", sj)
sj = mohr_coulomb.overburden{particle_density = 1680, solid_fraction = 0.5, depth = 1e-6, janssen = jan}
check(near(sj / (1680 * 0.5 * 9.81 * 1e-6), 1, 1e-4), "shallow Janssen not hydrostatic")
sj = mohr_coulomb.overburden{particle_density = 1680, solid_fraction = 0.5, depth = 10, janssen = jan}
check(near(sj, 1680 * 0.5 * 9.81 * lambda, 1e-6), "deep Janssen %.17g", sj)
check(not pcall(mohr_coulomb.overburden, {particle_density = 1680, solid_fraction = 0.5, depth = 0.06,
                                      janssen = {lateral_ratio = -1, wall_friction = 0.6, radius = 0.05}}),
      "accepted a negative lateral stress ratio")

-- Synthetic vane torques from a known material: c = 180 Pa, tanφ = 1.3, at three depths (fill
-- levels above blades 30–90 mm high in a 50 mm vane), through the vane relation both ways.
local vane = {diameter = 0.05, height = 0.06, cup_diameter = 0.1, sheared_ends = 2}
local factor = measure.vane_torque_factor(vane)
local c0, t0 = 180, 1.3
local sigma, tau = {}, {}
for k, fill in ipairs({0.102, 0.12, 0.15}) do
  sigma[k] = mohr_coulomb.overburden{particle_density = 1680, solid_fraction = 0.52, depth = fill - 0.06}
  local torque = (c0 + t0 * sigma[k]) * factor
  tau[k] = measure.vane_shear_stress(vane, torque)
end
local f = mohr_coulomb.fit{sigma = sigma, tau = tau}
check(near(f.c, c0, 1e-8) and near(f.tan_phi, t0, 1e-11), "exact: c = %.17g, tan phi = %.17g", f.c, f.tan_phi)
check(f.n == 3 and f.dof == 1, "n = %s, dof = %s", tostring(f.n), tostring(f.dof))
check(f.se_c < 1e-8 and f.se_tan_phi < 1e-11, "exact data: standard errors %.3g, %.3g", f.se_c, f.se_tan_phi)
check(near(f.r2, 1, 1e-12), "r2 = %.17g", f.r2)

-- With scatter (two seeds, ± 40 Pa alternating): the closed form of least squares on
-- x = 100, 200, 300 twice, y = 50 + 2x ± 40: slope 2 exactly (the ± cancels per x), intercept
-- 50 + (mean of the ±) = 50; s² = SSE/(n−2) = 6·1600/4 = 2400; Sxx = 2·(100² + 0 + 100²) = 40000;
-- se(tanφ) = √(2400/40000), se(c) = √2400 · √(1/6 + 200²/40000).
local xs, ys = {100, 200, 300, 100, 200, 300}, {}
for k, x in ipairs(xs) do ys[k] = 50 + 2 * x + (k <= 3 and 40 or -40) end
f = mohr_coulomb.fit{sigma = xs, tau = ys}
check(near(f.c, 50, 1e-10) and near(f.tan_phi, 2, 1e-12), "scatter: c = %.17g, tan phi = %.17g", f.c, f.tan_phi)
check(near(f.se_tan_phi, math.sqrt(2400 / 40000), 1e-12), "se tan phi %.17g", f.se_tan_phi)
check(near(f.se_c, math.sqrt(2400) * math.sqrt(1 / 6 + 1), 1e-10), "se c %.17g", f.se_c)
-- Pure friction (c = 0) is found as such, and a strength independent of the pressure as tanφ = 0.
f = mohr_coulomb.fit{sigma = {300, 450, 700}, tau = {0.8 * 300, 0.8 * 450, 0.8 * 700}}
check(near(f.c, 0, 1e-9) and near(f.tan_phi, 0.8, 1e-13), "frictional: c = %.3g, tan phi = %.17g", f.c, f.tan_phi)
f = mohr_coulomb.fit{sigma = {300, 450, 700}, tau = {210, 210, 210}}
check(near(f.c, 210, 1e-10) and near(f.tan_phi, 0, 1e-14), "cohesive: c = %.17g, tan phi = %.3g", f.c, f.tan_phi)
-- Two points: the exact line, no standard errors.
f = mohr_coulomb.fit{sigma = {100, 300}, tau = {150, 250}}
check(near(f.c, 100, 1e-12) and near(f.tan_phi, 0.5, 1e-15) and f.se_c == nil and f.dof == 0, "two points")

-- Refusals: fewer than 2 depths, one overburden only, a non-positive or non-finite stress, unequal lengths.
local function refuses(args, what, pattern)
  local ok, msg = pcall(mohr_coulomb.fit, args)
  check(not ok, "accepted %s", what)
  check(tostring(msg):find(pattern), "%s: message '%s' lacks '%s'", what, tostring(msg), pattern)
end
refuses({sigma = {300}, tau = {500}}, "one point", "at least 2")
refuses({sigma = {}, tau = {}}, "no point", "at least 2")
refuses({sigma = {300, 300, 300}, tau = {400, 500, 450}}, "one overburden", "distinct")
refuses({sigma = {0, 300}, tau = {100, 500}}, "zero stress", "positive")
refuses({sigma = {-100, 300}, tau = {100, 500}}, "negative stress", "positive")
refuses({sigma = {0 / 0, 300}, tau = {100, 500}}, "NaN stress", "positive")
refuses({sigma = {math.huge, 300}, tau = {100, 500}}, "infinite stress", "positive")
refuses({sigma = {100, 300}, tau = {100, 0 / 0}}, "NaN shear stress", "finite")
refuses({sigma = {100, 300}, tau = {100}}, "unequal lengths", "shear stresses")
refuses({sigma = nil, tau = {100}}, "no sigma", "needs sigma")

-- lib/line_fit.lua, the line under both: three points worked by hand. x = -1, 0, 1; y = 0, 1, 5:
-- x̄ = 0, ȳ = 2, Sxx = 2, Sxy = 5 → b = 2.5, a = 2; residuals 0.5, −1, 0.5, SSE = 1.5 on 1 dof;
-- se(b) = √(1.5/2), se(a) = √(1.5/3), se at x0 = 2: √(1.5 (1/3 + 4/2)) = √3.5.
local line_fit = require("lib.line_fit")
local l = line_fit.fit{x = {-1, 0, 1}, y = {0, 1, 5}}
check(near(l.a, 2, 1e-14) and near(l.b, 2.5, 1e-14), "line: a = %.17g, b = %.17g", l.a, l.b)
check(near(l.se_b, math.sqrt(0.75), 1e-14) and near(l.se_a, math.sqrt(0.5), 1e-14), "line se: %.17g, %.17g", l.se_a, l.se_b)
local v2, se2 = line_fit.at(l, 2)
check(near(v2, 7, 1e-13) and near(se2, math.sqrt(3.5), 1e-13), "line at 2: %.17g +- %.17g", v2, se2)
check(near(l.residuals[2], -1, 1e-14) and near(l.r2, 1 - 1.5 / 14, 1e-14), "line residuals / r2")
-- A line through negative and zero x is fine for the line (not for Mohr–Coulomb), an exact pair has no se.
l = line_fit.fit{x = {0, 0.01}, y = {100, 200}}
check(near(l.b, 10000, 1e-9) and l.se_a == nil and select(2, line_fit.at(l, 0.002)) == nil, "two points: exact line, no se")
for _, bad in ipairs({{x = {1}, y = {2}}, {x = {1, 1}, y = {2, 3}}, {x = {1, 2}, y = {2, 0 / 0}}, {x = {1, 2}, y = {2}}}) do
  check(not pcall(line_fit.fit, bad), "line_fit accepted a bad input")
end
local ok, msg = pcall(line_fit.fit, {x = {1, 2}, y = {2, math.huge}, what = "vane yield stress"})
check(not ok and tostring(msg):find("vane yield stress: y%[2%]"), "line_fit error names the fit and the point: %s", tostring(msg))

-- mohr_coulomb.envelope: two seeds on exact lines τ = 100 + 0.5 σ (seed 1) and τ = 140 + 0.5 σ
-- (seed 2) at σ = 200, 400: per seed c = 100, 140; pooled through the four points c = 120,
-- tanφ = 0.5 (the seeds' mean line), residuals ±20 → SSE = 1600 on 2 dof, s² = 800, Sxx = 40 000,
-- σ̄ = 300: se(c) = √(800 (1/4 + 9/4)) = √2000; c / τ_slump per seed 100/80, 140/100; pooled 120/90.
-- A third seed with one point has no line of its own (its error reported), but counts in the pool
-- when it sits on the pooled line (σ = 300, τ = 270).
local env = mohr_coulomb.envelope{points = {{seed = 2, sigma = 200, tau = 240}, {seed = 1, sigma = 200, tau = 200},
                                  {seed = 1, sigma = 400, tau = 300}, {seed = 2, sigma = 400, tau = 340}},
                        slump_of = {[1] = 80, [2] = 100}, slump_mean = 90, target = 0.25}
check(#env.per_seed == 2 and env.per_seed[1].seed == 1 and env.per_seed[2].seed == 2, "envelope: seeds in order")
check(near(env.per_seed[1].fit.c, 100, 1e-12) and near(env.per_seed[2].fit.c, 140, 1e-12), "envelope: per-seed c")
check(near(env.pooled.c, 120, 1e-12) and near(env.pooled.tan_phi, 0.5, 1e-12), "envelope: pooled %.17g, %.17g", env.pooled.c, env.pooled.tan_phi)
check(near(env.pooled.se_c, math.sqrt(2000), 1e-12), "envelope: se(c) = %.17g", env.pooled.se_c)
check(near(env.c_over_slump.mean, (1.25 + 1.4) / 2, 1e-12) and near(env.pooled_c_over_slump, 120 / 90, 1e-12), "envelope: ratios")
check(near(env.c_Pa.mean, 120, 1e-12) and near(env.c_Pa.std, math.sqrt(800), 1e-12), "envelope: c over the seeds")
-- c = 120 > 2 √2000 = 89.4: determined; mean ratio 1.325 is outside 25 %.
check(env.c_determined == true and env.c_within_target == false, "envelope: determined, not within target")
env = mohr_coulomb.envelope{points = {{seed = 1, sigma = 200, tau = 200}, {seed = 1, sigma = 400, tau = 300}, {seed = 3, sigma = 300, tau = 250}},
                  slump_of = {[1] = 100}, slump_mean = 100, target = 0.25}
check(env.per_seed[2].fit == nil and tostring(env.per_seed[2].fit_error):find("at least 2"), "envelope: a one-point seed's error")
check(env.pooled.n == 3 and near(env.pooled.c, 100, 1e-12), "envelope: the one point in the pool")
check(env.c_within_target == false or env.c_determined, "envelope: within target only when determined")
-- seeds = {...}: the seeds reported in that order, a seed without points with its fit's error and
-- 0 points; the slopes over the seeds (0.3 and 0.5: mean 0.4, std √0.02) as tan_phi.
env = mohr_coulomb.envelope{points = {{seed = 2, sigma = 200, tau = 240}, {seed = 1, sigma = 200, tau = 200},
                              {seed = 1, sigma = 400, tau = 300}, {seed = 2, sigma = 400, tau = 300}},
                            seeds = {2, 5, 1}, slump_of = {[1] = 80, [2] = 100}, slump_mean = 90, target = 0.25}
check(#env.per_seed == 3 and env.per_seed[1].seed == 2 and env.per_seed[2].seed == 5 and env.per_seed[3].seed == 1, "envelope: the seeds as given")
check(env.per_seed[2].points == 0 and env.per_seed[2].fit == nil and env.per_seed[2].fit_error ~= nil, "envelope: a seed without points")
check(env.per_seed[1].points == 2 and near(env.per_seed[1].fit.tan_phi, 0.3, 1e-12), "envelope: seed 2's line")
check(near(env.tan_phi.mean, 0.4, 1e-12) and near(env.tan_phi.std, math.sqrt(0.02), 1e-12) and #env.tan_phi.values == 2,
      "envelope: tan_phi over the seeds %.17g, %.17g", env.tan_phi.mean, env.tan_phi.std)

paddy.result{ok = true}
