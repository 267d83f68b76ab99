-- Two virtual tests, one material: the yield stress from the vane start-up test
-- (experiments/rheometer.lua, peak torque and the vane relation of Nguyen & Boger 1983) against the
-- yield stress the slump implies (experiments/slump.lua, Schowalter & Christensen 1998 cone
-- model), for the same mud at several parameter sets (default: the JKR surface energy at the low,
-- centre and high levels of the reference's Table 3), each with several seeds.
-- Documentation: docs/validation.md §6.
--
--   paddy run experiments/validation/yield_stress.lua --out results/validation/yield_stress \
--       [--set surface_energies=0.02,0.06,0.1 --set seeds=1,2 --set slump_diameter=0.012 ...]
--
-- The runs are jobs of a campaign (docs/campaign.md) in <out>/campaign; a rerun skips the finished
-- ones. Per set: each seed's ratio τ_vane / τ_slump (the two tests of one seed share nothing but
-- the seed number), then mean ± std (n − 1) over the seeds of τ_vane, τ_slump and the ratio, and
-- whether the mean ratio is within `target` (25 %) of 1. Outputs in --out: ys_runs.csv,
-- ys_summary.csv, yield_stress_study.json, ys_ratio.png, result.json.
local util = require("lib.util")
local report = require("report")

local P = paddy.parameters{
  {name = "parameter", default = "jkr_surface_energy", description = "the mud parameter that differs between the sets"},
  {name = "values", default = "", description = "its values (comma-separated); empty: low, centre, high of table_parameter in table3_pb_levels.csv"},
  {name = "table_parameter", default = "jkr_surface_energy_mud", description = "the parameter's name in table3_pb_levels.csv (H7)"},
  {name = "seeds", default = "1,2", description = "seeds of each set (comma-separated, at least 2 for a std)"},
  {name = "slump_diameter", default = 0.014, unit = "m", min = 0.001, max = 0.04, description = "sphere diameter of the slump runs"},
  {name = "rheometer_diameter", default = 0.012, unit = "m", min = 0.001, max = 0.02, description = "sphere diameter of the rheometer runs"},
  {name = "slump_set", default = "", description = "extra slump.lua parameters for every run, e.g. 'max_time=4'"},
  {name = "rheometer_set", default = "", description = "extra rheometer.lua parameters for every run, e.g. 'startup_rpm=1'"},
  {name = "target", default = 0.25, min = 0, max = 10, description = "agreement target: |mean ratio − 1| within this"},
  {name = "max_parallel", default = 1, type = "integer", min = 1, max = 256, description = "runs at once"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each run"},
  {name = "max_attempts", default = 1, type = "integer", min = 1, max = 10, description = "attempts per job (the runs are deterministic)"},
  {name = "reference_dir", default = "", description = "shared/reference directory (empty: beside the source tree)"},
  {name = "campaign_dir", default = "", description = "campaign directory (empty: <out>/campaign)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys (empty: hash of the paddy executable)"},
  {name = "pictures", default = true, description = "draw ys_ratio.png with gnuplot"},
}

-- The parameter sets.
local values = report.numbers(P.values, "values")
local levels = {}
if values then
  for k, v in ipairs(values) do levels[k] = {label = string.format("%s = %g", P.parameter, v), value = v} end
else
  local path = report.reference_dir(P.reference_dir) .. "/table3_pb_levels.csv"
  for _, row in ipairs(util.read_csv(path)) do
    if row.parameter == P.table_parameter then
      for _, l in ipairs({"low", "center", "high"}) do
        levels[#levels + 1] = {label = l, value = row[l]}
      end
    end
  end
  if #levels == 0 then error(path .. ": no row for parameter '" .. P.table_parameter .. "' (give values= or table_parameter=)") end
end
local seeds = report.numbers(P.seeds, "seeds") or error("seeds is empty")
for k, s in ipairs(seeds) do
  seeds[k] = math.tointeger(s) or error("seeds: " .. s .. " is not an integer")
  if seeds[k] < 1 then error("seeds: " .. s .. " must be positive") end
end
local dir = report.script_dir()
local slump_extra = report.assignments(P.slump_set, "slump_set")
-- The rheometer runs only the start-up test (no speed steps) unless rheometer_set says otherwise.
local rheo_extra = report.merge({speeds_rpm = "", down_sweep = false}, report.assignments(P.rheometer_set, "rheometer_set"))
for _, extra in ipairs({slump_extra, rheo_extra}) do
  if extra[P.parameter] or extra.seed or extra.particle_diameter then
    error("slump_set / rheometer_set must not set " .. P.parameter .. ", seed or particle_diameter")
  end
end

local c = paddy.campaign{dir = P.campaign_dir ~= "" and P.campaign_dir or paddy.out_dir .. "/campaign",
                         max_parallel = P.max_parallel, threads_per_job = P.threads_per_job, max_attempts = P.max_attempts,
                         code_version = P.code_version ~= "" and P.code_version or nil}
local jobs = {}
for li, l in ipairs(levels) do
  for _, s in ipairs(seeds) do
    local sp = report.merge({particle_diameter = P.slump_diameter, progress = false, pictures = false, snapshot_interval = 0,
                             [P.parameter] = l.value}, slump_extra)
    local rp = report.merge({particle_diameter = P.rheometer_diameter, progress = false, pictures = false, snapshot_interval = 0,
                             [P.parameter] = l.value}, rheo_extra)
    jobs[#jobs + 1] = {level = li, seed = s, test = "vane", key = c:submit{script = dir .. "/../rheometer.lua", params = rp, seed = s}}
    jobs[#jobs + 1] = {level = li, seed = s, test = "slump", key = c:submit{script = dir .. "/../slump.lua", params = sp, seed = s}}
  end
end
io.stderr:write(string.format("yield_stress: %d sets x %d seeds x 2 tests = %d runs\n", #levels, #seeds, #jobs))
local results = c:run()

-- Collect per set and seed.
local by = {}  -- by[level][seed] = {slump = result, vane = result}
local failed = 0
for i, run in ipairs(results) do
  local j = jobs[i]
  by[j.level] = by[j.level] or {}
  by[j.level][j.seed] = by[j.level][j.seed] or {}
  if run.status == "done" then
    by[j.level][j.seed][j.test] = {result = run.result, wall = run.metadata and run.metadata.wall_time}
  else
    failed = failed + 1
    io.stderr:write(string.format("yield_stress: %s, seed %d, %s failed: %s\n", levels[j.level].label, j.seed, j.test,
                                  tostring(run.error)))
  end
end

local run_rows, runs, summary, sum_rows = {}, {}, {}, {}
for li, l in ipairs(levels) do
  local tv, ts, ratios = {}, {}, {}
  for _, s in ipairs(seeds) do
    local e = by[li] and by[li][s] or {}
    local sl, va = e.slump and e.slump.result, e.vane and e.vane.result
    local row = {set = l.label, value = l.value, seed = s,
                 slump_mm = sl and sl.slump_mm, slump_flow_mm = sl and sl.slump_flow_mm,
                 fill_solid_fraction = sl and sl.fill_solid_fraction,
                 slump_yield_stress_Pa = sl and sl.yield_stress_Pa, slump_at_rest = sl and sl.at_rest,
                 vane_peak_torque_Nm = va and va.startup and va.startup.peak_torque_Nm,
                 vane_peak_angle_deg = va and va.startup and va.startup.peak_angle_deg,
                 vane_peak_reached = va and va.startup and va.startup.peak_reached,
                 vane_yield_stress_Pa = va and va.yield_stress_Pa,
                 slump_wall_s = e.slump and e.slump.wall, vane_wall_s = e.vane and e.vane.wall}
    if row.slump_yield_stress_Pa and row.vane_yield_stress_Pa then
      row.ratio = row.vane_yield_stress_Pa / row.slump_yield_stress_Pa
      tv[#tv + 1], ts[#ts + 1], ratios[#ratios + 1] = row.vane_yield_stress_Pa, row.slump_yield_stress_Pa, row.ratio
    end
    runs[#runs + 1] = row
  end
  local s = {set = l.label, value = l.value, seeds = #ratios}
  s.vane_yield_stress_Pa = {report.mean_std(tv)}
  s.slump_yield_stress_Pa = {report.mean_std(ts)}
  s.ratio = {report.mean_std(ratios)}
  s.vane_yield_stress_Pa = {mean = s.vane_yield_stress_Pa[1], std = s.vane_yield_stress_Pa[2], values = tv}
  s.slump_yield_stress_Pa = {mean = s.slump_yield_stress_Pa[1], std = s.slump_yield_stress_Pa[2], values = ts}
  s.ratio = {mean = s.ratio[1], std = s.ratio[2], values = ratios}
  s.within_target = #ratios > 0 and math.abs(s.ratio.mean - 1) <= P.target
  summary[#summary + 1] = s
  sum_rows[#sum_rows + 1] = {l.label, l.value, #ratios, report.cell(s.vane_yield_stress_Pa.mean), report.cell(s.vane_yield_stress_Pa.std),
                             report.cell(s.slump_yield_stress_Pa.mean), report.cell(s.slump_yield_stress_Pa.std),
                             report.cell(s.ratio.mean), report.cell(s.ratio.std), tostring(s.within_target)}
end
local run_cols = {"set", "value", "seed", "slump_mm", "slump_flow_mm", "fill_solid_fraction", "slump_yield_stress_Pa",
                  "slump_at_rest", "vane_peak_torque_Nm", "vane_peak_angle_deg", "vane_peak_reached", "vane_yield_stress_Pa", "ratio",
                  "slump_wall_s", "vane_wall_s"}
for _, r in ipairs(runs) do
  local line = {}
  for k, col in ipairs(run_cols) do
    local v = r[col]
    if type(v) == "boolean" then v = tostring(v) end
    line[k] = report.cell(v)
  end
  run_rows[#run_rows + 1] = line
end
util.write_csv("ys_runs.csv", run_cols, run_rows)
util.write_csv("ys_summary.csv", {"set", "value", "seeds", "vane_Pa", "vane_std_Pa", "slump_Pa", "slump_std_Pa", "ratio", "ratio_std",
                                  "within_target"}, sum_rows)
local doc = {parameter = P.parameter, seeds = seeds, slump_diameter = P.slump_diameter, rheometer_diameter = P.rheometer_diameter,
             slump_set = P.slump_set, rheometer_set = P.rheometer_set, target = P.target, runs = runs, summary = summary,
             failed = failed, finished = os.date("!%Y-%m-%dT%H:%M:%SZ")}
report.write_json("yield_stress_study.json", doc)

local pictures = {}
if P.pictures then
  local rows = {}
  for k, s in ipairs(summary) do rows[k] = {k, s.ratio.mean, s.ratio.std, s.vane_yield_stress_Pa.mean, s.slump_yield_stress_Pa.mean} end
  util.write_columns("ys_ratio.dat", "set ratio ratio_std vane_Pa slump_Pa", rows)
  local xt = {}
  for k, s in ipairs(summary) do xt[k] = string.format("'%s' %d", s.set, k) end
  pictures.ratio = util.gnuplot("ys_ratio", string.format([[
set title 'Yield stress: vane start-up / slump (Schowalter-Christensen), mean +- std over seeds'
set xlabel '%s'; set ylabel 'tau_vane / tau_slump'; set grid; set key top left
set xrange [0.5:%d.5]; set yrange [0:*]; set xtics (%s)
plot '%s' using 1:2:3 with yerrorbars pt 7 ps 1.5 title 'ratio', 1 lc rgb 'black' title 'agreement', \
     %g lc rgb 'gray' dt 2 title '+-%g %%', %g lc rgb 'gray' dt 2 notitle]],
    P.parameter, #summary, table.concat(xt, ", "), util.out("ys_ratio.dat"), 1 + P.target, 100 * P.target, 1 - P.target))
end

print(string.format("%-10s %8s  %18s  %18s  %14s", "set", "value", "vane [Pa]", "slump [Pa]", "ratio"))
for _, s in ipairs(summary) do
  print(string.format("%-10s %8g  %9.1f +- %-6.1f  %9.1f +- %-6.1f  %6.3f +- %-5.3f %s", s.set, s.value, s.vane_yield_stress_Pa.mean,
                      s.vane_yield_stress_Pa.std, s.slump_yield_stress_Pa.mean, s.slump_yield_stress_Pa.std, s.ratio.mean,
                      s.ratio.std, s.within_target and "within target" or "NOT within target"))
end
paddy.result{summary = summary, runs = runs, failed = failed, pictures = pictures}
