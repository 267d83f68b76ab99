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
-- <out>/campaign: a rerun skips the finished ones, so an interrupted study resumes.
-- Outputs in --out: pb_runs.csv, pb_effects.csv, pb_validation.json, pb_runs.png,
-- pb_effects.png, result.json.
local util = require("lib.util")
local mud = require("lib.mud")
local report = require("report")
local doe = require("paddy.doe")

local P = paddy.parameters{
  {name = "particle_diameter", default = 0.010, unit = "m", min = 0.001, max = 0.04,
   description = "sphere diameter of the slump runs (the reference: 0.002; coarse grained above)"},
  {name = "runs", default = "", description = "comma-separated run numbers of Table 4 to simulate (empty: all 13)"},
  {name = "seed", default = 1, type = "integer", min = 1, max = 2147483647, description = "seed of every run (fill jitter)"},
  {name = "max_parallel", default = 1, type = "integer", min = 1, max = 256, description = "slump runs at once"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each slump run"},
  {name = "contact_conventions", default = "paddy", choices = mud.convention_names,
   description = "contact conventions of every run (lib/mud.lua; edem: EDEM as documented, 0.2 T_R by default)"},
  {name = "timestep_fraction", default = 0.0, min = 0, max = 0.5, description = "time step / Rayleigh time of every run (0: slump.lua's default for the conventions: paddy 0.1, edem 0.2)"},
  {name = "fallback_timestep_fraction", default = 0.05, min = 0, max = 0.5,
   description = "a run that stops because its time step is too large runs again with this fraction (0: never)"},
  {name = "max_attempts", default = 1, type = "integer", min = 1, max = 10, description = "attempts per job (the runs are deterministic)"},
  {name = "slump_set", default = "", description = "extra slump.lua parameters for every run, e.g. 'cone=none,max_time=0.5'"},
  {name = "slump_script", default = "../slump.lua", description = "the slump experiment (relative: beside this script)"},
  {name = "reference_dir", default = "", description = "shared/reference directory (empty: <repo>/../shared/reference)"},
  {name = "campaign_dir", default = "", description = "campaign directory (empty: <out>/campaign)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys (empty: hash of the paddy executable)"},
  {name = "pictures", default = true, description = "draw pb_runs.png and pb_effects.png with gnuplot"},
}

-- Reference tables. Table 3 names → the slump.lua parameter (experiments/lib/mud.lua) of each factor.
local PARAM = {
  H1 = "mud_mud_restitution", H2 = "mud_mud_friction", H3 = "mud_mud_rolling_friction",
  H4 = "mud_steel_restitution", H5 = "mud_steel_friction", H6 = "mud_steel_rolling_friction",
  H7 = "jkr_surface_energy",
}
local FACTORS = {"H1", "H2", "H3", "H4", "H5", "H6", "H7"}
local ref_dir = report.reference_dir(P.reference_dir)
local table4 = util.read_csv(ref_dir .. "/table4_plackett_burman.csv")
local levels = {}
for _, row in ipairs((util.read_csv(ref_dir .. "/table3_pb_levels.csv"))) do levels[row.symbol] = row end
for _, h in ipairs(FACTORS) do
  if not levels[h] then error("table3_pb_levels.csv has no row " .. h) end
end
-- The centre is computed as the midpoint of the levels, as the calibration computes it
-- (lib/calibration/input.lua), so that the two share the run's job (the Table 3 centre column
-- agrees to rounding; a table that disagrees more is an error).
local function real_level(h, coded)
  local lv = levels[h]
  if coded == 0 then
    local mid = (lv.low + lv.high) / 2
    if math.abs(mid - lv.center) > 1e-9 * math.max(1, math.abs(mid)) then
      error(string.format("table3_pb_levels.csv: %s centre %g is not the midpoint of %g and %g", h, lv.center, lv.low, lv.high))
    end
    return mid
  end
  return coded < 0 and lv.low or lv.high
end

local wanted = {}
local run_list = report.numbers(P.runs, "runs")
if run_list then
  for _, n in ipairs(run_list) do wanted[math.tointeger(n) or n] = true end
end

local script = P.slump_script
if not script:match("^/") then script = report.script_dir() .. "/" .. script end
local extra = report.assignments(P.slump_set, "slump_set")
for _, h in ipairs(FACTORS) do
  if extra[PARAM[h]] ~= nil then error("slump_set must not set the design factor " .. PARAM[h]) end
end

local campaign_dir = P.campaign_dir ~= "" and P.campaign_dir or paddy.out_dir .. "/campaign"
local function campaign()
  return paddy.campaign{dir = campaign_dir, max_parallel = P.max_parallel, threads_per_job = P.threads_per_job,
                        max_attempts = P.max_attempts, code_version = P.code_version ~= "" and P.code_version or nil}
end
-- The error a job left in an earlier invocation (failed.json), or nil.
local function earlier_error(key)
  local f = io.open(campaign_dir .. "/jobs/" .. key .. "/failed.json", "r")
  if not f then return nil end
  local text = f:read("a")
  f:close()
  return text
end
local function timestep_failure(message)
  return P.fallback_timestep_fraction > 0 and message ~= nil and message:find("time step", 1, true) ~= nil
         and message:find("too large", 1, true) ~= nil
end

-- Round 1: every run at timestep_fraction; a run that failed before on its time step goes
-- straight to round 2 (its key is found with a second campaign object that never runs).
local c, probe = campaign(), campaign()
local design = {}
for _, row in ipairs(table4) do
  if not run_list or wanted[row.run] then
    local params = report.merge({particle_diameter = P.particle_diameter, progress = false}, extra)
    if P.timestep_fraction > 0 then params.timestep_fraction = P.timestep_fraction end
    -- Only a non-default choice enters the job (the paddy runs keep their earlier job keys).
    if P.contact_conventions ~= mud.default_conventions then params.contact_conventions = P.contact_conventions end
    local real = {}
    for _, h in ipairs(FACTORS) do
      real[h] = real_level(h, row[h])
      params[PARAM[h]] = real[h]
    end
    local d = {row = row, real = real, params = params,  -- else slump.lua's default of the conventions
               timestep_fraction = P.timestep_fraction > 0 and P.timestep_fraction or mud.conventions[P.contact_conventions].timestep_fraction}
    local key = probe:submit{script = script, params = params, seed = P.seed}
    local before = earlier_error(key)
    if probe:status(key) ~= "done" and timestep_failure(before) then
      d.first_key, d.first_error = key, before
    else
      d.key = c:submit{script = script, params = params, seed = P.seed}
    end
    design[#design + 1] = d
  end
end
io.stderr:write(string.format("plackett_burman: %d runs of %s, d = %.1f mm, campaign %s\n",
                              #design, script, P.particle_diameter * 1000, campaign_dir))
local t0 = os.time()
local round1 = {}
for i, run in ipairs(c:run()) do round1[i] = run end
local results, k1 = {}, 0
local c2, second = nil, {}
for i, d in ipairs(design) do
  local run
  if d.key then
    k1 = k1 + 1
    run = round1[k1]
    if run.status ~= "done" and timestep_failure(run.error) then d.first_key, d.first_error, run = run.key, run.error, nil end
  end
  if not d.key or not run then
    c2 = c2 or campaign()
    local params = report.merge(d.params, {timestep_fraction = P.fallback_timestep_fraction})
    d.fallback = true
    d.timestep_fraction = P.fallback_timestep_fraction
    io.stderr:write(string.format("plackett_burman: run %d stopped on its time step; again with timestep_fraction = %g\n",
                                  d.row.run, P.fallback_timestep_fraction))
    second[#second + 1] = i
    c2:submit{script = script, params = params, seed = P.seed}
  end
  results[i] = run
end
if c2 then
  for k, run in ipairs(c2:run()) do results[second[k]] = run end
end

-- Collect.
local rows, done, failed = {}, {}, {}
for i, run in ipairs(results) do
  local d = design[i]
  local entry = {run = d.row.run, key = run.key, status = run.status, error = run.error,
                 timestep_fraction = d.timestep_fraction, fallback = d.fallback or false,
                 first_key = d.first_key, first_error = d.first_error and d.first_error:sub(1, 400) or nil,
                 coded = {}, real = d.real, edem = {slump_mm = d.row.slump_mm, slump_flow_mm = d.row.slump_flow_mm}}
  for k = 1, 11 do entry.coded["H" .. k] = d.row["H" .. k] end
  if run.status == "done" then
    entry.paddy = report.slump_row(run)
    entry.difference = {slump_mm = entry.paddy.slump_mm - d.row.slump_mm,
                        slump_flow_mm = entry.paddy.slump_flow_mm - d.row.slump_flow_mm}
    done[#done + 1] = entry
  else
    failed[#failed + 1] = entry
    io.stderr:write(string.format("plackett_burman: run %d failed: %s\n", d.row.run, tostring(run.error)))
  end
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
local RESPONSES = {"slump_mm", "slump_flow_mm"}
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

-- Agreement over the runs: mean difference, RMS difference, correlation.
local function agreement(y)
  local n, sd, sq, sx, sy, sxx, syy, sxy = 0, 0, 0, 0, 0, 0, 0, 0
  for _, e in ipairs(done) do
    local a, b = e.edem[y], e.paddy[y]
    n, sd, sq = n + 1, sd + (b - a), sq + (b - a) ^ 2
    sx, sy, sxx, syy, sxy = sx + a, sy + b, sxx + a * a, syy + b * b, sxy + a * b
  end
  if n == 0 then return {runs = 0} end
  local cov, vx, vy = sxy - sx * sy / n, sxx - sx * sx / n, syy - sy * sy / n
  local corr = (vx > 0 and vy > 0) and cov / math.sqrt(vx * vy) or nil
  local _, edem_sd = report.mean_std((function() local t = {} for _, e in ipairs(done) do t[#t + 1] = e.edem[y] end return t end)())
  local _, paddy_sd = report.mean_std((function() local t = {} for _, e in ipairs(done) do t[#t + 1] = e.paddy[y] end return t end)())
  return {runs = n, mean_difference = sd / n, rms_difference = math.sqrt(sq / n), correlation = corr,
          edem_mean = sx / n, paddy_mean = sy / n, edem_std = edem_sd, paddy_std = paddy_sd}
end

local wall = {}
for _, e in ipairs(done) do wall[#wall + 1] = e.paddy.wall_time_s or 0 end
local wall_mean = report.mean_std(wall)
local wall_total = 0
for _, w in ipairs(wall) do wall_total = wall_total + w end

local doc = {
  study = "Plackett-Burman screening of the reference (Table 4), Paddy vs EDEM",
  particle_diameter = P.particle_diameter, seed = P.seed, slump_set = extra,
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
  agreement = {slump_mm = agreement("slump_mm"), slump_flow_mm = agreement("slump_flow_mm")},
  finished = #done, failed = #failed,
  run_wall_time_s = {mean = wall_mean, total = wall_total},
  campaign_wall_time_s = os.difftime(os.time(), t0),
}
report.write_json("pb_validation.json", doc)

-- Pictures: per run (EDEM vs Paddy), and the main-effect coefficients side by side. Both are two
-- clustered bar charts (slump above, slump-flow below) of the columns 2-5 of a data file.
local function edem_vs_paddy(stem, title, dat, key, xlabel, yrange)
  return util.gnuplot(stem, string.format([[
set terminal pngcairo size 900,800 noenhanced font 'sans,11'
set output '%s'
set multiplot layout 2,1 title '%s'
set style data histogram; set style histogram clustered gap 1; set style fill solid 0.8 border -1
set boxwidth 0.9; set grid ytics; set key %s horizontal; set xzeroaxis lt -1; set yrange %s
set ylabel 'slump [mm]'
plot '%s' using 2:xtic(1) title 'EDEM' lc rgb '#4477aa', '' using 3 title 'Paddy' lc rgb '#cc6644'
set ylabel 'slump-flow [mm]'; set xlabel '%s'
plot '%s' using 4:xtic(1) title 'EDEM' lc rgb '#4477aa', '' using 5 title 'Paddy' lc rgb '#cc6644'
unset multiplot]], util.out(stem .. ".png"), title, key, yrange, dat, xlabel, dat))
end
local pictures = {}
if P.pictures and #done > 0 then
  local lines = {}
  for _, e in ipairs(done) do
    lines[#lines + 1] = {e.run, e.edem.slump_mm, e.paddy.slump_mm, e.edem.slump_flow_mm, e.paddy.slump_flow_mm}
  end
  util.write_columns("pb_runs.dat", "run edem_slump paddy_slump edem_flow paddy_flow", lines)
  pictures.runs = edem_vs_paddy("pb_runs", string.format("Plackett-Burman runs (Table 4): EDEM (reference, 2 mm) vs Paddy (%.0f mm spheres)",
                                                         P.particle_diameter * 1000),
                                util.out("pb_runs.dat"), "top right", "run (13 = centre point)", "[0:*]")
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
    pictures.effects = edem_vs_paddy("pb_effects",
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
