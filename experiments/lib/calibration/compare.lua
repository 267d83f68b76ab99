-- How the two strategies compare: simulations used until each reached its result, and the best
-- worst-response error so far against the simulations used (screening counted for both).
local jobs = require("lib.calibration.jobs")
local M = {}

function M.convergence(o)
  -- Best single-run worst error against the number of simulations each strategy has used.
  local series = {}
  local pb = #o.screening.runs
  local function add(name, list)
    local best, pts = math.huge, {}
    for i, w in ipairs(list) do
      best = math.min(best, w)
      pts[#pts + 1] = {i, 100 * best}
    end
    series[#series + 1] = {name = name, points = pts}
  end
  local scr = {}
  for i, row in ipairs(o.screening.runs) do
    local _, w = jobs.errors(row.responses, o.measured)
    scr[i] = w
  end
  if o.reference then
    local list = {table.unpack(scr)}
    for _, s in ipairs(o.reference.steepest_ascent) do list[#list + 1] = s.worst end
    for _, r in ipairs(o.reference.runs) do
      for _, row in ipairs(r.rows) do
        local _, w = jobs.errors(row.responses, o.measured)
        list[#list + 1] = w
      end
    end
    for _, row in ipairs(o.reference.verification.runs) do
      local _, w = jobs.errors(row.responses, o.measured)
      list[#list + 1] = w
    end
    add("reference (PB, steepest ascent, Box-Behnken, verification)", list)
  end
  if o.surrogate then
    local list = {table.unpack(scr)}
    for _, ev in ipairs(o.surrogate.evaluations) do list[#list + 1] = ev.worst end
    add("surrogate (PB screening, then Gaussian process + EI)", list)
  end
  return series, pb
end

-- Simulations each strategy needed to reach the tolerance with a seed-averaged point.
function M.to_tolerance(o)
  local pb = #o.screening.runs
  local t = {}
  if o.reference then
    local r = o.reference
    local n = pb + #r.steepest_ascent
    for _, run in ipairs(r.runs) do n = n + #run.rows end
    n = n + #r.verification.runs
    t.reference = {simulations = n, reached = r.verification.worst <= o.tolerance, error = r.verification.worst,
                   seeds = #r.verification.runs}
  end
  if o.surrogate then
    local s = o.surrogate
    t.surrogate = {simulations = pb + (s.confirmed and s.confirmed.simulations or #s.evaluations), reached = s.success,
                   error = s.confirmed and s.confirmed.worst or s.best and s.best.worst, seeds = s.confirmed and s.confirmed.seeds or 1}
  end
  return t
end

return M
