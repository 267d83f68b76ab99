-- The stacked observable vector of the discovery workflow: every measured entry of every
-- experiment in one fixed order (experiment, then result key in alphabetical order, then index),
-- standardised by its measurement standard deviation so that millimetres, newtons and newton
-- metres can be mixed: y_i = value_i / sigma_i.
--
--   local stack = require("lib.discovery.stack")
--   local L = stack.layout(input)                 --> {{block, key, index, measured, sigma, label}, ...}
--   local y = stack.simulated(L, results)         --> results = {experiment name = result table}
local M = {}

-- Grids beside the vector observables, for labels (the entry's radius, time or speed).
M.AXES = {profile_mm = {key = "profile_radii_mm", unit = "mm", what = "r"},
          profile_mean_mm = {key = "profile_radii_mm", unit = "mm", what = "r"},
          history_mm = {key = "history_times_s", unit = "s", what = "t"}}

-- The value(s) of a result key; "a.b" reads result.a.b. → list of numbers, or nil, message.
function M.extract(result, key)
  local v = result
  for part in key:gmatch("[^%.]+") do
    if type(v) ~= "table" then return nil, "no key '" .. key .. "'" end
    v = v[part]
  end
  if type(v) == "number" then return {v} end
  if type(v) ~= "table" or #v == 0 then return nil, "key '" .. key .. "' is not a number or a list of numbers" end
  local out = {}
  for i, x in ipairs(v) do
    if type(x) ~= "number" then return nil, string.format("%s[%d] is not a number", key, i) end
    out[i] = x
  end
  return out
end

function M.layout(input)
  local L = {}
  for _, e in ipairs(input.experiments) do
    for _, o in ipairs(e.observables) do
      for i = 1, #o.measured do
        L[#L + 1] = {block = e.name, key = o.key, index = i, vector = o.vector, measured = o.measured[i], sigma = o.sigma[i],
                     label = o.vector and string.format("%s %s[%d]", e.name, o.key, i) or string.format("%s %s", e.name, o.key)}
      end
    end
  end
  return L
end

-- The measurement errors the entries share (the experiments' shared_error), in standardised
-- units: C_ij = rel_sd^2 y_i y_j for entries i, j of the same experiment's shared keys, y_i =
-- measured_i / sigma_i; 0 elsewhere. nil when no experiment has one (Sigma_meas = I).
function M.shared_covariance(input, L)
  local rel = {}
  for _, e in ipairs(input.experiments) do
    if e.shared_error then rel[e.name] = e.shared_error end
  end
  if next(rel) == nil then return nil end
  local m, C = #L, {}
  for i = 1, m do
    C[i] = {}
    local li = L[i]
    local si = rel[li.block]
    for j = 1, m do
      local lj = L[j]
      if si and lj.block == li.block and si.keys[li.key] and si.keys[lj.key] then
        C[i][j] = si.rel_sd ^ 2 * (li.measured / li.sigma) * (lj.measured / lj.sigma)
      else
        C[i][j] = 0
      end
    end
  end
  return C
end

-- Labels with the grid value of vector entries (from one set of results: the grids are fixed).
function M.label(L, results)
  for _, l in ipairs(L) do
    local axis = l.vector and M.AXES[l.key]
    local grid = axis and results[l.block] and M.extract(results[l.block], axis.key)
    if grid and grid[l.index] then
      l.label = string.format("%s %s %s=%g %s", l.block, l.key, axis.what, grid[l.index], axis.unit)
      l.axis = grid[l.index]
    end
  end
end

-- Simulated values, standardised (value / sigma), in layout order. Errors name the experiment and
-- key when a result lacks one or has a vector of another length than measured.
function M.simulated(L, results, where)
  local y, cache = {}, {}
  for i, l in ipairs(L) do
    local id = l.block .. "\0" .. l.key
    if not cache[id] then
      local r = results[l.block]
      if not r then error(string.format("discovery: %s: no result for experiment '%s'", where or "", l.block), 0) end
      local v, msg = M.extract(r, l.key)
      if not v then error(string.format("discovery: %s: experiment '%s': %s", where or "", l.block, msg), 0) end
      cache[id] = v
    end
    local v = cache[id]
    local n = 0
    for _, m in ipairs(L) do if m.block == l.block and m.key == l.key then n = n + 1 end end
    if #v ~= n then
      error(string.format("discovery: %s: experiment '%s' key '%s' has %d entries, the measurement %d", where or "", l.block, l.key, #v, n), 0)
    end
    y[i] = v[l.index] / l.sigma
  end
  return y
end

function M.measured(L)
  local y = {}
  for i, l in ipairs(L) do y[i] = l.measured / l.sigma end
  return y
end

-- Elementwise helpers on plain Lua vectors.
function M.mean(vectors)
  local m = {}
  for i = 1, #vectors[1] do
    local s = 0
    for _, v in ipairs(vectors) do s = s + v[i] end
    m[i] = s / #vectors
  end
  return m
end

function M.minus(a, b)
  local d = {}
  for i = 1, #a do d[i] = a[i] - b[i] end
  return d
end

function M.scale(a, s)
  local d = {}
  for i = 1, #a do d[i] = a[i] * s end
  return d
end

-- RMS of residuals standardised by the square root of the covariance's diagonal.
function M.rms_standardised(r, cov)
  local s = 0
  for i = 1, #r do s = s + r[i] ^ 2 / cov[i][i] end
  return math.sqrt(s / #r)
end

return M
