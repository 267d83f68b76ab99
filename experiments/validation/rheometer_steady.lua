-- Steady torques of the vane rheometer (experiments/rheometer.lua) against particle size and step
-- length: every (diameter, step length, seed) is one rheometer run with the default speed steps
-- (up, then down). Step length 0 is the steady criterion (each step runs until its torque is
-- steady, measure.steady_torque); a positive value runs every step that long (the criterion still
-- says whether it became steady). Documentation: docs/validation.md §7.
--
--   paddy run experiments/validation/rheometer_steady.lua --out results/validation/rheometer_steady \
--       [--set diameters=0.008,0.012 --set step_times=0,0.5,2 --set seeds=1,2 --set max_parallel=2]
--
-- The runs are jobs of a campaign (docs/campaign.md) in <out>/campaign; a rerun skips the finished
-- ones. Outputs in --out: rs_steps.csv (every speed step of every run), rs_runs.csv (per run:
-- spheres, simulated and wall time, steady steps, the Herschel–Bulkley fit, the start-up yield
-- stress), rs_summary.csv (per size, step length and up-sweep speed: torque mean and std over the
-- seeds, steady steps, the ratio to the steady criterion's torque of the same size),
-- rheometer_steady.json, rs_torques.png.
local util = require("lib.util")
local report = require("report")

local P = paddy.parameters{
  {name = "diameters", default = "0.008,0.012", unit = "m", description = "particle diameters (comma-separated)"},
  {name = "step_times", default = "0,0.5,2", unit = "s", description = "step lengths (comma-separated; 0 = until steady, the rheometer's default)"},
  {name = "seeds", default = "1,2", description = "fill seeds (comma-separated)"},
  {name = "max_parallel", default = 2, type = "integer", min = 1, max = 256, description = "rheometer runs at once"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each run"},
  {name = "rheometer_set", default = "", description = "extra rheometer.lua parameters for every run, 'name=value,...' (e.g. speeds_rpm=5;10;20)"},
  {name = "campaign_dir", default = "", description = "campaign directory (empty: <out>/campaign)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys (empty: hash of the paddy executable)"},
  {name = "pictures", default = true, description = "draw rs_torques.png with gnuplot"},
}

local diameters = report.numbers(P.diameters, "diameters") or error("diameters is empty", 0)
local step_times = report.numbers(P.step_times, "step_times") or error("step_times is empty", 0)
local seeds = report.seed_list(P.seeds)
for _, t in ipairs(step_times) do
  if t < 0 or t > 100 then error(string.format("step_times: %g s is outside the allowed range 0-100 s", t), 0) end
end
table.sort(diameters)
local extra = report.assignments(P.rheometer_set, "rheometer_set")
for _, name in ipairs({"particle_diameter", "step_time", "seed"}) do
  if extra[name] ~= nil then error("rheometer_set must not set " .. name .. " (use diameters, step_times, seeds)", 0) end
end
local script = report.script_dir() .. "/../rheometer.lua"
local c, campaign_dir = report.campaign(P, 1)
local jobs = {}
for _, d in ipairs(diameters) do
  for _, st in ipairs(step_times) do
    for _, s in ipairs(seeds) do
      local params = report.merge({particle_diameter = d, step_time = st, progress = false, pictures = false,
                                   snapshot_interval = 0}, extra)
      jobs[#jobs + 1] = {d = d, step_time = st, seed = s, key = c:submit{script = script, params = params, seed = s}}
    end
  end
end
io.stderr:write(string.format("rheometer_steady: %d sizes x %d step lengths x %d seeds = %d runs, campaign %s\n",
                              #diameters, #step_times, #seeds, #jobs, campaign_dir))
local results = c:run()

local function mode_name(st) return st == 0 and "until steady" or string.format("%g s", st) end
local step_rows, run_rows, runs = {}, {}, {}
-- torques[d][st][speed] = {up-sweep torques over the seeds}, steady counts alike
local torques, steady_n = {}, {}
for i, run in ipairs(results) do
  local j = jobs[i]
  local e = {d_mm = j.d * 1000, step_time_s = j.step_time, seed = j.seed, status = run.status, error = run.error}
  runs[#runs + 1] = e
  if run.status ~= "done" then
    io.stderr:write(string.format("rheometer_steady: d = %g mm, step %s, seed %d failed: %s\n", j.d * 1000,
                                  mode_name(j.step_time), j.seed, tostring(run.error)))
  else
    local r = run.result
    local hb, su = r.herschel_bulkley or {}, r.startup or {}
    local n_steady, n_steps = 0, 0
    local function add(sweep, s)
      n_steps = n_steps + 1
      if s.steady then n_steady = n_steady + 1 end
      step_rows[#step_rows + 1] = {e.d_mm, j.step_time, j.seed, sweep, s.speed_rpm, s.torque_Nm, report.cell(s.torque_se),
                                   s.steady and 1 or 0, s.angle_deg, s.duration_s, report.cell(s.trend_p), report.cell(s.drift),
                                   s.not_steady_because or ""}
    end
    for _, s in ipairs(r.steps or {}) do
      add("up", s)
      torques[j.d] = torques[j.d] or {}
      torques[j.d][j.step_time] = torques[j.d][j.step_time] or {}
      local list = torques[j.d][j.step_time]
      list[s.speed_rpm] = list[s.speed_rpm] or {}
      table.insert(list[s.speed_rpm], s.torque_Nm)
      steady_n[j.d] = steady_n[j.d] or {}
      steady_n[j.d][j.step_time] = steady_n[j.d][j.step_time] or {}
      local sn = steady_n[j.d][j.step_time]
      sn[s.speed_rpm] = (sn[s.speed_rpm] or 0) + (s.steady and 1 or 0)
    end
    for _, s in ipairs((r.down_sweep or {}).steps or {}) do add("down", s) end
    e.particles, e.simulated_time_s, e.wall_time_s = r.particles, r.simulated_time_s, r.wall_time_s
    e.steady_steps, e.steps = n_steady, n_steps
    e.tau0_Pa, e.K, e.n, e.r2 = hb.tau0, hb.K, hb.n, hb.r2
    e.startup_yield_stress_Pa, e.startup_peak_Nm, e.startup_peak_angle_deg = su.yield_stress_Pa, su.peak_torque_Nm, su.peak_angle_deg
    run_rows[#run_rows + 1] = {e.d_mm, j.step_time, j.seed, report.cell(e.particles), report.cell(e.simulated_time_s),
                               report.cell(e.wall_time_s), n_steady, n_steps, report.cell(e.tau0_Pa), report.cell(e.K),
                               report.cell(e.n), report.cell(e.r2), report.cell(e.startup_yield_stress_Pa)}
  end
end
util.write_csv("rs_steps.csv", {"d_mm", "step_time_s", "seed", "sweep", "speed_rpm", "torque_Nm", "torque_se_Nm", "steady",
                                "angle_deg", "duration_s", "trend_p", "drift", "not_steady_because"}, step_rows)
util.write_csv("rs_runs.csv", {"d_mm", "step_time_s", "seed", "particles", "simulated_time_s", "wall_time_s", "steady_steps",
                               "steps", "tau0_Pa", "K_Pa_sn", "n", "r2", "startup_yield_stress_Pa"}, run_rows)

-- Per size, step length and up-sweep speed: mean ± std over the seeds, and the ratio to the
-- steady criterion's mean torque at the same size and speed (when step length 0 was run).
local summary, sum_rows = {}, {}
local dat = {}
for _, d in ipairs(diameters) do
  for _, st in ipairs(step_times) do
    local list = (torques[d] or {})[st] or {}
    local speeds = {}
    for v in pairs(list) do speeds[#speeds + 1] = v end
    table.sort(speeds)
    local block = {}
    for _, v in ipairs(speeds) do
      local m, sd = report.mean_std(list[v])
      local ref = ((torques[d] or {})[0] or {})[v]
      local ratio = ref and st ~= 0 and m / (report.mean_std(ref)) or nil
      local row = {d_mm = d * 1000, step_time_s = st, speed_rpm = v, torque_mean_Nm = m, torque_std_Nm = sd, runs = #list[v],
                   steady = steady_n[d][st][v], ratio_to_steady_criterion = ratio}
      summary[#summary + 1] = row
      sum_rows[#sum_rows + 1] = {row.d_mm, st, v, m, report.cell(sd), row.runs, row.steady, report.cell(ratio)}
      block[#block + 1] = string.format("%g %.9g %.9g", v, m, sd or 0)
    end
    if #block > 0 then dat[#dat + 1] = {title = string.format("%g mm, %s", d * 1000, mode_name(st)), lines = block} end
  end
end
util.write_csv("rs_summary.csv", {"d_mm", "step_time_s", "speed_rpm", "torque_mean_Nm", "torque_std_Nm", "runs",
                                  "steady_runs", "ratio_to_steady_criterion"}, sum_rows)

local pictures = {}
if P.pictures and #dat > 0 then
  local blocks, plots = {}, {}
  for k, b in ipairs(dat) do
    blocks[#blocks + 1] = table.concat(b.lines, "\n")
    plots[#plots + 1] = string.format("%s index %d using 1:2:3 with yerrorlines lw 2 title %s",
                                      k == 1 and util.gnuplot_text(util.out("rs_torques.dat")) or "''", k - 1,
                                      util.gnuplot_text(b.title))
  end
  util.write_file(util.out("rs_torques.dat"), "# speed_rpm torque_mean_Nm torque_std_Nm, one block per size and step length\n"
                  .. table.concat(blocks, "\n\n\n") .. "\n")
  pictures.torques = util.gnuplot("rs_torques", "set logscale x\nset xlabel 'vane speed [rpm]'\n"
    .. "set ylabel 'torque, up-sweep, mean over the seeds [N m]'\nset key top left\nset grid\n"
    .. "plot " .. table.concat(plots, ", "))
end

local failed = 0
for _, e in ipairs(runs) do if e.status ~= "done" then failed = failed + 1 end end
report.write_json("rheometer_steady.json", {diameters_mm = (function() local t = {} for k, d in ipairs(diameters) do t[k] = d * 1000 end return t end)(),
                                            step_times_s = step_times, seeds = seeds, runs = runs, summary = summary,
                                            pictures = pictures, failed = failed})
paddy.result{runs = #runs, failed = failed, summary = summary}
if failed > 0 then error(string.format("rheometer_steady: %d of %d runs failed (see above)", failed, #runs), 0) end
