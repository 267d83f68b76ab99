-- The calibration's job runner (lib/calibration/jobs.lua) on a stand-in campaign whose runs are
-- unstable above a step: an unstable run is run again at half its step (as often as allowed), the
-- rows and the log say so, the stable runs keep their step, and any other failure still fails.
local jobs = require("lib.calibration.jobs")
local function check(cond, fmt, ...)
  if not cond then error(string.format(fmt, ...), 2) end
end

-- A campaign stand-in: a run with timestep_fraction above its point's `limit` stops with the
-- engine's overlap message; `broken` fails with another error.
local function fake()
  local c = {jobs = {}, submitted = 0}
  function c:submit(job)
    self.submitted = self.submitted + 1
    local key = string.format("%040d", self.submitted)
    self.jobs[key] = job
    return key
  end
  function c:run(keys)
    local out = {}
    for i, key in ipairs(keys) do
      local p = self.jobs[key].params
      if p.broken then
        out[i] = {key = key, status = "failed", error = "the mesh file is missing"}
      elseif p.timestep_fraction > p.limit then
        out[i] = {key = key, status = "failed",
                  error = "contact overlap reached 50 % ...: the time step 0.0001 s (0.16 x Rayleigh time) is too large for these velocities; reduce it"}
      else
        out[i] = {key = key, status = "done", dir = "d", result = {slump_mm = 100 + p.timestep_fraction}, metadata = {wall_time = 1}}
      end
    end
    return out
  end
  return c
end

local pts = {{params = {limit = 1}, seed = 1, label = "run 1"}, {params = {limit = 0.06}, seed = 2, label = "run 2"},
             {params = {limit = 0.03}, seed = 3, label = "run 3"}}
local r = jobs.new{campaign = fake(), script = "x.lua", fixed = {timestep_fraction = 0.1}, responses = {"slump_mm"}, step_halvings = 2}
local rows = r:run("screening", pts)
check(rows[1].step_halvings == 0 and rows[1].timestep_fraction == 0.1, "a stable run keeps its step")
check(rows[2].step_halvings == 1 and rows[2].timestep_fraction == 0.05 and rows[2].responses.slump_mm == 100.05, "one halving")
check(rows[3].step_halvings == 2 and rows[3].timestep_fraction == 0.025, "two halvings")
check(r.log[1].step_halvings == nil and r.log[2].step_halvings == 1 and r.log[3].timestep_fraction == 0.025, "the log says which runs were halved")

-- Without halvings (the default) or beyond them the unstable run fails the step, naming it.
local strict = jobs.new{campaign = fake(), script = "x.lua", fixed = {timestep_fraction = 0.1}, responses = {"slump_mm"}}
local ok, e = pcall(strict.run, strict, "screening", pts)
check(not ok and e:match("2 simulation%(s%) of the screening step failed") and e:match("screening run 2") and e:match("too large"),
      "unstable runs fail without halvings: %s", tostring(e))
local once = jobs.new{campaign = fake(), script = "x.lua", fixed = {timestep_fraction = 0.1}, responses = {"slump_mm"}, step_halvings = 1}
ok, e = pcall(once.run, once, "screening", pts)
check(not ok and e:match("1 simulation%(s%)") and e:match("screening run 3"), "one halving is not enough for run 3: %s", tostring(e))
-- Another failure is not retried at a shorter step.
local c = fake()
local other = jobs.new{campaign = c, script = "x.lua", fixed = {timestep_fraction = 0.1}, responses = {"slump_mm"}, step_halvings = 2}
ok, e = pcall(other.run, other, "screening", {{params = {limit = 1, broken = true}, seed = 1, label = "run 1"}})
check(not ok and e:match("the mesh file is missing") and c.submitted == 1, "other failures are not retried (%d submissions)", c.submitted)
check(not pcall(jobs.new, {campaign = c, script = "x", responses = {}, step_halvings = 1.5}), "step_halvings must be an integer")

paddy.result{ok = true}
