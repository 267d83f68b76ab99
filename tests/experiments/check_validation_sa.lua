-- Checks the steepest-ascent validation (experiments.validation_sa) against its inputs and the
-- closed forms of its statistics:
--   * sa_runs.csv has the 4 steps of Table 6 in order, its EDEM columns equal the table's values
--     (read from the reference's CSV here), A/B/C equal the job's factor columns and the other four
--     factors sit at the midpoint of Table 3's low and high;
--   * Paddy's relative errors are 100 |Y - Y_measured| / Y_measured with the measurement in the JSON;
--   * the agreement per response (sa_validation.json) is mean(d), sqrt(mean(d^2)), Pearson's r and
--     the means over the runs, d = Paddy - EDEM, recomputed from the CSV;
--   * the best step (EDEM and Paddy) has the smallest relative error among the steps;
--   * every slump lies within the released column (>= -40 mm, <= 300 mm), every slump-flow > 0.
local util = require("lib.util")
local P = paddy.parameters{
  {name = "dir", default = "", description = "output directory of steepest_ascent.lua"},
  {name = "reference_dir", default = "", description = "shared/reference directory"},
}
local check = require("checks").check
-- a == b up to the CSV's 9 significant digits (util.write_csv: %.9g) of numbers of magnitude scale.
local function close(a, b, what, scale)
  if not (type(a) == "number" and type(b) == "number" and math.abs(a - b) <= 1e-7 * math.max(1, math.abs(b), scale or 0)) then
    error(string.format("%s: %s, expected %s", what, tostring(a), tostring(b)), 2)
  end
end

local table6 = util.read_csv(P.reference_dir .. "/table6_steepest_ascent.csv")
local levels = {}
for _, row in ipairs((util.read_csv(P.reference_dir .. "/table3_pb_levels.csv"))) do levels[row.symbol] = row end
local rows = util.read_csv(P.dir .. "/sa_runs.csv")
local doc = paddy.read_json(P.dir .. "/sa_validation.json")
check(#rows == 4 and #table6 == 4, "%d rows in sa_runs.csv, %d in Table 6, expected 4", #rows, #table6)

local EDEM = {edem_slump_mm = "slump_mm", edem_slump_flow_mm = "slump_flow_mm",
              edem_slump_rel_error_percent = "slump_rel_error_percent",
              edem_slump_flow_rel_error_percent = "slump_flow_rel_error_percent",
              A = "A_mud_mud_restitution", B = "B_mud_steel_static_friction", C = "C_jkr_surface_energy_J_m2"}
local CENTRE = {H2 = "mud_mud_friction", H3 = "mud_mud_rolling_friction", H4 = "mud_steel_restitution",
                H6 = "mud_steel_rolling_friction"}
local measured = doc.measured
for i, r in ipairs(rows) do
  local t = table6[i]
  check(r.step == i and t.run == i, "row %d: step %s, Table 6 run %s", i, tostring(r.step), tostring(t.run))
  check(r.status == "done", "step %d: status %s", i, tostring(r.status))
  for col, ref in pairs(EDEM) do close(r[col], t[ref], string.format("step %d %s", i, col)) end
  close(r.mud_mud_restitution, r.A, "step " .. i .. " mud_mud_restitution")
  close(r.mud_steel_friction, r.B, "step " .. i .. " mud_steel_friction")
  close(r.jkr_surface_energy, r.C, "step " .. i .. " jkr_surface_energy")
  for h, col in pairs(CENTRE) do
    close(r[col], (levels[h].low + levels[h].high) / 2, string.format("step %d %s", i, col))
  end
  check(r.paddy_slump_mm >= -40 and r.paddy_slump_mm <= 300, "step %d: slump %g mm outside [-40, 300] mm", i,
        r.paddy_slump_mm)
  check(r.paddy_slump_flow_mm > 0, "step %d: slump-flow %g mm", i, r.paddy_slump_flow_mm)
  close(r.diff_slump_mm, r.paddy_slump_mm - r.edem_slump_mm, "step " .. i .. " diff_slump_mm", 1000)
  close(r.diff_slump_flow_mm, r.paddy_slump_flow_mm - r.edem_slump_flow_mm, "step " .. i .. " diff_slump_flow_mm", 1000)
  close(r.paddy_slump_rel_error_percent, 100 * math.abs(r.paddy_slump_mm - measured.slump_mm) / measured.slump_mm,
        "step " .. i .. " paddy_slump_rel_error_percent", 1000)
  close(r.paddy_slump_flow_rel_error_percent,
        100 * math.abs(r.paddy_slump_flow_mm - measured.slump_flow_mm) / measured.slump_flow_mm,
        "step " .. i .. " paddy_slump_flow_rel_error_percent", 1000)
  check(type(r.key) == "string" and #r.key == 64, "step %d: key '%s'", i, tostring(r.key))
end

-- Agreement from the CSV.
for _, y in ipairs({"slump_mm", "slump_flow_mm"}) do
  local n, sd, sq, sx, sy = 0, 0, 0, 0, 0
  for _, r in ipairs(rows) do
    local a, b = r["edem_" .. y], r["paddy_" .. y]
    n, sd, sq, sx, sy = n + 1, sd + (b - a), sq + (b - a) ^ 2, sx + a, sy + b
  end
  local mx, my = sx / n, sy / n
  local cxy, cxx, cyy = 0, 0, 0
  for _, r in ipairs(rows) do
    local a, b = r["edem_" .. y] - mx, r["paddy_" .. y] - my
    cxy, cxx, cyy = cxy + a * b, cxx + a * a, cyy + b * b
  end
  local a = doc.agreement[y]
  check(a.runs == 4, "%s: agreement over %s runs", y, tostring(a.runs))
  close(a.mean_difference, sd / n, y .. " mean_difference", 1000)
  close(a.rms_difference, math.sqrt(sq / n), y .. " rms_difference", 1000)
  close(a.edem_mean, mx, y .. " edem_mean", 1000)
  close(a.paddy_mean, my, y .. " paddy_mean", 1000)
  if cxx > 0 and cyy > 0 then
    check(math.abs(a.correlation - cxy / math.sqrt(cxx * cyy)) <= 1e-5, "%s correlation %s, expected %.12g", y,
          tostring(a.correlation), cxy / math.sqrt(cxx * cyy))
  else
    check(a.correlation == nil, "%s: correlation of a constant column", y)
  end
end

-- Best steps: the smallest relative error (per response and of the mean of the two).
for _, side in ipairs({"edem", "paddy"}) do
  local best = doc.best_step[side]
  for _, crit in ipairs({"slump", "slump_flow", "mean"}) do
    local function value(r)
      if crit == "mean" then
        return (r[side .. "_slump_rel_error_percent"] + r[side .. "_slump_flow_rel_error_percent"]) / 2
      end
      return r[side .. "_" .. crit .. "_rel_error_percent"]
    end
    local b = best[crit]
    check(b and rows[b.step], "%s best step by %s missing", side, crit)
    close(b.rel_error_percent, value(rows[b.step]), side .. " best " .. crit, 1000)
    for _, r in ipairs(rows) do
      check(value(r) >= b.rel_error_percent - 1e-4, "%s best %s: step %d (%g %%) beats step %d (%g %%)", side, crit, r.step,
            value(r), b.step, b.rel_error_percent)
    end
  end
end
-- Table 6 itself: step 4 is best in both responses (the reference's choice).
check(doc.best_step.edem.mean.step == 4 and doc.best_step.edem.slump.step == 4 and doc.best_step.edem.slump_flow.step == 4,
      "EDEM best step %s, the reference chose 4", tostring(doc.best_step.edem.mean.step))
paddy.result{ok = true, paddy_best_step = doc.best_step.paddy.mean.step}
