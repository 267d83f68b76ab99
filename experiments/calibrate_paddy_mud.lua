-- Calibration of the paddy-mud contact parameters against a laboratory slump test, the
-- reference procedure end to end on Paddy's own simulations (shared/reference/README.md), and
-- a surrogate-based strategy beside it. Documentation: docs/calibration.md.
--
--   paddy run experiments/calibrate_paddy_mud.lua --out results/calibration            # full
--   paddy run experiments/calibrate_paddy_mud.lua --set quick=true --out results/quick # ~10 min
--
-- What is measured and which parameters may move comes from the input file (default
-- calibration/paddy_mud.json beside this script): calibrate another mud by editing that file.
-- Every simulation is a campaign job keyed by its content (docs/campaign.md): running the same
-- command again after an interruption repeats nothing that finished.
--
-- The steps, each a block below:
--   1. Plackett-Burman screening of the factors (dummy columns, centre point), ANOVA with
--      curvature; the significant factors (p < alpha for either response) go on.
--   2. Steepest ascent from the origin in the input file along the significant factors, in the
--      direction that reduces the squared relative errors of the screening model; stops when
--      the error rises again. The best step becomes the centre of
--   3. a Box-Behnken design (half-ranges = the steps), each run replicated with other seeds and
--      averaged; quadratic model and ANOVA per response.
--   4. Desirability optimum toward the measured values inside the Box-Behnken region.
--   5. Verification: simulations at the optimum with several seeds against the measurements,
--      and the vane rheometer at the optimum (against a measured torque curve when one is given).
--   6. Report: report.html (offline), calibration.json, CSV tables, figures.
-- strategy = "surrogate" or "both": Gaussian-process surrogates of each response with expected
-- improvement of the worst relative error (paddy.doe surrogate_suggest, docs/doe.md) over the
-- factors the screening selected, run until a point confirmed with extra seeds is within the
-- tolerance or the budget is spent; the report puts simulations-to-tolerance side by side.
local doe = require("paddy.doe")
local util = require("lib.util")
local mud = require("lib.mud")
local input_file = require("lib.calibration.input")
local jobs = require("lib.calibration.jobs")
local surrogate = require("lib.calibration.surrogate")
local report = require("lib.calibration.report")

local here = paddy.script:match("^(.*)/[^/]*$") or "."
local P = paddy.parameters{
  {name = "input", default = here .. "/calibration/paddy_mud.json", description = "calibration input file (JSON): targets, factors, design sizes"},
  {name = "strategy", default = "both", choices = {"reference", "surrogate", "both"}, description = "reference procedure, surrogate-based, or both side by side"},
  {name = "quick", default = false, description = "demonstration variant: coarser particles, fewer replicates and seeds (about 10 minutes on 2 cores)"},
  {name = "particle_diameter", default = 0.010, unit = "m", min = 0.001, max = 0.04, description = "slump-test sphere diameter (quick: 0.018 unless set)"},
  {name = "timestep_fraction", default = 0.1, min = 0.01, max = 0.5, description = "time step / Rayleigh time at the reference damping; one step for all runs, shortened for the lowest restitution any run may use"},
  {name = "unstable_step_halvings", default = 1, type = "integer", min = 0, max = 3,
   description = "a run that stops because the step is too large for the velocities it reached is run again at half the step, at most this often (0: it fails the calibration); the report lists such runs"},
  {name = "experiment_params", default = "", description = "further experiment parameters for every run, 'name=value,name=value'"},
  {name = "rheometer_particle_diameter", default = 0.008, unit = "m", min = 0.001, max = 0.02, description = "sphere diameter of the verification rheometer (quick: 0.012 unless set)"},
  {name = "rheometer_params", default = "", description = "further rheometer parameters, 'name=value,...' (e.g. speeds_rpm=5;10;20)"},
  {name = "executor", default = "local", choices = {"local", "slurm"}, description = "where the simulations run"},
  {name = "max_parallel", default = 0, type = "integer", min = 0, max = 1024, description = "simulations at once (0: cores / threads_per_job; Slurm: array throttle)"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each simulation"},
  {name = "slurm_partition", default = "", description = "Slurm partition ('' = default)"},
  {name = "slurm_time", default = "01:00:00", description = "Slurm time limit of one simulation"},
  {name = "slurm_poll_interval", default = 5, unit = "s", min = 0.1, max = 600, description = "how often squeue is asked"},
  {name = "campaign_dir", default = "", description = "where the jobs are kept ('' = <out>/campaign); point two calibrations at one to share runs"},
  {name = "code_version", default = "", description = "fixed code version for the job keys ('' = hash of the binaries)"},
  {name = "pictures", default = true, description = "figures (gnuplot) and pile pictures of the verification run"},
}

local wall_start = os.time()
local input = input_file.read(P.input)
local resp = input.responses
local measured = input.measured
local particle_diameter, rheometer_diameter = P.particle_diameter, P.rheometer_particle_diameter
if P.quick then
  if particle_diameter == 0.010 then particle_diameter = 0.018 end  -- ~10 min at the converged step
  if rheometer_diameter == 0.008 then rheometer_diameter = 0.012 end
  input.box_behnken.replicates, input.box_behnken.center_points = 1, 3
  input.verification.seeds = 2
  input.surrogate.budget = math.min(input.surrogate.budget, 20)
  input.surrogate.confirm_seeds = math.min(input.surrogate.confirm_seeds, 1)
end
local seed0 = paddy.seed

local fixed = {particle_diameter = particle_diameter, pictures = false, snapshot_interval = 0, progress = false}
for _, f in ipairs(input.factors) do fixed[f.parameter] = f.center end   -- factors not varied: centre
-- One time step for every simulation: the slump test's results depend on the step
-- (docs/validation.md), so a step that changed with the restitution of each design point would
-- add its own effect to the restitution's. The step is the experiments' damping-aware one
-- (docs/physics.md) at the lowest restitution any run may use: a restitution factor's lower bound,
-- else the parameter's fixed value.
local lowest = {}
for _, e in ipairs(mud.contact) do
  if e.name:match("restitution$") then lowest[e.name] = e.default end
end
local user = util.assignments(P.experiment_params, "experiment_params")
for name in pairs(lowest) do
  if type(user[name]) == "number" then lowest[name] = user[name] end
end
for _, f in ipairs(input.factors) do
  if lowest[f.parameter] then
    lowest[f.parameter] = f.bounds[1] > -math.huge and f.bounds[1] or math.min(f.low, f.origin, f.search[1])
  end
end
local e_low = math.huge
for _, v in pairs(lowest) do e_low = math.min(e_low, v) end
local step = {lowest_restitution = e_low, factor = mud.timestep_factor(e_low)}
-- The base step: timestep_fraction if given, else the conventions' (paddy 0.1 T_R, edem 0.2 T_R).
local base_fraction = P.timestep_fraction
if (paddy.set_parameters or {}).timestep_fraction == nil then base_fraction = mud.conventions[input.conventions].timestep_fraction end
step.fraction = base_fraction * step.factor
fixed.timestep_fraction, fixed.timestep_damping = step.fraction, false
-- The input's contact conventions (only a non-default choice enters the jobs, so paddy jobs keep their keys).
if input.conventions ~= "paddy" then fixed.contact_conventions = input.conventions end
for k, v in pairs(user) do fixed[k] = v end

local campaign = paddy.campaign{
  dir = P.campaign_dir ~= "" and P.campaign_dir or nil, executor = P.executor,
  max_parallel = P.max_parallel > 0 and P.max_parallel or nil, threads_per_job = P.threads_per_job,
  code_version = P.code_version ~= "" and P.code_version or nil,
  slurm = P.executor == "slurm" and {partition = P.slurm_partition ~= "" and P.slurm_partition or nil, time = P.slurm_time,
                                        poll_interval = P.slurm_poll_interval} or nil,
}
local parallel = P.max_parallel > 0 and P.max_parallel or math.max(1, paddy.threads // P.threads_per_job)
local runner = jobs.new{campaign = campaign, script = input.experiment, fixed = fixed, responses = resp,
                        step_halvings = P.unstable_step_halvings}
local function say(fmt, ...) io.stderr:write("calibration: ", string.format(fmt, ...), "\n") end
local function params_of(values)            -- {symbol = value} → {parameter = value}
  local p = {}
  for sym, v in pairs(values) do p[input.by_symbol[sym].parameter] = v end
  return p
end
local function row_of(values, responses)    -- a data row for paddy.doe: factors and responses
  local r = {}
  for k, v in pairs(values) do r[k] = v end
  for k, v in pairs(responses) do r[k] = v end
  return r
end
-- Real value of a coded level: the design's own low/centre/high exactly (no rounding that would
-- put 0.01 - 1e-18 below a parameter's lower bound), linear in between.
local function level(lo, hi, coded)
  if coded == -1 then return lo elseif coded == 1 then return hi elseif coded == 0 then return (lo + hi) / 2 end
  return (lo + hi) / 2 + coded * (hi - lo) / 2
end
local figures = util.mkdir(util.out("figures"))
local plots = P.pictures and function(name) return util.mkdir(figures .. "/" .. name) end or function() return nil end
say("one time step for all runs: %.4g x Rayleigh time (damping factor %.3f at restitution %g)", step.fraction, step.factor, e_low)
local outcome = {input = input, parameters = P, particle_diameter = particle_diameter, time_step = step, measured = measured, responses = resp, tolerance = input.tolerance}

-----------------------------------------------------------------------------------------------
-- 1. Plackett-Burman screening.
local S = input.screening
local names, real = {}, {}
for _, f in ipairs(input.factors) do names[#names + 1] = f.symbol; real[#real + 1] = f.symbol end
for k = 1, S.dummy_columns do names[#names + 1] = "D" .. k end
local levels = {}
for _, f in ipairs(input.factors) do levels[f.symbol] = {f.low, f.high} end
local pb = doe.design{type = "pb", runs = S.runs, names = names, center = S.center_points, levels = levels}
local points, centre_no = {}, 0
for i, run in ipairs(pb.runs) do
  local values = {}
  for _, sym in ipairs(real) do values[sym] = level(levels[sym][1], levels[sym][2], run.coded[sym]) end
  if run.type == "center" then centre_no = centre_no + 1 end
  -- Common random numbers: one seed for the factorial runs; replicated centre points need their own.
  points[i] = {params = params_of(values), values = values, seed = seed0 + (run.type == "center" and centre_no - 1 or 0),
               label = "run " .. run.run}
end
say("1. Plackett-Burman screening: %d runs of %d factors (+ %d dummy columns)", #points, #real, S.dummy_columns)
local pb_rows = runner:run("screening", points)
local pb_data = {}
for i, row in ipairs(pb_rows) do pb_data[i] = row_of(points[i].values, row.responses) end
local pb_fit = doe.analyze{data = pb_data, factors = real, responses = resp, model = "linear+curvature",
                           levels = levels, plots = plots("screening")}
-- Significant factors: smallest p over the responses below alpha; at least min_factors (a
-- Box-Behnken design needs 3), at most max_factors, filled up / cut by p.
local ranked = {}
for _, sym in ipairs(real) do
  local p_min, by = 1, {}
  for _, r in ipairs(resp) do
    for _, a in ipairs(pb_fit.responses[r].anova) do
      if a.source == sym then by[r] = a.p; p_min = math.min(p_min, a.p or 1) end
    end
  end
  ranked[#ranked + 1] = {symbol = sym, p = p_min, p_by_response = by, significant = p_min < S.alpha}
end
table.sort(ranked, function(a, b) return a.p < b.p end)
local selected = {}
for i, f in ipairs(ranked) do
  if #selected < S.max_factors and (f.significant or #selected < S.min_factors) then
    selected[#selected + 1] = f.symbol
    f.selected, f.reason = true, f.significant and "significant" or "added: a Box-Behnken design needs " .. S.min_factors
  end
end
say("   selected: %s", table.concat(selected, ", "))
outcome.screening = {design = pb, runs = pb_rows, data = pb_data, fit = pb_fit, ranking = ranked, selected = selected}

-----------------------------------------------------------------------------------------------
-- Strategy A: the reference procedure (steps 2-5).
local function reference_procedure()
  -- 2. Steepest ascent: direction -sign(dE/dx_j) of E = sum_r ((y_r - t_r)/t_r)^2 at the origin,
  -- from the screening model (coded units), each factor moving by its step.
  local origin, grad = {}, {}
  local coded_origin = {}
  for _, sym in ipairs(selected) do
    local f = input.by_symbol[sym]
    origin[sym] = f.origin
    coded_origin[sym] = (f.origin - f.center) / ((f.high - f.low) / 2)
  end
  for _, sym in ipairs(selected) do grad[sym] = 0 end
  for _, r in ipairs(resp) do
    local b = pb_fit.responses[r].coefficients
    local y = b.Intercept
    for _, sym in ipairs(selected) do y = y + (b[sym] or 0) * coded_origin[sym] end
    for _, sym in ipairs(selected) do grad[sym] = grad[sym] + 2 * (y - measured[r]) / measured[r] ^ 2 * (b[sym] or 0) end
  end
  local factors, coefficients, steps, org = {}, {}, {}, {}
  for _, sym in ipairs(selected) do
    local f = input.by_symbol[sym]
    factors[#factors + 1] = {name = sym, low = f.low, high = f.high}
    coefficients[#coefficients + 1] = grad[sym] == 0 and -1 or -grad[sym]   -- ascent along -grad E
    steps[#steps + 1], org[#org + 1] = f.step, f.origin
  end
  local path = doe.steepest_ascent{factors = factors, coefficients = coefficients, real_steps = steps, origin = org,
                                   steps = input.steepest_ascent.max_steps - 1}
  say("2. Steepest ascent along %s: up to %d steps, %d at a time", table.concat(selected, ", "), #path, parallel)
  local sa, best = {}, nil
  local k = 1
  while k <= #path do
    local batch = {}
    for j = k, math.min(#path, k + parallel - 1) do
      local values = {}
      for _, sym in ipairs(selected) do
        local b = input.by_symbol[sym].bounds
        values[sym] = math.min(b[2], math.max(b[1], path[j].real[sym]))
      end
      batch[#batch + 1] = {params = params_of(values), values = values, seed = seed0, label = "step " .. path[j].step}
    end
    local rows = runner:run("steepest ascent", batch)
    for j, row in ipairs(rows) do
      local e, worst = jobs.errors(row.responses, measured)
      sa[#sa + 1] = {step = #sa, values = batch[j].values, responses = row.responses, errors = e, worst = worst, index = row.index}
      if not best or worst < best.worst then best = sa[#sa] end
    end
    say("   steps %d-%d: best so far step %d, worst error %.1f %%", k - 1, k - 2 + #rows, best.step, 100 * best.worst)
    if sa[#sa] ~= best then break end   -- the error rose again: the minimum along the path is passed
    k = k + #batch
  end

  -- 3. Box-Behnken around the best step, half-ranges = the steps (kept inside the bounds).
  local B = input.box_behnken
  local box = {}
  for _, sym in ipairs(selected) do
    local f = input.by_symbol[sym]
    local h = math.min(f.step, (f.bounds[2] - f.bounds[1]) / 2)
    local c = math.min(f.bounds[2] - h, math.max(f.bounds[1] + h, best.values[sym]))
    box[sym] = {c - h, c + h}
  end
  local bbd = doe.design{type = "bbd", names = selected, center = B.center_points, levels = box}
  local bb_points = {}
  for i, run in ipairs(bbd.runs) do
    for _, sym in ipairs(selected) do run.real[sym] = level(box[sym][1], box[sym][2], run.coded[sym]) end
    for rep = 1, B.replicates do
      bb_points[#bb_points + 1] = {params = params_of(run.real), values = run.real, run = i,
                                   seed = seed0 + 100 + (i - 1) * B.replicates + rep - 1,
                                   label = string.format("run %d, replicate %d", run.run, rep)}
    end
  end
  say("3. Box-Behnken: %d runs x %d replicates = %d simulations", #bbd.runs, B.replicates, #bb_points)
  local bb_rows = runner:run("box-behnken", bb_points)
  local bb_runs, bb_data = {}, {}
  for i, run in ipairs(bbd.runs) do bb_runs[i] = {run = run, rows = {}} end
  for j, row in ipairs(bb_rows) do
    local r = bb_runs[bb_points[j].run]
    r.rows[#r.rows + 1] = row
    r.last_index = math.max(r.last_index or 0, row.index)
  end
  for i, r in ipairs(bb_runs) do
    r.mean, r.sd = jobs.mean_responses(r.rows, resp)
    r.errors, r.worst = jobs.errors(r.mean, measured)
    bb_data[i] = row_of(r.run.real, r.mean)
  end
  local bb_fit = doe.analyze{data = bb_data, factors = selected, responses = resp, model = "quadratic",
                             levels = box, plots = plots("box_behnken")}

  -- 4. Desirability optimum toward the measured values inside the design region. The
  -- desirability ramps run from the observed range, widened to hold the target.
  local goals = {}
  for _, r in ipairs(resp) do
    local lo, hi = bb_fit.responses[r].min, bb_fit.responses[r].max
    goals[#goals + 1] = {response = r, goal = "target", target = measured[r],
                         lower = math.min(lo, 0.9 * measured[r]), upper = math.max(hi, 1.1 * measured[r])}
  end
  local opt = doe.optimize{fit = bb_fit, goals = goals, bounds = box, plots = plots("desirability")}
  local optimum = opt.solutions[1]
  say("4. Optimum: %s (desirability %.3f)", (function()
    local t = {}
    for _, sym in ipairs(selected) do t[#t + 1] = string.format("%s = %.4g", sym, optimum.factors[sym]) end
    return table.concat(t, ", ")
  end)(), optimum.desirability)

  -- 5. Verification at the optimum with new seeds (the first draws the pile pictures), and the
  -- rheometer at the optimum in the same batch: the longer vane run first, so that it runs beside
  -- the slump runs instead of alone after them.
  local V = input.verification
  local batch, rheo_point = {}, nil
  if input.rheometer.run then
    local rp = {particle_diameter = rheometer_diameter, pictures = P.pictures, snapshot_interval = 0, progress = false,
                timestep_fraction = step.fraction, timestep_damping = false}
    for k, v in pairs(util.assignments(P.rheometer_params, "rheometer_params")) do rp[k] = v end
    for _, f in ipairs(input.factors) do rp[f.parameter] = f.center end
    for sym, v in pairs(optimum.factors) do rp[input.by_symbol[sym].parameter] = v end
    if input.rheometer.measured_torque_csv then
      local csv = input.rheometer.measured_torque_csv
      if not csv:match("^/") then csv = (input.path:match("^(.*)/[^/]*$") or ".") .. "/" .. csv end
      rp.measured_csv = csv
    end
    rheo_point = {script = "rheometer.lua", params = rp, standalone = true, seed = seed0 + 1000, responses = {},
                  label = "vane", stage = "rheometer"}
    batch[1] = rheo_point
  end
  for s = 1, V.seeds do
    batch[#batch + 1] = {params = params_of(optimum.factors), values = optimum.factors, seed = seed0 + 1000 + s - 1,
                         extra = s == 1 and P.pictures and {pictures = true} or nil, label = "seed " .. (seed0 + 1000 + s - 1)}
  end
  say("5. Verification: %d simulations at the optimum%s", V.seeds, rheo_point and ", and the rheometer there" or "")
  local batch_rows = runner:run("verification", batch)
  local v_rows = {table.unpack(batch_rows, rheo_point and 2 or 1)}
  local v_mean, v_sd = jobs.mean_responses(v_rows, resp)
  local v_err, v_worst = jobs.errors(v_mean, measured)
  for _, r in ipairs(resp) do
    say("   %s: %.1f +- %.1f (measured %g, error %.2f %%)", r, v_mean[r], v_sd[r], measured[r], 100 * v_err[r])
  end
  local rheo
  if rheo_point then
    local row = batch_rows[1]
    rheo = {result = row.result, dir = row.dir, index = row.index}
  end
  return {path = path, steepest_ascent = sa, best_step = best, box = box, design = bbd, runs = bb_runs, data = bb_data,
          fit = bb_fit, goals = goals, optimization = opt, optimum = optimum,
          verification = {runs = v_rows, mean = v_mean, sd = v_sd, errors = v_err, worst = v_worst,
                          last_index = v_rows[#v_rows].index},
          rheometer = rheo}
end

if P.strategy ~= "surrogate" then
  outcome.reference = reference_procedure()
end

-----------------------------------------------------------------------------------------------
-- Strategy B: sequential surrogate-based calibration over the selected factors.
if P.strategy ~= "reference" then
  say("Surrogate strategy over %s (budget %d simulations)", table.concat(selected, ", "), input.surrogate.budget)
  outcome.surrogate = surrogate.run{runner = runner, input = input, selected = selected, params_of = params_of,
                                    row_of = row_of, seed = seed0 + 2000, batch = parallel, say = say}
end

-----------------------------------------------------------------------------------------------
-- 6. Report.
outcome.simulations = runner.log
-- Runs that needed a shorter step than the calibration's (jobs.lua): named in the report.
outcome.runs_at_shorter_step = {}
for _, r in ipairs(runner.log) do
  if r.step_halvings then
    outcome.runs_at_shorter_step[#outcome.runs_at_shorter_step + 1] = {stage = r.stage, label = r.label, timestep_fraction = r.timestep_fraction,
                                                                        step_halvings = r.step_halvings}
    say("note: %s %s ran at timestep_fraction %.4g (%d halving(s)): unstable at the calibration's step", r.stage, r.label or "", r.timestep_fraction, r.step_halvings)
  end
end
outcome.wall_time_s = os.difftime(os.time(), wall_start)
local files = report.write{outcome = outcome, figures = figures, pictures = P.pictures}
say("report: %s", files.html)
paddy.result(report.summary(outcome, files))
