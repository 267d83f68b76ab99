-- A small two-stage campaign for campaign_kill.sh, shaped like a calibration: stage 1 runs four
-- jobs (campaign_job.lua), an analysis between the stages picks the stage-2 parameters from the
-- stage-1 results and saves them (stage1.json), stage 2 runs two more jobs, and a summary
-- (summary.json, result.json) closes it. Killed at any moment and started again with the same
-- output directory, it must end in the same result. Progress markers go to stdout unbuffered.
local P = paddy.parameters{
  steps = {default = 15000, type = "integer", min = 1, max = 1000000, description = "time steps of each job"},
  analysis_seconds = {default = 0.3, min = 0, max = 10, description = "CPU time of the analysis between the stages"},
}
io.stdout:setvbuf("no")
local function mark(text) io.stdout:write(text, "\n") end
local c = paddy.campaign{dir = paddy.out_dir .. "/campaign", executor = "local", max_parallel = 2, threads_per_job = 1,
                         max_attempts = 1, progress = false}
local function run(stage, frictions)
  local keys = {}
  for i, f in ipairs(frictions) do
    keys[i] = c:submit{script = "campaign_job.lua", params = {steps = P.steps, friction = f}, seed = 100 + i}
  end
  mark("stage " .. stage .. " submitted")
  local out = {}
  for i, r in ipairs(c:run(keys)) do
    if r.status ~= "done" then error("stage " .. stage .. " job " .. r.key .. " failed: " .. tostring(r.error)) end
    out[i] = {key = r.key, friction = frictions[i], hash = r.result.hash, height = r.result.height, n = r.result.n}
  end
  mark("stage " .. stage .. " done")
  return out
end

local first = run(1, {0.1, 0.3, 0.6, 1.0})
-- The analysis: deterministic work on the stage-1 results (a stand-in for the design fits).
mark("analysis")
local t0, acc = os.clock(), 0
while os.clock() - t0 < P.analysis_seconds do
  for k = 1, 10000 do acc = acc + math.sin(k) end
end
table.sort(first, function(a, b) return a.height < b.height end)
local next_f = {(first[1].friction + first[2].friction) / 2, (first[3].friction + first[4].friction) / 2}
paddy.write_json("stage1.json", {runs = first, next = next_f})
local second = run(2, next_f)
mark("summary")
local summary = {first = first, second = second}
paddy.write_json("summary.json", summary)
local hashes = {}
for _, r in ipairs(first) do hashes[#hashes + 1] = r.hash end
for _, r in ipairs(second) do hashes[#hashes + 1] = r.hash end
paddy.result{hashes = table.concat(hashes, ","), stage2_friction = next_f}
mark("end")
