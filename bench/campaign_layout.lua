-- A batch of slump runs as one campaign with a given layout (jobs at once × threads per job):
-- the work of a calibration stage, for bench/campaign_layout.py, which times it. The runs are
-- the main job's experiment (experiments/slump.lua, its defaults) with pictures and snapshots off,
-- as the calibration runs them, seeds 1..jobs.
--   paddy run bench/campaign_layout.lua --out DIR --set jobs=4 --set max_parallel=2 --set threads_per_job=1
local P = paddy.parameters{
  {name = "jobs", default = 4, type = "integer", min = 1, max = 256, description = "slump runs in the batch (seeds 1..jobs)"},
  {name = "max_parallel", default = 2, type = "integer", min = 1, max = 256, description = "runs at once"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each run"},
  {name = "particle_diameter", default = 0.01, unit = "m", min = 0.004, max = 0.05, description = "sphere diameter of every run"},
}
local here = paddy.script:match("^(.*)/[^/]*$") or "."
local c = paddy.campaign{dir = paddy.out_dir .. "/campaign", max_parallel = P.max_parallel,
                         threads_per_job = P.threads_per_job, max_attempts = 1, progress = false}
for s = 1, P.jobs do
  c:submit{script = here .. "/../experiments/slump.lua", seed = s,
           params = {particle_diameter = P.particle_diameter, pictures = false, snapshot_interval = 0, progress = false}}
end
local failed = 0
for _, r in ipairs(c:run()) do if r.status ~= "done" then failed = failed + 1 end end
paddy.result{jobs = P.jobs, failed = failed}
if failed > 0 then error(string.format("campaign_layout: %d of %d runs failed", failed, P.jobs), 0) end
