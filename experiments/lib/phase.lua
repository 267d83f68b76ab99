-- Phase runner: one stage of an experiment (settle, lift, a speed step) as one sim:run. At each
-- callback (every `every` seconds and at the end, docs/scripting.md) it runs `before`, records
-- the samplers (lib/sampler.lua), checks the one-off events in order and then the stop trigger
-- (lib/trigger.lua).
--
--   local phase = require("lib.phase")
--   local settle = phase.run(sim, {
--     duration = P.settle_max_time, every = P.history_interval,   -- time limit and sampling interval
--     sample = tops,                                              -- a sampler or an array of them
--     stop = trigger.all{trigger.elapsed(P.min_rest_time), trigger.at_rest(P.rest_speed)},
--     snapshot_every = ..., progress = ...,                       -- passed on to sim:run
--   })
--   --> {t0 =, t1 =, duration =, stopped_by = name of the stop trigger or nil, steps =}
--
-- events = {{when = trigger, act = function(s, name) ... end}, ...}: each acts once, at the first
-- sample its trigger fires (e.g. stop the cone when it has cleared the pile); at a sample where an
-- event acted the stop trigger is not checked (the state it judges has just changed).
-- before = function(s) ... end: an action at every sample before the samplers (e.g. record the
-- loads on a wall). Without `every` the phase runs its duration with no callback.
local M = {}

local RUN_OPTIONS = {"snapshot_every", "progress", "record_loads_every", "record_loads"}

local function samplers_of(o)
  if o.sample == nil then return {} end
  if o.sample.record then return {o.sample} end
  return o.sample
end

function M.run(sim, o)
  if not (type(o.duration) == "number" and o.duration >= 0) then
    error("phase.run: duration must be a number of seconds >= 0", 2)
  end
  local phase = {t0 = sim:time()}
  local samplers = samplers_of(o)
  local events, acted = o.events or {}, {}
  local args = {duration = o.duration}
  for _, k in ipairs(RUN_OPTIONS) do args[k] = o[k] end
  if o.every then
    args.every = o.every
    args.callback = function(s)
      if o.before then o.before(s) end
      for _, smp in ipairs(samplers) do smp:record(s) end
      local any_acted = false
      for k, e in ipairs(events) do
        if not acted[k] then
          local name = e.when(s, phase)
          if name then
            acted[k] = true
            any_acted = true
            e.act(s, name)
          end
        end
      end
      if any_acted or not o.stop then return true end
      local name = o.stop(s, phase)
      if name then
        phase.stopped_by = name
        return false
      end
      return true
    end
  elseif o.stop or #samplers > 0 or #events > 0 or o.before then
    error("phase.run: sampling, events and stop triggers need `every`", 2)
  end
  phase.steps = sim:run(args)
  phase.t1 = sim:time()
  phase.duration = phase.t1 - phase.t0
  return phase
end

return M
