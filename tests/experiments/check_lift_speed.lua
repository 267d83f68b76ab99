-- experiments.validation_lift_speed: checks what experiments/validation/slump_lift_speed.lua wrote
-- (its CSV files, printed to 9 digits) against its own runs: every run finished at rest with the
-- lift speed and time limit it was given, and the summary's means, factors, halving changes and
-- lines are those of the runs.
local util = require("lib.util")
local P = paddy.parameters{
  {name = "dir", default = "", description = "output directory of slump_lift_speed.lua"},
  {name = "speeds", default = "", description = "the lift speeds the study was given"},
  {name = "test_speed", default = 0.05, description = "its test_speed"},
  {name = "values", default = "", description = "its values"},
  {name = "seeds", default = "1,2", description = "its seeds"},
  {name = "cone_height", default = 0.3, description = "its cone_height"},
  {name = "rest_margin", default = 5, description = "its rest_margin"},
}
local checks = require("checks")
local check, near = checks.check, checks.near
local REL = 1e-7  -- the files hold 9 significant digits

local speeds, values, seeds = util.numbers(P.speeds, "speeds"), util.numbers(P.values, "values"), util.numbers(P.seeds, "seeds")
table.sort(speeds, function(a, b) return a > b end)
local runs = util.read_csv(P.dir .. "/lift_speed_runs.csv")
check(#runs == #speeds * #values * #seeds, "%d runs, expected %d", #runs, #speeds * #values * #seeds)
local tau = {}
for _, r in ipairs(runs) do
  check(r.at_rest == "true", "run %s %g m/s seed %s not at rest", r.set, r.lift_speed_m_s, tostring(r.seed))
  -- the study's time limit, and the speed slump.lua really lifted at (its lift: speed x time)
  near(r.max_time_s, math.min(60, P.cone_height / r.lift_speed_m_s + P.rest_margin), REL, "time limit")
  near(r.cone_lift_mm / (1000 * r.lift_stop_s), r.lift_speed_m_s, 1e-6, "lift speed seen by slump.lua")
  check(r.yield_stress_Pa > 0, "yield stress %s", tostring(r.yield_stress_Pa))
  tau[r.value] = tau[r.value] or {}
  tau[r.value][r.lift_speed_m_s] = tau[r.value][r.lift_speed_m_s] or {}
  tau[r.value][r.lift_speed_m_s][r.seed] = r.yield_stress_Pa
end

local function mean(list)
  local s = 0
  for _, v in ipairs(list) do s = s + v end
  return s / #list
end
-- Summary: per set and speed, the mean yield stress and the mean of the seeds' ratios to the test speed.
local summary = util.read_csv(P.dir .. "/lift_speed_summary.csv")
check(#summary == #speeds * #values, "%d summary rows, expected %d", #summary, #speeds * #values)
for _, s in ipairs(summary) do
  local t, ratios = {}, {}
  for _, seed in ipairs(seeds) do
    t[#t + 1] = tau[s.value][s.lift_speed_m_s][seed]
    ratios[#ratios + 1] = tau[s.value][s.lift_speed_m_s][seed] / tau[s.value][P.test_speed][seed]
  end
  check(s.runs == #seeds, "summary runs %s", tostring(s.runs))
  near(s.yield_stress_Pa, mean(t), REL, "mean yield stress")
  near(s.factor_to_test_speed, mean(ratios), REL, "factor to the test speed")
  if s.lift_speed_m_s == P.test_speed then check(s.factor_to_test_speed == 1, "factor of the test speed itself") end
end

-- Per set: the last halving's paired change, the slowest speed's factor, and the line's value at the test speed.
local sets = util.read_csv(P.dir .. "/lift_speed_sets.csv")
check(#sets == #values, "%d set rows", #sets)
local slow, before = speeds[#speeds], speeds[#speeds - 1]
for _, s in ipairs(sets) do
  check(s.slowest_m_s == slow, "slowest speed %s", tostring(s.slowest_m_s))
  local d, f = {}, {}
  for _, seed in ipairs(seeds) do
    d[#d + 1] = tau[s.value][slow][seed] - tau[s.value][before][seed]
    f[#f + 1] = tau[s.value][slow][seed] / tau[s.value][P.test_speed][seed]
  end
  near(s.last_halving_change_Pa, mean(d), 1e-6, "last halving change")
  near(s.slowest_factor, mean(f), REL, "slowest factor")
  -- the line through every run, from its own sums
  local xs, ys = {}, {}
  for _, v in ipairs(speeds) do
    for _, seed in ipairs(seeds) do xs[#xs + 1], ys[#ys + 1] = v, tau[s.value][v][seed] end
  end
  local xm, ym = mean(xs), mean(ys)
  local sxx, sxy = 0, 0
  for k = 1, #xs do sxx, sxy = sxx + (xs[k] - xm) ^ 2, sxy + (xs[k] - xm) * (ys[k] - ym) end
  local b = sxy / sxx
  local a = ym - b * xm
  near(s.line_at_0_Pa, a, 1e-6, "line at v = 0")
  near(s.line_slope_Pa_s_per_m, b, 1e-6, "line slope")
  near(s.line_quasi_static_factor, a / (a + b * P.test_speed), 1e-6, "quasi-static factor")
end
paddy.result{ok = true}
