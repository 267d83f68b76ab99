-- Checks of the discovery workflow's Lua libraries on data with known answers: the exact binomial
-- (Clopper-Pearson) bounds, the scoring of trials, the stacking of observables, the slump
-- observables on synthetic histories and load samples, and the input file's errors.
local score = require("lib.discovery.score")
local stack = require("lib.discovery.stack")
local input = require("lib.discovery.input")
local obs = require("lib.slump_observables")
local function check(cond, fmt, ...)
  if not cond then error(string.format(fmt, ...), 2) end
end
local function near(a, b, tol) return math.abs(a - b) <= tol end

-- Clopper-Pearson, closed forms at the ends: 0 of n → upper 1 - alpha^(1/n); n of n → lower alpha^(1/n).
for _, n in ipairs({20, 30, 50}) do
  local u = score.clopper_pearson_upper(0, n)
  check(near(u, 1 - 0.05 ^ (1 / n), 1e-9), "upper bound 0/%d = %.12g, expected %.12g", n, u, 1 - 0.05 ^ (1 / n))
  local l = score.clopper_pearson_lower(n, n)
  check(near(l, 0.05 ^ (1 / n), 1e-9), "lower bound %d/%d = %.12g, expected %.12g", n, n, l, 0.05 ^ (1 / n))
end
-- The figures of shared/design/discovery-method.md: 0/20 → 13.9 %, 30/30 → 90.5 %, 49/50 → 91.0 % (> 90 %),
-- 48/50 below 90 %, 96/100 above.
check(string.format("%.3f", score.clopper_pearson_upper(0, 20)) == "0.139", "0/20: %.4f", score.clopper_pearson_upper(0, 20))
check(score.clopper_pearson_lower(49, 50) > 0.90 and score.clopper_pearson_lower(48, 50) < 0.90, "49/50 vs 48/50: %.4f %.4f",
      score.clopper_pearson_lower(49, 50), score.clopper_pearson_lower(48, 50))
check(score.clopper_pearson_lower(96, 100) > 0.90 and score.clopper_pearson_lower(95, 100) < 0.90, "96/100 vs 95/100")
-- Interior point against the binomial tail it inverts: P(X >= 7 | 10, p_L) = 0.05.
local pl = score.clopper_pearson_lower(7, 10)
check(near(1 - score.binomial_cdf(6, 10, pl), 0.05, 1e-9), "tail at the lower bound of 7/10: %.12g", 1 - score.binomial_cdf(6, 10, pl))
check(near(score.binomial_cdf(2, 4, 0.5), 11 / 16, 1e-15), "Binomial(4, 1/2) cdf at 2 = %.17g", score.binomial_cdf(2, 4, 0.5))

-- Judging answers.
local names = {a = true, b = true}
check(score.judge({kind = "none"}, "none", names) == true, "null answered none is right")
local right, wrong = score.judge({kind = "none"}, "a", names)
check(not right and wrong, "null answered a is a wrong name")
right, wrong = score.judge({kind = "candidate", name = "a"}, "b", names)
check(not right and wrong, "a answered b is wrong")
check(score.judge({kind = "candidate", name = "a"}, "a", names), "a answered a is right")
right, wrong = score.judge({kind = "outside", name = "x"}, "unknown", names)
check(right and not wrong, "outside answered unknown is right")
right, wrong = score.judge({kind = "outside", name = "x"}, "a", names)
check(not right and wrong, "outside answered a is a wrong name")
check(score.answer({decision = "effect", named_effect = "b"}) == "b" and score.answer({decision = "ambiguous"}) == "ambiguous", "answers")
-- Correct names by visibility: expected z = z_at_high * strength / high, bins [lo, hi), nulls left out.
local vis = score.by_visibility({
  {trial = 1, truth = {kind = "candidate", name = "a", strength = 1}, answer = "none", right = false},  -- z 2
  {trial = 2, truth = {kind = "candidate", name = "b", strength = 0.5}, answer = "a", right = false},   -- z 5, wrong name
  {trial = 3, truth = {kind = "candidate", name = "a", strength = 4}, answer = "a", right = true},     -- z 8
  {trial = 4, truth = {kind = "none"}, answer = "none", right = true},
  {trial = 5, truth = {kind = "candidate", name = "b", strength = 1}, answer = "b", right = true},    -- z 10
}, {a = {z_at_high = 20, high = 10}, b = {z_at_high = 10, high = 1}}, {3, 6}, names)
check(#vis.rows == 4 and vis.rows[1].trial == 1 and vis.rows[1].z_expected == 2 and vis.rows[4].z_expected == 10,
      "visibility rows sorted by expected z")
check(vis.bins[1].trials == 1 and vis.bins[1].right == 0 and vis.bins[2].trials == 1 and vis.bins[2].wrong_names == 1
      and vis.bins[3].trials == 2 and vis.bins[3].right == 2 and near(vis.bins[3].lower95, score.clopper_pearson_lower(2, 2), 0),
      "visibility bins")
check(not pcall(score.by_visibility, {{trial = 1, truth = {kind = "candidate", name = "c", strength = 1}, answer = "none"}},
                {a = {z_at_high = 1, high = 1}}, {3}, names), "a candidate the sensitivity study lacks is refused")
-- By the misfit's p-value: bins [0, 0.001), [0.001, 0.05), [0.05, 1]; an edge value falls in the bin above it.
local mb = score.by_misfit({
  {trial = 1, truth = {kind = "candidate", name = "a"}, answer = "a", right = true, q0_p = 0},
  {trial = 2, truth = {kind = "candidate", name = "b"}, answer = "a", right = false, q0_p = 0.0005},   -- wrong name
  {trial = 3, truth = {kind = "candidate", name = "a"}, answer = "none", right = false, q0_p = 0.3},
  {trial = 4, truth = {kind = "none"}, answer = "none", right = true, q0_p = 0.001},                   -- edge: middle bin
  {trial = 5, truth = {kind = "none"}, answer = "ambiguous", right = false, q0_p = 0.02},              -- a false alarm
  {trial = 6, truth = {kind = "outside"}, answer = "b", right = false, q0_p = 0.9},                    -- a wrong name
  {trial = 7, truth = {kind = "outside"}, answer = "unknown", right = true, q0_p = 1},
}, {0.001, 0.05}, names)
local b1, b2, b3 = mb.bins[1], mb.bins[2], mb.bins[3]
check(#mb.bins == 3 and b1.from == 0 and b1.to == 0.001 and b3.to == 1, "misfit bins' edges")
check(b1.effect.trials == 2 and b1.effect.right == 1 and b1.effect.wrong_names == 1
      and near(b1.effect.lower95, score.clopper_pearson_lower(1, 2), 0) and b1.null.trials == 0,
      "misfit bin 1: two effect trials, one named, one wrong name")
check(b2.null.trials == 2 and b2.null.alarms == 1 and near(b2.null.upper95, score.clopper_pearson_upper(1, 2), 0)
      and b2.effect.trials == 0 and b2.effect.lower95 == nil, "misfit bin 2: the edge value and a false alarm")
check(b3.effect.trials == 1 and b3.effect.right == 0 and b3.outside.trials == 2 and b3.outside.wrong_names == 1,
      "misfit bin 3: a missed effect and an outside trial wrongly named")
check(not pcall(score.by_misfit, {{trial = 9, truth = {kind = "none"}, answer = "none", right = true}}, {0.05}, names),
      "a trial without q0_p is refused")
check(not pcall(score.by_misfit, {}, {0.05, 0.01}, names), "descending p edges are refused")
-- By the workflow's own detection limits: declared detectable when the strength reaches the limit
-- (nil: nowhere); `none` answers covered when the upper limit (nil: unbounded) reaches the strength.
local bd = score.by_detection({
  {truth = {kind = "candidate", name = "a", strength = 0.5}, answer = "a", right = true, hidden_detection_limit = 0.5},  -- at the limit
  {truth = {kind = "candidate", name = "a", strength = 0.4}, answer = "b", right = false, hidden_detection_limit = 0.3}, -- wrong name
  {truth = {kind = "candidate", name = "b", strength = 0.2}, answer = "none", right = false, hidden_detection_limit = 0.3,
   hidden_upper_limit = 0.1},                                                                                          -- not covered
  {truth = {kind = "candidate", name = "b", strength = 0.9}, answer = "none", right = false},                         -- nowhere, unbounded
  {truth = {kind = "none"}, answer = "none", right = true, hidden_detection_limit = 0},                               -- not an effect trial
}, names)
check(bd.detectable.trials == 2 and bd.detectable.right == 1 and bd.detectable.wrong_names == 1
      and near(bd.detectable.lower95, score.clopper_pearson_lower(1, 2), 0), "declared detectable: 2 trials, 1 named, 1 wrong name")
check(bd.undetectable.trials == 2 and bd.undetectable.right == 0 and bd.undetectable.answers.none == 2, "below the limit: 2 answered none")
check(bd.none_answers.trials == 2 and bd.none_answers.covered == 1, "none answers: the unbounded one covers, 0.1 < 0.2 does not")
check(bd.per_candidate.a.trials == 2 and bd.per_candidate.a.detectable == 2 and bd.per_candidate.a.detectable_right == 1
      and bd.per_candidate.b.trials == 2 and bd.per_candidate.b.detectable == 0 and bd.per_candidate.b.none_covered == 1,
      "per candidate")
local s = score.summarise({
  {truth = {kind = "candidate", name = "a", strength = 2}, answer = "a", right = true, strength = 2.5, misfit_before = 4, misfit_after = 1},
  {truth = {kind = "candidate", name = "b", strength = 1}, answer = "ambiguous", right = false},
  {truth = {kind = "none"}, answer = "none", right = true, misfit_before = 1, misfit_after = 1},
  {truth = {kind = "none"}, answer = "unknown", right = false},
  {truth = {kind = "outside", name = "x"}, answer = "a", right = false, wrong_name = true},
}, {"a", "b"})
check(s.confusion.a.a == 1 and s.confusion.b.ambiguous == 1 and s.confusion.none.none == 1 and s.confusion.none.unknown == 1
      and s.confusion.outside.a == 1, "confusion matrix")
check(s.correct_names == 1 and s.effect_trials == 2 and s.false_alarms == 1 and s.null_trials == 2 and s.outside_wrong_names == 1, "counts")
check(near(s.strength_relative_error.mean, 0.25, 1e-15), "strength error %.17g", s.strength_relative_error.mean)
check(near(s.misfit_after_over_before.mean, (0.25 + 1) / 2, 1e-15), "misfit ratio")
-- Named strengths: the interval's coverage, the extrapolated strength's error and coverage, the
-- misfit left against the 1.2 target (right names only).
local sn = score.summarise({
  {truth = {kind = "candidate", name = "a", strength = 0.2}, answer = "a", right = true, strength = 0.25, misfit_before = 3, misfit_after = 1.1, misfit_whitened_after = 1.25,
   strength_interval = {value = 0.25, low = 0.22, high = 0.28, resolution_corrected = {value = 0.21, low = 0.18, high = 0.24}}},
  {truth = {kind = "candidate", name = "a", strength = 0.1}, answer = "a", right = true, strength = 0.1, misfit_before = 2, misfit_after = 1.3, misfit_whitened_after = 0.9,
   strength_interval = {value = 0.1, low = 0.09, high = 0.11}},
  {truth = {kind = "candidate", name = "b", strength = 1}, answer = "a", right = false, strength = 2, misfit_after = 0.9, misfit_whitened_after = 0.8,
   strength_interval = {value = 2, low = 0.5, high = 3, resolution_corrected = {value = 1, low = 0.5, high = 1.5}}},
}, {"a", "b"})
check(sn.strength_interval_coverage.covered == 1 and sn.strength_interval_coverage.trials == 2, "interval coverage %d of %d",
      sn.strength_interval_coverage.covered, sn.strength_interval_coverage.trials)
check(sn.strength_resolution_corrected.trials == 1 and sn.strength_resolution_corrected.covered == 1
      and near(sn.strength_resolution_corrected.relative_error.mean, 0.05, 1e-12), "extrapolated strength: error %.6g",
      sn.strength_resolution_corrected.relative_error.mean)
check(sn.misfit_after_named.at_most_1_2 == 1 and sn.misfit_after_named.stats.n == 2, "misfit after right names: %d of %d at most 1.2",
      sn.misfit_after_named.at_most_1_2, sn.misfit_after_named.stats.n)
check(sn.misfit_whitened_after_named.at_most_1_2 == 1 and sn.misfit_whitened_after_named.stats.n == 2
      and near(sn.misfit_whitened_after_named.stats.mean, (1.25 + 0.9) / 2, 1e-15), "whitened misfit after right names: %d of %d, mean %.17g",
      sn.misfit_whitened_after_named.at_most_1_2, sn.misfit_whitened_after_named.stats.n, sn.misfit_whitened_after_named.stats.mean)
check(s.strength_interval_coverage == nil and s.strength_resolution_corrected == nil, "no intervals: no coverage reported")

-- Stacking: dotted keys, vectors, standardisation, length errors.
local result = {slump_mm = 200, profile_mm = {10, 20, 30}, profile_radii_mm = {12.5, 37.5, 62.5}, cone_force_N = {mean = 1.5}}
check(stack.extract(result, "cone_force_N.mean")[1] == 1.5, "dotted key")
check(select(2, stack.extract(result, "nope")) ~= nil, "missing key gives a message")
local inp = {experiments = {{name = "e", observables = {
  {key = "cone_force_N.mean", measured = {2}, sigma = {0.5}, vector = false},
  {key = "profile_mm", measured = {11, 19, 33}, sigma = {1, 2, 3}, vector = true},
  {key = "slump_mm", measured = {210}, sigma = {5}, vector = false}}}}}
local L = stack.layout(inp)
check(#L == 5, "layout entries %d", #L)
local y = stack.simulated(L, {e = result})
local expect = {1.5 / 0.5, 10, 10, 10, 40}
for i = 1, 5 do check(near(y[i], expect[i], 1e-15), "y[%d] = %g, expected %g", i, y[i], expect[i]) end
stack.label(L, {e = result})
check(L[3].label:match("r=37.5 mm"), "profile label %s", L[3].label)
local ok, err = pcall(stack.simulated, L, {e = {slump_mm = 1, profile_mm = {1, 2}, cone_force_N = {mean = 1}}}, "test")
check(not ok and err:match("profile_mm' has 2 entries, the measurement 3"), "length error: %s", tostring(err))
check(near(stack.rms_standardised({3, 4}, {{1, 0}, {0, 4}}), math.sqrt((9 + 4) / 2), 1e-15), "RMS standardised")

-- Slump observables: interpolation on the fixed times, the lift's force, carried mud.
local h = {{t = 0, slump_mm = 0}, {t = 0.5, slump_mm = 100}, {t = 1.0, slump_mm = 150}}
local at = obs.history_at(h, {0.25, 0.5, 0.75, 3})
check(at[1] == 50 and at[2] == 100 and at[3] == 125 and at[4] == 150, "history_at %g %g %g %g", at[1], at[2], at[3], at[4])
local samples = {{t = 1, force = {0, 0, -2}}, {t = 2, force = {0, 0, -4}}, {t = 3, force = {0, 0, 6}}}
local f = obs.cone_force(samples, 1, 2)
check(f.mean == 3 and f.peak == 4 and f.samples == 2, "cone force mean %g peak %g n %d", f.mean, f.peak, f.samples)
-- After the mud let go of the cone its samples are exact zeros: they do not count, however many
-- (the mean is the same whether the lift ended early or rose on); a zero between loads does.
local free = {{t = 1, force = {0, 0, -2}}, {t = 2, force = {0, 0, 0}}, {t = 3, force = {1, 0, -4}}}
for k = 4, 40 do free[k] = {t = k, force = {0, 0, 0}} end
local g, g_short = obs.cone_force(free, 1, 40), obs.cone_force(free, 1, 5)
check(g.mean == 2 and g.peak == 4 and g.samples == 3 and g_short.mean == 2 and g_short.samples == 3,
      "cone force with the cone free at the end: mean %g / %g, peak %g, n %d / %d", g.mean, g_short.mean, g.peak, g.samples, g_short.samples)
local none = obs.cone_force({{t = 1, force = {0, 0, 0}}, {t = 2, force = {0, 0, 0}}}, 0, 3)
check(none.mean == 0 and none.peak == 0 and none.samples == 0, "no load at all: zeros")
check(#obs.HISTORY_TIMES > 3 and math.floor(obs.PROFILE_R_MAX / obs.PROFILE_BIN + 0.5) == 12, "fixed grids")
-- A fake simulation: one sphere rising with the cone inside it, one at rest inside, one rising outside.
local fake = {
  xyz = function() return {0, 0.05, 0.5}, {0, 0, 0}, {0.15, 0.15, 0.15} end,
  radii = function() return {0.01, 0.01, 0.01} end,
  velocities = function() return {{0, 0, 0.05}, {0, 0, 0}, {0, 0, 0.05}} end,
}
local c = obs.carried_by_cone(fake, {lift_speed = 0.05, z_bottom = 0.1, radius_bottom = 0.1, radius_top = 0.05, height = 0.3, density = 1000})
check(c.count == 1 and near(c.mass_g, 4 / 3 * math.pi * 1e-6 * 1000 * 1000, 1e-9), "carried %d spheres, %g g", c.count, c.mass_g)

-- Input errors name the file, the key and the allowed values.
local dir = paddy.out_dir
local function bad(doc, pattern)
  local path = paddy.write_json(dir .. "/bad_input.json", doc)
  local ok2, e = pcall(input.read, path)
  check(not ok2, "accepted a bad input (expected %s)", pattern)
  check(e:match("^discovery input '[^']*bad_input%.json': ") and e:match(pattern), "message '%s' lacks '%s'", e, pattern)
end
local good = function()
  return {experiments = {{name = "slow", script = "slump.lua", set = {lift_speed = 0.05}, measured = {slump_mm = 231, profile_mm = {1, 2}},
                          sigma = {slump_mm = 3, profile_mm = 2}}},
          free_parameters = {{parameter = "jkr_surface_energy", low = 0, high = 0.2}},
          candidates = {{name = "wall_adhesion", parameter = "mud_steel_surface_energy", low = 0, high = 0.3}}}
end
local g = input.read(paddy.write_json(dir .. "/good_input.json", good()))
check(#g.experiments[1].observables == 2 and g.experiments[1].observables[1].sigma[2] == 2, "one sigma for a vector is repeated")
check(g.candidates[1].probe == 0.15 and g.free_parameters[1].start == 0.1 and g.settings.replicates == 5, "defaults")
local t = good(); t.experiments[1].script = "cone.lua"; bad(t, "script = cone.lua %(allowed: slump.lua, rheometer.lua, tack.lua%)")
t = good(); t.experiments[1].sigma.slump_mm = nil; bad(t, "experiments%[1%]%.sigma%.slump_mm is missing")
t = good(); t.experiments[1].sigma.profile_mm = {1, 2, 3}; bad(t, "sigma%.profile_mm has 3 entries, measured%.profile_mm has 2")
t = good(); t.experiments[1].sigma.slump_mm = 0; bad(t, "sigma%.slump_mm%[1%] = 0 must be > 0")
t = good(); t.candidates[1].low = 0.1; bad(t, "candidates%[1%]%.low = 0%.1: a candidate's strength starts at 0")
t = good(); t.candidates[1].high = -1; bad(t, "candidates%[1%]: high = %-1 must be greater than low = 0")
t = good(); t.candidates[1].parameter = "jkr_surface_energy"; bad(t, "already a free parameter")
t = good(); t.free_parameters[1].start = 5; bad(t, "free_parameters%[1%]%.start = 5 is outside the allowed range %[0, 0%.2%]")
t = good(); t.settings = {replicates = 3}; bad(t, "settings%.replicates = 3 is outside the allowed range %[5, 50%]")
t = good(); t.extra = 1; bad(t, "unknown key 'extra' %(allowed:")
t = good(); t.settings = {iteration = 3}; bad(t, "unknown key 'settings%.iteration' %(allowed: iterations,")
t = good(); t.settings = {resolution_factor = 0.3}; bad(t, "settings%.resolution_factor = 0%.3: allowed 0 %(off%) or 0%.5 to 0%.99")
t = good(); t.settings = {refit = "newton"}; bad(t, "settings%.refit = 'newton': allowed surface, gauss_newton")
t = good(); t.settings = {calibration_start = "best"}; bad(t, "settings%.calibration_start = 'best': allowed surface, best_scan")
t = good(); t.settings = {signature_baseline = "replicate"}; bad(t, "settings%.signature_baseline = 'replicate': allowed own, replicates")
t = good(); t.settings = {signature_baseline = "replicates", signature_seeds = 6}
bad(t, "settings%.signature_seeds = 6 with signature_baseline = 'replicates' needs as many replicates")
t = good(); t.settings = {measured_repeats = -1}; bad(t, "settings%.measured_repeats = %-1 is outside the allowed range")
t = good(); t.settings = {strong_margin = 2}; bad(t, "settings%.strong_margin = 2 is outside the allowed range %[3,")
check(g.settings.refit_zoom == 0.15 and g.settings.refit_zoom_rounds == 3 and g.settings.ambiguous_refits == true, "zoom and ambiguous refits on by default")
t = good(); t.settings = {ambiguous_refits = "yes"}; bad(t, "settings%.ambiguous_refits = yes: allowed true, false")
t = good(); t.settings = {ambiguous_refits = false}
check(input.read(paddy.write_json(dir .. "/ambiguous_input.json", t)).settings.ambiguous_refits == false, "ambiguous refits can be turned off")
t = good(); t.settings = {refit_zoom = 0.01}; bad(t, "settings%.refit_zoom = 0%.01: allowed 0 %(off%) or 0%.02 to 0%.5")
check(g.settings.refit_zoom_above == 1.2, "a zoom also above 1.2 noise sd by default")
t = good(); t.settings = {refit_zoom_above = 0.8}; bad(t, "settings%.refit_zoom_above = 0%.8: allowed 0 %(off%) or 1 to 10")
t = good(); t.settings = {refit_zoom_above = 0}
check(input.read(paddy.write_json(dir .. "/zoom_above_input.json", t)).settings.refit_zoom_above == 0, "the zoom above a misfit can be turned off")
check(g.settings.runner_up_refits == 0, "no runner-up refits by default")
t = good(); t.settings = {runner_up_refits = 4}; bad(t, "settings%.runner_up_refits = 4 is outside the allowed range %[0, 3%]")
t = good(); t.settings = {runner_up_refits = 2}
check(input.read(paddy.write_json(dir .. "/runner_up_input.json", t)).settings.runner_up_refits == 2, "runner-up refits as given")
check(g.settings.measured_repeats == 0 and g.settings.resolution_factor == 0 and g.settings.strong_margin == nil
      and g.settings.backtracks == 2 and g.settings.converge == 0.01 and g.settings.start_scan == 4 and g.settings.refit == "surface"
      and g.settings.calibration_start == "surface" and g.settings.signature_baseline == "own", "defaults of the start scan, the calibration's start, the refit, step control, specimen scatter, resolution and strong margin")
t = good(); t.candidates = {}; bad(t, "'candidates' must be a non%-empty list")
t = good(); t.candidates[1].relevant = 0.3; bad(t, "candidates%[1%]%.relevant = 0%.3 must be below high = 0%.3")
t = good(); t.candidates[1].relevant = -0.01; bad(t, "candidates%[1%]%.relevant = %-0%.01 is outside the allowed range %[0, 0%.3%]")
t = good(); t.candidates[1].relevant = 0.03
check(input.read(paddy.write_json(dir .. "/relevant_input.json", t)).candidates[1].relevant == 0.03 and g.candidates[1].relevant == nil,
      "relevant is read, and absent by default")

-- A shared error: read, refused when malformed, and its covariance C_ij = rel^2 y_i y_j over the
-- listed keys of its experiment only (y = measured / sigma).
t = good(); t.experiments[1].shared_error = {rel_sd = 0.05, keys = {"profile_mm"}}
t.experiments[2] = {name = "vane", script = "rheometer.lua", measured = {torque_Nm = {10, 20}}, sigma = {torque_Nm = 0.2}}
local sh = input.read(paddy.write_json(dir .. "/shared_input.json", t))
check(sh.experiments[1].shared_error.rel_sd == 0.05 and sh.experiments[1].shared_error.keys.profile_mm
      and g.experiments[1].shared_error == nil, "shared_error is read, and absent by default")
local SL = stack.layout(sh)   -- slow profile_mm[1], [2], slow slump_mm, vane torque_Nm[1], [2]
local C = stack.shared_covariance(sh, SL)
check(#C == 5 and near(C[1][2], 0.05 ^ 2 * (1 / 2) * (2 / 2), 1e-15) and near(C[2][2], 0.05 ^ 2, 1e-15), "C within the shared key")
check(C[1][3] == 0 and C[3][3] == 0 and C[4][4] == 0 and C[1][4] == 0, "no shared error outside the listed keys or across experiments")
check(stack.shared_covariance(g, stack.layout(g)) == nil, "no shared error: nil")
t = good(); t.experiments[1].shared_error = {rel_sd = 0, keys = {"slump_mm"}}; bad(t, "experiments%[1%]%.shared_error%.rel_sd = 0 must be in %(0, 1%]")
t = good(); t.experiments[1].shared_error = {rel_sd = 0.05, keys = {"torque_Nm"}}
bad(t, "experiments%[1%]%.shared_error%.keys%[1%] = torque_Nm is not a measured key of this experiment")
t = good(); t.experiments[1].shared_error = {rel_sd = 0.05, keys = {}}; bad(t, "shared_error%.keys must be a non%-empty list")
t = good(); t.experiments[1].shared_error = {rel = 0.05, keys = {"slump_mm"}}; bad(t, "shared_error: unknown key 'rel' %(allowed: rel_sd, keys%)")

-- The refit's zoom design: centre, axial points, corners; clipped to the ranges.
local zoom = require("lib.discovery.zoom")
local X, zlo, zhi = zoom.design({0.2, 0.095}, {0, 0}, {0.3, 0.1}, 0.15)
check(#X == 9 and X[1][1] == 0.2 and X[1][2] == 0.095, "1 + 2d + 2^d points, the centre first")
check(near(zlo[1], 0.155, 1e-15) and near(zhi[1], 0.245, 1e-15) and near(zlo[2], 0.08, 1e-15) and zhi[2] == 0.1, "box clipped to the range")
check(X[2][1] == zlo[1] and X[2][2] == 0.095 and X[5][2] == zhi[2] and X[5][1] == 0.2, "axial points on the faces")
local corners = {}
for k = 6, 9 do corners[string.format("%g,%g", X[k][1], X[k][2])] = true end
check(corners["0.155,0.08"] and corners["0.245,0.08"] and corners["0.155,0.1"] and corners["0.245,0.1"], "every corner once")
check(#zoom.design({1, 2, 3}, {0, 0, 0}, {4, 4, 4}, 0.1) == 1 + 6 + 8, "three dimensions: 15 points")
local okz, ez = pcall(zoom.design, {0.5}, {0}, {0.3}, 0.15)
check(not okz and ez:match("centre 0.5 lies outside"), "a centre outside its range is refused: %s", tostring(ez))
check(not pcall(zoom.design, {0.1}, {0}, {0.3}, 0), "a zero half-width is refused")
-- A centre on a bound (a refit that ran into it): the box reaches 2h inward and that dimension
-- gets three levels, so the quadratic surface is determined (with the plain box it has two and
-- paddy.doe.response_surface refuses the design as rank-deficient).
do
  local Xb, blo, bhi = zoom.design({0.3, 0.05}, {0.05, 0}, {0.3, 0.1}, 0.15)
  check(#Xb == 9 and near(blo[1], 0.225, 1e-15) and bhi[1] == 0.3 and near(blo[2], 0.035, 1e-15) and near(bhi[2], 0.065, 1e-15),
        "box at the upper bound: [%.6g, %.6g] x [%.6g, %.6g]", blo[1], bhi[1], blo[2], bhi[2])
  check(near(Xb[2][1], 0.225, 1e-15) and near(Xb[3][1], 0.2625, 1e-15) and Xb[2][2] == 0.05, "axial points at the far side and half-way")
  local levels = {}
  for _, x in ipairs(Xb) do levels[string.format("%.6g", x[1])] = true end
  check(levels["0.225"] and levels["0.2625"] and levels["0.3"], "three levels of the bounded dimension")
  local Xl = zoom.design({0.05, 0.0}, {0.05, 0}, {0.3, 0.1}, 0.15)
  check(near(Xl[2][1], 0.05 + 0.0375, 1e-15) and near(Xl[3][1], 0.125, 1e-15) and near(Xl[4][2], 0.015, 1e-15) and near(Xl[5][2], 0.03, 1e-15),
        "centre on both lower bounds: axial points half-way and at the far side")
  local values = {}
  for k, x in ipairs(Xb) do values[k] = {100 * (x[1] - 0.26) ^ 2 + 100 * (x[2] - 0.045) ^ 2 + 1, 10 * (x[1] - 0.26) + 5 * (x[2] - 0.045)} end
  local rs = require("paddy.doe").response_surface{points = Xb, values = values, measured = {1, 0}, covariance = {{1, 0}, {0, 1}}, lower = blo, upper = bhi}
  check(near(rs.x[1], 0.26, 1e-6) and near(rs.x[2], 0.045, 1e-6), "the surface through the bounded zoom finds the minimum: %.6g %.6g", rs.x[1], rs.x[2])
end

-- When the refit zooms: a significant misfit, or an RMS above the setting (not at or below it; never with 0).
check(zoom.reason(true, 0.9, 1.2) == "misfit left significant", "a significant misfit zooms")
check(zoom.reason(false, 1.72, 1.2):find("RMS standardised residual 1.72 above 1.2 noise sd", 1, true), "an RMS above the setting zooms")
check(zoom.reason(false, 1.2, 1.2) == nil and zoom.reason(false, 1.1, 1.2) == nil, "an RMS at or below the setting does not")
check(zoom.reason(false, 5, 0) == nil and zoom.reason(false, nil, 1.2) == nil, "never with the setting 0 or no RMS")

-- The refit's valley: θ on the line θ̂ − β·λ (and its half-stratum twins), λ from λ̂ up to the top;
-- over the whole range when the linear estimate is at or above the top.
local valley = require("lib.discovery.valley")
check(valley.whole_range(0.654, 0.3) and valley.whole_range(0.3, 0.3) and not valley.whole_range(0.26, 0.3)
      and not valley.whole_range(nil, 0.3), "whole range when the estimate is at or above the top")
local vbase = {theta = {0.14}, beta = {0.1}, theta_low = {0.05}, theta_high = {0.3}, lambda_low = 0, lambda_high = 0.3, n = 5}
local function with(t, extra) local c = {}; for k, v in pairs(t) do c[k] = v end; for k, v in pairs(extra) do c[k] = v end; return c end
local vp = valley.points(with(vbase, {lambda = 0.2}))
check(#vp == 11 and vp[1].lambda == 0.2 and near(vp[1].theta[1], 0.14 - 0.1 * 0.2, 1e-15), "λ̂ first, on the line: %d points", #vp)
for i = 2, #vp, 2 do
  local k = i // 2
  local lam = 0.2 + k / 5 * 0.1
  check(near(vp[i].lambda, lam, 1e-15) and vp[i + 1].lambda == vp[i].lambda, "point %d: λ = %.4g, expected %.4g", i, vp[i].lambda, lam)
  check(near(vp[i].theta[1], 0.14 - 0.1 * lam, 1e-15), "point %d on the line", i)
  local twin = 0.14 - 0.1 * lam + (k % 2 == 1 and 1 or -1) * 0.25 / 10
  check(near(vp[i + 1].theta[1], twin, 1e-15), "twin %d half a stratum %s: %.6g, expected %.6g", i + 1, k % 2 == 1 and "up" or "down", vp[i + 1].theta[1], twin)
end
local vw = valley.points(with(vbase, {lambda = 0.3, whole_range = true}))
check(#vw == 10, "whole range: n points and their twins, %d", #vw)
local lams = {}
for i = 1, #vw, 2 do lams[#lams + 1] = vw[i].lambda end
for k = 1, 5 do check(near(lams[k], 0.3 * k / 5, 1e-15), "whole range: λ_%d = %.4g, expected %.4g", k, lams[k], 0.3 * k / 5) end
check(lams[1] < 0.3 / 2, "whole range: strengths well below the linear estimate are tried")
local vc = valley.points(with(vbase, {lambda = 0.2, beta = {-2}}))
for _, q in ipairs(vc) do check(q.theta[1] <= 0.3 and q.theta[1] >= 0.05, "θ clipped to its box: %.4g", q.theta[1]) end
check(not pcall(valley.points, with(vbase, {lambda = 0.2, n = 0})), "n = 0 is refused")
check(not pcall(valley.points, with(vbase, {lambda = 0.2, lambda_low = 0.3})), "an empty strength range is refused")

-- The strength extrapolated to a finer model: Δ = −(GᵀWG)⁻¹GᵀW b. On a linear model b = G δ the
-- shift is −δ_λ exactly, a part of b that G cannot express (orthogonal in W) moves nothing, and
-- the seed noise of the shift follows from deviations d_k = G e_k in closed form.
local resolution = require("lib.discovery.resolution")
do
  local G = {{1, 0.5}, {0, 1}, {2, -1}, {1, 1}, {0.5, 0}, {-1, 2}}
  local W = {}
  for i = 1, 6 do W[i] = {}; for j = 1, 6 do W[i][j] = i == j and 1 or 0 end end
  local function Gx(x) local v = {}; for i = 1, 6 do v[i] = G[i][1] * x[1] + G[i][2] * x[2] end; return v end
  -- o: orthogonal to both columns of G (Gᵀo = 0).
  local o = {2, -1, 0, 0, -4, 0}
  local go1, go2 = 0, 0
  for i = 1, 6 do go1, go2 = go1 + G[i][1] * o[i], go2 + G[i][2] * o[i] end
  check(go1 == 0 and go2 == 0, "the test's orthogonal vector: %g %g", go1, go2)
  local b = Gx({0.01, -0.02})
  for i = 1, 6 do b[i] = b[i] + 3 * o[i] end
  local e = {{0.001, 0.004}, {-0.002, -0.001}, {0.0005, -0.003}}
  local devs = {Gx(e[1]), Gx(e[2]), Gx(e[3])}
  local rc = resolution.corrected{jacobian = G, shift = b, deviations = devs, weights = W, lambda = 0.1, se = 0.003,
                                  low = 0, high = 0.3, resolution_seeds = 2}
  check(near(rc.shift, 0.02, 1e-12) and near(rc.value, 0.12, 1e-12) and not rc.clipped, "shift %.15g, value %.15g", rc.shift, rc.value)
  local ss = 0.004 ^ 2 + 0.001 ^ 2 + 0.003 ^ 2
  local se_shift = math.sqrt(ss / 2 * (1 / 2 + 1 / 3))
  check(near(rc.se_shift, se_shift, 1e-12), "se_shift %.15g, expected %.15g", rc.se_shift, se_shift)
  check(near(rc.se, math.sqrt(0.003 ^ 2 + se_shift ^ 2), 1e-12) and near(rc.low, 0.12 - 1.96 * rc.se, 1e-12), "se and interval")
  local top = resolution.corrected{jacobian = G, shift = b, deviations = devs, weights = W, lambda = 0.29, se = 0.003,
                                   low = 0, high = 0.3, resolution_seeds = 2}
  check(top.value == 0.3 and top.clipped and top.high == 0.3, "clipped to the range's top: %.6g", top.value)
  check(resolution.corrected{jacobian = G, shift = b, deviations = {devs[1]}, weights = W, lambda = 0.1, se = 0.003,
                             low = 0, high = 0.3, resolution_seeds = 2} == nil, "one confirmation run: no correction")
  local Gd = {}
  for i = 1, 6 do Gd[i] = {G[i][1], 2 * G[i][1]} end
  check(resolution.corrected{jacobian = Gd, shift = b, deviations = devs, weights = W, lambda = 0.1, se = 0.003,
                             low = 0, high = 0.3, resolution_seeds = 2} == nil, "a rank-deficient Jacobian: no correction")
end

-- The benchmark's vane read as one specimen: its torques share the fill's error.
local bench = require("lib.discovery.benchmark")
local ve = bench.experiments{variant = "small", vane_scale = 4, vane_speeds = "10,40,160", vane_shared_sd = 0.05, vane_startup_rpm = 10}
local vane = ve[#ve]
check(vane.set.startup_rpm == 10 and vane.set.speeds_rpm == "10,40,160" and vane.shared_error.rel_sd == 0.05 and vane.observables[1].rel == bench.VANE_READING_SD,
      "benchmark vane: speeds, shared error and reading error")
local plain = bench.experiments{variant = "small", vane_scale = 4}
check(plain[#plain].shared_error == nil and plain[#plain].observables[1].rel == 0.05 and plain[#plain].set.speeds_rpm == "10,40" and plain[#plain].set.startup_rpm == 5,
      "benchmark vane by default: two speeds, 5 % each")
local okv, ev = pcall(bench.experiments, {variant = "small", vane_scale = 4, vane_speeds = "10,400"})
check(not okv and ev:match("vane_speeds = 10,400: each speed must be in %(0, 300%] rpm"), "vane speed range: %s", tostring(ev))

-- The benchmark's tack test: every length of the default test scaled, the speed as given.
local te = bench.experiments{variant = "small", tack_scale = 5, tack_speed = 0.02}
local tack = te[#te]
check(#te == 2 and tack.script == "tack.lua" and tack.name == "tack_x5", "benchmark tack: one tack experiment after the slump")
check(math.abs(tack.set.cup_diameter - 0.4) < 1e-12 and math.abs(tack.set.plate_diameter - 0.25) < 1e-12 and
      math.abs(tack.set.pull_distance - 0.06) < 1e-12 and math.abs(tack.set.press_depth - 0.01) < 1e-12 and tack.set.pull_speed == 0.02,
      "benchmark tack: lengths scaled 5x, the pull speed kept")
check(#bench.experiments{variant = "small"} == 1, "benchmark without tack_scale: no tack test")
local okt, et = pcall(bench.experiments, {variant = "small", tack_scale = 20})
check(not okt and et:match("tack_scale = 20: must be 0 %(no tack test%) or in %[1, 10%]"), "tack scale range: %s", tostring(et))
local t2 = bench.experiments{variant = "small", tack_scale = 5, tack_speed = 0.02, tack_speeds = "0.04,0.2"}
check(#t2 == 3 and t2[2].name == "tack_x5_40mm_per_s" and t2[3].name == "tack_x5_200mm_per_s" and
      t2[2].set.pull_speed == 0.04 and t2[3].set.pull_speed == 0.2 and t2[3].set.plate_diameter == t2[2].set.plate_diameter and
      t2[2].set.press_speed == bench.TACK_PRESS_SPEED,
      "benchmark tack at two speeds: one test per speed, named by it, tack_speed ignored")
check(bench.experiments{variant = "small", tack_scale = 5, tack_press_speed = 0.04}[2].set.press_speed == 0.04, "benchmark tack: the press speed as given")
local oks, es = pcall(bench.experiments, {variant = "small", tack_scale = 5, tack_speeds = "0.04,2"})
check(not oks and es:match("tack_speeds = 0.04,2: each speed must be in %(0, 1%] m/s"), "tack speeds range: %s", tostring(es))

-- The strength's spread over specimens (paddy.doe.response_surface's specimen_runs, used by step 4
-- of discover.lua) on a linear model, where it has a closed form: observables f(x) = a x, identity
-- weights, so the refit of y + d is x(y) + g . d with g = a / (a . a); the spread is the sample sd
-- of g . d_k over the runs.
do
  local doe = require("paddy.doe")
  local a = {1, 2, 0.5, 1}
  local X, V = {}, {}
  for k, x in ipairs({-1, -0.5, 0, 0.5, 1}) do
    X[k] = {x}
    V[k] = {}
    for i = 1, #a do V[k][i] = a[i] * x end
  end
  local W = {}
  for i = 1, #a do
    W[i] = {}
    for k = 1, #a do W[i][k] = i == k and 1 or 0 end
  end
  local y = {}
  for i = 1, #a do y[i] = a[i] * 0.2 end
  local runs = {{0.05, -0.02, 0.01, 0.03}, {-0.04, 0.03, 0.0, -0.01}, {0.01, 0.02, -0.03, 0.02}}
  local aa = 0
  for i = 1, #a do aa = aa + a[i] * a[i] end
  local gd, mean = {}, 0
  for k, f in ipairs(runs) do
    gd[k] = 0
    for i = 1, #a do gd[k] = gd[k] + a[i] / aa * f[i] end
    mean = mean + gd[k] / #runs
  end
  local ss = 0
  for _, v in ipairs(gd) do ss = ss + (v - mean) ^ 2 end
  local expected = math.sqrt(ss / (#runs - 1))
  local design = {points = X, values = V, measured = y, covariance = W, lower = {-1}, upper = {1}}
  check(doe.response_surface(design).specimen_se == nil, "no specimen runs: no spread")
  design.specimen_runs = runs
  local se = doe.response_surface(design).specimen_se
  check(se and near(se[1], expected, 1e-6 * expected), "specimen se %s, expected %.12g", tostring(se and se[1]), expected)
  design.specimen_runs = {runs[1]}
  local ok, err = pcall(doe.response_surface, design)
  check(not ok and tostring(err):match("specimen_runs: at least two runs"), "one specimen run: %s", tostring(err))
end

paddy.result{ok = true}
