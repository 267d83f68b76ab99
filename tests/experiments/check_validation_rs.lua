-- Checks the rheometer steady-torque study (experiments.validation_rs: 1 size x 2 step lengths x
-- 2 seeds of tiny runs) against its own per-step table: every summary row's mean and std are those
-- of the up-sweep torques of rs_steps.csv at its size, step length and speed; its steady count is
-- the number of those steps marked steady; its ratio is its mean over the mean of the steady
-- criterion (step length 0) at the same size and speed. A fixed step lasts its step length (to a
-- sampling interval); a step the criterion calls steady has turned at least min_step_angle; both
-- runs have a down sweep.
local util = require("lib.util")
local P = paddy.parameters{
  {name = "dir", default = "", description = "output directory of rheometer_steady.lua"},
  {name = "min_step_angle", default = 60, description = "the runs' min_step_angle [deg]"},
  {name = "sample_interval", default = 0.005, description = "the runs' torque sampling interval [s]"},
}
local check = require("checks").check
local r = paddy.read_json(P.dir .. "/result.json").results
check(r.failed == 0, "%d runs failed", r.failed)
local steps = util.read_csv(P.dir .. "/rs_steps.csv")
local up, steady, down = {}, {}, 0
for _, s in ipairs(steps) do
  local key = string.format("%g/%g/%g", s.d_mm, s.step_time_s, s.speed_rpm)
  if s.sweep == "up" then
    up[key] = up[key] or {}
    table.insert(up[key], s.torque_Nm)
    steady[key] = (steady[key] or 0) + s.steady
  else
    check(s.sweep == "down", "sweep '%s'", tostring(s.sweep))
    down = down + 1
  end
  if s.step_time_s > 0 then
    check(math.abs(s.duration_s - s.step_time_s) <= P.sample_interval + 1e-9,
          "a fixed step of %g s lasted %g s", s.step_time_s, s.duration_s)
  elseif s.steady == 1 then
    check(s.angle_deg >= P.min_step_angle - 1e-6, "a step called steady turned %g deg < %g", s.angle_deg, P.min_step_angle)
  end
end
check(down > 0, "no down-sweep steps")
local rows = 0
for _, row in ipairs(r.summary) do
  rows = rows + 1
  local key = string.format("%g/%g/%g", row.d_mm, row.step_time_s, row.speed_rpm)
  local list = up[key]
  check(list and #list == 2, "%s: %s up-sweep torques in rs_steps.csv, expected 2 seeds", key, list and #list or 0)
  local m = (list[1] + list[2]) / 2
  local sd = math.abs(list[1] - list[2]) / math.sqrt(2)
  check(math.abs(row.torque_mean_Nm - m) <= 1e-7 * math.abs(m), "%s: mean %.9g, recomputed %.9g", key, row.torque_mean_Nm, m)
  check(math.abs(row.torque_std_Nm - sd) <= 1e-7 * math.max(sd, 1e-9), "%s: std %.9g, recomputed %.9g", key, row.torque_std_Nm, sd)
  check(row.steady == steady[key], "%s: %s steady, rs_steps.csv says %s", key, row.steady, steady[key])
  if row.step_time_s > 0 then
    local ref = up[string.format("%g/0/%g", row.d_mm, row.speed_rpm)]
    local ratio = m / ((ref[1] + ref[2]) / 2)
    check(math.abs(row.ratio_to_steady_criterion - ratio) <= 1e-7 * ratio, "%s: ratio %.9g, recomputed %.9g", key,
          row.ratio_to_steady_criterion, ratio)
  else
    check(row.ratio_to_steady_criterion == nil, "%s: the criterion's own row has a ratio", key)
  end
end
check(rows == 4, "%d summary rows, expected 2 step lengths x 2 speeds", rows)
paddy.result{ok = true}
