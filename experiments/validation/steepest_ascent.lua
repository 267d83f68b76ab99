-- Validation against the reference's steepest ascent (shared/reference/README.md, step 2 of the
-- calibration; table6_steepest_ascent.csv): Paddy's slump test at the 4 steps, side by side with
-- the reference's EDEM results. Each step sets A = mud_mud_restitution (H1), B = mud_steel_friction
-- (H5, static friction) and C = jkr_surface_energy (H7, J/m² at 2 mm); the other four factors stay
-- at their Table 3 centre, computed as plackett_burman.lua computes it, so the two scripts share
-- jobs in one campaign directory. Documentation: docs/validation.md.
--
--   paddy run experiments/validation/steepest_ascent.lua --out results/validation/sa \
--       [--set max_parallel=1 --set threads_per_job=1 --set particle_diameter=0.010]
--
-- The relative error to the measurement (slump 231 mm, slump-flow 480 mm; lib/reference_measurement)
-- is δ = |Y_sim − Y_measured| / Y_measured: the README states the denominator as Y_sim, but
-- Table 6's percentages are relative to the measurement (step 1: 27/231 = 11.69 %, not
-- 27/258 = 10.47 %); the script recomputes them from the table's values and stops if they differ.
-- The best step has the smallest mean of the two δ (the reference chose step 4).
--
-- The runs are experiments/slump.lua jobs of a campaign (docs/campaign.md) in <out>/campaign: a
-- rerun skips the finished ones, so an interrupted study resumes.
-- Outputs in --out: sa_runs.csv, sa_validation.json, sa_runs.png, result.json.
local util = require("lib.util")
local measurement = require("lib.reference_measurement")
local report = require("report")
local slump_jobs = require("slump_jobs")

local P = paddy.parameters(slump_jobs.parameters{
  {name = "runs", default = "", description = "comma-separated step numbers of Table 6 to simulate (empty: all 4)"},
  {name = "pictures", default = true, description = "draw sa_runs.png with gnuplot"},
})
local PARAM, FACTORS, RESPONSES = slump_jobs.PARAM, slump_jobs.FACTORS, slump_jobs.RESPONSES
local study = slump_jobs.new(P, "steepest_ascent")
local levels = slump_jobs.levels(study.ref_dir)
local measured = measurement.slump()

-- Table 6, checked: every column a number in every row, the steps 1..4 in order, and the relative
-- errors recomputable from the responses.
local TABLE6 = "table6_steepest_ascent.csv"
local COLUMNS = {
  {name = "run", key = "step"},
  {name = "A_mud_mud_restitution", key = "A"},
  {name = "B_mud_steel_static_friction", key = "B"},
  {name = "C_jkr_surface_energy_J_m2", key = "C"},
  {name = "slump_mm", key = "slump_mm"},
  {name = "slump_rel_error_percent", key = "slump_rel_error_percent"},
  {name = "slump_flow_mm", key = "slump_flow_mm"},
  {name = "slump_flow_rel_error_percent", key = "slump_flow_rel_error_percent"},
}
local table6_path = study.ref_dir .. "/" .. TABLE6
local table6_rows, header = util.read_csv(table6_path)
local have = {}
for _, name in ipairs(header) do have[name] = true end
for _, col in ipairs(COLUMNS) do
  if not have[col.name] then error(string.format("%s: no column '%s'", table6_path, col.name), 0) end
end
local steps = {}
for i, row in ipairs(table6_rows) do
  local s = {}
  for _, col in ipairs(COLUMNS) do
    local v = row[col.name]
    if type(v) ~= "number" then
      error(string.format("%s line %d: column '%s' is '%s', not a number", table6_path, row._line, col.name,
                          tostring(v or "")), 0)
    end
    s[col.key] = v
  end
  if s.step ~= i then
    error(string.format("%s line %d: column 'run' is %g, expected step %d", table6_path, row._line, s.step, i), 0)
  end
  s.step = math.tointeger(s.step)
  for _, y in ipairs(RESPONSES) do
    local col = y:gsub("_mm$", "_rel_error_percent")
    local delta = 100 * math.abs(s[y] - measured[y]) / measured[y]
    if math.abs(delta - s[col]) > 0.006 then
      error(string.format("%s line %d: column '%s' is %g, but |%g - %g| / %g = %.2f %%", table6_path, row._line, col,
                          s[col], s[y], measured[y], measured[y], delta), 0)
    end
  end
  steps[i] = s
end
if #steps ~= 4 then error(string.format("%s: %d steps, expected 4", table6_path, #steps), 0) end

-- Relative error [%] of a value to the measurement of response y.
local function delta(y, value)
  return 100 * math.abs(value - measured[y]) / measured[y]
end

local wanted = {}
local run_list = report.numbers(P.runs, "runs")
if run_list then
  for _, n in ipairs(run_list) do
    n = math.tointeger(n) or n
    if not steps[n] then error(string.format("runs: there is no step %s in %s (1..%d)", tostring(n), TABLE6, #steps), 0) end
    wanted[n] = true
  end
end

-- The design: A, B, C of the step; H2, H3, H4, H6 at the Table 3 centre.
local design = {}
for _, s in ipairs(steps) do
  if not run_list or wanted[s.step] then
    local real = {}
    for _, h in ipairs(FACTORS) do real[h] = slump_jobs.real_level(levels, h, 0) end
    real.H1, real.H5, real.H7 = s.A, s.B, s.C
    design[#design + 1] = {label = "step " .. s.step, step = s, real = real, params = study:params(real)}
  end
end
local t0 = os.time()
local results = study:run(design)

-- Collect.
local rows, done, failed = {}, {}, {}
for i, run in ipairs(results) do
  local d = design[i]
  local s = d.step
  local entry = study:entry(d, run, {slump_mm = s.slump_mm, slump_flow_mm = s.slump_flow_mm,
                                     slump_rel_error_percent = s.slump_rel_error_percent,
                                     slump_flow_rel_error_percent = s.slump_flow_rel_error_percent})
  entry.step, entry.A, entry.B, entry.C, entry.real = s.step, s.A, s.B, s.C, d.real
  entry.edem.mean_rel_error_percent = (s.slump_rel_error_percent + s.slump_flow_rel_error_percent) / 2
  if entry.paddy then
    local p = entry.paddy
    p.slump_rel_error_percent = delta("slump_mm", p.slump_mm)
    p.slump_flow_rel_error_percent = delta("slump_flow_mm", p.slump_flow_mm)
    p.mean_rel_error_percent = (p.slump_rel_error_percent + p.slump_flow_rel_error_percent) / 2
    done[#done + 1] = entry
  else
    failed[#failed + 1] = entry
  end
  rows[#rows + 1] = entry
end

local columns = {"step", "A", "B", "C"}
for _, h in ipairs(FACTORS) do columns[#columns + 1] = PARAM[h] end
for _, name in ipairs{"edem_slump_mm", "edem_slump_flow_mm", "edem_slump_rel_error_percent",
                      "edem_slump_flow_rel_error_percent", "paddy_slump_mm", "paddy_slump_flow_mm",
                      "diff_slump_mm", "diff_slump_flow_mm", "paddy_slump_rel_error_percent",
                      "paddy_slump_flow_rel_error_percent", "paddy_slump_flow_ruler_mm", "particles", "at_rest",
                      "simulated_time_s", "wall_time_s", "threads", "timestep_fraction", "status", "key"} do
  columns[#columns + 1] = name
end
local csv_rows = {}
for _, e in ipairs(rows) do
  local p, dif = e.paddy or {}, e.difference or {}
  local line = {e.step, e.A, e.B, e.C}
  for _, h in ipairs(FACTORS) do line[#line + 1] = e.real[h] end
  -- table.pack keeps the nils (a failed run has no Paddy values): ipairs would stop there.
  local values = table.pack(e.edem.slump_mm, e.edem.slump_flow_mm, e.edem.slump_rel_error_percent,
                            e.edem.slump_flow_rel_error_percent, p.slump_mm, p.slump_flow_mm, dif.slump_mm,
                            dif.slump_flow_mm, p.slump_rel_error_percent, p.slump_flow_rel_error_percent,
                            p.slump_flow_ruler_mm, p.particles, p.at_rest, p.simulated_time_s, p.wall_time_s,
                            p.threads, e.timestep_fraction, e.status, e.key)
  for k = 1, values.n do line[#line + 1] = report.cell(values[k]) end
  csv_rows[#csv_rows + 1] = line
end
util.write_csv("sa_runs.csv", columns, csv_rows)

-- The best step by δ, for each response and for the mean of the two: EDEM's among the steps of
-- this invocation, Paddy's among its finished runs.
local function best(entries, source)
  local out = {}
  for _, crit in ipairs{"slump_rel_error_percent", "slump_flow_rel_error_percent", "mean_rel_error_percent"} do
    local step, value
    for _, e in ipairs(entries) do
      local v = source(e)[crit]
      if not value or v < value then step, value = e.step, v end
    end
    out[(crit:gsub("_rel_error_percent$", ""))] = step and {step = step, rel_error_percent = value} or nil
  end
  return out
end
local best_step = {edem = best(rows, function(e) return e.edem end), paddy = best(done, function(e) return e.paddy end),
                   reference_choice = 4}

local agreement = {}
for _, y in ipairs(RESPONSES) do agreement[y] = slump_jobs.agreement(done, y) end

local doc = {
  study = "Steepest ascent of the reference (Table 6), Paddy vs EDEM",
  particle_diameter = P.particle_diameter, seed = P.seed, slump_set = study.extra,
  measured = measured,
  rel_error = "100 |Y_sim - Y_measured| / Y_measured [%] (reproduces Table 6's percentages)",
  best_by = "smallest mean of the slump and slump-flow relative errors (also per response)",
  factors = (function()
    local t = {}
    for _, h in ipairs(FACTORS) do
      local varied = ({H1 = "A", H5 = "B", H7 = "C"})[h]
      t[#t + 1] = {symbol = h, parameter = PARAM[h], reference_name = levels[h].parameter, step_column = varied,
                   value = not varied and slump_jobs.real_level(levels, h, 0) or nil}
    end
    return t
  end)(),
  runs = rows,
  agreement = agreement,
  best_step = best_step,
  finished = #done, failed = #failed,
  run_wall_time_s = slump_jobs.wall_times(done),
  campaign_wall_time_s = os.difftime(os.time(), t0),
}
report.write_json("sa_validation.json", doc)

local pictures = {}
if P.pictures and #done > 0 then
  pictures.runs = slump_jobs.runs_chart("sa_runs", done, "step",
    string.format("Steepest ascent (Table 6): EDEM (reference, 2 mm) vs Paddy (%.0f mm spheres)", P.particle_diameter * 1000),
    "step (A, B, C rising)")
end

-- Summary on stdout.
print(string.format("%4s %9s %9s %7s | %9s %9s %7s | %7s %7s", "step", "EDEM s", "Paddy s", "diff", "EDEM sf",
                    "Paddy sf", "diff", "EDEM δ%", "Paddy δ%"))
for _, e in ipairs(rows) do
  if e.paddy then
    print(string.format("%4d %9.1f %9.1f %+7.1f | %9.1f %9.1f %+7.1f | %7.2f %7.2f", e.step, e.edem.slump_mm,
                        e.paddy.slump_mm, e.difference.slump_mm, e.edem.slump_flow_mm, e.paddy.slump_flow_mm,
                        e.difference.slump_flow_mm, e.edem.mean_rel_error_percent, e.paddy.mean_rel_error_percent))
  else
    print(string.format("%4d  %s: %s", e.step, e.status, tostring(e.error)))
  end
end
for _, y in ipairs(RESPONSES) do
  local a = agreement[y]
  if a.runs > 0 then
    print(string.format("%s: mean difference %+.1f mm, RMS %.1f mm, correlation %s", y, a.mean_difference,
                        a.rms_difference, a.correlation and string.format("%.3f", a.correlation) or "n/a"))
  end
end
local function best_text(b)
  return b.mean and string.format("step %d (mean δ %.2f %%)", b.mean.step, b.mean.rel_error_percent) or "none"
end
print(string.format("best step by δ: EDEM %s, Paddy %s (the reference chose step 4)",
                    best_text(best_step.edem), best_text(best_step.paddy)))

paddy.result{
  finished = #done, failed = #failed, runs = #rows,
  agreement = agreement, best_step = best_step, measured = measured,
  files = {runs_csv = util.out("sa_runs.csv"), json = util.out("sa_validation.json"), pictures = pictures},
  run_wall_time_s = doc.run_wall_time_s,
}
if #failed > 0 then
  error(string.format("steepest_ascent: %d of %d runs failed (rerun to retry them; see sa_runs.csv)", #failed, #rows))
end
