-- Find what the model is missing: the step after a calibration that does not fit.
-- Documentation: docs/discovery.md ("The workflow"; the statistics in "The statistics").
--
--   paddy run experiments/discover.lua --set input=FILE.json --out DIR
--
-- The input file lists experiments (slump.lua, rheometer.lua, tack.lua at given settings) with
-- measured observables and their standard deviations, the free parameters and the candidate
-- effects (a parameter each, strength 0 = today's model). Every simulation is a campaign job keyed
-- by its content (docs/campaign.md): running the same command again after an interruption repeats
-- nothing that finished. Steps, each a block below and a section of DIR/report.html:
--   1. Calibrate the free parameters to all measurements: Gauss-Newton (paddy.doe.gauss_newton)
--      on forward differences with common random numbers (the same seed at θ and θ + h), bounded.
--   2. Locate: replicates at θ̂ (other seeds) give the seed scatter; with the measurement sigma,
--      the noise covariance (paddy.doe.noise_covariance); standardised residual per observable
--      and the global misfit test.
--   3. Name: each candidate's signature at zero strength (secant to a probe strength, the same
--      seeds as replicates, averaged over signature_seeds) and paddy.doe.diagnose.
--   4. Add and recalibrate: the named effect with the free parameters jointly (Gauss-Newton),
--      confirmed at new seeds; its strength with an interval, misfit before and after,
--      paddy.doe.compare_fits.
--   5. Report: DIR/result.json and DIR/report.html.
-- Observables are standardised by their measurement sigma (lib/discovery/stack.lua): residuals,
-- Jacobians and signatures are in units of sigma.
local doe = require("paddy.doe")
local mud = require("lib.mud")
local jobs = require("lib.calibration.jobs")
local input_file = require("lib.discovery.input")
local stack = require("lib.discovery.stack")
local zoom = require("lib.discovery.zoom")
local valley_design = require("lib.discovery.valley")
local resolution = require("lib.discovery.resolution")
local report = require("lib.discovery.report")

local P = paddy.parameters{
  {name = "input", default = "", description = "discovery input file (JSON; docs/discovery.md)"},
  {name = "particle_diameter", default = 0.010, unit = "m", min = 0.001, max = 0.04, description = "sphere diameter of every simulation"},
  {name = "timestep_fraction", default = 0.1, min = 0.01, max = 0.5, description = "time step / Rayleigh time at the reference damping; one step for all runs, shortened for the lowest restitution any run may use"},
  {name = "experiment_params", default = "", description = "further parameters for every run, 'name=value,name=value' (parameters both scripts accept)"},
  {name = "max_parallel", default = 0, type = "integer", min = 0, max = 1024, description = "simulations at once (0: cores / threads_per_job)"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each simulation"},
  {name = "campaign_dir", default = "", description = "where the jobs are kept ('' = <out>/campaign)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys ('' = hash of the binaries)"},
  {name = "pictures", default = true, description = "figures of the report (gnuplot)"},
}
if P.input == "" then error("discover.lua: give the input file: --set input=FILE.json (schema: docs/discovery.md)", 0) end

local wall_start = os.time()
-- The experiment scripts live beside this one (experiments/), wherever the workflow is started from.
local here = (debug.getinfo(1, "S").source:match("^@(.*)/[^/]*$")) or "."
local input = input_file.read(P.input)
for _, f in ipairs({"gauss_newton", "noise_covariance", "diagnose", "compare_fits", "compare_non_nested", "bootstrap_thresholds"}) do
  if type(doe[f]) ~= "function" then
    error("discover.lua: this build has no paddy.doe." .. f .. " (the statistics of docs/discovery.md)", 0)
  end
end
local S = input.settings
local seed0 = paddy.seed
local function say(fmt, ...) io.stderr:write("discovery: ", string.format(fmt, ...), "\n") end

-- One time step for every run (as the calibration: the slump depends on the step, so a step that
-- changed with a restitution would add its own effect): the damping-aware step at the lowest
-- restitution any run may use.
local e_low = math.huge
for _, e in ipairs(mud.contact) do
  if e.name:match("restitution$") then e_low = math.min(e_low, e.default) end
end
for _, list in ipairs({input.free_parameters, input.candidates}) do
  for _, f in ipairs(list) do
    if f.parameter:match("restitution$") then e_low = math.min(e_low, f.low > 0 and f.low or e_low) end
  end
end
for _, e in ipairs(input.experiments) do
  for k, v in pairs(e.set) do if k:match("restitution$") and type(v) == "number" then e_low = math.min(e_low, v) end end
end
local fixed = {particle_diameter = P.particle_diameter, pictures = false, snapshot_interval = 0, progress = false,
               timestep_fraction = P.timestep_fraction * mud.timestep_factor(e_low), timestep_damping = false}
local util = require("lib.util")
for k, v in pairs(util.assignments(P.experiment_params, "experiment_params")) do fixed[k] = v end

local campaign = paddy.campaign{
  dir = P.campaign_dir ~= "" and P.campaign_dir or nil, executor = "local",
  max_parallel = P.max_parallel > 0 and P.max_parallel or nil, threads_per_job = P.threads_per_job,
  code_version = P.code_version ~= "" and P.code_version or nil,
}
local runner = jobs.new{campaign = campaign, script = "slump.lua", fixed = fixed, responses = {}}
local L = stack.layout(input)
local y = stack.measured(L)
local m = #L
local free, cands = input.free_parameters, input.candidates
local p = #free
local labels, blocks = {}, {}
for i, l in ipairs(L) do labels[i], blocks[i] = l.label, l.block end

-- Simulations of model points: a point {theta = {value per free parameter}, lambda = {name = strength},
-- seed =, label =} runs every experiment; → one stacked standardised vector per point.
local first_results
local function evaluate(stage, points)
  local jp = {}
  for _, pt in ipairs(points) do
    for _, e in ipairs(input.experiments) do
      local params = {}
      for k, v in pairs(e.set) do params[k] = v end
      for j, f in ipairs(free) do params[f.parameter] = pt.theta[j] end
      for _, c in ipairs(cands) do params[c.parameter] = (pt.lambda or {})[c.name] or 0 end
      if pt.diameter then params.particle_diameter = pt.diameter end
      jp[#jp + 1] = {script = here .. "/" .. e.script, params = params, seed = pt.seed, label = (pt.label or "") .. " " .. e.name, responses = {}}
    end
  end
  local rows = runner:run(stage, jp)
  local out, res, k = {}, {}, 0
  for i, pt in ipairs(points) do
    local results = {}
    for _, e in ipairs(input.experiments) do
      k = k + 1
      results[e.name] = rows[k].result
    end
    if not first_results then first_results = results; stack.label(L, results) end
    out[i] = stack.simulated(L, results, stage .. " " .. (pt.label or i))
    res[i] = results
  end
  return out, res
end

-- Forward-difference step of parameter j at theta: fd_step of its range, toward the inside.
local function fd_step(lo, hi, v)
  local h = S.fd_step * (hi - lo)
  if v + h > hi then h = -h end
  return h
end
-- f(point) and the Jacobian by forward differences at one seed (common random numbers).
-- `dims` = {{get = function(pt) -> value, set = function(pt, v) -> new point, lo =, hi =}, ...}.
local function jacobian_at(stage, base, dims)
  local pts = {base}
  local steps = {}
  for j, d in ipairs(dims) do
    steps[j] = fd_step(d.lo, d.hi, d.get(base))
    local pt = d.set(base, d.get(base) + steps[j])
    pt.label = base.label .. " +h" .. j
    pts[#pts + 1] = pt
  end
  local f = evaluate(stage, pts)
  local J = {}
  for i = 1, m do
    J[i] = {}
    for j = 1, #dims do J[i][j] = (f[j + 1][i] - f[1][i]) / steps[j] end
  end
  return f[1], J, steps
end
local function copy_point(pt)
  local theta, lambda = {}, {}
  for j, v in ipairs(pt.theta) do theta[j] = v end
  for k, v in pairs(pt.lambda or {}) do lambda[k] = v end
  return {theta = theta, lambda = lambda, seed = pt.seed, label = pt.label}
end
local function theta_dims()
  local dims = {}
  for j, f in ipairs(free) do
    dims[j] = {lo = f.low, hi = f.high, get = function(pt) return pt.theta[j] end,
               set = function(pt, v) local q = copy_point(pt); q.theta[j] = v; return q end}
  end
  return dims
end
local function identity(n)
  local I = {}
  for i = 1, n do I[i] = {}; for j = 1, n do I[i][j] = i == j and 1 or 0 end end
  return I
end
local function fmt_theta(theta)
  local t = {}
  for j, f in ipairs(free) do t[j] = string.format("%s = %.4g", f.parameter, theta[j]) end
  return #t > 0 and table.concat(t, ", ") or "(no free parameters)"
end

local function fmt_point(pt)
  local t = {fmt_theta(pt.theta)}
  for k, v in pairs(pt.lambda or {}) do t[#t + 1] = string.format("%s = %.4g", k, v) end
  return table.concat(t, ", ")
end

local outcome = {input = input, parameters = P, layout = L, measured = y, fixed = fixed}

-- Start scan: with a few hundred spheres one seed's misfit is rough in θ, and a forward difference
-- at a poor start can point the wrong way (the step is then rejected and the fit stops far from
-- the optimum). So a fit (below) starts at the best of its start point and start_scan points spread over
-- the free parameters' box (a Latin-hypercube-like design: point k puts parameter j at the centre
-- of stratum (k·(2j − 1)) mod n of its range; any effect strength stays as in the start), every
-- point at the start's seed. When the fit's dimensions hold more than the free parameters (the
-- recalibration with an effect, its strength the last dimension), 2·start_scan + 1 more points
-- follow the valley along which the free parameters absorb the effect (`valley`): the
-- calibration moved θ by β·λ to absorb an effect of strength λ, with β = (JᵀΣ⁻¹J)⁻¹JᵀΣ⁻¹g the
-- least-squares fit of the effect's signature g by the free parameters' Jacobian J, so the truth
-- lies near θ(λ) = θ̂ − β·λ (the points: lib/discovery/valley.lua; λ from λ̂ up to the range's top,
-- over the whole range when λ̂ is at or above it). The score test's strength λ̂ is linear in the effect and
-- a strong one (wall adhesion that lifts the mud with the cone) is underestimated by far, so the
-- refit must not start only at it; nor at a strength paired with a θ that has absorbed none of it.
-- Returns the best point and the scan's record.
local function scan_start(stage, start, weights, dims, valley)
  if S.start_scan <= 0 or p == 0 then return start, nil end
  local n = S.start_scan
  local pts = {copy_point(start)}
  pts[1].label = stage .. " scan 0"
  local function spread(q, k, list)
    for j, d in ipairs(list) do
      local stratum = (k * (2 * j - 1)) % n
      q = d.set(q, d.lo + (stratum + 0.5) / n * (d.hi - d.lo))
    end
    return q
  end
  local theta_only = theta_dims()
  for k = 1, n do
    local q = spread(copy_point(start), k, theta_only)
    q.label = stage .. " scan " .. k
    pts[#pts + 1] = q
  end
  if valley then
    local ld = dims[#dims]
    local tlo, thi = {}, {}
    for j, d in ipairs(theta_only) do tlo[j], thi[j] = d.lo, d.hi end
    for _, v in ipairs(valley_design.points{theta = valley.theta, beta = valley.beta, lambda = valley.lambda, n = n,
                                            whole_range = valley.whole_range, theta_low = tlo, theta_high = thi,
                                            lambda_low = ld.lo, lambda_high = ld.hi}) do
      local q = ld.set(copy_point(start), v.lambda)
      for j, d in ipairs(theta_only) do q = d.set(q, v.theta[j]) end
      q.label = stage .. " scan " .. #pts
      pts[#pts + 1] = q
    end
  end
  local fs = evaluate(stage, pts)
  local best_k, best_rms, record = 1, math.huge, {}
  for k, f in ipairs(fs) do
    local rms = stack.rms_standardised(stack.minus(y, f), weights)
    record[k] = {theta = pts[k].theta, lambda = pts[k].lambda, rms_sigma = rms}
    if rms < best_rms then best_k, best_rms = k, rms end
  end
  say("   start scan of %d point(s): best %s, RMS residual %.3g", #pts, fmt_point(pts[best_k]), best_rms)
  local best = copy_point(pts[best_k])
  best.label = nil
  return best, record, pts, fs
end
-- Gauss-Newton with step control over `dims` from the point `start` (the calibration and the
-- recalibration with an effect). Every point runs at start.seed (common random numbers), so the
-- misfits of successive points compare like for like; a step that raises the misfit is halved
-- toward the last accepted point (at most S.backtracks times); the fit stops after S.iterations
-- steps, when the next step would move no coordinate by more than S.converge of its range, or when
-- no halving helps, and returns the best point run with its f, Jacobian, residual and the
-- Gauss-Newton step computed there (its se), every point run (`history`) and the start scan (`scan`).
-- The recalibration with an effect (`valley` given) with settings.refit = "surface" (the default)
-- does not step from one seed's differences: it fits a quadratic response surface through the
-- start scan's points (paddy.doe.response_surface) and takes the point of the box where the
-- surface fits the measurements best, with the surface's linearised se; Gauss-Newton from the
-- best scan point remains the fallback when the scan cannot determine a surface.
local function fit(stage, start, dims, weights, valley)
  local scan, scan_pts, scan_fs
  start, scan, scan_pts, scan_fs = scan_start(stage, start, weights, dims, valley)
  local history = {}
  local lo, hi = {}, {}
  for j, d in ipairs(dims) do lo[j], hi[j] = d.lo, d.hi end
  local function coords(pt) local x = {}; for j, d in ipairs(dims) do x[j] = d.get(pt) end; return x end
  local function at(x)
    local pt = copy_point(start)
    for j, d in ipairs(dims) do pt = d.set(pt, x[j]) end
    return pt
  end
  -- The quadratic response surface through the start scan's points (paddy.doe.response_surface):
  -- ok, its result (or the error), the number of points and the design (points, values, box).
  local function scan_surface()
    local X = {}
    for k, pt in ipairs(scan_pts) do X[k] = coords(pt) end
    local ok, rs = pcall(doe.response_surface, {points = X, values = scan_fs, measured = y, covariance = weights, lower = lo, upper = hi})
    return ok, rs, #X, {points = X, values = scan_fs, lower = lo, upper = hi}
  end
  -- The calibration (no valley): Gauss-Newton starts at the best point of a quadratic response
  -- surface through the scan. At a few hundred spheres one seed's misfit is rough in θ: the
  -- scan's best single point can sit a stratum away from the optimum, and forward differences at
  -- one seed there can call it converged. The surface through all scan points averages that
  -- noise. With fewer scan points than a quadratic has coefficients it starts at the best point.
  local surface_start
  if not valley and S.calibration_start == "surface" and scan_pts then
    local ok, rs, npts = scan_surface()
    if ok then
      local pt = at(rs.x)
      say("   response surface through %d scan point(s): best %s, predicted RMS residual %.3g; Gauss-Newton starts there",
          npts, fmt_point(pt), rs.misfit_predicted)
      surface_start = {theta = pt.theta, misfit_predicted = rs.misfit_predicted, at_bound = rs.at_bound, points = npts}
      start = pt
    else
      say("   no response surface (%s): Gauss-Newton starts at the best scan point", tostring(rs))
    end
  end
  if valley and S.refit == "surface" and scan_pts then
    local ok, rs, npts, design = scan_surface()
    if ok then
      local pt = at(rs.x)
      say("   response surface through %d scan point(s): best %s, predicted RMS residual %.3g", npts, fmt_point(pt), rs.misfit_predicted)
      return {point = pt, step = {se = rs.se, jacobian = rs.jacobian}, history = history, scan = scan,
              surface = {x = rs.x, se = rs.se, misfit_predicted = rs.misfit_predicted, residual_sd = rs.residual_sd,
                         at_bound = rs.at_bound, points = npts},
              design = design}
    end
    say("   no response surface (%s): Gauss-Newton from the best scan point", tostring(rs))
  end
  local x, best, it, tries = coords(start), nil, 0, 0
  while true do
    local base = at(x)
    base.label = string.format("%s %d%s", stage, it, tries > 0 and ("." .. tries) or "")
    local f, Jt = jacobian_at(stage, base, dims)
    local r = stack.minus(y, f)
    local rms = stack.rms_standardised(r, weights)
    local accepted = not best or rms <= best.rms
    history[#history + 1] = {iteration = it, theta = base.theta, lambda = base.lambda, rms_sigma = rms, accepted = accepted,
                             backtrack = tries}
    say("   %s %d%s: %s, RMS residual %.3g%s", stage, it, tries > 0 and string.format(" (step halved %d x)", tries) or "",
        fmt_point(base), rms, accepted and "" or " - rejected")
    if accepted then
      best = {x = x, point = base, f = f, J = Jt, r = r, rms = rms}
      best.step = #dims > 0 and doe.gauss_newton{theta = x, residual = r, jacobian = Jt, covariance = weights,
                                                 lower = lo, upper = hi, damping = 0} or nil
      tries = 0
    elseif tries < S.backtracks then
      tries = tries + 1
      local half = {}
      for j = 1, #dims do half[j] = 0.5 * (best.x[j] + x[j]) end
      x = half
      goto continue
    else
      say("   no step lowered the misfit: stopping at the best point run")
      break
    end
    if it == S.iterations or #dims == 0 then break end
    do
      local largest = 0
      for j = 1, #dims do largest = math.max(largest, math.abs(best.step.theta[j] - best.x[j]) / (hi[j] - lo[j])) end
      if largest < S.converge then
        say("   converged: the next step moves no parameter by more than %.3g of its range", S.converge)
        break
      end
      x, it, tries = best.step.theta, it + 1, 0
    end
    ::continue::
  end
  best.history, best.scan, best.surface_start = history, scan, surface_start
  return best
end

-----------------------------------------------------------------------------------------------
-- 1. Calibrate the free parameters (the measurement errors as the weights: the seed scatter is not
-- known yet). Errors the measurements share (an experiment's shared_error: one specimen read at
-- several speeds; nil when none) are part of them: Sigma_meas = I + C (docs/discovery.md).
local shared = stack.shared_covariance(input, L)
local function measurement_weights()
  local W = identity(m)
  if shared then
    for i = 1, m do for j = 1, m do W[i][j] = W[i][j] + shared[i][j] end end
  end
  return W
end
local theta = {}
for j, f in ipairs(free) do theta[j] = f.start end
local calib = {}
say("1. calibration of %d free parameter(s) to %d observables of %d experiment(s), at most %d Gauss-Newton iteration(s)",
    p, m, #input.experiments, S.iterations)
local cal = fit("calibration", {theta = theta, lambda = {}, seed = seed0}, theta_dims(), measurement_weights())
calib.iterations, calib.scan, calib.surface_start = cal.history, cal.scan, cal.surface_start
theta = cal.point.theta
local J, f_hat = cal.J, cal.f
calib.theta = theta
outcome.calibration = calib

-----------------------------------------------------------------------------------------------
-- 2. Locate: replicates at θ̂, noise covariance, standardised residuals, global misfit.
say("2. %d replicates at the calibrated parameters", S.replicates)
local rep_points = {}
for k = 1, S.replicates do rep_points[k] = {theta = theta, lambda = {}, seed = seed0 + 100 + k, label = "replicate " .. k} end
local reps, rep_results = evaluate("replicates", rep_points)
local f_bar = stack.mean(reps)
local r0 = stack.minus(y, f_bar)
local ones = {}
for i = 1, m do ones[i] = 1 end
-- Seeds behind a simulated value, with the specimen scatter of the measurements folded in:
-- Sigma_seed / n + Sigma_seed / measured_repeats = Sigma_seed / n_eff.
local function n_eff(n)
  if S.measured_repeats > 0 then return 1 / (1 / n + 1 / S.measured_repeats) end
  return n
end
local noise = doe.noise_covariance{replicates = reps, sigma = ones, n_avg = n_eff(S.replicates), measurement_covariance = shared}
local cov = noise.covariance
local located = {}
for i, l in ipairs(L) do
  located[i] = {label = l.label, block = l.block, key = l.key, index = l.index, axis = l.axis, measured = l.measured,
                simulated = f_bar[i] * l.sigma, z = r0[i] / math.sqrt(cov[i][i])}
end
outcome.located = {residuals = located, noise = noise, rms = stack.rms_standardised(r0, cov)}
say("   RMS standardised residual %.3g (seed scatter shrinkage %.3g)", outcome.located.rms, noise.shrinkage or 0 / 0)

-- Resolution bias: the observables' shift from the particle diameter to resolution_factor x it
-- at θ̂ (mean of resolution_seeds runs minus the replicates' mean). Added to the Jacobian as a
-- nuisance column: a misfit along it is what refining the model would change, never evidence of
-- a missing effect. resolution_shift runs them at a model point (θ, the effects' strengths λ)
-- and returns b = their mean minus f_ref (the mean at the workflow's diameter there) and J with b
-- as a last column; step 4 calls it again at the refit point.
local d_fine = P.particle_diameter * S.resolution_factor
local function resolution_shift(stage, at_theta, lambda, f_ref)
  local points = {}
  for k = 1, S.resolution_seeds do
    points[k] = {theta = at_theta, lambda = lambda, seed = seed0 + 300 + k, diameter = d_fine, label = stage .. " " .. k}
  end
  local b = stack.minus(stack.mean(evaluate(stage, points)), f_ref)
  local Jb = {}
  for i = 1, m do
    Jb[i] = {}
    for j = 1, p do Jb[i][j] = J[i][j] end
    Jb[i][p + 1] = b[i]
  end
  return b, Jb
end
local J_diag = J
if S.resolution_factor > 0 then
  say("   resolution bias: %d run(s) at %.4g m", S.resolution_seeds, d_fine)
  local b
  b, J_diag = resolution_shift("resolution", theta, {}, f_bar)
  local bias = {}
  for i, l in ipairs(L) do bias[i] = {label = l.label, shift = b[i] * l.sigma, z = b[i] / math.sqrt(cov[i][i])} end
  outcome.resolution = {diameter = d_fine, seeds = S.resolution_seeds, shift = bias,
                        rms = stack.rms_standardised(b, cov)}
  say("   resolution shift: RMS %.3g noise sd", outcome.resolution.rms)
end

-----------------------------------------------------------------------------------------------
-- 3. Name: signatures at zero strength and the diagnosis.
say("3. signatures of %d candidate(s), %d seed(s) each", #cands, S.signature_seeds)
-- Each signature seed s is a pair of runs at θ̂, the probe and λ = 0 (common random numbers). The
-- λ = 0 run is the baseline's own (signature_baseline = "own", seed seed0 + 400 + s, which no
-- replicate has): were it replicate s, the signature's noise (−f(seed_s)/probe) and the residual's
-- (−mean of the replicates) would share f(seed_s), and z = gᵀPr/√a would have a positive mean under
-- the null, largest for a signature that is mostly seed noise. "replicates" is the earlier rule.
local function signature_seed(s)
  return S.signature_baseline == "own" and seed0 + 400 + s or rep_points[s].seed
end
local base_runs = {}
if S.signature_baseline == "own" then
  local base_points = {}
  for s = 1, S.signature_seeds do
    base_points[s] = {theta = theta, lambda = {}, seed = signature_seed(s), label = string.format("signature baseline seed %d", s)}
  end
  base_runs = evaluate("signature baselines", base_points)
else
  for s = 1, S.signature_seeds do base_runs[s] = reps[s] end
end
local sig_points = {}
for _, c in ipairs(cands) do
  for s = 1, S.signature_seeds do
    sig_points[#sig_points + 1] = {theta = theta, lambda = {[c.name] = c.probe}, seed = signature_seed(s),
                                   label = string.format("%s probe seed %d", c.name, s), candidate = c, s = s}
  end
end
local sig_runs = evaluate("signatures", sig_points)
local signatures, dcands = {}, {}
for k, c in ipairs(cands) do
  local g, per_seed = {}, {}
  for i = 1, m do g[i] = 0 end
  for n, pt in ipairs(sig_points) do
    if pt.candidate == c then
      local gs = {}
      for i = 1, m do
        gs[i] = (sig_runs[n][i] - base_runs[pt.s][i]) / c.probe
        g[i] = g[i] + gs[i] / S.signature_seeds
      end
      per_seed[#per_seed + 1] = gs
    end
  end
  signatures[c.name] = g
  -- The per-seed secants: their spread is the signature's own noise, which the detection limits
  -- allow for (doe detection.hpp); with one seed there is no spread to measure.
  dcands[k] = {name = c.name, signature = g, low = c.low, high = c.high, relevant = c.relevant,
               signature_seeds = #per_seed >= 2 and per_seed or nil}
end
-- The decision's thresholds: bootstrap null trials of the fitted noise model (Sigma re-estimated
-- from S.replicates draws in every trial), or the chi^2 tables. n_avg: seeds behind a simulated value.
local function thresholds(n_avg, candidates, seed_covariance, replicates, jacobian)
  if S.thresholds ~= "bootstrap" then return {} end
  return doe.bootstrap_thresholds{seed_covariance = seed_covariance or noise.seed_covariance, replicates = replicates or S.replicates,
                                  n_avg = n_avg, sigma = ones, measurement_covariance = shared,
                                  jacobian = jacobian or J_diag, candidates = candidates, alpha = S.alpha, confusable = S.confusable, strong_margin = S.strong_margin,
                                  trials = S.bootstrap_trials, seed = seed0}
end
local thr = thresholds(n_eff(S.replicates), dcands)
local diag = doe.diagnose{residual = r0, covariance = cov, jacobian = J_diag, candidates = dcands, labels = labels, blocks = blocks,
                          alpha = S.alpha, confusable = S.confusable, strong_margin = S.strong_margin, z_threshold = thr.z_threshold,
                          q0_threshold = thr.q0_threshold, q_after_threshold = thr.q_after_threshold}
diag.thresholds = thr
say("   decision: %s%s (Q0 = %.4g on %s df, p = %.3g)", diag.decision, diag.named and (" - " .. diag.named) or "",
    diag.q0 or 0 / 0, tostring(diag.q0_df), diag.q0_p or 0 / 0)
for _, c in ipairs(diag.candidates or {}) do
  say("   %-24s z = %7.3f  p_holm = %.3g  strength %.4g +- %.3g  detectable from %s", c.name, c.z or 0 / 0, c.p_holm or 0 / 0,
      c.strength or 0 / 0, c.strength_se or 0 / 0, c.detection_limit and string.format("%.4g", c.detection_limit) or "nowhere")
end
outcome.signatures, outcome.diagnosis = signatures, diag

-----------------------------------------------------------------------------------------------
-- 4. Add the named effect and recalibrate jointly; confirm at new seeds. The score test is linear:
-- a strong effect leaves a large linearised remainder Q0 - z^2 even when it is the whole story.
-- So when the screening says `unknown` only because of that remainder (a best candidate that
-- passes, lies in its range and has no rival), the candidate is added and recalibrated too, and
-- the decision is taken on the misfit left after the nonlinear refit at new seeds: not
-- significant -> `effect`; still significant -> `unknown`, with the tried effect reported.
local screening = {decision = diag.decision, reason = diag.reason}
local no_rival = diag.ambiguous_with == nil or #diag.ambiguous_with == 0
local tentative = diag.decision == "unknown" and diag.best ~= nil and no_rival
local named = diag.decision == "effect" and diag.named or (tentative and diag.best) or nil
-- Adds the candidate `named` to the model and recalibrates it with the free parameters (valley
-- scan, response surface, zoom), assessed at the confirmation seeds. Returns the assessed point
-- (misfit, seed scatter after, diagnosis of what is left, comparison with the misfit before), the
-- joint fit and the candidate.
local function refit_effect(named, tentative)
  local c
  for _, x in ipairs(cands) do if x.name == named then c = x end end
  local est
  for _, x in ipairs(diag.candidates) do if x.name == named then est = x end end
  local lam = math.min(c.high, math.max(c.low, est and est.strength or c.probe))
  if lam <= 0 then lam = c.probe end
  local dims = theta_dims()
  dims[#dims + 1] = {lo = c.low, hi = c.high, get = function(pt) return pt.lambda[named] end,
                     set = function(pt, v) local q = copy_point(pt); q.lambda[named] = v; return q end}
  say("4. recalibration with %s (start %.4g)%s", named, lam, tentative and ": tried, its linearised remainder being significant" or "")
  -- The free parameters were calibrated without the effect and have absorbed part of it: fit's
  -- start scan re-scans them with the effect at its estimated strength.
  local zeros = {}
  for j = 1, p do zeros[j] = 0 end
  local beta = doe.gauss_newton{theta = zeros, residual = signatures[named], jacobian = J, covariance = cov, damping = 0}.step
  -- A linear estimate at or above the top of the range says the response is not linear in the
  -- strength (strong wall adhesion lifts a whole layer of mud with the tack plate: the carried
  -- mass rises in a step once the adhesion exceeds the mud's own surface energy by a margin — at
  -- γ = 0.10 J/m² between 0.15 and 0.20 J/m² — then saturates; docs/results/tack_wall_adhesion_threshold.csv),
  -- so it is no guide to where the strength lies: the valley spans the whole range.
  local whole_range = valley_design.whole_range(est and est.strength, c.high)
  if whole_range then say("   linear estimate %.4g at or above the range's top %.4g: the valley spans the whole range", est.strength, c.high) end
  local best = fit("recalibration", {theta = theta, lambda = {[named] = lam}, seed = seed0}, dims, cov,
                   {theta = theta, beta = beta, lambda = lam, whole_range = whole_range})
  local joint = {theta = best.point.theta, lambda = best.point.lambda[named], iterations = best.history, scan = best.scan,
                 surface = best.surface, method = best.surface and "surface" or "gauss_newton"}
  -- The joint point assessed at the confirmation seeds: the misfit left, the seed scatter after,
  -- the resolution shift there and the diagnosis of what is left.
  local function assess(joint, last)
    local conf_points = {}
    for k = 1, S.confirm_seeds do
      conf_points[k] = {theta = joint.theta, lambda = {[named] = joint.lambda}, seed = seed0 + 200 + k, label = "confirmation " .. k}
    end
    local conf, conf_results = evaluate("confirmation", conf_points)
    local f_after = stack.mean(conf)
    local r1 = stack.minus(y, f_after)
    -- The seed scatter after: the replicates' and the confirmation runs' deviations from their own
    -- means, pooled (a strong effect can scatter the pile more than the calibrated model did: mud
    -- that sticks to the lifted cone lets go at a random moment). Scaled by sqrt((N-1)/(N-2)), the
    -- pooled deviations' sample covariance is the pooled within-group estimator on N - 2 degrees of
    -- freedom; the bootstrap thresholds draw the same number of effective replicates.
    local pooled = {}
    do
      local N = #reps + #conf
      local scale = math.sqrt((N - 1) / (N - 2))
      for _, group in ipairs({reps, conf}) do
        local mean = stack.mean(group)
        for _, x in ipairs(group) do
          local d = {}
          for i = 1, m do d[i] = scale * (x[i] - mean[i]) end
          pooled[#pooled + 1] = d
        end
      end
    end
    local noise_after = doe.noise_covariance{replicates = #conf >= 2 and pooled or reps, sigma = ones, n_avg = n_eff(S.confirm_seeds),
                                             measurement_covariance = shared}
    -- The resolution shift at the refit point: the same runs as step 2's, with the effect added
    -- (the shift a finer model makes depends on the model: wall adhesion acts through the spheres
    -- that touch the cone, whose number per area the sphere size sets). It replaces step 2's
    -- nuisance column in the diagnosis after.
    local J_after, resolution_after, b_after = J_diag, nil, nil
    if S.resolution_factor > 0 then
      local b
      b, J_after = resolution_shift("resolution after", joint.theta, {[named] = joint.lambda}, f_after)
      resolution_after = {diameter = d_fine, seeds = S.resolution_seeds, rms = stack.rms_standardised(b, noise_after.covariance)}
      b_after = b
      say("   resolution shift at the refit point: RMS %.3g noise sd", resolution_after.rms)
    end
    local rest = {}
    for _, x in ipairs(dcands) do if x.name ~= named then rest[#rest + 1] = x end end
    local thr_after = #rest > 0 and thresholds(n_eff(S.confirm_seeds), rest, noise_after.seed_covariance,
                                               #conf >= 2 and #pooled - 1 or S.replicates, J_after) or {}
    local diag_after = #rest > 0 and doe.diagnose{residual = r1, covariance = noise_after.covariance, jacobian = J_after, candidates = rest,
                                                  labels = labels, blocks = blocks, alpha = S.alpha, confusable = S.confusable, strong_margin = S.strong_margin,
                                                  z_threshold = thr_after.z_threshold, q0_threshold = thr_after.q0_threshold,
                                                  q_after_threshold = thr_after.q_after_threshold} or nil
    -- The strength's se: the fit's (measurement and shrunk seed covariance) and its spread over
    -- specimens, added in quadrature. The spread: the refit's response surface solved again with
    -- the measurements moved by +- each confirmation run's deviation (paddy.doe.response_surface,
    -- specimen_runs; the confirmation runs scatter as the effect makes them, the replicates without
    -- it do not). With measured_repeats = n > 0 the measurements are means of n specimens (spread
    -- / sqrt(n)); with 0 their sigma already holds the scatter of repeated tests.
    local se_fit = last.se and last.se[p + 1] or 0
    local se_spec
    if S.measured_repeats > 0 and last.design and #conf >= 2 then
      local d = last.design
      local ok, rs = pcall(doe.response_surface, {points = d.points, values = d.values, measured = y, covariance = cov,
                                                  lower = d.lower, upper = d.upper, specimen_runs = conf})
      if ok and rs.specimen_se then se_spec = rs.specimen_se[p + 1] / math.sqrt(S.measured_repeats) end
    end
    local se = math.sqrt(se_fit ^ 2 + (se_spec or 0) ^ 2)
    local after = {theta = joint.theta, strength = {value = joint.lambda, low = math.max(c.low, joint.lambda - 1.96 * se),
                                              high = math.min(c.high, joint.lambda + 1.96 * se), se = se,
                                              se_fit = se_fit, se_specimen = se_spec},
             joint = joint, simulated = f_after, residual = r1, covariance = noise_after.covariance, diagnosis = diag_after,
             rms = stack.rms_standardised(r1, noise_after.covariance), results = conf_results, resolution = resolution_after}
    if diag_after then
      -- diagnose's misfit is an RMS, sqrt(Q / m); the likelihood ratio compares the Q themselves.
      after.comparison = doe.compare_fits{q_before = diag.misfit ^ 2 * m, q_after = diag_after.misfit ^ 2 * m, df = 1, n = m,
                                          k_before = p, k_after = p + 1}
    end
    say("   %s = %.4g [%.4g, %.4g]; RMS standardised residual %.3g -> %.3g", named, after.strength.value, after.strength.low,
        after.strength.high, outcome.located.rms, after.rms)
    if b_after and last.jacobian then
      -- The strength extrapolated to the resolution runs' diameter (lib/discovery/resolution.lua).
      local devs = {}
      for k, x in ipairs(conf) do devs[k] = stack.minus(x, f_after) end
      local rc = resolution.corrected{jacobian = last.jacobian, shift = b_after, deviations = devs, weights = cov, lambda = joint.lambda,
                                      se = se, low = c.low, high = c.high, resolution_seeds = S.resolution_seeds}
      if rc then
        rc.diameter = d_fine
        after.strength.resolution_corrected = rc
        say("   at %.4g m (the resolution runs): %s = %.4g [%.4g, %.4g] (shift %+.3g +- %.3g)", d_fine, named, rc.value, rc.low, rc.high,
            rc.shift, rc.se_shift)
      end
    end
    local z = {}
    for i = 1, m do z[i] = r1[i] / math.sqrt(noise_after.covariance[i][i]) end
    after.z = z
    return after
  end
  local first = best.step or {}
  first.design = best.design
  first.jacobian = first.jacobian or best.J
  local after = assess(joint, first)
  -- Zoom: when the misfit left at the confirmation seeds is significant (or its RMS above
  -- refit_zoom_above noise sd: lib/discovery/zoom.lua, M.reason), a second response surface
  -- in a box of +-refit_zoom of each range around the refit point (a central composite design:
  -- centre, 2 axial points per dimension, every corner; clipped to the ranges), and its optimum
  -- assessed at the same confirmation seeds; the point that leaves the smaller misfit is kept, and
  -- zoomed around again while the misfit it leaves is significant (at most refit_zoom_rounds). A
  -- strong effect's response is far from quadratic over the whole valley the first surface spans
  -- (wall adhesion near the top of its range lifts mud with the cone), a quadratic in a small box
  -- around the optimum fits it.
  local zooms = {}
  for round = 1, S.refit_zoom > 0 and S.refit_zoom_rounds or 0 do
    local why = zoom.reason(after.diagnosis and after.diagnosis.q0_significant, after.rms, S.refit_zoom_above)
    if not why then break end
    local h = S.refit_zoom
    local x0, lower, upper = {}, {}, {}
    -- The centre clamped to the ranges: a surface's optimum on a bound can lie a rounding error outside it.
    for j, d in ipairs(dims) do
      x0[j], lower[j], upper[j] = math.min(d.hi, math.max(d.lo, j <= p and joint.theta[j] or joint.lambda)), d.lo, d.hi
    end
    local X, zlo, zhi = zoom.design(x0, lower, upper, h)
    local base = {theta = joint.theta, lambda = {[named] = joint.lambda}, seed = seed0}
    local function at(x)
      local pt = copy_point(base)
      for j, d in ipairs(dims) do pt = d.set(pt, x[j]) end
      return pt
    end
    local zpts = {}
    for k, x in ipairs(X) do zpts[k] = at(x); zpts[k].label = string.format("recalibration zoom %d.%d", round, k - 1) end
    say("   %s: zoom %d, %d point(s) within +-%.3g of each range around the refit point", why, round, #zpts, h)
    local zfs = evaluate("recalibration zoom", zpts)
    local ok, rs = pcall(doe.response_surface, {points = X, values = zfs, measured = y, covariance = cov, lower = zlo, upper = zhi})
    if ok then
      local pt = at(rs.x)
      local zjoint = {theta = pt.theta, lambda = pt.lambda[named], iterations = joint.iterations, scan = joint.scan, surface = joint.surface,
                      method = "surface, zoomed",
                      zoom = {x = rs.x, se = rs.se, misfit_predicted = rs.misfit_predicted, residual_sd = rs.residual_sd,
                              at_bound = rs.at_bound, points = #X, half_width = h, round = round,
                              from = {theta = joint.theta, lambda = joint.lambda}}}
      say("   zoomed surface: best %s, predicted RMS residual %.3g", fmt_point(pt), rs.misfit_predicted)
      local zafter = assess(zjoint, {se = rs.se, jacobian = rs.jacobian, design = {points = X, values = zfs, lower = zlo, upper = zhi}})
      zjoint.zoom.kept = zafter.rms < after.rms
      say("   zoomed point: RMS standardised residual %.3g against %.3g at the point it zoomed from: %s", zafter.rms, after.rms,
          zjoint.zoom.kept and "kept" or "not kept")
      zooms[#zooms + 1] = zjoint.zoom
      zjoint.zooms = zooms
      if not zjoint.zoom.kept then after.joint.zooms = zooms; break end
      after, joint = zafter, zjoint
    else
      say("   no zoomed surface (%s): the point stays", tostring(rs))
      break
    end
  end
  return after, joint, c
end

-- What a refit says of its effect: `weak` (its strength at or below the candidate's smallest
-- relevant one, or 0), `no_gain` (the misfit at the new seeds not significantly below the misfit
-- before: likelihood ratio on 1 df at alpha) and `left` (a significant misfit remains).
local function refit_checks(after, joint, c)
  local weak = joint.lambda <= (c.relevant or 0)
  local no_gain = after.comparison ~= nil and not (after.comparison.p < S.alpha)
  local left = after.diagnosis and after.diagnosis.q0_significant or false
  return weak, no_gain, left
end

-- An ambiguous answer: the two candidates that explain the misfit alike (their linearised
-- signatures are confusable) are each added and recalibrated, and their refits compared at the
-- same confirmation seeds with Vuong's test for non-nested models (paddy.doe.compare_non_nested,
-- doe/include/paddy/doe/non_nested.hpp): a strong effect bends the response in its own way, which
-- the linear signatures cannot show. One is named when the test prefers it at alpha and its refit
-- confirms it (strength above its smallest relevant one, misfit significantly lower than before,
-- nothing significant left); otherwise the answer stays ambiguous and reports both refits.
local after, resolved
if diag.decision == "ambiguous" and S.ambiguous_refits and diag.ambiguous_with and #diag.ambiguous_with >= 2 then
  local pair = {diag.ambiguous_with[1], diag.ambiguous_with[2]}
  say("4. ambiguous between %s and %s: each added and recalibrated", pair[1], pair[2])
  local fits = {}
  for k, name in ipairs(pair) do
    local a, jt, cc = refit_effect(name, false)
    fits[k] = {after = a, joint = jt, c = cc}
  end
  local C = {}
  for i = 1, m do
    C[i] = {}
    for j = 1, m do C[i][j] = 0.5 * (fits[1].after.covariance[i][j] + fits[2].after.covariance[i][j]) end
  end
  local v = doe.compare_non_nested{residual_a = fits[1].after.residual, residual_b = fits[2].after.residual, covariance = C,
                                   k_a = p + 1, k_b = p + 1, alpha = S.alpha}
  local function confirmed(f)
    local weak, no_gain, left = refit_checks(f.after, f.joint, f.c)
    return not (weak or no_gain or left)
  end
  local rec = {candidates = pair, vuong = v}
  for k, f in ipairs(fits) do
    rec[k == 1 and "a" or "b"] = {name = pair[k], strength = f.after.strength, misfit_after = f.after.rms, confirmed = confirmed(f),
                                  q0_after = f.after.diagnosis and f.after.diagnosis.q0 or nil,
                                  q0_significant = f.after.diagnosis and f.after.diagnosis.q0_significant or false}
  end
  local win = v.preferred == "a" and 1 or v.preferred == "b" and 2 or nil
  say("   Vuong z = %.3g (p = %.3g): %s; misfit after %.3g (%s) and %.3g (%s)", v.z, v.p,
      win and (pair[win] .. " fits better") or "neither fits better", fits[1].after.rms, pair[1], fits[2].after.rms, pair[2])
  if win and confirmed(fits[win]) then
    local f = fits[win]
    named, after, resolved = pair[win], f.after, true
    diag.decision, diag.named = "effect", named
    diag.reason = string.format("%s and %s explained the misfit alike to first order; added and recalibrated each, %s fits "
                                .. "better (Vuong z = %.3g, p = %.3g) and leaves no significant misfit", pair[1], pair[2], named, v.z, v.p)
    rec.named = named
  else
    diag.reason = diag.reason .. string.format("; added and recalibrated each: %s (Vuong z = %.3g, p = %.3g)",
                                               win and (pair[win] .. " fits better but its refit does not confirm it")
                                               or "neither fits significantly better", v.z, v.p)
  end
  outcome.ambiguous_refits = rec
  say("   decision after the refits: %s%s", diag.decision, diag.named and (" - " .. diag.named) or "")
end
if resolved then
  -- named by the refits above
elseif named then
  local joint, c
  after, joint, c = refit_effect(named, tentative)
  local diag_after = after.diagnosis or nil
  -- The refit must confirm the effect: a strength below the candidate's smallest relevant one (or
  -- 0 when none is given) means the joint fit did not need it, and so does a misfit at the new
  -- seeds that is not significantly smaller than before (likelihood ratio on 1 df at alpha); the
  -- screening's misfit was then the calibration's (nothing significant left: `none`) or another
  -- effect's (`unknown`).
  local weak, no_gain, left = refit_checks(after, joint, c)
  if weak or no_gain then
    diag.decision = left and "unknown" or "none"
    diag.reason = (weak and string.format("%s was %s, but its refit put its strength at %.4g, not above its smallest relevant strength %.4g; ",
                                          named, tentative and "tried" or "named", joint.lambda, c.relevant or 0)
                   or string.format("%s was %s, but adding it did not lower the misfit significantly (likelihood ratio %.3g, p = %.3g); ",
                                    named, tentative and "tried" or "named", after.comparison.lr, after.comparison.p))
                  .. (left and "a significant misfit is left" or "the misfit left is not significant")
    diag.named = nil
    outcome.tried, after = after, nil
    named = nil
    say("   decision after the recalibration: %s (the refit did not need %s)", diag.decision, c.name)
  elseif tentative then
    if diag_after and not diag_after.q0_significant then
      diag.decision, diag.named = "effect", named
      diag.reason = named .. " passes and lies in its range; its linearised remainder was significant, the misfit left after "
                    .. "adding it and recalibrating (Q0 = " .. string.format("%.4g", diag_after.q0) .. ") is not"
    else
      diag.reason = diag.reason .. "; added and recalibrated, it still leaves a significant misfit"
                    .. (diag_after and string.format(" (Q0 = %.4g)", diag_after.q0) or " (no other candidate to test the remainder with)")
      outcome.tried, after = after, nil
      named = nil
      -- Runner-ups (settings.runner_up_refits = k > 0): the score test is linear, and a strong
      -- effect's linear estimate can fall outside its range or its score below another's; so the
      -- next k candidates whose scores are significant (by z) are added and recalibrated in turn,
      -- and the first whose refit confirms it (strength above its smallest relevant one, misfit
      -- significantly lower, nothing significant left at the new seeds) is named.
      local order = {}
      for _, x in ipairs(diag.candidates or {}) do
        if x.name ~= diag.best and (x.p_holm or 1) < S.alpha then order[#order + 1] = x end
      end
      table.sort(order, function(a, b) return (a.z or 0) > (b.z or 0) end)
      local runner_ups = {}
      for k = 1, math.min(S.runner_up_refits, #order) do
        local name2 = order[k].name
        say("4. runner-up %d: %s (z = %.3g) added and recalibrated", k, name2, order[k].z or 0 / 0)
        local a2, j2, c2 = refit_effect(name2, true)
        local w2, ng2, left2 = refit_checks(a2, j2, c2)
        local ok2 = not (w2 or ng2 or left2)
        runner_ups[#runner_ups + 1] = {name = name2, strength = a2.strength, misfit_after = a2.rms, confirmed = ok2,
                                       q0_after = a2.diagnosis and a2.diagnosis.q0 or nil}
        if ok2 then
          diag.decision, diag.named = "effect", name2
          diag.reason = diag.reason .. string.format("; the runner-up %s, added and recalibrated, leaves no significant misfit", name2)
          after, named = a2, name2
          break
        end
      end
      if #runner_ups > 0 then outcome.runner_up_refits = runner_ups end
    end
    say("   decision after the recalibration: %s%s", diag.decision, diag.named and (" - " .. diag.named) or "")
  end
else
  say("4. no effect named (%s): nothing to add", diag.decision)
end
outcome.after = after
outcome.screening = screening

-----------------------------------------------------------------------------------------------
-- 5. Report.
outcome.simulations = runner.log
outcome.replicates, outcome.replicate_results, outcome.f_bar, outcome.residual = reps, rep_results, f_bar, r0
outcome.wall_time_s = os.difftime(os.time(), wall_start)
local files = report.write{outcome = outcome, pictures = P.pictures}
say("report: %s", files.html)
paddy.result(report.summary(outcome, files))
