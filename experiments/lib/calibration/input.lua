-- The calibration input file (JSON): measured targets, the factors with their screening levels,
-- steepest-ascent steps and search ranges, and the sizes of each design. Checked on reading;
-- every error names the file and the entry. Format: docs/calibration.md.
local M = {}

-- The checks, for any kind of input file ("calibration input", "discovery input", ...): every
-- message names the kind, the file and the entry.
local function checks(kind)
  local function fail(path, what)
    error(string.format("%s '%s': %s", kind, path, what), 0)
  end

  local function number(path, where, v, lo, hi)
    if type(v) ~= "number" or v ~= v then fail(path, where .. " must be a number") end
    if (lo and v < lo) or (hi and v > hi) then
      fail(path, string.format("%s = %g is outside the allowed range [%s, %s]", where, v, tostring(lo or "-inf"), tostring(hi or "inf")))
    end
    return v
  end

  local function range(path, where, v)
    if type(v) ~= "table" or #v ~= 2 then fail(path, where .. " must be [low, high]") end
    number(path, where .. "[1]", v[1]); number(path, where .. "[2]", v[2])
    if not (v[2] > v[1]) then fail(path, where .. ": high must be greater than low") end
    return {v[1], v[2]}
  end

  return fail, number, range
end
local fail, number, range = checks("calibration input")

-- For other input files: local c = require("lib.calibration.input").checks("discovery input");
-- c.fail(path, what), c.number(path, where, v, lo, hi), c.range(path, where, {lo, hi}).
function M.checks(kind)
  local f, n, r = checks(kind)
  return {fail = f, number = n, range = r}
end

local function section(t, name, defaults)
  local s = t[name] or {}
  for k, v in pairs(defaults) do if s[k] == nil then s[k] = v end end
  return s
end

-- Reads and checks the file; returns the input with defaults filled in:
--   conventions ("paddy" or "edem", default paddy),
--   measured = {response = value}, responses = {names in a fixed order}, tolerance (fraction),
--   factors = {{symbol, parameter, low, high, center, step, origin, search = {lo, hi}, bounds = {lo, hi}}},
--   screening, steepest_ascent, box_behnken, verification, rheometer, surrogate.
function M.read(path)
  local ok, t = pcall(paddy.read_json, path)
  if not ok then error((tostring(t):gsub("^%s+", "")), 0) end
  if type(t) ~= "table" then fail(path, "the top level must be an object") end
  -- Free text (description, units) is shown HTML-escaped in the report; names (responses,
  -- parameters, symbols) become result keys, CSV columns, --set names and gnuplot labels, so
  -- they must be plain names.
  if t.description ~= nil and type(t.description) ~= "string" then fail(path, "'description' must be a text") end
  if t.experiment ~= nil and (type(t.experiment) ~= "string" or t.experiment == "" or t.experiment:find("[%c]")) then
    fail(path, "'experiment' must be the file name of an experiment script, such as slump.lua")
  end
  local input = {path = path, description = t.description or "", experiment = t.experiment or "slump.lua"}
  -- Contact conventions of every simulation (experiments/lib/mud.lua: paddy or edem).
  input.conventions = t.conventions or "paddy"
  if input.conventions ~= "paddy" and input.conventions ~= "edem" then
    fail(path, string.format("conventions = %s: allowed are \"paddy\" and \"edem\"", tostring(t.conventions)))
  end

  if type(t.measured) ~= "table" then fail(path, "'measured' must be an object {response = measured value}") end
  input.measured, input.responses = {}, {}
  for name, v in pairs(t.measured) do
    if type(name) ~= "string" or not name:match("^[%a][%w_]*$") then
      fail(path, string.format("measured: the response name %q must be a name such as slump_mm (a result key of the experiment)", tostring(name)))
    end
    input.measured[name] = number(path, "measured." .. name, v)
    if v == 0 then fail(path, "measured." .. name .. " is 0: relative errors are undefined") end
    input.responses[#input.responses + 1] = name
  end
  table.sort(input.responses)
  if #input.responses == 0 then fail(path, "'measured' names no response") end
  input.tolerance = number(path, "tolerance_percent", t.tolerance_percent or 2, 0.01, 100) / 100

  if type(t.factors) ~= "table" or #t.factors < 3 then fail(path, "'factors' must list at least 3 factors") end
  input.factors, input.by_symbol = {}, {}
  for i, f in ipairs(t.factors) do
    local where = string.format("factors[%d]", i)
    if type(f.symbol) ~= "string" or not f.symbol:match("^[%a][%w_]*$") then fail(path, where .. ".symbol must be a name such as H1") end
    if type(f.parameter) ~= "string" or not f.parameter:match("^[%a][%w_]*$") then
      fail(path, where .. ".parameter must name a parameter of the experiment (a name such as mud_mud_friction)")
    end
    if f.unit ~= nil and type(f.unit) ~= "string" then fail(path, where .. ".unit must be a text such as J/m^2") end
    if input.by_symbol[f.symbol] then fail(path, where .. ": symbol '" .. f.symbol .. "' is used twice") end
    local x = {symbol = f.symbol, parameter = f.parameter, unit = f.unit or ""}
    x.low, x.high = number(path, where .. ".low", f.low), number(path, where .. ".high", f.high)
    if not (x.high > x.low) then fail(path, where .. ": high must be greater than low") end
    x.center = (x.low + x.high) / 2
    x.bounds = f.bounds and range(path, where .. ".bounds", f.bounds) or {-math.huge, math.huge}
    if x.low < x.bounds[1] or x.high > x.bounds[2] then fail(path, where .. ": low/high outside bounds") end
    x.step = f.step and number(path, where .. ".step", f.step, 1e-12) or (x.high - x.low) / 3
    x.origin = f.origin and number(path, where .. ".origin", f.origin, x.bounds[1], x.bounds[2]) or x.center
    x.search = f.search and range(path, where .. ".search", f.search) or {x.low, x.high}
    if x.search[1] < x.bounds[1] or x.search[2] > x.bounds[2] then fail(path, where .. ".search lies outside bounds") end
    input.factors[i], input.by_symbol[f.symbol] = x, x
  end

  input.screening = section(t, "screening", {runs = 12, dummy_columns = 4, center_points = 1, alpha = 0.05, min_factors = 3, max_factors = 4})
  local s = input.screening
  number(path, "screening.runs", s.runs, 4, 48)
  number(path, "screening.alpha", s.alpha, 1e-6, 0.5)
  if #input.factors + s.dummy_columns > s.runs - 1 then
    fail(path, string.format("screening: %d factors + %d dummy columns do not fit a %d-run Plackett-Burman design (at most %d columns)",
                             #input.factors, s.dummy_columns, s.runs, s.runs - 1))
  end
  number(path, "screening.min_factors", s.min_factors, 3, 7)
  number(path, "screening.max_factors", s.max_factors, s.min_factors, 7)
  input.steepest_ascent = section(t, "steepest_ascent", {max_steps = 6})
  number(path, "steepest_ascent.max_steps", input.steepest_ascent.max_steps, 1, 50)
  input.box_behnken = section(t, "box_behnken", {center_points = 5, replicates = 3})
  number(path, "box_behnken.center_points", input.box_behnken.center_points, 1, 20)
  number(path, "box_behnken.replicates", input.box_behnken.replicates, 1, 20)
  input.verification = section(t, "verification", {seeds = 3})
  number(path, "verification.seeds", input.verification.seeds, 1, 50)
  input.rheometer = section(t, "rheometer", {run = true})
  if input.rheometer.measured_torque_csv ~= nil and type(input.rheometer.measured_torque_csv) ~= "string" then
    fail(path, "rheometer.measured_torque_csv must be a file name or null")
  end
  input.surrogate = section(t, "surrogate", {initial_points = 6, budget = 30, confirm_seeds = 2, warp_inputs = true})
  number(path, "surrogate.initial_points", input.surrogate.initial_points, 2, 100)
  number(path, "surrogate.budget", input.surrogate.budget, input.surrogate.initial_points, 1000)
  number(path, "surrogate.confirm_seeds", input.surrogate.confirm_seeds, 0, 20)
  if type(input.surrogate.warp_inputs) ~= "boolean" then
    fail(path, "surrogate.warp_inputs must be true or false, not " .. tostring(input.surrogate.warp_inputs))
  end
  return input
end

return M
