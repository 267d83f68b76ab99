-- Checks the outputs of a miniature calibration (calibration_e2e.sh): result.json and
-- calibration.json agree with each other and with the input, the optimum lies inside the
-- Box-Behnken box, the verification means are the means of its runs, every simulation is
-- counted once, and (optionally) a second result is identical to the first.
local P = paddy.parameters{
  {name = "dir", default = "", description = "output directory of the calibration"},
  {name = "same_as", default = "", description = "another calibration's result.json that must agree exactly"},
  {name = "same_reference_as", default = "", description = "a result.json whose reference procedure must agree exactly (e.g. local vs Slurm)"},
  {name = "strategy", default = "both", choices = {"reference", "surrogate", "both"}, description = "strategy that was run"},
}
local function check(cond, fmt, ...)
  if not cond then error("check failed: " .. string.format(fmt, ...), 2) end
end
local doc = paddy.read_json(P.dir .. "/result.json")
check(doc.status == "complete", "status %s", tostring(doc.status))
local r = doc.results
local cal = paddy.read_json(P.dir .. "/calibration.json")
check(cal.measured.slump_mm == 231 and cal.measured.slump_flow_mm == 480, "targets read from the input file")

-- Screening: 12 + 1 runs, the ANOVA has a curvature row and the 4 dummy columns as residual (df 4).
check(#cal.screening.runs == 13, "screening runs %d", #cal.screening.runs)
for _, resp in ipairs({"slump_mm", "slump_flow_mm"}) do
  local df = {}
  for _, a in ipairs(cal.screening.fit.responses[resp].anova) do df[a.source] = a.df end
  check(df.Curvature == 1 and df.Residual == 4 and df.Model == 7, "screening ANOVA of %s: df model/curv/res %s/%s/%s",
        resp, tostring(df.Model), tostring(df.Curvature), tostring(df.Residual))
end
check(#r.selected_factors == 3, "three factors selected, got %d", #r.selected_factors)

-- One time step for every simulation: the damping-aware step at the lowest restitution bound
-- (0.01 in the input: factor 0.8043416 of 0.2), the same in every job's result.json.
check(math.abs(cal.time_step.factor - 0.8043416) < 1e-6 and cal.time_step.lowest_restitution == 0.01,
      "time step factor %s at restitution %s", tostring(cal.time_step.factor), tostring(cal.time_step.lowest_restitution))
-- Every simulation is logged once, with a distinct key and its job's own wall time (the cost figures).
local keys = {}
for _, s in ipairs(cal.simulations) do
  local job = paddy.read_json(P.dir .. "/campaign/jobs/" .. s.key .. "/result.json")
  check(job.results.time_step_fraction == cal.time_step.fraction and job.results.time_step_damping_factor == 1,
        "simulation %d (%s): time step fraction %s, expected %s", s.index, s.stage, tostring(job.results.time_step_fraction),
        tostring(cal.time_step.fraction))
  check(not keys[s.key], "simulation %s logged twice", s.key)
  keys[s.key] = true
  local wall = job.metadata.wall_time
  check(type(s.wall_time_s) == "number" and s.wall_time_s > 0 and s.wall_time_s == wall,
        "simulation %d (%s): wall time %s, its job's %s", s.index, s.stage, tostring(s.wall_time_s), tostring(wall))
end
check(r.simulations == #cal.simulations, "simulation count %d vs %d", r.simulations, #cal.simulations)

if P.strategy ~= "surrogate" then
  local ref = cal.reference
  -- The optimum lies in the Box-Behnken box, and the box is centred on the best steepest-ascent step.
  for sym, v in pairs(ref.optimum.factors) do
    local b = ref.box[sym]
    check(v >= b[1] - 1e-12 and v <= b[2] + 1e-12, "optimum %s = %g outside [%g, %g]", sym, v, b[1], b[2])
  end
  local best = ref.steepest_ascent[ref.best_step + 1]
  for _, s in ipairs(ref.steepest_ascent) do
    check(s.worst >= best.worst, "best step %d is not the smallest error (step %d smaller)", ref.best_step, s.step)
  end
  -- 12 edges + 3 centre points, one replicate each in this input.
  check(#ref.box_behnken == 15, "Box-Behnken runs %d", #ref.box_behnken)
  -- Verification mean = mean of its runs; errors = |mean - measured| / measured.
  for _, resp in ipairs({"slump_mm", "slump_flow_mm"}) do
    local s = 0
    for _, v in ipairs(ref.verification.runs) do s = s + v.responses[resp] end
    local mean = s / #ref.verification.runs
    check(math.abs(mean - ref.verification.mean[resp]) < 1e-9, "verification mean of %s", resp)
    check(math.abs(ref.verification.errors[resp] - math.abs(mean - cal.measured[resp]) / cal.measured[resp]) < 1e-12,
          "verification error of %s", resp)
  end
  check(#ref.verification.runs == 2, "verification seeds %d", #ref.verification.runs)
  -- The rheometer ran at the optimum and was compared with the measured torque file.
  check(ref.rheometer and ref.rheometer.comparison and ref.rheometer.comparison.mean_relative_error,
        "rheometer comparison with the measured torque curve")
  -- The rheometer ran in the verification's batch, first (its run logged just before the
  -- verification runs), and is logged under its own stage.
  local rh = cal.simulations[ref.rheometer.index]
  check(rh and rh.stage == "rheometer", "the rheometer's run is logged under stage '%s'", rh and tostring(rh.stage) or "?")
  for k, v in ipairs(ref.verification.runs) do
    check(v.index == ref.rheometer.index + k, "verification run %d logged as simulation %s, expected %d (right after the rheometer)",
          k, tostring(v.index), ref.rheometer.index + k)
    check(cal.simulations[v.index].stage == "verification", "simulation %d logged under stage '%s'", v.index,
          tostring(cal.simulations[v.index].stage))
  end
  check(r.reference.optimum.mud_mud_friction ~= nil, "result lists every calibrated parameter")
end
if P.strategy ~= "reference" then
  local s = cal.surrogate
  local searched = 0
  for _, ev in ipairs(s.evaluations) do
    if ev.kind ~= "confirm" then searched = searched + 1 end
  end
  check(searched <= s.budget, "surrogate searched with %d simulations, budget %d", searched, s.budget)
  check(#s.evaluations >= 4, "surrogate ran its initial points")
  for _, ev in ipairs(s.evaluations) do
    for _, f in ipairs(s.factors) do
      local v = ev.values[f.name]
      check(v >= f.low - 1e-12 and v <= f.high + 1e-12, "surrogate point %d: %s = %g outside its search box", ev.n, f.name, v)
    end
  end
end

local function same(a, b, path)
    check(type(a) == type(b), "%s: %s vs %s", path, type(a), type(b))
    if type(a) == "table" then
      for k, v in pairs(a) do same(v, b[k], path .. "." .. k) end
      for k in pairs(b) do check(a[k] ~= nil, "%s.%s missing", path, k) end
    elseif path ~= ".wall_time_s" and not path:match("report$") and not path:match("json$") and not path:match("csv%.%d+$") then
      check(a == b, "%s: %s vs %s", path, tostring(a), tostring(b))
    end
end
if P.same_as ~= "" then same(r, paddy.read_json(P.same_as).results, "") end
if P.same_reference_as ~= "" then
  same(r.reference, paddy.read_json(P.same_reference_as).results.reference, ".reference")
end
paddy.result{ok = true}
