-- Checks experiments/examples/restitution_step.lua (experiments.restitution_step) on a small set:
--   * restitution_step.csv has one row per scheme x restitution x step, in that order, and its
--     relative error is measured / set - 1 of its own mean, which lies within its min and max;
--   * at 0.01 T_R both schemes give the set restitution within 1.5 % (e = 0.13);
--   * from 0.1 to 0.01 T_R each scheme's error shrinks, and at 0.1 T_R Euler's (first order) is
--     larger than Verlet's (docs/physics.md §3's table: -10 % against -2 %).
local util = require("lib.util")
local check = require("checks").check
local P = paddy.parameters{{name = "dir", default = "", description = "output directory of restitution_step.lua"}}

local rows = util.read_csv(P.dir .. "/restitution_step.csv")
local order = {{"velocity_verlet", 0.1}, {"velocity_verlet", 0.01}, {"euler", 0.1}, {"euler", 0.01}}
check(#rows == #order, "%d rows, expected %d", #rows, #order)
local err = {}
for k, want in ipairs(order) do
  local r = rows[k]
  check(r.scheme == want[1] and r.restitution == 0.13 and r.step_fraction == want[2], "row %d: %s %s %s", k,
        tostring(r.scheme), tostring(r.restitution), tostring(r.step_fraction))
  check(r.measured_min <= r.measured_mean and r.measured_mean <= r.measured_max, "row %d: mean outside its range", k)
  check(math.abs(r.relative_error - (r.measured_mean / r.restitution - 1)) < 1e-8, "row %d: relative error %g", k, r.relative_error)
  err[r.scheme .. "@" .. r.step_fraction] = r.relative_error
end
for _, s in ipairs({"velocity_verlet", "euler"}) do
  check(math.abs(err[s .. "@0.01"]) < 0.015, "%s at 0.01 T_R: %g", s, err[s .. "@0.01"])
  check(math.abs(err[s .. "@0.01"]) < math.abs(err[s .. "@0.1"]), "%s: error does not shrink with the step", s)
end
check(math.abs(err["euler@0.1"]) > math.abs(err["velocity_verlet@0.1"]) + 0.03,
      "at 0.1 T_R Euler %g, Verlet %g: the first-order scheme should be further off", err["euler@0.1"], err["velocity_verlet@0.1"])
paddy.result{ok = true}
