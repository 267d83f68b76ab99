-- Two virtual tests, one material, at several sphere sizes: the yield stress from the vane start-up
-- test and the one the slump implies (the same runs as validation/yield_stress.lua: the vane
-- relation of Nguyen & Boger 1983 on the peak torque; Schowalter & Christensen 1998 on the slump),
-- each at a series of sphere diameters d, for one parameter set and several seeds. Each test's
-- yield stress is fitted as a straight line in d over all its runs (lib/line_fit.lua) and read at
-- d → 0 (the continuum both formulas assume) and at the real grain (grain_diameter, the size the
-- contact parameters are given for; coarse graining keeps the stresses of an exact scaling
-- unchanged, so a trend in d is the tests' resolution error). The ratio τ_vane / τ_slump at each
-- and its standard error (the two fits are independent: δr/r = √((δv/v)² + (δs/s)²)).
-- Documentation: docs/validation.md §6.2.
--
--   paddy run experiments/validation/yield_stress_resolution.lua --out results/ys_resolution \
--       [--set rheometer_diameters=0.012,0.01,0.008,0.006 --set slump_diameters=0.02,0.014,0.01 --set seeds=1,2]
--
-- The runs are jobs of a campaign (docs/campaign.md); their parameters are validation/yield_stress.lua's
-- (validation/yield_stress_jobs.lua), so a campaign_dir shared with that study reuses its runs. Outputs in --out: ys_resolution_runs.csv,
-- ys_resolution_fit.csv, ys_resolution.json (= result.json), ys_resolution.png.
local util = require("lib.util")
local line_fit = require("lib.line_fit")
local report = require("report")
local ys_jobs = require("yield_stress_jobs")

local P = paddy.parameters{
  {name = "parameter", default = "jkr_surface_energy", description = "the mud parameter set to `value` in every run"},
  {name = "value", default = 0.06, min = 0, max = 10, description = "its value (2 mm value; default: the centre of Table 3's H7)"},
  {name = "seeds", default = "1,2", description = "seeds of every diameter (comma-separated)"},
  {name = "rheometer_diameters", default = "0.012,0.01,0.008,0.006", description = "sphere diameters of the vane runs [m] (comma-separated, at least 2 distinct)"},
  {name = "slump_diameters", default = "0.02,0.014,0.01", description = "sphere diameters of the slump runs [m] (comma-separated, at least 2 distinct)"},
  {name = "grain_diameter", default = 0.002, unit = "m", min = 0, max = 0.04, description = "the real grain the parameters are given for: where the lines are read besides d = 0"},
  {name = "slump_set", default = "", description = "extra slump.lua parameters for every run, e.g. 'max_time=4'"},
  {name = "rheometer_set", default = "", description = "extra rheometer.lua parameters for every run, e.g. 'startup_rpm=1'"},
  {name = "target", default = 0.25, min = 0, max = 10, description = "agreement target: |ratio − 1| within this"},
  {name = "max_parallel", default = 1, type = "integer", min = 1, max = 256, description = "runs at once"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each run"},
  {name = "campaign_dir", default = "", description = "campaign directory (empty: <out>/campaign)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys (empty: hash of the paddy executable)"},
  {name = "pictures", default = true, description = "draw ys_resolution.png with gnuplot"},
}

local function diameters(text, name, max)
  local d = report.numbers(text, name) or error(name .. " is empty", 0)
  local distinct = {}
  for _, v in ipairs(d) do
    if not (v > 0 and v <= max) then
      error(string.format("%s: %g m is outside the allowed range (0, %g] m", name, v, max), 0)
    end
    distinct[v] = true
  end
  local n = 0
  for _ in pairs(distinct) do n = n + 1 end
  if n < 2 then error(string.format("%s = %s: a line in d needs at least 2 distinct diameters", name, text), 0) end
  return d
end
local d_vane = diameters(P.rheometer_diameters, "rheometer_diameters", 0.02)
local d_slump = diameters(P.slump_diameters, "slump_diameters", 0.04)
local seeds = report.seed_list(P.seeds)
local slump_extra, rheo_extra = ys_jobs.extras(P.parameter, P.slump_set, P.rheometer_set)

local dir = report.script_dir()
local c = report.campaign(P)  -- the campaign's default attempts
local jobs = {}
local function submit(test, d, s)
  local script, extra = test == "vane" and "rheometer.lua" or "slump.lua", test == "vane" and rheo_extra or slump_extra
  local params = ys_jobs.params(d, P.parameter, P.value, extra)
  jobs[#jobs + 1] = {test = test, d = d, seed = s, key = c:submit{script = dir .. "/../" .. script, params = params, seed = s}}
end
for _, s in ipairs(seeds) do
  for _, d in ipairs(d_vane) do submit("vane", d, s) end
  for _, d in ipairs(d_slump) do submit("slump", d, s) end
end
io.stderr:write(string.format("yield_stress_resolution: %d vane + %d slump diameters x %d seeds = %d runs\n", #d_vane, #d_slump,
                              #seeds, #jobs))
local results = c:run()

-- Per run, then per test and diameter.
-- A finished run without a yield stress (a slump the cone model cannot read, e.g. none at all) is
-- listed and counted, and left out of the line.
local runs, failed, without = {}, 0, 0
local points = {vane = {x = {}, y = {}}, slump = {x = {}, y = {}}}
for i, run in ipairs(results) do
  local j = jobs[i]
  local row = {test = j.test, diameter_m = j.d, seed = j.seed}
  if run.status == "done" then
    local r = run.result
    row.particles = r.particles
    row.wall_s = run.metadata and run.metadata.wall_time
    row.yield_stress_Pa = r.yield_stress_Pa
    if j.test == "vane" then
      row.peak_torque_Nm = r.startup and r.startup.peak_torque_Nm
      row.peak_angle_deg = r.startup and r.startup.peak_angle_deg
      row.peak_reached = r.startup and r.startup.peak_reached
    else
      row.slump_mm, row.slump_flow_mm, row.fill_solid_fraction = r.slump_mm, r.slump_flow_mm, r.fill_solid_fraction
    end
    if type(row.yield_stress_Pa) == "number" then
      local pt = points[j.test]
      pt.x[#pt.x + 1], pt.y[#pt.y + 1] = j.d, row.yield_stress_Pa
    else
      without = without + 1
      io.stderr:write(string.format("yield_stress_resolution: %s at %g m, seed %d gives no yield stress%s: left out of the line\n",
                                    j.test, j.d, j.seed, row.slump_mm and string.format(" (slump %.1f mm)", row.slump_mm) or ""))
    end
  else
    failed = failed + 1
    io.stderr:write(string.format("yield_stress_resolution: %s at %g m, seed %d failed: %s\n", j.test, j.d, j.seed, tostring(run.error)))
  end
  runs[#runs + 1] = row
end

local function by_diameter(test, ds)
  local out = {}
  for _, d in ipairs(ds) do
    local v = {}
    for _, r in ipairs(runs) do
      if r.test == test and r.diameter_m == d and r.yield_stress_Pa then v[#v + 1] = r.yield_stress_Pa end
    end
    local m, sd = report.mean_std(v)
    out[#out + 1] = {diameter_m = d, runs = #v, mean_Pa = m, std_Pa = sd, values = v}
  end
  return out
end

-- The lines and their values at d = 0 and at the grain.
local fits, errors = {}, {}
for _, test in ipairs({"vane", "slump"}) do
  local ok, f = pcall(line_fit.fit, {x = points[test].x, y = points[test].y, what = test .. " yield stress against d"})
  if ok then fits[test] = f else errors[test] = tostring(f) end
end
local function read_at(x0)
  local out = {diameter_m = x0}
  for _, test in ipairs({"vane", "slump"}) do
    if fits[test] then
      local v, se = line_fit.at(fits[test], x0)
      out[test] = {value_Pa = v, se_Pa = se}
    end
  end
  if out.vane and out.slump and out.slump.value_Pa > 0 then
    local v, s = out.vane, out.slump
    out.ratio = v.value_Pa / s.value_Pa
    if v.se_Pa and s.se_Pa then
      out.ratio_se = math.abs(out.ratio) * math.sqrt((v.se_Pa / v.value_Pa) ^ 2 + (s.se_Pa / s.value_Pa) ^ 2)
    end
    out.within_target = math.abs(out.ratio - 1) <= P.target
    -- agreement shown only when the whole 2-se interval lies inside the band
    out.shown_within_target = out.ratio_se ~= nil and math.abs(out.ratio - 1) + 2 * out.ratio_se <= P.target
  end
  return out
end
local at = {continuum = read_at(0), grain = read_at(P.grain_diameter)}
-- The ratio at the coarsest and finest diameters measured (per-diameter means).
local vane_d, slump_d = by_diameter("vane", d_vane), by_diameter("slump", d_slump)

-- Files.
local cols = {"test", "diameter_m", "seed", "particles", "yield_stress_Pa", "peak_torque_Nm", "peak_angle_deg", "peak_reached",
              "slump_mm", "slump_flow_mm", "fill_solid_fraction", "wall_s"}
util.write_csv("ys_resolution_runs.csv", cols, report.cells(runs, cols))
local frows = {}
for _, test in ipairs({"vane", "slump"}) do
  local f = fits[test]
  frows[#frows + 1] = {test, report.cell(f and f.n), report.cell(f and f.a), report.cell(f and f.se_a), report.cell(f and f.b),
                       report.cell(f and f.se_b), report.cell(f and f.r2),
                       report.cell(at.grain[test] and at.grain[test].value_Pa), report.cell(at.grain[test] and at.grain[test].se_Pa)}
end
util.write_csv("ys_resolution_fit.csv", {"test", "points", "at_d0_Pa", "at_d0_se_Pa", "slope_Pa_per_m", "slope_se_Pa_per_m", "r2",
                                         "at_grain_Pa", "at_grain_se_Pa"}, frows)

local doc = {parameter = P.parameter, value = P.value, seeds = seeds, grain_diameter = P.grain_diameter, target = P.target,
             slump_set = P.slump_set, rheometer_set = P.rheometer_set,
             runs = runs, vane = {by_diameter = vane_d, fit = fits.vane, fit_error = errors.vane},
             slump = {by_diameter = slump_d, fit = fits.slump, fit_error = errors.slump},
             at = at, failed = failed, without_yield_stress = without, finished = os.date("!%Y-%m-%dT%H:%M:%SZ")}
report.write_json("ys_resolution.json", doc)

local picture
if P.pictures and fits.vane and fits.slump then
  local data = {}
  for _, r in ipairs(runs) do
    if r.yield_stress_Pa then
      data[#data + 1] = {r.test == "vane" and 1 or 2, 1000 * r.diameter_m, r.yield_stress_Pa}
    end
  end
  util.write_columns("ys_resolution.dat", "test(1=vane,2=slump) d_mm tau_Pa", data)
  local dmax = 1000 * math.max(math.max(table.unpack(d_slump)), math.max(table.unpack(d_vane)))
  picture = util.gnuplot("ys_resolution", string.format([[
set title 'Yield stress against sphere diameter: vane start-up and slump, lines to d = 0'
set xlabel 'sphere diameter d [mm]'; set ylabel 'yield stress [Pa]'; set grid; set key top left
set xrange [0:%g]; set yrange [0:*]
set arrow from %g, graph 0 to %g, graph 1 nohead dt 3 lc rgb 'gray'
plot '%s' using ($1 == 1 ? $2 : 1/0):3 with points pt 7 ps 1.3 lc rgb '#d95f02' title 'vane (runs)', \
     %g + %g * x / 1000 lc rgb '#d95f02' title 'vane line', \
     '%s' using ($1 == 2 ? $2 : 1/0):3 with points pt 5 ps 1.3 lc rgb '#1b9e77' title 'slump (runs)', \
     %g + %g * x / 1000 lc rgb '#1b9e77' title 'slump line']],
    dmax * 1.05, 1000 * P.grain_diameter, 1000 * P.grain_diameter, util.out("ys_resolution.dat"), fits.vane.a, fits.vane.b,
    util.out("ys_resolution.dat"), fits.slump.a, fits.slump.b))
end

-- Console.
local function pm(v, se) return report.plus_minus(v, se, 1) end
print(string.format("%-6s %10s %6s %14s", "test", "d [mm]", "runs", "tau [Pa]"))
for _, t in ipairs({{"vane", vane_d}, {"slump", slump_d}}) do
  for _, e in ipairs(t[2]) do
    print(string.format("%-6s %10.1f %6d %14s", t[1], 1000 * e.diameter_m, e.runs, e.mean_Pa and pm(e.mean_Pa, e.std_Pa) or "-"))
  end
end
for _, name in ipairs({"continuum", "grain"}) do
  local a = at[name]
  if a.ratio then
    print(string.format("at d = %g mm: vane %s Pa, slump %s Pa, ratio %s (%s)", 1000 * a.diameter_m, pm(a.vane.value_Pa, a.vane.se_Pa),
                        pm(a.slump.value_Pa, a.slump.se_Pa), a.ratio_se and string.format("%.2f +- %.2f", a.ratio, a.ratio_se)
                        or string.format("%.2f", a.ratio),
                        a.shown_within_target and "within target" or a.within_target and "within target, not shown (se)" or "NOT within target"))
  end
end
for test, e in pairs(errors) do print("no line for " .. test .. ": " .. e) end

paddy.result{
  study = "ys_resolution.json",
  runs = #runs,
  failed = failed,
  without_yield_stress = without,
  vane_fit = fits.vane and {at_d0_Pa = fits.vane.a, se_at_d0_Pa = fits.vane.se_a, slope_Pa_per_m = fits.vane.b, se_slope = fits.vane.se_b, r2 = fits.vane.r2, n = fits.vane.n} or nil,
  slump_fit = fits.slump and {at_d0_Pa = fits.slump.a, se_at_d0_Pa = fits.slump.se_a, slope_Pa_per_m = fits.slump.b, se_slope = fits.slump.se_b, r2 = fits.slump.r2, n = fits.slump.n} or nil,
  continuum = at.continuum,
  grain = at.grain,
  pictures = picture and {resolution = picture} or nil,
}
