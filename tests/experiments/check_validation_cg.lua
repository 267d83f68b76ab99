-- Checks the coarse-graining campaign's statistics against their closed forms (experiments.
-- validation_cg: 2 sizes x 2 seeds). For each response, the one-way ANOVA over the sizes is
-- recomputed from the per-size values in result.json:
--   F = [sum_g n_g (m_g - m)^2 / (G - 1)] / [sum_g sum_i (y_gi - m_g)^2 / (N - G)],
-- with G = 2 sizes and N = 4 runs, so df = (1, 2), and for F(1, 2) = t_2^2 the p-value has the
-- closed form p = P(F_{1,2} > F) = 1 - sqrt(F / (F + 2)). Every run's slump lies between 0 and the
-- released column's height (300 mm, less a particle diameter of rattle: >= -40 mm).
local P = paddy.parameters{
  {name = "dir", default = "", description = "output directory of coarse_graining.lua"},
}
local check = require("checks").check
local r = paddy.read_json(P.dir .. "/result.json").results
check(#r.summary == 2, "%d sizes in the summary, expected 2", #r.summary)
for _, y in ipairs({"slump_mm", "slump_flow_mm"}) do
  local groups, n, total = {}, 0, 0
  for g, s in ipairs(r.summary) do
    groups[g] = s[y].values
    check(#groups[g] == 2, "%s: %d values at %g mm, expected 2 seeds", y, #groups[g], s.d_mm)
    for _, v in ipairs(groups[g]) do n, total = n + 1, total + v end
  end
  local grand = total / n
  local ssb, ssw = 0, 0
  for _, g in ipairs(groups) do
    local m = (g[1] + g[2]) / 2
    ssb = ssb + 2 * (m - grand) ^ 2
    ssw = ssw + (g[1] - m) ^ 2 + (g[2] - m) ^ 2
  end
  check(ssw > 0, "%s: the two seeds of each size give identical values (seeds ignored?)", y)
  local F = (ssb / 1) / (ssw / 2)
  local a = r.tests[y].anova
  check(a.df_between == 1 and a.df_within == 2, "%s: ANOVA df (%s, %s), expected (1, 2)", y, a.df_between, a.df_within)
  check(math.abs(a.F - F) <= 1e-9 * math.max(1, F), "%s: ANOVA F = %.12g, recomputed %.12g", y, a.F, F)
  local p = 1 - math.sqrt(F / (F + 2))
  check(math.abs(a.p - p) <= 1e-9, "%s: ANOVA p = %.12g, closed form for F(1,2) %.12g", y, a.p, p)
end
for _, s in ipairs(r.summary) do
  for _, v in ipairs(s.slump_mm.values) do
    check(v >= -40 and v <= 300, "slump %g mm at %g mm spheres outside [-40, 300] mm", v, s.d_mm)
  end
end
paddy.result{ok = true}
