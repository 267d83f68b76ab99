-- Triggers: conditions a phase (lib/phase.lua) checks at each of its samples, to end the phase
-- or to act once (stop the cone). A trigger is a function(s, phase) returning a name (a string:
-- which condition fired, for result.json) or false; `s` is the simulation in a sim:run callback,
-- `phase` the running phase ({t0 = its start time}). Build them from the constructors below and
-- combine them with all / any.
--
--   local trigger = require("lib.trigger")
--   local at_rest = trigger.all{
--     trigger.elapsed(P.min_rest_time),                                -- since the phase started
--     trigger.any{trigger.at_rest(P.rest_speed),                      -- "kinetic_energy"
--                 trigger.steady(history, "top", P.rest_window, tol)},  -- "top_steady"
--   }
local util = require("lib.util")

local M = {}

-- Wraps a function(s, phase) -> boolean as a trigger that fires with `name`.
function M.named(name, test)
  return function(s, phase)
    if test(s, phase) then return name end
    return false
  end
end

-- At least `duration` seconds after `since` (a function returning an absolute time, or nil while
-- that time is not known yet; nil `since`: the start of the phase).
function M.elapsed(duration, since)
  return function(s, phase)
    local t0
    if since then t0 = since() else t0 = phase.t0 end
    if not t0 then return false end
    return s:time() - t0 >= duration and "elapsed"
  end
end

-- At rest: the particles' RMS speed sqrt(2 KE / M) (util.rms_speed) below `speed`. With `top`,
-- the RMS speed of the spheres wholly below z = top (fires as "fill_kinetic_energy").
function M.at_rest(speed, top)
  return M.named(top and "fill_kinetic_energy" or "kinetic_energy", function(s) return util.rms_speed(s, top) < speed end)
end

-- The last row of `sampler` has `name` below `limit` (a quantity the phase samples anyway).
function M.below(sampler, name, limit, label)
  return M.named(label or name, function() return sampler:last()[name] < limit end)
end

-- `name` in `sampler` steady over the last `window` seconds within `tolerance` (sampler.steady;
-- tolerance 0 never fires). Fires as "<name>_steady" unless `label` is given.
function M.steady(sampler, name, window, tolerance, label)
  return M.named(label or name .. "_steady", function() return sampler:steady(name, window, tolerance) end)
end

-- Fires each time value(s) enters a new multiple of `period` (e.g. each completed window of
-- rotation angle): on fixed grids of a quantity other than time.
function M.periodic(value, period)
  local seen = 0
  return function(s)
    local n = math.floor(value(s) / period)
    if n <= seen then return false end
    seen = n
    return "periodic"
  end
end

-- Fires when every trigger fires (checked in order, stopping at the first that does not), with
-- the name of the last one.
function M.all(triggers)
  return function(s, phase)
    local name = false
    for _, t in ipairs(triggers) do
      name = t(s, phase)
      if not name then return false end
    end
    return name
  end
end

-- Fires when one of the triggers fires (checked in order), with the name of the first that does.
function M.any(triggers)
  return function(s, phase)
    for _, t in ipairs(triggers) do
      local name = t(s, phase)
      if name then return name end
    end
    return false
  end
end

return M
