-- The slump runs of a validation study against the reference's EDEM tables (plackett_burman.lua:
-- Table 4, steepest_ascent.lua: Table 6): the parameters both scripts share, the map from the
-- reference's factors H1..H7 (Table 3) to slump.lua's parameters, the Table 3 levels, the runs as
-- jobs of one campaign with the time-step fallback, the entry of a run beside the reference's
-- values, the agreement statistics and the EDEM-vs-Paddy bar chart.
--
--   local slump_jobs = require("slump_jobs")
--   local P = paddy.parameters(slump_jobs.parameters{ {name = "runs", ...}, {name = "pictures", ...} })
--   local study = slump_jobs.new(P, "plackett_burman")
--   local design = {{label = "run 1", params = study:params{H1 = 0.01, ...}}, ...}
--   local results = study:run(design)   -- results[i]: the c:run() entry of design[i]
--   local entry = study:entry(design[i], results[i], {slump_mm = 265, slump_flow_mm = 635})
--
-- A job's parameters: particle_diameter, progress = false, slump_set, timestep_fraction (only if
-- > 0), contact_conventions (only a non-default choice) and the 7 factors. Two scripts that ask
-- for the same point therefore share its job in one campaign directory.
local util = require("lib.util")
local mud = require("lib.mud")
local report = require("report")
local M = {}

-- Table 3 symbols → the slump.lua parameter (experiments/lib/mud.lua) of each real factor.
M.PARAM = {
  H1 = "mud_mud_restitution", H2 = "mud_mud_friction", H3 = "mud_mud_rolling_friction",
  H4 = "mud_steel_restitution", H5 = "mud_steel_friction", H6 = "mud_steel_rolling_friction",
  H7 = "jkr_surface_energy",
}
M.FACTORS = {"H1", "H2", "H3", "H4", "H5", "H6", "H7"}
M.RESPONSES = {"slump_mm", "slump_flow_mm"}

-- The parameter specifications the study scripts share, followed by the script's own.
function M.parameters(own)
  local specs = {
    {name = "particle_diameter", default = 0.010, unit = "m", min = 0.001, max = 0.04,
     description = "sphere diameter of the slump runs (the reference: 0.002; coarse grained above)"},
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
  }
  for _, s in ipairs(own or {}) do specs[#specs + 1] = s end
  return specs
end

-- The rows of table3_pb_levels.csv by symbol; an error naming the file if a factor is missing.
function M.levels(ref_dir)
  local levels = {}
  for _, row in ipairs((util.read_csv(ref_dir .. "/table3_pb_levels.csv"))) do levels[row.symbol] = row end
  for _, h in ipairs(M.FACTORS) do
    if not levels[h] then error("table3_pb_levels.csv has no row " .. h) end
  end
  return levels
end

-- The real value of factor h at a coded level (-1 / 0 / +1). The centre is computed as the
-- midpoint of the levels, as the calibration computes it (lib/calibration/input.lua), so that the
-- two share the run's job (the Table 3 centre column agrees to rounding; a table that disagrees
-- more is an error).
function M.real_level(levels, h, coded)
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

local Study = {}
Study.__index = Study

-- A study of the parameters P (from M.parameters); name prefixes its messages.
function M.new(P, name)
  local self = setmetatable({P = P, name = name}, Study)
  self.ref_dir = report.reference_dir(P.reference_dir)
  local script = P.slump_script
  if not script:match("^/") then script = report.script_dir() .. "/" .. script end
  self.script = script
  self.extra = report.assignments(P.slump_set, "slump_set")
  for _, h in ipairs(M.FACTORS) do
    if self.extra[M.PARAM[h]] ~= nil then error("slump_set must not set the design factor " .. M.PARAM[h]) end
  end
  self.campaign_dir = report.campaign_dir(P)
  -- The step of a run that is not a fallback: the given fraction, else slump.lua's default of the conventions.
  self.timestep_fraction = P.timestep_fraction > 0 and P.timestep_fraction or mud.conventions[P.contact_conventions].timestep_fraction
  return self
end

-- The job parameters of a run with the real factor values `real` ({H1 = ..., ..., H7 = ...}).
function Study:params(real)
  local P = self.P
  local params = report.merge({particle_diameter = P.particle_diameter, progress = false}, self.extra)
  if P.timestep_fraction > 0 then params.timestep_fraction = P.timestep_fraction end
  -- Only a non-default choice enters the job (the paddy runs keep their earlier job keys).
  if P.contact_conventions ~= mud.default_conventions then params.contact_conventions = P.contact_conventions end
  for _, h in ipairs(M.FACTORS) do
    if real[h] == nil then error(self.name .. ": no value of factor " .. h) end
    params[M.PARAM[h]] = real[h]
  end
  return params
end

function Study:campaign()
  return (report.campaign(self.P, self.P.max_attempts))
end

-- The error a job left in an earlier invocation (failed.json), or nil.
function Study:earlier_error(key)
  local f = io.open(self.campaign_dir .. "/jobs/" .. key .. "/failed.json", "r")
  if not f then return nil end
  local text = f:read("a")
  f:close()
  return text
end

function Study:timestep_failure(message)
  return self.P.fallback_timestep_fraction > 0 and message ~= nil and message:find("time step", 1, true) ~= nil
         and message:find("too large", 1, true) ~= nil
end

-- Runs the design (a list of {label =, params =}) and returns the c:run() entry of each point, in
-- order. Round 1: every run at timestep_fraction; a run that stops because its time step is too
-- large runs again at fallback_timestep_fraction (round 2), and so does one that failed so in an
-- earlier invocation (its key is found with a second campaign object that never runs). Sets on
-- each point: timestep_fraction, fallback (true in round 2), first_key and first_error (round 1's
-- job and error).
function Study:run(design)
  local P, script = self.P, self.script
  local c, probe = self:campaign(), self:campaign()
  for _, d in ipairs(design) do
    d.timestep_fraction = self.timestep_fraction
    local key = probe:submit{script = script, params = d.params, seed = P.seed}
    local before = self:earlier_error(key)
    if probe:status(key) ~= "done" and self:timestep_failure(before) then
      d.first_key, d.first_error = key, before
    else
      d.key = c:submit{script = script, params = d.params, seed = P.seed}
    end
  end
  io.stderr:write(string.format("%s: %d runs of %s, d = %.1f mm, campaign %s\n",
                                self.name, #design, script, P.particle_diameter * 1000, self.campaign_dir))
  local round1 = {}
  for i, run in ipairs(c:run()) do round1[i] = run end
  local results, k1 = {}, 0
  local c2, second = nil, {}
  for i, d in ipairs(design) do
    local run
    if d.key then
      k1 = k1 + 1
      run = round1[k1]
      if run.status ~= "done" and self:timestep_failure(run.error) then d.first_key, d.first_error, run = run.key, run.error, nil end
    end
    if not d.key or not run then
      c2 = c2 or self:campaign()
      local params = report.merge(d.params, {timestep_fraction = P.fallback_timestep_fraction})
      d.fallback = true
      d.timestep_fraction = P.fallback_timestep_fraction
      io.stderr:write(string.format("%s: %s stopped on its time step; again with timestep_fraction = %g\n",
                                    self.name, d.label, P.fallback_timestep_fraction))
      second[#second + 1] = i
      c2:submit{script = script, params = params, seed = P.seed}
    end
    results[i] = run
  end
  if c2 then
    for k, run in ipairs(c2:run()) do results[second[k]] = run end
  end
  return results
end

-- The entry of a point d of the design and its run beside the reference's values edem
-- ({slump_mm =, slump_flow_mm =}): key, status, error, time step, fallback, edem, and for a
-- finished run paddy (report.slump_row) and difference (Paddy − EDEM). A failed run is reported
-- on stderr.
function Study:entry(d, run, edem)
  local e = {key = run.key, status = run.status, error = run.error, timestep_fraction = d.timestep_fraction,
             fallback = d.fallback or false, first_key = d.first_key,
             first_error = d.first_error and d.first_error:sub(1, 400) or nil, edem = edem}
  if run.status == "done" then
    e.paddy = report.slump_row(run)
    e.difference = {}
    for _, y in ipairs(M.RESPONSES) do e.difference[y] = e.paddy[y] - edem[y] end
  else
    io.stderr:write(string.format("%s: %s failed: %s\n", self.name, d.label, tostring(run.error)))
  end
  return e
end

-- Agreement of Paddy with EDEM over the finished entries (each with .edem and .paddy) for
-- response y: mean and RMS of the difference Paddy − EDEM, Pearson's correlation (nil if either
-- side is constant), the means and the sample standard deviations.
function M.agreement(done, y)
  local n, sd, sq, sx, sy, sxx, syy, sxy = 0, 0, 0, 0, 0, 0, 0, 0
  local edem, paddy_values = {}, {}
  for _, e in ipairs(done) do
    local a, b = e.edem[y], e.paddy[y]
    n, sd, sq = n + 1, sd + (b - a), sq + (b - a) ^ 2
    sx, sy, sxx, syy, sxy = sx + a, sy + b, sxx + a * a, syy + b * b, sxy + a * b
    edem[#edem + 1], paddy_values[#paddy_values + 1] = a, b
  end
  if n == 0 then return {runs = 0} end
  local cov, vx, vy = sxy - sx * sy / n, sxx - sx * sx / n, syy - sy * sy / n
  local corr = (vx > 0 and vy > 0) and cov / math.sqrt(vx * vy) or nil
  local _, edem_sd = report.mean_std(edem)
  local _, paddy_sd = report.mean_std(paddy_values)
  return {runs = n, mean_difference = sd / n, rms_difference = math.sqrt(sq / n), correlation = corr,
          edem_mean = sx / n, paddy_mean = sy / n, edem_std = edem_sd, paddy_std = paddy_sd}
end

-- Wall time of the finished runs: {mean =, total =} [s].
function M.wall_times(done)
  local wall, total = {}, 0
  for _, e in ipairs(done) do
    wall[#wall + 1] = e.paddy.wall_time_s or 0
    total = total + wall[#wall]
  end
  return {mean = report.mean_std(wall), total = total}
end

-- Two clustered bar charts, EDEM vs Paddy (slump above, slump-flow below), of the columns 2-5 of
-- the data file dat (label edem_slump paddy_slump edem_flow paddy_flow) into <stem>.png.
function M.edem_vs_paddy_chart(stem, title, dat, key, xlabel, yrange)
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

-- The per-run chart of a study: EDEM vs Paddy for every finished entry, labelled on the x axis by
-- its field label_key ("run", "step"); the data in <stem>.dat, the picture in <stem>.png
-- (edem_vs_paddy_chart).
function M.runs_chart(stem, done, label_key, title, xlabel)
  local lines = {}
  for _, e in ipairs(done) do
    lines[#lines + 1] = {e[label_key], e.edem.slump_mm, e.paddy.slump_mm, e.edem.slump_flow_mm, e.paddy.slump_flow_mm}
  end
  util.write_columns(stem .. ".dat", label_key .. " edem_slump paddy_slump edem_flow paddy_flow", lines)
  return M.edem_vs_paddy_chart(stem, title, util.out(stem .. ".dat"), "top right", xlabel, "[0:*]")
end

return M
