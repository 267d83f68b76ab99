-- experiments.validation_ys: a study of seed 2 that pools a finished study of seed 1 (with_studies),
-- or a study without seeds of its own that reads the study of both again, must report what the
-- study of seeds 1 and 2 together reports, from the same runs: every number of its runs, depth
-- rows, summary and depth-series fits (per seed, pooled, at failure, static), to the 10 significant
-- digits the pooled study's JSON keeps; and it must say which study it pooled, with its seeds.
local P = paddy.parameters{
  {name = "both", default = "", description = "output directory of the study of both seeds"},
  {name = "pooled", default = "", description = "output directory of the study that pooled the other's seed"},
  {name = "first", default = "", description = "output directory of the study it pooled"},
  {name = "first_seeds", default = 1, type = "integer", description = "seeds of that study (1, or 1 and 2)"},
}
local checks = require("checks")
local check, near = checks.check, checks.near
local REL = 1e-8

local both = paddy.read_json(P.both .. "/yield_stress_study.json")
local pooled = paddy.read_json(P.pooled .. "/yield_stress_study.json")

-- Every leaf of a against the same leaf of b: numbers to REL, the rest equal; same keys both ways.
local compared = 0
local function same(a, b, where)
  check(type(a) == type(b), "%s: %s against %s", where, type(a), type(b))
  if type(a) == "number" then
    near(a, b, REL, where)
    compared = compared + 1
  elseif type(a) == "table" then
    for k, v in pairs(a) do same(v, b[k], where .. "." .. tostring(k)) end
    for k in pairs(b) do check(a[k] ~= nil, "%s.%s only in the study of both seeds", where, tostring(k)) end
  elseif type(a) == "string" then
    -- A fit's refusal quotes its numbers: compared to 8 digits as well.
    local function digits(t) return (t:gsub("%-?%d+%.%d+", function(x) return string.format("%.8g", tonumber(x)) end)) end
    check(digits(a) == digits(b), "%s: %s against %s", where, a, b)
  else
    check(a == b, "%s: %s against %s", where, tostring(a), tostring(b))
  end
end
for _, key in ipairs({"seeds", "runs", "summary", "depth_runs", "depth_series"}) do
  check(both[key] ~= nil, "%s missing in the study of both seeds", key)
  same(pooled[key], both[key], key)
end
check(#pooled.depth_runs == 4, "%d depth rows, expected 2 seeds x 2 levels", #pooled.depth_runs)
check(pooled.depth_series.sets[1].failure ~= nil, "no line at failure in the pooled study")
check(#pooled.pooled_studies == 1 and pooled.pooled_studies[1].study == P.first .. "/yield_stress_study.json",
      "pooled_studies does not name %s", P.first)
check(#pooled.pooled_studies[1].seeds == P.first_seeds, "pooled_studies' seeds: %d, expected %d", #pooled.pooled_studies[1].seeds, P.first_seeds)
for k, s in ipairs(pooled.pooled_studies[1].seeds) do check(s == k, "pooled_studies' seed %d is %s", k, tostring(s)) end
check(both.pooled_studies == nil, "a study that pooled nothing lists pooled studies")
check(compared > 100, "only %d numbers compared", compared)
paddy.result{ok = true, compared = compared}
