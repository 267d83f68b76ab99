-- The discovery input file (JSON; schema in docs/discovery.md, "The workflow"): experiments with
-- their settings, measured observables and measurement standard deviations, the free parameters
-- to calibrate and the candidate effects. Checked on reading: every error names the file, the
-- entry and the allowed values (checks shared with the calibration input, lib/calibration/input.lua).
local check = require("lib.calibration.input").checks("discovery input")
local fail, number = check.fail, check.number
local M = {}

local SCRIPTS = {["slump.lua"] = true, ["rheometer.lua"] = true, ["tack.lua"] = true}
local NAME = "^[%a][%w_]*$"
-- A result key: names joined by dots (a.b reads result.a.b).
local function result_key(key)
  return type(key) == "string" and key:match("^[%a][%w_%.]*$") ~= nil and not key:find("%.%.") and not key:find("%.$")
end

-- measured/sigma value: a number or a non-empty list of numbers (a vector observable).
local function values(path, where, v)
  if type(v) == "number" then return {number(path, where, v)}, false end
  if type(v) ~= "table" or #v == 0 then fail(path, where .. " must be a number or a non-empty list of numbers") end
  local out = {}
  for i, x in ipairs(v) do out[i] = number(path, string.format("%s[%d]", where, i), x) end
  return out, true
end

local function strength(path, where, e, t)
  t.low = number(path, where .. ".low", e.low)
  t.high = number(path, where .. ".high", e.high)
  if not (t.high > t.low) then fail(path, string.format("%s: high = %g must be greater than low = %g", where, t.high, t.low)) end
end

-- Returns {path, experiments = {{name, script, set, observables = {{key, measured = {..}, sigma = {..},
-- vector}}}}, free_parameters = {{parameter, low, high, start}}, candidates = {{name, parameter, low,
-- high, probe, relevant}}, settings = {...}}.
function M.read(path)
  local ok, t = pcall(paddy.read_json, path)
  if not ok then error((tostring(t):gsub("^%s+", "")), 0) end
  if type(t) ~= "table" then fail(path, "the top level must be an object") end
  local known = {experiments = true, free_parameters = true, candidates = true, description = true, settings = true}
  for k in pairs(t) do
    if not known[k] then fail(path, "unknown key '" .. tostring(k) .. "' (allowed: experiments, free_parameters, candidates, description, settings)") end
  end
  -- Free text (the description, string values of set) is shown HTML-escaped in the report;
  -- names (experiments, observables, parameters, candidates) become result keys, figure labels
  -- and --set names, so they must be plain names.
  if t.description ~= nil and type(t.description) ~= "string" then fail(path, "'description' must be a text") end
  local input = {path = path, description = t.description or "", experiments = {}, free_parameters = {}, candidates = {}}

  if type(t.experiments) ~= "table" or #t.experiments == 0 then fail(path, "'experiments' must be a non-empty list") end
  local names = {}
  for i, e in ipairs(t.experiments) do
    local where = string.format("experiments[%d]", i)
    if type(e.name) ~= "string" or not e.name:match(NAME) then fail(path, where .. ".name must be a name such as slump_slow") end
    if names[e.name] then fail(path, where .. ": name '" .. e.name .. "' is used twice") end
    names[e.name] = true
    if not SCRIPTS[e.script] then fail(path, where .. ".script = " .. tostring(e.script) .. " (allowed: slump.lua, rheometer.lua, tack.lua)") end
    if e.set ~= nil and type(e.set) ~= "table" then fail(path, where .. ".set must be an object {parameter = value}") end
    for k, v in pairs(e.set or {}) do
      if type(k) ~= "string" or not k:match(NAME) then
        fail(path, string.format("%s.set: %q must be a parameter name such as cone_lift_speed", where, tostring(k)))
      end
      if type(v) ~= "number" and type(v) ~= "string" and type(v) ~= "boolean" then
        fail(path, string.format("%s.set.%s must be a number, string or boolean", where, tostring(k)))
      end
    end
    if type(e.measured) ~= "table" or next(e.measured) == nil then fail(path, where .. ".measured must be an object {result key = value or list}") end
    if type(e.sigma) ~= "table" then fail(path, where .. ".sigma must be an object with the keys of measured") end
    local x = {name = e.name, script = e.script, set = e.set or {}, observables = {}}
    local keys = {}
    for key in pairs(e.measured) do
      if not result_key(key) then
        fail(path, string.format("%s.measured: %q must be a result key of the experiment such as slump_mm or a.b", where, tostring(key)))
      end
      keys[#keys + 1] = key
    end
    table.sort(keys)
    for _, key in ipairs(keys) do
      local m, vec = values(path, where .. ".measured." .. key, e.measured[key])
      if e.sigma[key] == nil then fail(path, string.format("%s.sigma.%s is missing (every measured key needs a sigma)", where, key)) end
      local s = values(path, where .. ".sigma." .. key, e.sigma[key])
      if #s == 1 and #m > 1 then for k = 2, #m do s[k] = s[1] end end
      if #s ~= #m then fail(path, string.format("%s.sigma.%s has %d entries, measured.%s has %d (give one sigma or one per entry)", where, key, #s, key, #m)) end
      for k, v in ipairs(s) do
        if not (v > 0) then fail(path, string.format("%s.sigma.%s[%d] = %g must be > 0", where, key, k, v)) end
      end
      x.observables[#x.observables + 1] = {key = key, measured = m, sigma = s, vector = vec}
    end
    for key in pairs(e.sigma) do
      if e.measured[key] == nil then fail(path, string.format("%s.sigma.%s has no measured value", where, key)) end
    end
    -- shared_error: a relative error that every entry of the listed keys shares (one specimen read
    -- at several speeds: all multiplied by the same 1 + eps, eps ~ N(0, rel_sd^2)); sigma then
    -- holds each entry's own reading error.
    if e.shared_error ~= nil then
      local se, w = e.shared_error, where .. ".shared_error"
      if type(se) ~= "table" then fail(path, w .. " must be an object {rel_sd = number, keys = [measured keys]}") end
      for k in pairs(se) do
        if k ~= "rel_sd" and k ~= "keys" then fail(path, string.format("%s: unknown key '%s' (allowed: rel_sd, keys)", w, tostring(k))) end
      end
      local rel = number(path, w .. ".rel_sd", se.rel_sd, 0, 1)
      if not (rel > 0) then fail(path, string.format("%s.rel_sd = %g must be in (0, 1]", w, rel)) end
      if type(se.keys) ~= "table" or #se.keys == 0 then fail(path, w .. ".keys must be a non-empty list of measured keys") end
      local shared = {}
      for n, key in ipairs(se.keys) do
        if type(key) ~= "string" or e.measured[key] == nil then
          fail(path, string.format("%s.keys[%d] = %s is not a measured key of this experiment", w, n, tostring(key)))
        end
        shared[key] = true
      end
      x.shared_error = {rel_sd = rel, keys = shared}
    end
    input.experiments[i] = x
  end

  local used = {}
  if type(t.free_parameters) ~= "table" then fail(path, "'free_parameters' must be a list (it may be empty)") end
  for i, f in ipairs(t.free_parameters) do
    local where = string.format("free_parameters[%d]", i)
    if type(f.parameter) ~= "string" or not f.parameter:match(NAME) then fail(path, where .. ".parameter must name a parameter of the experiments") end
    if used[f.parameter] then fail(path, where .. ": parameter '" .. f.parameter .. "' is used twice") end
    used[f.parameter] = true
    local x = {parameter = f.parameter}
    strength(path, where, f, x)
    x.start = f.start and number(path, where .. ".start", f.start, x.low, x.high) or (x.low + x.high) / 2
    input.free_parameters[i] = x
  end

  if type(t.candidates) ~= "table" or #t.candidates == 0 then fail(path, "'candidates' must be a non-empty list") end
  local cnames = {}
  for i, c in ipairs(t.candidates) do
    local where = string.format("candidates[%d]", i)
    if type(c.name) ~= "string" or not c.name:match(NAME) then fail(path, where .. ".name must be a name such as wall_adhesion") end
    if cnames[c.name] then fail(path, where .. ": name '" .. c.name .. "' is used twice") end
    cnames[c.name] = true
    if type(c.parameter) ~= "string" or not c.parameter:match(NAME) then fail(path, where .. ".parameter must name a parameter of the experiments") end
    if used[c.parameter] then fail(path, where .. ": parameter '" .. c.parameter .. "' is already a free parameter or another candidate") end
    used[c.parameter] = true
    local x = {name = c.name, parameter = c.parameter}
    strength(path, where, c, x)
    if x.low ~= 0 then fail(path, string.format("%s.low = %g: a candidate's strength starts at 0 (0 = today's model, effect off)", where, x.low)) end
    x.probe = c.probe and number(path, where .. ".probe", c.probe, 1e-300, x.high) or x.high / 2
    -- relevant: the smallest strength that matters; a weaker effect is not named (docs/discovery.md, "Decision").
    if c.relevant ~= nil then
      x.relevant = number(path, where .. ".relevant", c.relevant, 0, x.high)
      if x.relevant >= x.high then fail(path, string.format("%s.relevant = %g must be below high = %g", where, x.relevant, x.high)) end
    end
    input.candidates[i] = x
  end

  -- Optional workflow settings (defaults in docs/discovery.md).
  local s = t.settings or {}
  if type(s) ~= "table" then fail(path, "'settings' must be an object") end
  local allowed = {"iterations", "replicates", "signature_seeds", "confirm_seeds", "fd_step", "alpha", "confusable",
                   "strong_margin", "thresholds", "bootstrap_trials", "measured_repeats", "resolution_factor", "resolution_seeds", "backtracks", "converge", "start_scan", "refit", "refit_zoom", "refit_zoom_rounds", "refit_zoom_above", "ambiguous_refits", "runner_up_refits",
                   "calibration_start", "signature_baseline"}
  local allowed_set = {}
  for _, k in ipairs(allowed) do allowed_set[k] = true end
  for k in pairs(s) do
    if not allowed_set[k] then fail(path, string.format("unknown key 'settings.%s' (allowed: %s)", tostring(k), table.concat(allowed, ", "))) end
  end
  local S = {}
  S.iterations = number(path, "settings.iterations", s.iterations or 3, 0, 20)
  S.replicates = number(path, "settings.replicates", s.replicates or 5, 5, 50)
  S.signature_seeds = number(path, "settings.signature_seeds", s.signature_seeds or 2, 1, 10)
  S.confirm_seeds = number(path, "settings.confirm_seeds", s.confirm_seeds or 3, 1, 50)
  S.fd_step = number(path, "settings.fd_step", s.fd_step or 0.1, 1e-4, 0.5)
  S.alpha = number(path, "settings.alpha", s.alpha or 0.05, 1e-6, 0.5)
  S.confusable = number(path, "settings.confusable", s.confusable or 0.9, 0.5, 1)
  -- Optional: name one of two confusable candidates when its Bayes factor beats the other's by this
  -- factor (absent: a confusable rival always makes the answer ambiguous; docs/discovery.md).
  S.strong_margin = s.strong_margin ~= nil and number(path, "settings.strong_margin", s.strong_margin, 3, 1e6) or nil
  -- Thresholds of the decision: bootstrap (null trials of the fitted noise model, which knows
  -- that Sigma was estimated from few seeds; doe/include/paddy/doe/bootstrap_null.hpp) or the
  -- chi^2 / normal tables with Holm (right only when Sigma is known).
  S.thresholds = s.thresholds or "bootstrap"
  if S.thresholds ~= "bootstrap" and S.thresholds ~= "tables" then
    fail(path, string.format("settings.thresholds = '%s': allowed bootstrap, tables", tostring(S.thresholds)))
  end
  S.bootstrap_trials = number(path, "settings.bootstrap_trials", s.bootstrap_trials or 2000, 100, 100000)
  -- Specimen scatter: the measured values are means of measured_repeats specimens and sigma is the
  -- instrument's alone; the workflow then adds the specimen-to-specimen scatter, taken to be the
  -- model's seed scatter, / measured_repeats (0: sigma already holds it, nothing is added).
  S.measured_repeats = number(path, "settings.measured_repeats", s.measured_repeats or 0, 0, 1000)
  -- Resolution bias: runs at resolution_factor x the particle diameter (0: none) give the direction in which
  -- the observables move as the model is refined; it is projected out like a free parameter.
  S.resolution_factor = number(path, "settings.resolution_factor", s.resolution_factor or 0, 0, 0.99)
  if S.resolution_factor > 0 and S.resolution_factor < 0.5 then
    fail(path, string.format("settings.resolution_factor = %g: allowed 0 (off) or 0.5 to 0.99", S.resolution_factor))
  end
  S.resolution_seeds = number(path, "settings.resolution_seeds", s.resolution_seeds or 3, 1, 50)
  -- Step control of the calibration: a Gauss-Newton step that raises the misfit is halved, at most backtracks times.
  S.backtracks = number(path, "settings.backtracks", s.backtracks or 2, 0, 10)
  -- ... and stops early when the next step would move no parameter by more than converge x its range.
  S.converge = number(path, "settings.converge", s.converge or 0.01, 0, 0.5)
  -- ... from the best of its start and start_scan points spread over the free parameters' box.
  S.start_scan = number(path, "settings.start_scan", s.start_scan or 4, 0, 100)
  -- The recalibration with an effect: a response surface through its start scan (default) or
  -- Gauss-Newton steps from the scan's best point (docs/discovery.md, step 4).
  -- ... and, when the misfit left at the confirmation seeds is significant, a second surface in a
  -- box of +-refit_zoom of each range around the refit point (0: none), again around each better
  -- point while the misfit stays significant, at most refit_zoom_rounds times.
  S.refit_zoom = number(path, "settings.refit_zoom", s.refit_zoom or 0.15, 0, 0.5)
  if S.refit_zoom > 0 and S.refit_zoom < 0.02 then
    fail(path, string.format("settings.refit_zoom = %g: allowed 0 (off) or 0.02 to 0.5", S.refit_zoom))
  end
  S.refit_zoom_rounds = number(path, "settings.refit_zoom_rounds", s.refit_zoom_rounds or 3, 1, 10)
  -- ... and also while the RMS standardised residual it leaves is above refit_zoom_above noise sd
  -- though not significant (0: only when significant; lib/discovery/zoom.lua).
  S.refit_zoom_above = number(path, "settings.refit_zoom_above", s.refit_zoom_above or 1.2, 0, 10)
  if S.refit_zoom_above > 0 and S.refit_zoom_above < 1 then
    fail(path, string.format("settings.refit_zoom_above = %g: allowed 0 (off) or 1 to 10", S.refit_zoom_above))
  end
  -- An ambiguous answer: refit both confusable candidates and compare the refits (Vuong's test).
  if s.ambiguous_refits ~= nil and type(s.ambiguous_refits) ~= "boolean" then
    fail(path, string.format("settings.ambiguous_refits = %s: allowed true, false", tostring(s.ambiguous_refits)))
  end
  S.ambiguous_refits = s.ambiguous_refits ~= false
  S.runner_up_refits = number(path, "settings.runner_up_refits", s.runner_up_refits or 0, 0, 3)
  S.refit = s.refit or "surface"
  if S.refit ~= "surface" and S.refit ~= "gauss_newton" then
    fail(path, string.format("settings.refit = '%s': allowed surface, gauss_newton", tostring(S.refit)))
  end
  -- Where the calibration's Gauss-Newton starts: the best point of a quadratic response surface
  -- through its start scan (default; the surface averages the scan points' seed noise) or the
  -- scan's best single point (docs/discovery.md, step 1).
  S.calibration_start = s.calibration_start or "surface"
  if S.calibration_start ~= "surface" and S.calibration_start ~= "best_scan" then
    fail(path, string.format("settings.calibration_start = '%s': allowed surface, best_scan", tostring(S.calibration_start)))
  end
  -- The λ = 0 run of each signature seed: its own run at a seed no replicate has (default; the
  -- signature's noise is then independent of the residual's) or the replicate of that seed (the
  -- earlier rule, one run fewer per seed; docs/discovery.md, step 3).
  S.signature_baseline = s.signature_baseline or "own"
  if S.signature_baseline ~= "own" and S.signature_baseline ~= "replicates" then
    fail(path, string.format("settings.signature_baseline = '%s': allowed own, replicates", tostring(S.signature_baseline)))
  end
  if S.signature_baseline == "replicates" and S.signature_seeds > S.replicates then
    fail(path, string.format("settings.signature_seeds = %d with signature_baseline = 'replicates' needs as many replicates "
                             .. "(settings.replicates = %d); allowed: signature_seeds <= replicates, or signature_baseline = 'own'",
                             S.signature_seeds, S.replicates))
  end
  input.settings = S
  return input
end

return M
