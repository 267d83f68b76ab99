-- Samplers: record named quantities of a running simulation, one row per call, for result.json,
-- data files and stop criteria (lib/trigger.lua). A phase (lib/phase.lua) records its samplers at
-- every callback of sim:run, i.e. at the fixed interval `every` of that phase.
--
--   local sampler = require("lib.sampler")
--   local history = sampler.new{
--     {"t", function(s) return s:time() - t_lift end},          -- the time column is called t
--     {"slump_mm", function(s) return measure_slump().slump * 1000 end},
--   }
--   history:record(sim)                       --> the new row {t =, slump_mm =}
--   history.rows                              --> every row, in order (result.json: history = history.rows)
--   history:at("slump_mm", {0.5, 1})          --> linear interpolation on a fixed time grid
--   history:steady("slump_mm", 0.5, 1)        --> whether the last 0.5 s varied by at most 1 mm
--   history:write("slump_history.dat", "t_s slump_mm", {"t", "slump_mm"}) --> columns for a chart
local util = require("lib.util")

local M = {}
local Sampler = {}
Sampler.__index = Sampler

-- quantities: array of {name, function(s) -> value}; a value may be nil (the row has no entry).
function M.new(quantities)
  if type(quantities) ~= "table" or #quantities == 0 then
    error("sampler.new: give an array of {name, function(s) ... end}", 2)
  end
  for k, q in ipairs(quantities) do
    if type(q[1]) ~= "string" or type(q[2]) ~= "function" then
      error(string.format("sampler.new: quantity %d is not {name, function(s) ... end}", k), 2)
    end
  end
  return setmetatable({quantities = quantities, rows = {}}, Sampler)
end

-- Evaluates every quantity on `s` (the simulation, or the `s` of a sim:run callback) in the order
-- given, appends the row and returns it.
function Sampler:record(s)
  local row = {}
  for _, q in ipairs(self.quantities) do row[q[1]] = q[2](s) end
  self.rows[#self.rows + 1] = row
  return row
end

function Sampler:last()
  return self.rows[#self.rows]
end

function Sampler:column(name)
  local out = {}
  for k, row in ipairs(self.rows) do out[k] = row[name] end
  return out
end

-- Linear interpolation of rows[k][name] (rows[k].t ascending) at each of `times`; before the
-- first row the first value, after the last row the last (a run that stopped early holds its
-- last value).
function M.interpolate(rows, name, times)
  if #rows == 0 then error("sampler.interpolate: no samples of " .. name, 2) end
  local out, k = {}, 1
  for i, t in ipairs(times) do
    while k < #rows and rows[k + 1].t <= t do k = k + 1 end
    local a, b = rows[k], rows[k + 1]
    if t <= rows[1].t then
      out[i] = rows[1][name]
    elseif not b then
      out[i] = a[name]
    else
      local w = (t - a.t) / (b.t - a.t)
      out[i] = a[name] + w * (b[name] - a[name])
    end
  end
  return out
end

function Sampler:at(name, times)
  return M.interpolate(self.rows, name, times)
end

-- Steady window: true when tolerance > 0, the rows of the last `window` seconds (t >= t_last −
-- window) span at least `window`, and their values of `name` vary by no more than `tolerance`
-- (max − min, in the quantity's unit). A 1e-9 s allowance absorbs the rounding of sampled times.
function M.steady(rows, name, window, tolerance)
  if not (tolerance > 0) or #rows == 0 then return false end
  local t = rows[#rows].t
  local lo, hi, span = math.huge, -math.huge, 0
  for k = #rows, 1, -1 do
    local row = rows[k]
    if row.t < t - window - 1e-9 then break end
    lo, hi, span = math.min(lo, row[name]), math.max(hi, row[name]), t - row.t
  end
  return span >= window - 1e-9 and hi - lo <= tolerance
end

function Sampler:steady(name, window, tolerance)
  return M.steady(self.rows, name, window, tolerance)
end

-- Writes the columns `names` of every row into the output directory (util.write_columns) with a
-- header comment; a missing value is written as `missing` (error if that is nil too). Returns the path.
function Sampler:write(file, header, names, missing)
  local rows = {}
  for k, row in ipairs(self.rows) do
    local r = {}
    for j, name in ipairs(names) do
      local v = row[name]
      if v == nil then v = missing end
      if v == nil then error(string.format("sampler:write %s: row %d has no %s", file, k, name), 2) end
      r[j] = v
    end
    rows[k] = r
  end
  return util.write_columns(file, header, rows)
end

return M
