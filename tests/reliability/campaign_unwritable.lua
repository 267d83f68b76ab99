-- A campaign of four small jobs (write_outputs.lua) of which two write an output larger than the
-- `ulimit -f` that unwritable_output.sh sets: those must be reported failed with the message
-- naming the file and the cause, the others done, and every state file of the campaign must stay
-- parseable. Run again without the limit, the failed jobs run and complete.
local P = paddy.parameters{
  max_parallel = {default = 2, type = "integer", min = 1, max = 8, description = "jobs at once"},
}
local c = paddy.campaign{dir = paddy.out_dir .. "/campaign", executor = "local", max_parallel = P.max_parallel,
                         threads_per_job = 1, max_attempts = 1, progress = false}
local jobs = {
  {outputs = "json", big = 0, label = "small_json"},
  {outputs = "json", big = 1, label = "big_json"},
  {outputs = "snapshot", big = 1, label = "big_snapshot"},
  {outputs = "all", big = 0, label = "small_all"},
}
for _, j in ipairs(jobs) do c:submit{script = "write_outputs.lua", params = j, seed = 1} end
local out = {}
for i, r in ipairs(c:run()) do
  out[i] = {label = jobs[i].label, status = r.status, error = r.error, dir = r.dir}
  print(string.format("%s: %s%s", jobs[i].label, r.status, r.error and (": " .. r.error) or ""))
end
paddy.write_json("jobs.json", out)
paddy.result{jobs = out}
