-- experiments.surrogate_trials: phase=data writes a stand-in simulations.csv of a known linear
-- slump test (16 points of H7 × H5, each run three times with deviations −d_n, 0, +d_n, so the
-- seeds' pooled scatter is known; labels with commas in quotes, as the calibration writes them; a
-- screening run, a rheometer run and a run with a non-selected factor off its centre, which the
-- emulator must leave out). phase=check reads what surrogate_trials.lua made of it.
local util = require("lib.util")
local P = paddy.parameters{
  {name = "phase", default = "check", choices = {"data", "check"}, description = "write the data, or check the outputs"},
  {name = "dir", default = "", description = "phase=check: output directory of surrogate_trials.lua"},
  {name = "trials", default = 3, description = "trials per emulator and strategy the run made"},
}
local check = require("checks").check
local D_SLUMP, D_FLOW = 1.5, 2.5
local params = {"mud_mud_restitution", "mud_mud_friction", "mud_mud_rolling_friction", "mud_steel_restitution",
                "mud_steel_friction", "mud_steel_rolling_friction", "jkr_surface_energy"}
-- The known slump test: both targets (231, 480 mm) met at H7 = 0.085 J/m², H5 = 0.5.
local function slump(h7, h5) return 231 + 100 * (h5 - 0.5) + 200 * (h7 - 0.085) end
local function flow(h7, h5) return 480 + 400 * (h7 - 0.085) - 300 * (h5 - 0.5) end
-- Point n's deviations are ±d·scale(n): groups of unequal scatter, whose pooled variance is
-- d² · mean(scale²) and whose sum depends on its order in the last bits (the run must fix it).
local function scale(n) return 0.5 + n / 7 end
local function pooled(d)
  local s = 0
  for n = 1, 16 do s = s + scale(n) ^ 2 end
  return d * math.sqrt(s / 16)
end

if P.phase == "data" then
  local cols = {"index", "stage", "label", "seed", "key"}
  for _, p in ipairs(params) do cols[#cols + 1] = p end
  for _, c in ipairs({"slump_flow_mm", "slump_mm", "wall_time_s"}) do cols[#cols + 1] = c end
  local rows = {}
  local function add(stage, label, values, s, f)
    local row = {#rows + 1, stage, label, #rows + 1, string.format("k%d", #rows + 1)}
    for _, p in ipairs(params) do row[#row + 1] = values[p] or "" end
    row[#row + 1], row[#row + 2], row[#row + 3] = f, s, 1
    rows[#rows + 1] = row
  end
  add("screening", "run 1", {jkr_surface_energy = 0.1, mud_steel_friction = 0.2, mud_mud_restitution = 0.1}, 999, 999)
  local n = 0
  for a = 0, 3 do
    for b = 0, 3 do
      n = n + 1
      local h7, h5 = 0.01 + 0.05 * a, 0.2 + 0.2 * b
      for r, dev in ipairs({-1, 0, 1}) do
        add("box-behnken", string.format("run %d, replicate %d", n, r), {jkr_surface_energy = h7, mud_steel_friction = h5},
            slump(h7, h5) + dev * D_SLUMP * scale(n), flow(h7, h5) - dev * D_FLOW * scale(n))
      end
    end
  end
  add("rheometer", "vane", {jkr_surface_energy = 0.05, mud_steel_friction = 0.3}, "", "")
  add("steepest ascent", "step 1, H1 off centre", {jkr_surface_energy = 0.05, mud_steel_friction = 0.3, mud_mud_restitution = 0.2}, 1, 1)
  util.write_csv("simulations.csv", cols, rows)
  return
end

local r = paddy.read_json(P.dir .. "/result.json").results
check(r.simulations == 48, "the emulator used %s simulations, expected the 48 of the designs (screening, rheometer and an off-centre run left out)",
      tostring(r.simulations))
check(math.abs(r.noise_sd.slump_mm - pooled(D_SLUMP)) < 1e-6, "seeds' scatter of the slump %.12g, expected %.12g (pooled over the replicates)",
      r.noise_sd.slump_mm, pooled(D_SLUMP))
check(math.abs(r.noise_sd.slump_flow_mm - pooled(D_FLOW)) < 1e-6, "seeds' scatter of the slump-flow %.12g, expected %.12g", r.noise_sd.slump_flow_mm,
      pooled(D_FLOW))
local doc = paddy.read_json(P.dir .. "/surrogate_trials.json")
check(#doc.summary == 4, "%d summary rows, expected 2 emulators x 2 strategies", #doc.summary)
for _, kind in ipairs({"plain", "warped"}) do
  local e = doc.emulators[kind]
  check(e and e.within_fraction > 0, "emulator %s: no part of the box within the tolerance on a function that meets both targets", kind)
  check(e.best_sampled_error < 0.01, "emulator %s: best sampled point %.3f off a function that meets both targets", kind, e.best_sampled_error)
end
local runs = util.read_csv(P.dir .. "/surrogate_trials_runs.csv")
check(#runs == 4 * P.trials, "%d trial rows, expected %d", #runs, 4 * P.trials)
local seen = {}
for _, t in ipairs(runs) do
  -- mini_mud.json: 4 initial points, budget 8, 1 confirming seed
  check(t.simulations >= 4 and t.simulations <= 9, "trial %s/%s %d: %d simulations outside 4..9", t.emulator, t.strategy, t.trial, t.simulations)
  if t.success == 1 then
    check(type(t.true_error_at_confirmed) == "number", "a success without the true error at its point")
    check(t.best_run_error <= 0.02, "a success whose best run is %.4f off", t.best_run_error)
  end
  seen[t.emulator .. "/" .. t.strategy] = (seen[t.emulator .. "/" .. t.strategy] or 0) + t.success
end
for _, s in ipairs(doc.summary) do
  check(s.successes == seen[s.emulator .. "/" .. s.strategy], "summary %s/%s: %d successes, the runs say %d", s.emulator, s.strategy,
        s.successes, seen[s.emulator .. "/" .. s.strategy])
  -- A linear response with a wide region within 2 %: both strategies reach it.
  check(s.successes >= 1, "%s strategy on the %s emulator never reached a linear function's targets", s.strategy, s.emulator)
  check(s.success_low <= s.successes / s.trials and s.success_high >= s.successes / s.trials, "interval does not hold the rate")
end
-- Held-out check: 12 of the 48 runs of a linear function predict the other 36 to about the
-- seeds' scatter (a Gaussian process that interpolated wrongly would be off by tens of mm).
check(#doc.holdout == 2, "%d held-out rows, expected 1 size x 2 kinds", #doc.holdout)
for _, h in ipairs(doc.holdout) do
  check(h.size == 12 and h.repeats == 3, "held-out row of size %s, %s repeats", tostring(h.size), tostring(h.repeats))
  check(h.rms.slump_mm < 3 * pooled(D_SLUMP) and h.rms.slump_flow_mm < 3 * pooled(D_FLOW), "%s: held-out RMS errors %.2f / %.2f mm on a linear function",
        h.kind, h.rms.slump_mm, h.rms.slump_flow_mm)
end
check(#doc.paired == 2, "%d paired comparisons, expected one per emulator", #doc.paired)
for _, pr in ipairs(doc.paired) do
  check(pr.p_success > 0 and pr.p_success <= 1 and pr.p_fewer > 0 and pr.p_fewer <= 1, "paired p-values outside (0, 1]")
end
print("surrogate_trials: checked")
