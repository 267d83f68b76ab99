-- bench/compare_seed_runs.lua -- two sets of slump runs side by side, to show whether a change
-- moved the results beyond the seeds' scatter: the cg_runs.csv of two studies of
-- experiments/validation/coarse_graining.lua at one size (e.g. with and without a slump_set). Per
-- response: mean ± sample sd over the seeds of each set, the difference of the means with Welch's t
-- test (experiments/validation/report.lua), and the differences paired by seed (mean ± sd; the
-- pairs are independent draws when the change alters the runs' trajectories, so their sd should be
-- about √2 times a set's sd).
-- Run from the repository root:
--   paddy run bench/compare_seed_runs.lua --set a=DIR_A/cg_runs.csv --set b=DIR_B/cg_runs.csv --out DIR
-- Writes result.json (the table) and prints it.
package.path = "experiments/?.lua;experiments/validation/?.lua;" .. package.path
local util = require("lib.util")
local report = require("report")

local P = paddy.parameters{
  {name = "a", default = "", description = "first set: a cg_runs.csv (coarse_graining.lua)"},
  {name = "b", default = "", description = "second set: a cg_runs.csv"},
  {name = "responses", default = "slump_mm,slump_flow_mm,slump_flow_ruler_mm,fill_solid_fraction,simulated_time_s",
   description = "columns compared (comma-separated)"},
}
if P.a == "" or P.b == "" then error("compare_seed_runs: give both sets, --set a=FILE --set b=FILE (cg_runs.csv)") end

local function by_seed(path)
  local rows, seeds = {}, {}
  local size
  for _, r in ipairs(util.read_csv(path)) do
    if size and r.d_mm ~= size then
      error(string.format("compare_seed_runs: %s line %d: runs of %s and %s mm; compare one size", path, r._line, size, r.d_mm))
    end
    size = r.d_mm
    if rows[r.seed] then error(string.format("compare_seed_runs: %s line %d: seed %s twice", path, r._line, r.seed)) end
    rows[r.seed] = r
    seeds[#seeds + 1] = r.seed
  end
  table.sort(seeds)
  return rows, seeds, size
end
local ra, seeds_a, size_a = by_seed(P.a)
local rb, seeds_b, size_b = by_seed(P.b)
if size_a ~= size_b then error(string.format("compare_seed_runs: %s mm against %s mm", size_a, size_b)) end

local out = {a = P.a, b = P.b, d_mm = size_a, seeds_a = seeds_a, seeds_b = seeds_b, responses = {}}
print(string.format("%-22s %-20s %-20s %-24s %s", "response", "a: mean ± sd (n)", "b: mean ± sd (n)", "b − a (Welch p)", "paired b − a"))
-- One set's values of column `name`, in seed order.
local function column(rows, seeds, path, name)
  local out = {}
  for _, s in ipairs(seeds) do
    local x = rows[s][name]
    if type(x) ~= "number" then error(string.format("compare_seed_runs: %s: no number in column %s (seed %s)", path, name, s)) end
    out[#out + 1] = x
  end
  return out
end
for name in P.responses:gmatch("[^,%s]+") do
  local va, vb, diff = column(ra, seeds_a, P.a, name), column(rb, seeds_b, P.b, name), {}
  for k, s in ipairs(seeds_b) do
    if ra[s] then diff[#diff + 1] = vb[k] - ra[s][name] end
  end
  local ma, sa, na = report.mean_std(va)
  local mb, sb, nb = report.mean_std(vb)
  local md, sd = report.mean_std(diff)
  local w = report.welch(vb, va)
  out.responses[name] = {a_mean = ma, a_sd = sa, a_n = na, b_mean = mb, b_sd = sb, b_n = nb, difference = w.difference,
                         welch_t = w.t, welch_df = w.df, welch_p = w.p, paired_n = #diff, paired_mean = md, paired_sd = sd}
  print(string.format("%-22s %9.4g ± %-7.3g (%d) %9.4g ± %-7.3g (%d) %+9.3g (p %.2g)%6s %+.3g ± %.3g (%d)", name, ma, sa, na,
                      mb, sb, nb, w.difference, w.p or 0 / 0, "", md, sd, #diff))
end
paddy.result(out)
