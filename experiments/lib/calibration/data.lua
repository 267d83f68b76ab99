-- The calibration's numbers for other tools: calibration.json (everything) and CSV tables in
-- data/ (every simulation, each design with its results, the ANOVA tables).
local util = require("lib.util")
local compare = require("lib.calibration.compare")
local M = {}

local function strip(rows)
  local out = {}
  for i, r in ipairs(rows) do
    out[i] = {label = r.label, seed = r.seed, key = r.key, index = r.index, params = r.params, responses = r.responses}
  end
  return out
end

function M.document(o)
  local doc = {measured = o.measured, tolerance = o.tolerance, time_step = o.time_step, input = o.input.path, responses = o.responses,
               wall_time_s = o.wall_time_s, simulations = o.simulations, to_tolerance = compare.to_tolerance(o),
               screening = {design = o.screening.design, runs = strip(o.screening.runs), fit = o.screening.fit,
                            ranking = o.screening.ranking, selected = o.screening.selected}}
  if o.reference then
    local r = o.reference
    local bb = {}
    for i, run in ipairs(r.runs) do
      bb[i] = {run = run.run.run, type = run.run.type, coded = run.run.coded, real = run.run.real, mean = run.mean, sd = run.sd,
               errors = run.errors, replicates = strip(run.rows)}
    end
    doc.reference = {steepest_ascent = r.steepest_ascent, best_step = r.best_step.step, box = r.box, box_behnken = bb,
                     fit = r.fit, goals = r.goals, solutions = r.optimization.solutions, optimum = r.optimum,
                     verification = {runs = strip(r.verification.runs), mean = r.verification.mean, sd = r.verification.sd,
                                     errors = r.verification.errors, worst = r.verification.worst},
                     rheometer = r.rheometer and {steps = r.rheometer.result.steps, herschel_bulkley = r.rheometer.result.herschel_bulkley,
                                                  comparison = r.rheometer.result.comparison, index = r.rheometer.index} or nil}
  end
  if o.surrogate then
    local s = o.surrogate
    doc.surrogate = {factors = s.factors, evaluations = s.evaluations, confirmed = s.confirmed, success = s.success,
                     budget = s.budget, rounds = s.rounds}
  end
  return doc
end

function M.write_csvs(o)
  local files = {}
  local function csv(name, cols, rows)
    files[#files + 1] = util.write_csv("data/" .. name, cols, rows)
  end
  local input, resp = o.input, o.responses
  -- Every simulation.
  local names = {}
  for _, f in ipairs(input.factors) do names[#names + 1] = f.parameter end
  local cols = {"index", "stage", "label", "seed", "key"}
  for _, n in ipairs(names) do cols[#cols + 1] = n end
  for _, r in ipairs(resp) do cols[#cols + 1] = r end
  cols[#cols + 1] = "wall_time_s"
  local rows = {}
  for _, s in ipairs(o.simulations) do
    local row = {s.index, s.stage, s.label or "", s.seed, s.key}
    for _, n in ipairs(names) do row[#row + 1] = s.params[n] or "" end
    for _, r in ipairs(resp) do row[#row + 1] = s.responses[r] or "" end
    row[#row + 1] = s.wall_time_s or ""
    rows[#rows + 1] = row
  end
  csv("simulations.csv", cols, rows)
  -- Screening design with results.
  local syms = {}
  for _, f in ipairs(input.factors) do syms[#syms + 1] = f.symbol end
  cols = {"run", "type"}
  for _, s in ipairs(syms) do cols[#cols + 1] = s end
  for k = 1, input.screening.dummy_columns do cols[#cols + 1] = "D" .. k .. "_coded" end
  for _, r in ipairs(resp) do cols[#cols + 1] = r end
  rows = {}
  for i, run in ipairs(o.screening.design.runs) do
    local row = {run.run, run.type}
    for _, s in ipairs(syms) do row[#row + 1] = run.real[s] end
    for k = 1, input.screening.dummy_columns do row[#row + 1] = run.coded["D" .. k] end
    for _, r in ipairs(resp) do row[#row + 1] = o.screening.runs[i].responses[r] end
    rows[#rows + 1] = row
  end
  csv("screening.csv", cols, rows)
  local function anova_csv(name, fit)
    local rws = {}
    for _, r in ipairs(resp) do
      for _, e in ipairs(fit.responses[r].anova) do
        rws[#rws + 1] = {r, e.source, e.ss or "", e.df or "", e.ms or "", e.F or "", e.p or ""}
      end
    end
    csv(name, {"response", "source", "sum_of_squares", "df", "mean_square", "F", "p"}, rws)
  end
  anova_csv("screening_anova.csv", o.screening.fit)
  if o.reference then
    local r = o.reference
    cols = {"step"}
    for _, s in ipairs(o.screening.selected) do cols[#cols + 1] = s end
    for _, x in ipairs(resp) do cols[#cols + 1] = x; cols[#cols + 1] = x .. "_rel_error_percent" end
    rows = {}
    for _, s in ipairs(r.steepest_ascent) do
      local row = {s.step}
      for _, sym in ipairs(o.screening.selected) do row[#row + 1] = s.values[sym] end
      for _, x in ipairs(resp) do row[#row + 1] = s.responses[x]; row[#row + 1] = 100 * s.errors[x] end
      rows[#rows + 1] = row
    end
    csv("steepest_ascent.csv", cols, rows)
    cols = {"run", "type"}
    for _, s in ipairs(o.screening.selected) do cols[#cols + 1] = s end
    for _, x in ipairs(resp) do cols[#cols + 1] = x; cols[#cols + 1] = x .. "_sd" end
    cols[#cols + 1] = "replicates"
    rows = {}
    for _, run in ipairs(r.runs) do
      local row = {run.run.run, run.run.type}
      for _, sym in ipairs(o.screening.selected) do row[#row + 1] = run.run.real[sym] end
      for _, x in ipairs(resp) do row[#row + 1] = run.mean[x]; row[#row + 1] = run.sd[x] end
      row[#row + 1] = #run.rows
      rows[#rows + 1] = row
    end
    csv("box_behnken.csv", cols, rows)
    anova_csv("box_behnken_anova.csv", r.fit)
    cols = {"seed"}
    for _, x in ipairs(resp) do cols[#cols + 1] = x end
    rows = {}
    for _, v in ipairs(r.verification.runs) do
      local row = {v.seed}
      for _, x in ipairs(resp) do row[#row + 1] = v.responses[x] end
      rows[#rows + 1] = row
    end
    csv("verification.csv", cols, rows)
  end
  if o.surrogate then
    cols = {"n", "kind", "seed"}
    for _, f in ipairs(o.surrogate.factors) do cols[#cols + 1] = f.name end
    for _, x in ipairs(resp) do cols[#cols + 1] = x; cols[#cols + 1] = x .. "_rel_error_percent" end
    rows = {}
    for _, ev in ipairs(o.surrogate.evaluations) do
      local row = {ev.n, ev.kind, ev.seed}
      for _, f in ipairs(o.surrogate.factors) do row[#row + 1] = ev.values[f.name] end
      for _, x in ipairs(resp) do row[#row + 1] = ev.responses[x]; row[#row + 1] = 100 * ev.errors[x] end
      rows[#rows + 1] = row
    end
    csv("surrogate.csv", cols, rows)
  end
  return files
end

return M
