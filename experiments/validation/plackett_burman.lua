-- Validation against the reference's Plackett-Burman screening (shared/reference/README.md,
-- table4_plackett_burman.csv with the levels of table3_pb_levels.csv): Paddy's slump test at the
-- 13 runs, side by side with the reference's EDEM results, and the main effects both produce
-- (paddy.doe, model linear+curvature on the 7 real factors: the 4 dummy columns form the
-- 4-df residual, as in the reference's Table 5). Documentation: docs/validation.md.
--
--   paddy run experiments/validation/plackett_burman.lua --out results/validation/pb \
--       [--set max_parallel=1 --set threads_per_job=1 --set particle_diameter=0.010]
--
-- The runs are experiments/slump.lua jobs of a campaign (docs/campaign.md) in
-- <out>/campaign: a rerun skips the finished ones, so an interrupted study resumes. The jobs, the
-- time-step fallback and the agreement statistics are slump_jobs.lua's (shared with
-- steepest_ascent.lua). Outputs in --out: pb_runs.csv, pb_effects.csv, pb_validation.json, pb_runs.png,
-- pb_effects.png, result.json.
local util = require("lib.util")
local report = require("report")
local slump_jobs = require("slump_jobs")
local doe = require("paddy.doe")

local P = paddy.parameters(slump_jobs.parameters{
  {name = "runs", default = "", description = "comma-separated run numbers of Table 4 to simulate (empty: all 13)"},
  {name = "pictures", default = true, description = "draw pb_runs.png and pb_effects.png with gnuplot"},
})

-- Reference tables (Table 3 symbols → slump.lua parameters: slump_jobs.PARAM).
local PARAM, FACTORS = slump_jobs.PARAM, slump_jobs.FACTORS
local study = slump_jobs.new(P, "plackett_burman")
local table4 = util.read_csv(study.ref_dir .. "/table4_plackett_burman.csv")
local levels = slump_jobs.levels(study.ref_dir)

local wanted = {}
local run_list = report.numbers(P.runs, "runs")
if run_list then
  for _, n in ipairs(run_list) do wanted[math.tointeger(n) or n] = true end
end

-- The runs as campaign jobs, with the time-step fallback (slump_jobs: Study:run).
local design = {}
for _, row in ipairs(table4) do
  if not run_list or wanted[row.run] then
    local real = {}
    for _, h in ipairs(FACTORS) do real[h] = slump_jobs.real_level(levels, h, row[h]) end
    design[#design + 1] = {label = "run " .. row.run, row = row, real = real, params = study:params(real)}
  end
end
local t0 = os.time()
local results = study:run(design)

-- Collect.
local rows, done, failed = {}, {}, {}
for i, run in ipairs(results) do
  local d = design[i]
  local entry = study:entry(d, run, {slump_mm = d.row.slump_mm, slump_flow_mm = d.row.slump_flow_mm})
  entry.run, entry.real, entry.coded = d.row.run, d.real, {}
  for k = 1, 11 do entry.coded["H" .. k] = d.row["H" .. k] end
  if entry.paddy then done[#done + 1] = entry else failed[#failed + 1] = entry end
  rows[#rows + 1] = entry
end

local columns = {"run"}
for k = 1, 11 do columns[#columns + 1] = "H" .. k end
for _, h in ipairs(FACTORS) do columns[#columns + 1] = PARAM[h] end
for _, name in ipairs{"edem_slump_mm", "edem_slump_flow_mm", "paddy_slump_mm", "paddy_slump_flow_mm",
                      "diff_slump_mm", "diff_slump_flow_mm", "paddy_slump_flow_ruler_mm", "paddy_slump_flow_area_mm",
                      "circle_rms_mm", "particles", "loose_particles", "at_rest", "rest_time_s", "lift_stop_s",
                      "simulated_time_s", "wall_time_s", "threads", "timestep_fraction", "status", "key"} do
  columns[#columns + 1] = name
end
local csv_rows = {}
for _, e in ipairs(rows) do
  local p, dif = e.paddy or {}, e.difference or {}
  local line = {e.run}
  for k = 1, 11 do line[#line + 1] = e.coded["H" .. k] end
  for _, h in ipairs(FACTORS) do line[#line + 1] = e.real[h] end
  -- table.pack keeps the nils (a run not at rest has no rest_time_s): ipairs would stop there.
  local values = table.pack(e.edem.slump_mm, e.edem.slump_flow_mm, p.slump_mm, p.slump_flow_mm, dif.slump_mm,
                            dif.slump_flow_mm, p.slump_flow_ruler_mm, p.slump_flow_area_mm, p.circle_rms_mm, p.particles,
                            p.loose_particles, p.at_rest, p.rest_time_s, p.lift_stop_s, p.simulated_time_s, p.wall_time_s,
                            p.threads, e.timestep_fraction, e.status, e.key)
  for k = 1, values.n do line[#line + 1] = report.cell(values[k]) end
  csv_rows[#csv_rows + 1] = line
end
util.write_csv("pb_runs.csv", columns, csv_rows)

-- Main effects: the same model for the reference's numbers and Paddy's (runs that finished).
local RESPONSES = slump_jobs.RESPONSES
local function fit(source)
  local data = {}
  for _, e in ipairs(done) do
    local r = {}
    for _, h in ipairs(FACTORS) do r[h] = e.coded[h] end
    for _, y in ipairs(RESPONSES) do r[y] = source(e)[y] end
    data[#data + 1] = r
  end
  local has_centre = false
  for _, e in ipairs(done) do
    if e.coded.H1 == 0 then has_centre = true end
  end
  -- linear+curvature has 9 parameters (8 without a centre point); it needs residual df.
  local model = has_centre and "linear+curvature" or "linear"
  local n_par = has_centre and 9 or 8
  if #data <= n_par then
    return nil, string.format("%d finished runs: too few for the %s model (%d parameters)", #data, model, n_par)
  end
  local ok, res = pcall(doe.analyze, {data = data, factors = FACTORS, responses = RESPONSES, model = model})
  if not ok then return nil, tostring(res) end
  return res
end
local fit_edem, why_edem = fit(function(e) return e.edem end)
local fit_paddy, why_paddy = fit(function(e) return e.paddy end)

local function term_stats(f, y, term)
  if not f then return nil end
  local r = f.responses[y]
  local out = {}
  for _, row in ipairs(r.coefficient_table or {}) do
    if row.term == term then out.coefficient, out.se, out.t, out.p = row.estimate, row.se, row.t, row.p end
  end
  if term == "Curvature" then out.coefficient = r.curvature_coefficient end
  for _, row in ipairs(r.anova or {}) do
    if row.source == term then out.ss, out.F, out.p = row.ss, row.F, row.p end
  end
  return out
end
local effects, effect_rows = {}, {}
for _, y in ipairs(RESPONSES) do
  effects[y] = {}
  for _, term in ipairs{"H1", "H2", "H3", "H4", "H5", "H6", "H7", "Curvature"} do
    local e, p = term_stats(fit_edem, y, term) or {}, term_stats(fit_paddy, y, term) or {}
    effects[y][term] = {parameter = PARAM[term] or "centre point vs factorial mean", edem = e, paddy = p}
    effect_rows[#effect_rows + 1] = {y, term, PARAM[term] or "curvature",
      report.cell(e.coefficient), report.cell(e.coefficient and 2 * e.coefficient), report.cell(e.F), report.cell(e.p),
      report.cell(p.coefficient), report.cell(p.coefficient and 2 * p.coefficient), report.cell(p.F), report.cell(p.p)}
  end
end
util.write_csv("pb_effects.csv", {"response", "term", "parameter", "edem_coefficient", "edem_effect", "edem_F", "edem_p",
                                  "paddy_coefficient", "paddy_effect", "paddy_F", "paddy_p"}, effect_rows)
local function summary(f, why)
  if not f then return {skipped = why} end
  local out = {model = f.model, runs = f.runs}
  for _, y in ipairs(RESPONSES) do
    local r = f.responses[y]
    local model_row = {}
    for _, row in ipairs(r.anova) do
      if row.source == "Model" then model_row = row end
    end
    out[y] = {r2 = r.r2, adj_r2 = r.adj_r2, adeq_precision = r.adeq_precision, cv_percent = r.cv_percent,
              mean = r.mean, std_dev = r.std_dev, model_F = model_row.F, model_p = model_row.p,
              intercept = r.coefficients and r.coefficients.Intercept}
  end
  return out
end

local doc = {
  study = "Plackett-Burman screening of the reference (Table 4), Paddy vs EDEM",
  particle_diameter = P.particle_diameter, seed = P.seed, slump_set = study.extra,
  factors = (function()
    local t = {}
    for _, h in ipairs(FACTORS) do
      t[#t + 1] = {symbol = h, parameter = PARAM[h], reference_name = levels[h].parameter,
                   low = levels[h].low, center = levels[h].center, high = levels[h].high}
    end
    return t
  end)(),
  runs = rows,
  fit = {edem = summary(fit_edem, why_edem), paddy = summary(fit_paddy, why_paddy)},
  effects = effects,
  agreement = {slump_mm = slump_jobs.agreement(done, "slump_mm"), slump_flow_mm = slump_jobs.agreement(done, "slump_flow_mm")},
  finished = #done, failed = #failed,
  run_wall_time_s = slump_jobs.wall_times(done),
  campaign_wall_time_s = os.difftime(os.time(), t0),
}
report.write_json("pb_validation.json", doc)

-- Pictures: per run (EDEM vs Paddy), and the main-effect coefficients side by side (both
-- slump_jobs.edem_vs_paddy_chart).
local pictures = {}
if P.pictures and #done > 0 then
  pictures.runs = slump_jobs.runs_chart("pb_runs", done, "run",
    string.format("Plackett-Burman runs (Table 4): EDEM (reference, 2 mm) vs Paddy (%.0f mm spheres)", P.particle_diameter * 1000),
    "run (13 = centre point)")
  if fit_edem and fit_paddy then
    local eff = {}
    for k, term in ipairs{"H1", "H2", "H3", "H4", "H5", "H6", "H7", "Curvature"} do
      local s, f = effects.slump_mm[term], effects.slump_flow_mm[term]
      eff[k] = {string.format("%q", term == "Curvature" and "curv." or term),
                s.edem.coefficient or 0, s.paddy.coefficient or 0, f.edem.coefficient or 0, f.paddy.coefficient or 0}
    end
    local f = assert(io.open(util.out("pb_effects.dat"), "w"))
    f:write("# term edem_slump paddy_slump edem_flow paddy_flow (coded coefficients, mm per coded unit)\n")
    for _, r in ipairs(eff) do f:write(string.format("%s %.6g %.6g %.6g %.6g\n", table.unpack(r))) end
    f:close()
    pictures.effects = slump_jobs.edem_vs_paddy_chart("pb_effects",
      "Main effects (coded coefficients, half the high-low difference); curv. = centre - factorial mean",
      util.out("pb_effects.dat"), "top left", "term", "[*:*]")
  end
end

-- Summary on stdout.
print(string.format("%4s %9s %9s %7s | %9s %9s %7s", "run", "EDEM s", "Paddy s", "diff", "EDEM sf", "Paddy sf", "diff"))
for _, e in ipairs(rows) do
  if e.paddy then
    print(string.format("%4d %9.1f %9.1f %+7.1f | %9.1f %9.1f %+7.1f", e.run, e.edem.slump_mm, e.paddy.slump_mm,
                        e.difference.slump_mm, e.edem.slump_flow_mm, e.paddy.slump_flow_mm, e.difference.slump_flow_mm))
  else
    print(string.format("%4d  %s: %s", e.run, e.status, tostring(e.error)))
  end
end
if fit_edem and fit_paddy then
  for _, y in ipairs(RESPONSES) do
    print(y .. ": coded coefficient (p)   EDEM | Paddy")
    for _, term in ipairs{"H1", "H2", "H3", "H4", "H5", "H6", "H7", "Curvature"} do
      local e = effects[y][term]
      print(string.format("  %-9s %8.2f (%.4f) | %8.2f (%.4f)", term, e.edem.coefficient or 0 / 0, e.edem.p or 0 / 0,
                          e.paddy.coefficient or 0 / 0, e.paddy.p or 0 / 0))
    end
  end
else
  print("main effects not fitted: " .. tostring(why_paddy or why_edem))
end

paddy.result{
  finished = #done, failed = #failed, runs = #rows,
  fit = doc.fit, effects = effects, agreement = doc.agreement,
  files = {runs_csv = util.out("pb_runs.csv"), effects_csv = util.out("pb_effects.csv"),
           json = util.out("pb_validation.json"), pictures = pictures},
  run_wall_time_s = doc.run_wall_time_s,
}
if #failed > 0 then
  error(string.format("plackett_burman: %d of %d runs failed (rerun to retry them; see pb_runs.csv)", #failed, #rows))
end
