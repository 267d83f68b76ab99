-- The slump test's lift speed and the yield stress it implies: one material slumped with the cone
-- lifted at a series of speeds, the yield stress read from each pile with the cone model of
-- Schowalter & Christensen (1998; `yield_stress_Pa` of slump.lua, docs/measurement.md).
--
-- Why: that model, like Pashias et al. (1996) for a cylinder, has the pile stop where the stress
-- first falls to the yield stress: a quasi-static collapse, no inertia. A pile that flows fast
-- overshoots that shape and slumps further, so the formula reads a yield stress below the
-- material's. Lifting the cone more slowly slows the flow; where τ_slump stops changing as the
-- speed halves, the test reads its quasi-static value, and the factor between that and the test's
-- own speed (GB/T 50080: 0.05 m/s) is the part of the slump that is inertia. Documentation:
-- docs/validation.md §6.5.
--
--   paddy run experiments/validation/slump_lift_speed.lua --out results/lift_speed \
--       [--set values=0.02,0.06,0.1 --set lift_speeds=0.05,0.025,0.0125,0.00625 --set seeds=1,2 --set slump_diameter=0.02]
--
-- Every run is a campaign job (docs/campaign.md): a rerun repeats nothing that finished. Each run's
-- time limit after the start of the lift is the time to lift the cone by its height plus
-- rest_margin (at most slump.lua's 60 s), unless slump_set gives max_time; a run that was not at
-- rest at its limit is listed and left out of the statistics. Outputs in --out:
-- lift_speed_runs.csv, lift_speed_summary.csv (per set and speed), lift_speed_sets.csv (per set:
-- the change of the last halving, the factor of the slowest speed, a straight line in the speed),
-- lift_speed.json (= result.json) and lift_speed.png.
local util = require("lib.util")
local line_fit = require("lib.line_fit")
local report = require("report")
local ys_jobs = require("yield_stress_jobs")

local MAX_TIME = 60  -- slump.lua's largest max_time [s]

local P = paddy.parameters{
  {name = "parameter", default = "jkr_surface_energy", description = "the mud parameter that differs between the sets"},
  {name = "values", default = "0.02,0.06,0.1", description = "its values (comma-separated; default: low, centre, high of Table 3's H7 at 2 mm)"},
  {name = "lift_speeds", default = "0.05,0.025,0.0125,0.00625", unit = "m/s",
   description = "cone lift speeds (comma-separated, at least 2 distinct, each in [0.001, 2] m/s)"},
  {name = "test_speed", default = 0.05, unit = "m/s", min = 0.001, max = 2,
   description = "the speed the factors are taken against (GB/T 50080: 0.05 m/s); one of lift_speeds"},
  {name = "seeds", default = "1,2", description = "seeds of every set and speed (comma-separated)"},
  {name = "slump_diameter", default = 0.02, unit = "m", min = 0.001, max = 0.04, description = "sphere diameter of the slump runs"},
  {name = "cone_height", default = 0.3, unit = "m", min = 0.01, max = 1, description = "slump.lua's cone height: the lift a run's time limit allows for"},
  {name = "rest_margin", default = 5, unit = "s", min = 0.1, max = 60, description = "time limit of a run = cone_height / lift speed + this (at most 60 s)"},
  {name = "slump_set", default = "", description = "extra slump.lua parameters for every run, e.g. 'max_time=4' (not lift_speed)"},
  {name = "max_parallel", default = 1, type = "integer", min = 1, max = 256, description = "runs at once"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each run"},
  {name = "campaign_dir", default = "", description = "campaign directory (empty: <out>/campaign)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys (empty: hash of the paddy executable)"},
  {name = "pictures", default = true, description = "draw lift_speed.png with gnuplot"},
}

-- Inputs.
local values = report.numbers(P.values, "values") or error("values is empty", 0)
for _, v in ipairs(values) do
  if not (v >= 0) then error(string.format("values: %g is outside the allowed range [0, inf)", v), 0) end
end
local speeds = report.numbers(P.lift_speeds, "lift_speeds") or error("lift_speeds is empty", 0)
local distinct, has_test = {}, false
for _, v in ipairs(speeds) do
  if not (v >= 0.001 and v <= 2) then
    error(string.format("lift_speeds: %g m/s is outside the allowed range [0.001, 2] m/s", v), 0)
  end
  distinct[v] = true
  has_test = has_test or v == P.test_speed
end
local n_distinct = 0
for _ in pairs(distinct) do n_distinct = n_distinct + 1 end
if n_distinct < 2 or n_distinct ~= #speeds then
  error(string.format("lift_speeds = %s: needs at least 2 speeds, each once", P.lift_speeds), 0)
end
if not has_test then
  error(string.format("test_speed = %g m/s is not one of lift_speeds = %s", P.test_speed, P.lift_speeds), 0)
end
table.sort(speeds, function(a, b) return a > b end)  -- fastest first: each next one a slower lift
local seeds = report.seed_list(P.seeds)
local slump_extra = ys_jobs.extras(P.parameter, P.slump_set, "")
if slump_extra.lift_speed then error("slump_set must not set lift_speed: the study sets it (lift_speeds)", 0) end

-- The runs.
local function time_limit(v)
  return slump_extra.max_time or math.min(MAX_TIME, P.cone_height / v + P.rest_margin)
end
local dir = report.script_dir()
local c = report.campaign(P)
local jobs = {}
for _, value in ipairs(values) do
  for _, v in ipairs(speeds) do
    for _, s in ipairs(seeds) do
      local max_time = time_limit(v)
      local params = ys_jobs.params(P.slump_diameter, P.parameter, value,
                                    report.merge(slump_extra, {lift_speed = v, max_time = max_time}))
      jobs[#jobs + 1] = {value = value, speed = v, seed = s, max_time = max_time,
                         key = c:submit{script = dir .. "/../slump.lua", params = params, seed = s}}
    end
  end
end
io.stderr:write(string.format("slump_lift_speed: %d sets x %d speeds x %d seeds = %d slump runs at %g mm\n", #values, #speeds,
                              #seeds, #jobs, 1000 * P.slump_diameter))
local results = c:run()

-- Per run. A run not at rest at its time limit, or without a yield stress, is listed and left out.
local runs, failed, left_out = {}, 0, 0
local kept = {}  -- kept[value][speed][seed] = the run's row, for runs at rest with a yield stress
for i, run in ipairs(results) do
  local j = jobs[i]
  local row = {set = string.format("%s = %g", P.parameter, j.value), value = j.value, lift_speed_m_s = j.speed, seed = j.seed,
               max_time_s = j.max_time}
  if run.status == "done" then
    local r = run.result
    row.particles, row.slump_mm, row.slump_flow_mm, row.yield_stress_Pa = r.particles, r.slump_mm, r.slump_flow_mm, r.yield_stress_Pa
    row.fill_solid_fraction, row.at_rest, row.lift_stop_s = r.fill_solid_fraction, r.at_rest, r.lift_stop_s
    row.cone_lift_mm, row.mass_on_cone_g, row.simulated_time_s = r.cone_lift_mm, r.mass_on_cone_g, r.simulated_time_s
    row.cone_force_mean_N = r.cone_force_N and r.cone_force_N.mean
    row.wall_s = run.metadata and run.metadata.wall_time
    if r.at_rest and type(r.yield_stress_Pa) == "number" then
      kept[j.value] = kept[j.value] or {}
      kept[j.value][j.speed] = kept[j.value][j.speed] or {}
      kept[j.value][j.speed][j.seed] = row
    else
      left_out = left_out + 1
      io.stderr:write(string.format("slump_lift_speed: %s, %g m/s, seed %d: %s; left out\n", row.set, j.speed, j.seed,
                                    r.at_rest and "no yield stress (slump outside the cone model)"
                                    or string.format("not at rest after max_time = %g s", row.max_time_s)))
    end
  else
    failed = failed + 1
    io.stderr:write(string.format("slump_lift_speed: %s, %g m/s, seed %d failed: %s\n", row.set, j.speed, j.seed, tostring(run.error)))
  end
  runs[#runs + 1] = row
end

-- The kept runs of one set and speed, by seed (nil where a seed's run was left out).
local function kept_at(value, v) return (kept[value] or {})[v] or {} end
-- Their yield stresses, in seed order.
local function values_of(value, v)
  local out, at = {}, kept_at(value, v)
  for _, s in ipairs(seeds) do
    if at[s] then out[#out + 1] = at[s].yield_stress_Pa end
  end
  return out
end
-- Per-seed ratios and differences of the yield stress between two speeds of one set: only seeds that have both.
local function paired(value, va, vb, f)
  local out, a, b = {}, kept_at(value, va), kept_at(value, vb)
  for _, s in ipairs(seeds) do
    if a[s] and b[s] then out[#out + 1] = f(a[s].yield_stress_Pa, b[s].yield_stress_Pa) end
  end
  return out
end

-- Per set and speed; the picture's means (set index, speed in mm/s, mean yield stress).
local summary, means = {}, {}
for k, value in ipairs(values) do
  for _, v in ipairs(speeds) do
    local slumps, flows, at = {}, {}, kept_at(value, v)
    for _, s in ipairs(seeds) do
      if at[s] then slumps[#slumps + 1], flows[#flows + 1] = at[s].slump_mm, at[s].slump_flow_mm end
    end
    local t = values_of(value, v)
    local tm, ts = report.mean_std(t)
    local sm, ss = report.mean_std(slumps)
    local fm, fs = report.mean_std(flows)
    local fac = paired(value, v, P.test_speed, function(x, y) return x / y end)
    local fm_, fs_ = report.mean_std(fac)
    summary[#summary + 1] = {set = string.format("%s = %g", P.parameter, value), value = value, lift_speed_m_s = v, runs = #t,
                             slump_mm = sm, slump_std_mm = ss, slump_flow_mm = fm, slump_flow_std_mm = fs,
                             yield_stress_Pa = tm, yield_stress_std_Pa = ts,
                             factor_to_test_speed = fm_, factor_std = fs_, factor_pairs = #fac}
    if #t > 0 then means[#means + 1] = {k, 1000 * v, tm} end
  end
end

-- Per set: the last halving (the two slowest speeds, paired by seed), the slowest speed against the
-- test speed, and a straight line τ = a + b v over every run (read at v = 0: an extrapolation that
-- assumes the line).
local sets = {}
for _, value in ipairs(values) do
  local slow, before = speeds[#speeds], speeds[#speeds - 1]
  local diffs = paired(value, slow, before, function(x, y) return x - y end)
  local dm, ds, dn = report.mean_std(diffs)
  local fac = paired(value, slow, P.test_speed, function(x, y) return x / y end)
  local fm, fs = report.mean_std(fac)
  local x, y = {}, {}
  for _, v in ipairs(speeds) do
    for _, t in ipairs(values_of(value, v)) do x[#x + 1], y[#y + 1] = v, t end
  end
  local ok, fit = pcall(line_fit.fit, {x = x, y = y, what = string.format("yield stress against lift speed (%s = %g)", P.parameter, value)})
  local set = {set = string.format("%s = %g", P.parameter, value), value = value, slowest_m_s = slow,
               last_halving_change_Pa = dm, last_halving_change_se_Pa = dn > 1 and ds / math.sqrt(dn) or nil, last_halving_pairs = dn,
               slowest_factor = fm, slowest_factor_std = fs, slowest_factor_pairs = #fac}
  if ok then
    local at_test = line_fit.at(fit, P.test_speed)
    set.line = {a_Pa = fit.a, se_a_Pa = fit.se_a, b_Pa_s_per_m = fit.b, se_b = fit.se_b, r2 = fit.r2, n = fit.n,
                at_test_speed_Pa = at_test, quasi_static_factor = at_test ~= 0 and fit.a / at_test or nil}
  else
    set.line_error = tostring(fit)
  end
  -- The last halving is within the seeds' scatter when its paired change is within two of its standard errors.
  if set.last_halving_change_se_Pa then
    set.last_halving_within_scatter = math.abs(dm) <= 2 * set.last_halving_change_se_Pa
  end
  sets[#sets + 1] = set
end

-- Files.
local run_cols = {"set", "value", "lift_speed_m_s", "seed", "max_time_s", "particles", "slump_mm", "slump_flow_mm", "yield_stress_Pa",
                  "fill_solid_fraction", "at_rest", "lift_stop_s", "cone_lift_mm", "mass_on_cone_g", "cone_force_mean_N",
                  "simulated_time_s", "wall_s"}
util.write_csv("lift_speed_runs.csv", run_cols, report.cells(runs, run_cols))
local sum_cols = {"set", "value", "lift_speed_m_s", "runs", "slump_mm", "slump_std_mm", "slump_flow_mm", "slump_flow_std_mm",
                  "yield_stress_Pa", "yield_stress_std_Pa", "factor_to_test_speed", "factor_std", "factor_pairs"}
util.write_csv("lift_speed_summary.csv", sum_cols, report.cells(summary, sum_cols))
local set_rows = {}
for _, s in ipairs(sets) do
  local l = s.line or {}
  set_rows[#set_rows + 1] = {s.set, s.value, s.slowest_m_s, report.cell(s.last_halving_change_Pa), report.cell(s.last_halving_change_se_Pa),
                             report.cell(s.last_halving_within_scatter), report.cell(s.slowest_factor), report.cell(s.slowest_factor_std),
                             report.cell(l.a_Pa), report.cell(l.se_a_Pa), report.cell(l.b_Pa_s_per_m), report.cell(l.r2),
                             report.cell(l.quasi_static_factor)}
end
util.write_csv("lift_speed_sets.csv", {"set", "value", "slowest_m_s", "last_halving_change_Pa", "last_halving_change_se_Pa",
                                       "last_halving_within_scatter", "slowest_factor", "slowest_factor_std", "line_at_0_Pa",
                                       "line_at_0_se_Pa", "line_slope_Pa_s_per_m", "line_r2", "line_quasi_static_factor"}, set_rows)
local doc = {parameter = P.parameter, values = values, lift_speeds = speeds, test_speed = P.test_speed, seeds = seeds,
             slump_diameter = P.slump_diameter, slump_set = P.slump_set, runs = runs, summary = summary, sets = sets,
             failed = failed, left_out = left_out, finished = os.date("!%Y-%m-%dT%H:%M:%SZ")}
report.write_json("lift_speed.json", doc)

local picture
if P.pictures then
  local data = {}
  for k, value in ipairs(values) do
    for _, v in ipairs(speeds) do
      for _, t in ipairs(values_of(value, v)) do data[#data + 1] = {k, 1000 * v, t} end
    end
  end
  if #data > 0 then
    util.write_columns("lift_speed.dat", "set lift_speed_mm_s tau_Pa", data)
    util.write_columns("lift_speed_means.dat", "set lift_speed_mm_s mean_tau_Pa", means)
    local tics = {}
    for _, v in ipairs(speeds) do tics[#tics + 1] = string.format("'%g' %g", 1000 * v, 1000 * v) end
    local colours = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02"}
    local plots = {}
    for k, value in ipairs(values) do
      local col = colours[(k - 1) % #colours + 1]
      plots[#plots + 1] = string.format("'%s' using ($1 == %d ? $2 : 1/0):3 with points pt 7 ps 1.1 lc rgb '%s' title '%s = %g (runs)'",
                                        util.out("lift_speed.dat"), k, col, P.parameter, value)
      plots[#plots + 1] = string.format("'%s' using ($1 == %d ? $2 : 1/0):3 with linespoints pt 6 ps 1.6 lw 2 lc rgb '%s' notitle",
                                        util.out("lift_speed_means.dat"), k, col)
    end
    picture = util.gnuplot("lift_speed", string.format([[
set title 'Yield stress the slump implies against the cone lift speed (%g mm spheres; dots: runs, circles: seed means)'
set xlabel 'cone lift speed [mm/s] (log scale; dotted: the test speed)'; set ylabel 'yield stress from the slump [Pa]'
set grid; set key bottom left box opaque
set logscale x; set xrange [%g:%g]; set yrange [0:*]; set xtics (%s)
set arrow from %g, graph 0 to %g, graph 1 nohead dt 3 lc rgb 'gray'
plot %s]], 1000 * P.slump_diameter, 1000 * speeds[#speeds] / 1.5, 1000 * speeds[1] * 1.5, table.concat(tics, ", "),
       1000 * P.test_speed, 1000 * P.test_speed,
       table.concat(plots, ", \\\n     ")))
  end
end

-- Console.
print(string.format("%-28s %10s %5s %12s %16s %14s", "set", "v [mm/s]", "runs", "slump [mm]", "tau_slump [Pa]", "vs test speed"))
for _, r in ipairs(summary) do
  print(string.format("%-28s %10.2f %5d %12s %16s %14s", r.set, 1000 * r.lift_speed_m_s, r.runs,
                      r.runs > 0 and string.format("%.1f", r.slump_mm) or "-",
                      r.runs > 0 and string.format("%.1f +- %.1f", r.yield_stress_Pa, r.yield_stress_std_Pa) or "-",
                      r.factor_pairs > 0 and string.format("%.3f +- %.3f", r.factor_to_test_speed, r.factor_std) or "-"))
end
for _, s in ipairs(sets) do
  print(string.format("%s: last halving %s Pa (%s); slowest / test speed %s", s.set,
                      s.last_halving_change_se_Pa and string.format("%+.1f +- %.1f", s.last_halving_change_Pa, s.last_halving_change_se_Pa)
                      or (s.last_halving_pairs > 0 and string.format("%+.1f", s.last_halving_change_Pa) or "-"),
                      s.last_halving_within_scatter == nil and "one seed: no scatter"
                      or s.last_halving_within_scatter and "within the seeds' scatter" or "NOT within the seeds' scatter",
                      s.slowest_factor_pairs > 0 and string.format("%.3f +- %.3f", s.slowest_factor, s.slowest_factor_std) or "-"))
end
if picture then print("picture     " .. picture) end

paddy.result{
  study = "lift_speed.json",
  runs = #runs,
  failed = failed,
  left_out = left_out,
  sets = sets,
  summary = summary,
  pictures = picture and {lift_speed = picture} or nil,
}
