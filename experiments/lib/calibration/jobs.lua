-- Simulations of a calibration as campaign jobs (docs/campaign.md): each point of a design is a
-- job keyed by its content (script, parameters, seed, code version), so an interrupted
-- calibration resumes without repeating finished runs. The runner keeps a log of every distinct
-- simulation in the order the calibration asked for it (that order defines "simulations used").
--
--   local jobs = require("lib.calibration.jobs")
--   local runner = jobs.new{campaign = c, script = "slump.lua", fixed = {...}, responses = {...},
--                           step_halvings = 1}
--   local rows = runner:run("screening", {{params = {...}, seed = 1, label = "run 1"}, ...})
--   -- rows[i] = {responses = {slump_mm = ...}, key =, dir =, index = <1-based in the log>, result =,
--   --            timestep_fraction =, step_halvings = <0 unless the run was unstable at the step>}
--
-- A run that stops because its step is too large for the velocities it reached (the engine's
-- overlap check: "... is too large for these velocities") is run again at half its
-- timestep_fraction, at most step_halvings times (default 0: a failure). The other runs keep
-- their step; the log and the row say which runs were halved, since the step moves a pile a little
-- (docs/physics.md, time-step convergence).
local M = {}
local Runner = {}
Runner.__index = Runner

function M.new(o)
  assert(o.campaign and o.script and o.responses, "jobs.new needs campaign, script and responses")
  local halvings = o.step_halvings or 0
  assert(math.type(halvings) == "integer" and halvings >= 0 and halvings <= 5, "jobs.new: step_halvings must be an integer in [0, 5]")
  return setmetatable({campaign = o.campaign, script = o.script, fixed = o.fixed or {}, responses = o.responses,
                       step_halvings = halvings, log = {}, by_key = {}}, Runner)
end

-- Runs the points (in parallel as the campaign allows) and returns one row per point, in order.
-- A point: {params = {name = value}, seed = n, label = "...", script = optional other script,
-- extra = {name = value} (parameters that are not factors: pictures, ...), standalone = true
-- (the runner's fixed parameters are not added: another experiment), responses = {...},
-- stage = "..." (logged under this stage instead of the batch's: runs of two stages in one batch)}.
local UNSTABLE = "is too large for these velocities"

function Runner:run(stage, points)
  local keys, submitted, halved = {}, {}, {}
  for i, p in ipairs(points) do
    local params = {}
    if not p.standalone then
      for k, v in pairs(self.fixed) do params[k] = v end
    end
    for k, v in pairs(p.extra or {}) do params[k] = v end
    for k, v in pairs(p.params) do params[k] = v end
    submitted[i], halved[i] = params, 0
    keys[i] = self.campaign:submit{script = p.script or self.script, params = params, seed = p.seed}
  end
  local entries = {}
  for _, e in ipairs(self.campaign:run(keys)) do entries[e.key] = e end
  -- Runs unstable at their step: again at half of it (a new job; the failed one stays on record).
  for _ = 1, self.step_halvings do
    local again = {}
    for i, p in ipairs(points) do
      local e = entries[keys[i]]
      local f = submitted[i].timestep_fraction
      if e and e.status ~= "done" and type(f) == "number" and tostring(e.error):find(UNSTABLE, 1, true) then
        local params = {}
        for k, v in pairs(submitted[i]) do params[k] = v end
        params.timestep_fraction = f / 2
        submitted[i], halved[i] = params, halved[i] + 1
        io.stderr:write(string.format("calibration: %s %s stopped, its step too large (%s); again at timestep_fraction = %.4g\n",
                                      stage, p.label or i, keys[i]:sub(1, 12), params.timestep_fraction))
        keys[i] = self.campaign:submit{script = p.script or self.script, params = params, seed = p.seed}
        again[#again + 1] = keys[i]
      end
    end
    if #again == 0 then break end
    for _, e in ipairs(self.campaign:run(again)) do entries[e.key] = e end
  end
  local rows, failures = {}, {}
  local batch_stage = stage
  for i, p in ipairs(points) do
    local stage = p.stage or batch_stage
    local e = entries[keys[i]]
    if not e or e.status ~= "done" then
      failures[#failures + 1] = string.format("  %s %s (job %s): %s", stage, p.label or i, keys[i]:sub(1, 12),
                                              e and tostring(e.error) or "not run")
    else
      local row = {key = keys[i], dir = e.dir, result = e.result, responses = {}, params = p.params, seed = p.seed,
                   label = p.label, stage = stage, timestep_fraction = submitted[i].timestep_fraction, step_halvings = halved[i]}
      for _, r in ipairs(p.responses or self.responses) do
        local v = e.result[r]
        if type(v) ~= "number" then
          failures[#failures + 1] = string.format("  %s %s: the result has no number '%s'", stage, p.label or i, r)
        end
        row.responses[r] = v
      end
      local logged = self.by_key[keys[i]]
      if not logged then
        logged = {index = #self.log + 1, stage = stage, label = p.label, key = keys[i], seed = p.seed, params = p.params,
                  responses = row.responses, wall_time_s = e.metadata and e.metadata.wall_time,
                  timestep_fraction = row.timestep_fraction, step_halvings = halved[i] > 0 and halved[i] or nil}
        self.log[#self.log + 1] = logged
        self.by_key[keys[i]] = logged
      end
      row.index = logged.index
      rows[i] = row
    end
  end
  if #failures > 0 then
    error(string.format("calibration: %d simulation(s) of the %s step failed after retries (see their job directories;"
                        .. " running the calibration again retries them and keeps the finished ones):\n%s",
                        #failures, stage, table.concat(failures, "\n")), 0)
  end
  return rows
end

-- Relative errors |y - measured| / measured per response and the worst of them.
function M.errors(values, measured)
  local e, worst = {}, 0
  for name, target in pairs(measured) do
    e[name] = math.abs(values[name] - target) / math.abs(target)
    worst = math.max(worst, e[name])
  end
  return e, worst
end

-- Mean and sample standard deviation of the rows' responses.
function M.mean_responses(rows, responses)
  local mean, sd = {}, {}
  for _, r in ipairs(responses) do
    local s, s2 = 0, 0
    for _, row in ipairs(rows) do s = s + row.responses[r] end
    mean[r] = s / #rows
    for _, row in ipairs(rows) do s2 = s2 + (row.responses[r] - mean[r]) ^ 2 end
    sd[r] = #rows > 1 and math.sqrt(s2 / (#rows - 1)) or 0
  end
  return mean, sd
end

return M
