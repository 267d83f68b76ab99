-- What the plate tack test (experiments/tack.lua) sees of the free parameter and of each candidate
-- effect of the discovery workflow (docs/discovery.md): every probe at every seed and pull speed
-- is one tack run at the default resolution with one parameter changed from the base (the default
-- material set, every candidate off). Documentation and the measured table: docs/experiments.md,
-- "Plate tack test", "What the tack test tells apart (measured)".
--
--   paddy run experiments/validation/tack_sensitivity.lua --out results/validation/tack_sensitivity \
--       [--set seeds=1,2 --set pull_speeds=0.01,0.04 --set max_parallel=1]
--
-- Probes: "base"; "cohesion": jkr_surface_energy raised by free_step (10 % of the discovery
-- range 0-0.2 J/m^2) from the material's value; and each of `candidates`, one at a time. Every run
-- gets the material's calibration time step explicitly (timestep_fraction, timestep_damping), so
-- that a run whose jkr_surface_energy is given steps like the base (lib/mud.lua: a contact
-- parameter given with --set would otherwise switch to the conventions' step).
-- Change of an observable y for a probe at one speed: the mean over the seeds of
-- y(probe, seed) − y(base, seed) (the same fill seed; the effects act from the pour on, so the fills
-- still differ), its scatter the standard deviation of those differences (n − 1).
-- The runs are jobs of a campaign (docs/campaign.md) in <out>/campaign; a rerun skips the finished
-- ones, so the study can be run a few jobs at a time (--set probes=..., seeds=..., pull_speeds=...
-- with the same campaign_dir) and then whole to write the tables. Outputs in --out:
-- tack_sensitivity.csv (every run: its observables, force and tension profiles; the grid is
-- tack.lua's tack_profile_mm), tack_sensitivity_changes.csv
-- (per probe, speed and observable: base and probe mean and sd over the seeds, the change and its
-- scatter), tack_sensitivity.json (all of it), tack_sensitivity_curves_<k>.png (the smoothed pull
-- force of every probe at the first seed, one picture per pull speed, k in the order of pull_speeds).
local util = require("lib.util")
local mud = require("lib.mud")
local chart = require("lib.chart")
local report = require("report")

local P = paddy.parameters{
  {name = "probes", default = "base,cohesion,candidates", description = "which probes: base, cohesion, candidates (all of `candidates`) or candidate parameter names, comma-separated"},
  {name = "candidates", default = "mud_steel_surface_energy=0.15;liquid_bridge_volume=0.025;lubrication_viscosity=0.02;plastic_adhesion=0.05",
   description = "candidate probes, 'parameter=value;...' (half of each candidate's discovery range, lubrication at the top of its range)"},
  {name = "free_step", default = 0.02, unit = "J/m^2", min = 1e-6, max = 1, description = "the cohesion probe: jkr_surface_energy raised by this from the material's value (10 % of the range 0-0.2)"},
  {name = "seeds", default = "1,2", description = "fill seeds (comma-separated)"},
  {name = "pull_speeds", default = "0.01,0.04", unit = "m/s", description = "pull speeds (comma-separated)"},
  {name = "tack_set", default = "", description = "extra tack.lua parameters for every run, 'name=value,...'"},
  {name = "max_parallel", default = 1, type = "integer", min = 1, max = 256, description = "tack runs at once"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each run"},
  {name = "campaign_dir", default = "", description = "campaign directory (empty: <out>/campaign)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys (empty: hash of the paddy executable)"},
  {name = "pictures", default = true, description = "draw tack_sensitivity_curves_<k>.png (one per pull speed) with gnuplot"},
}

-- Observables compared (result keys of tack.lua, all scalars), in the tables' order.
local OBSERVABLES = {"tack_peak_force_N", "tack_work_J", "tack_range_mm", "tack_detach_mm", "tack_final_force_N",
                     "tack_mass_on_plate_g", "tack_peak_mm", "tack_release_mm", "tack_preload_N", "tack_hold_end_N"}

local speeds = report.numbers(P.pull_speeds, "pull_speeds") or error("pull_speeds is empty", 0)
for _, v in ipairs(speeds) do
  if v < 1e-4 or v > 1 then error(string.format("pull_speeds: %g m/s is outside the allowed range 0.0001-1 m/s", v), 0) end
end
local seeds = report.seed_list(P.seeds)
local extra = report.assignments(P.tack_set, "tack_set")
for _, name in ipairs({"pull_speed", "seed", "timestep_fraction", "timestep_damping"}) do
  if extra[name] ~= nil then error("tack_set must not set " .. name .. " (use pull_speeds, seeds; the step is the material's)", 0) end
end

-- The base: the default material set (conventions paddy, material auto) and its calibration step.
local set = mud.materials[mud.conventions[mud.default_conventions].default_material]
local gamma0 = set.values.jkr_surface_energy
local cal = set.calibrated_with
local base_params = {timestep_fraction = cal.timestep_fraction, timestep_damping = cal.timestep_damping,
                     progress = false, pictures = false, snapshot_interval = 0}

-- Probes: {name, parameter, value}.
local all = {{name = "base"}, {name = "cohesion", parameter = "jkr_surface_energy", value = gamma0 + P.free_step}}
for item in P.candidates:gmatch("[^;]+") do
  local name, value = item:match("^%s*([%w_]+)%s*=%s*(.-)%s*$")
  if not name or not tonumber(value) then error("candidates: '" .. item .. "' is not parameter=number", 0) end
  all[#all + 1] = {name = name, parameter = name, value = tonumber(value), candidate = true}
end
local wanted = {}
for item in P.probes:gmatch("[^,]+") do wanted[item:match("^%s*(.-)%s*$")] = true end
local probes = {}
for _, p in ipairs(all) do
  if wanted[p.name] or (p.candidate and wanted.candidates) then probes[#probes + 1] = p end
end
if #probes == 0 then error("probes = '" .. P.probes .. "' selects none of: base, cohesion, candidates or a candidate's parameter", 0) end

local script = report.script_dir() .. "/../tack.lua"
local c, campaign_dir = report.campaign(P, 1)
local jobs = {}
for _, p in ipairs(probes) do
  for _, v in ipairs(speeds) do
    for _, s in ipairs(seeds) do
      local params = report.merge(base_params, extra)
      params.pull_speed = v
      if p.parameter then params[p.parameter] = p.value end
      jobs[#jobs + 1] = {probe = p, speed = v, seed = s, key = c:submit{script = script, params = params, seed = s}}
    end
  end
end
io.stderr:write(string.format("tack_sensitivity: %d probes x %d speeds x %d seeds = %d runs, campaign %s\n", #probes, #speeds,
                              #seeds, #jobs, campaign_dir))
local results = c:run()

-- Every run: one row.
local runs, rows, failed = {}, {}, 0
local dirs = {}     -- job directory of each run (for its curve; not in the JSON: a local path)
local value = {}   -- value[probe][speed][seed] = result table
local profile_n = 0
for i, run in ipairs(results) do
  local j = jobs[i]
  local e = {probe = j.probe.name, parameter = j.probe.parameter or "", value = j.probe.value, pull_speed = j.speed,
             seed = j.seed, status = run.status, error = run.error}
  runs[#runs + 1] = e
  dirs[e] = run.dir
  if run.status ~= "done" then
    failed = failed + 1
    io.stderr:write(string.format("tack_sensitivity: %s at %g m/s, seed %d failed: %s\n", j.probe.name, j.speed, j.seed,
                                  tostring(run.error)))
  else
    local r = run.result
    for _, k in ipairs(OBSERVABLES) do e[k] = r[k] end
    e.tack_force_profile_N, e.tack_tension_profile_N = r.tack_force_profile_N, r.tack_tension_profile_N
    e.tack_profile_mm = r.tack_profile_mm
    e.particles, e.simulated_time_s, e.wall_time_s = r.particles, r.simulated_time_s, (run.metadata or {}).wall_time
    e.final_state_hash = (run.metadata or {}).final_state_hash
    e.code_version = paddy.read_json(run.dir .. "/job.json").code_version  -- the build that ran it
    profile_n = math.max(profile_n, #r.tack_force_profile_N)
    value[j.probe.name] = value[j.probe.name] or {}
    value[j.probe.name][j.speed] = value[j.probe.name][j.speed] or {}
    value[j.probe.name][j.speed][j.seed] = r
  end
end
local columns = {"probe", "parameter", "value", "pull_speed_m_s", "seed", "status"}
for _, k in ipairs(OBSERVABLES) do columns[#columns + 1] = k end
for _, k in ipairs({"particles", "simulated_time_s", "wall_time_s", "final_state_hash"}) do columns[#columns + 1] = k end
for b = 1, profile_n do columns[#columns + 1] = "profile_" .. b .. "_N" end
for b = 1, profile_n do columns[#columns + 1] = "tension_" .. b .. "_N" end
for _, e in ipairs(runs) do
  local row = {e.probe, e.parameter, report.cell(e.value), e.pull_speed, e.seed, e.status}
  for _, k in ipairs(OBSERVABLES) do row[#row + 1] = report.cell(e[k]) end
  for _, k in ipairs({"particles", "simulated_time_s", "wall_time_s", "final_state_hash"}) do row[#row + 1] = report.cell(e[k]) end
  for b = 1, profile_n do row[#row + 1] = report.cell((e.tack_force_profile_N or {})[b]) end
  for b = 1, profile_n do row[#row + 1] = report.cell((e.tack_tension_profile_N or {})[b]) end
  rows[#rows + 1] = row
end
util.write_csv("tack_sensitivity.csv", columns, rows)

-- Changes against the base, per probe, speed and observable (the seeds both have).
local changes, change_rows = {}, {}
local function stats(list) local m, sd, n = report.mean_std(list) return {mean = m, sd = sd, n = n} end
for _, p in ipairs(probes) do
  if p.name ~= "base" then
    for _, v in ipairs(speeds) do
      local base_runs, probe_runs = ((value.base or {})[v]) or {}, ((value[p.name] or {})[v]) or {}
      for _, k in ipairs(OBSERVABLES) do
        local b, q, d = {}, {}, {}
        for _, s in ipairs(seeds) do
          local rb, rq = base_runs[s], probe_runs[s]
          if rb and rq and rb[k] and rq[k] then
            b[#b + 1], q[#q + 1], d[#d + 1] = rb[k], rq[k], rq[k] - rb[k]
          end
        end
        if #d > 0 then
          local sb, sq, sd = stats(b), stats(q), stats(d)
          local row = {probe = p.name, parameter = p.parameter, value = p.value, pull_speed = v, observable = k,
                       base_mean = sb.mean, base_sd = sb.sd, probe_mean = sq.mean, probe_sd = sq.sd,
                       change = sd.mean, change_sd = sd.sd, seeds = sd.n}
          changes[#changes + 1] = row
          change_rows[#change_rows + 1] = {p.name, p.parameter, p.value, v, k, sb.mean, report.cell(sb.sd), sq.mean,
                                           report.cell(sq.sd), sd.mean, report.cell(sd.sd), sd.n}
        end
      end
    end
  end
end
util.write_csv("tack_sensitivity_changes.csv", {"probe", "parameter", "value", "pull_speed_m_s", "observable", "base_mean",
                                                "base_sd", "probe_mean", "probe_sd", "change", "change_sd", "seeds"}, change_rows)

-- Picture: the smoothed pull force of every probe at the first seed, one chart per speed.
local pictures = {}
if P.pictures then
  local palette = {"#000000", "#8b5a2b", "#d62728", "#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf"}
  for iv, v in ipairs(speeds) do
    local series, peak = {}, 0.01
    for ip, p in ipairs(probes) do
      for _, e in ipairs(runs) do
        if e.probe == p.name and e.pull_speed == v and e.seed == seeds[1] and e.status == "done" then
          local curve = util.read_csv(dirs[e] .. "/tack_curve.csv")
          local pts = {}
          for k, row in ipairs(curve) do pts[k] = {row.displacement_mm, row.smoothed_pull_force_N} end
          peak = math.max(peak, e.tack_peak_force_N or 0)
          local label = p.parameter and string.format("%s = %g", p.parameter, p.value) or string.format("base (jkr_surface_energy = %g)", gamma0)
          series[#series + 1] = {rows = pts, using = "1:2", with = string.format("lines lw 2 lc rgb '%s'", palette[(ip - 1) % #palette + 1]),
                                 title = label}
        end
      end
    end
    if #series > 0 then
      local stem = string.format("tack_sensitivity_curves_%d", iv)
      local png = chart.plot(stem, {
        title = string.format("Plate tack: smoothed pull force at %g m/s, seed %d, one probe per line", v, seeds[1]),
        xlabel = "plate displacement u from the press depth [mm]", ylabel = "pull force of the mud on the plate [N]",
        settings = {"set key top right", "set xzeroaxis lt -1", "set autoscale xfix",
                    string.format("set yrange [%g:%g]", -0.25 * peak, 1.3 * peak)},
        series = series,
      })
      if png then pictures[#pictures + 1] = stem .. ".png" end
    end
  end
end

report.write_json("tack_sensitivity.json", {
  description = "plate tack test (experiments/tack.lua): each probe's change of the observables against the base, "
                .. "per pull speed; change = mean over the seeds of (probe - base) at the same seed, change_sd = their sd",
  base = {material = mud.conventions[mud.default_conventions].default_material, jkr_surface_energy = gamma0,
          timestep_fraction = cal.timestep_fraction, timestep_damping = cal.timestep_damping, tack_set = extra},
  probes = probes, seeds = seeds, pull_speeds_m_s = speeds, observables = OBSERVABLES,
  runs = runs, changes = changes, failed = failed, pictures = pictures,
})
paddy.result{runs = #runs, failed = failed, changes = changes}
print(string.format("tack_sensitivity: %d runs (%d failed); tables %s, %s", #runs, failed, util.out("tack_sensitivity.csv"),
                    util.out("tack_sensitivity_changes.csv")))
if failed > 0 then error(string.format("tack_sensitivity: %d of %d runs failed (see above)", failed, #runs), 0) end
