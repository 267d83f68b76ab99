-- Checks the Plackett-Burman validation's Paddy fit against the closed form of the design
-- (experiments.validation_pb). The 12 factorial runs have orthogonal +-1 columns and the centre
-- point is absorbed by the curvature term, so the least-squares main effect of H_j is
--   b_j = (1/12) sum over the factorial runs of x_ij y_i
-- for each response. Every Paddy run's slump lies between 0 and the released column's height
-- (300 mm, less a particle diameter of rattle: >= -40 mm) and its slump-flow is positive.
local P = paddy.parameters{
  {name = "dir", default = "", description = "output directory of plackett_burman.lua"},
}
local check = require("checks").check
local doc = paddy.read_json(P.dir .. "/pb_validation.json")
local factorial = {}
for _, run in ipairs(doc.runs) do
  check(run.paddy, "run %s has no Paddy result", tostring(run.run))
  check(run.paddy.slump_mm >= -40 and run.paddy.slump_mm <= 300, "run %d: slump %g mm outside [-40, 300] mm",
        run.run, run.paddy.slump_mm)
  check(run.paddy.slump_flow_mm > 0, "run %d: slump-flow %g mm", run.run, run.paddy.slump_flow_mm)
  if run.coded.H1 ~= 0 then factorial[#factorial + 1] = run end
end
check(#factorial == 12, "%d factorial runs, expected 12", #factorial)
for _, y in ipairs({"slump_mm", "slump_flow_mm"}) do
  for j = 1, 7 do
    local h = "H" .. j
    local sum, scale = 0, 0
    for _, run in ipairs(factorial) do
      sum = sum + run.coded[h] * run.paddy[y]
      scale = math.max(scale, math.abs(run.paddy[y]))
    end
    local b = doc.effects[y][h].paddy.coefficient
    check(b and math.abs(b - sum / 12) <= 1e-9 * scale, "%s %s: Paddy coefficient %s, closed form %.12g", y, h,
          tostring(b), sum / 12)
  end
end
paddy.result{ok = true}
