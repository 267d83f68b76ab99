-- The calibration report (docs/calibration.md): report.html (one page, opens offline: every
-- figure is a file beside it, no scripts, no network), calibration.json with every number, CSV
-- tables in data/, and the summary for result.json.
local util = require("lib.util")
local compare = require("lib.calibration.compare")
local data = require("lib.calibration.data")
local charts = require("lib.calibration.charts")
local page = require("lib.calibration.page")
local M = {}

local function copy(src, dst)
  local a = io.open(src, "rb")
  if not a then return nil end
  local data = a:read("a")
  a:close()
  return util.write_file(dst, data)
end

-- Writes everything; returns {html =, json =, csv = {...}, figures = {...}}.
function M.write(a)
  local o = a.outcome
  util.mkdir(util.out("data"))
  local files = {}
  files.json = paddy.write_json("calibration.json", data.document(o))
  files.csv = data.write_csvs(o)
  local ch, pics = {}, {}
  if a.pictures then
    ch = charts.draw(o)
    local function take(dir, list, into)
      pics[into] = {}
      for _, p in ipairs(list) do
        local dst = copy(dir .. "/" .. p[1], a.figures .. "/" .. into .. "_" .. p[1])
        if dst then pics[into][#pics[into] + 1] = {path = dst, caption = p[2]} end
      end
    end
    if o.reference then
      take(o.reference.verification.runs[1].dir, {{"side_view.png", "Final pile, side view (first verification seed)"},
                                                 {"slump_flow_top.png", "Top view with the fitted circle (slump-flow)"},
                                                 {"slump_history.png", "Slump against time"}}, "verification")
      if o.reference.rheometer then
        take(o.reference.rheometer.dir, {{"torque.png", "Vane torque against time"}, {"flow_curve.png", "Flow curve and Herschel–Bulkley fit"}}, "rheometer")
      end
    end
  end
  files.figures = ch
  local text = page.render(o, files, ch, pics)
  files.html = util.write_file(util.out("report.html"), text)  -- temporary + rename
  return files
end

-- The experiment's result.json entries.
function M.summary(o, files)
  local s = {measured = o.measured, tolerance = o.tolerance, time_step = o.time_step, simulations = #o.simulations, wall_time_s = o.wall_time_s,
             selected_factors = o.screening.selected, to_tolerance = compare.to_tolerance(o),
             report = files.html, calibration_json = files.json, csv = files.csv,
             runs_at_shorter_step = o.runs_at_shorter_step}
  if o.reference then
    local r = o.reference
    local params = {}
    for _, f in ipairs(o.input.factors) do params[f.parameter] = r.optimum.factors[f.symbol] or f.center end
    s.reference = {optimum = params, predicted = r.optimum.predicted, desirability = r.optimum.desirability,
                   verification = {mean = r.verification.mean, sd = r.verification.sd, errors = r.verification.errors,
                                   worst = r.verification.worst},
                   best_step = r.best_step.step, box = r.box,
                   rheometer = r.rheometer and {herschel_bulkley = r.rheometer.result.herschel_bulkley,
                                                comparison = r.rheometer.result.comparison} or nil}
  end
  if o.surrogate then
    local sg = o.surrogate
    local best = sg.confirmed or sg.best
    local params = {}
    for _, f in ipairs(o.input.factors) do params[f.parameter] = best and best.values[f.symbol] or f.center end
    s.surrogate = {success = sg.success, parameters = params, simulations = #sg.evaluations,
                   confirmed = sg.confirmed and {mean = sg.confirmed.mean, errors = sg.confirmed.errors, worst = sg.confirmed.worst} or nil}
  end
  return s
end

return M
