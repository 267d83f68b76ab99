-- experiments.validation_vfs: a depth study's own static line (its vanes' starting σ_n, recorded as
-- they ran: yield_stress.lua "static") is vane_fill_stress.lua's line through the same fills run
-- again alone: per set the same pooled intercept and slope, to the JSON's 10 digits.
local P = paddy.parameters{
  {name = "study", default = "", description = "output directory of yield_stress.lua"},
  {name = "fills", default = "", description = "output directory of vane_fill_stress.lua on that study"},
}
local checks = require("checks")
local check, near = checks.check, checks.near
local study = paddy.read_json(P.study .. "/yield_stress_study.json")
local fills = paddy.read_json(P.fills .. "/vane_fill_stress.json")
check(#study.depth_series.sets == #fills.sets and #fills.sets > 0, "%d sets in the study, %d in the fills' reading",
      #study.depth_series.sets, #fills.sets)
for k, ds in ipairs(study.depth_series.sets) do
  local mine, theirs = ds.static and ds.static.pooled, fills.sets[k].pooled
  check(mine ~= nil and theirs ~= nil, "set %s: a static line missing", ds.set)
  near(mine.c, theirs.c, 1e-8, "static intercept of " .. ds.set .. ": study against the fills run again")
  near(mine.tan_phi, theirs.tan_phi, 1e-8, "static slope of " .. ds.set .. ": study against the fills run again")
end
paddy.result{ok = true}
