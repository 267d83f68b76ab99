-- The calibration report: report.html (one page, opens offline: every figure is a file beside
-- it, no scripts, no network), calibration.json with every number, and CSV tables in data/.
-- The HTML is well-formed XHTML (polyglot HTML5), so any XML parser can check it.
local util = require("lib.util")
local M = {}

---------------------------------------------------------------------------- small helpers
local function esc(s)
  return (tostring(s):gsub("&", "&amp;"):gsub("<", "&lt;"):gsub(">", "&gt;"):gsub('"', "&quot;"))
end

local function num(v, digits)
  if v == nil then return "–" end
  if type(v) ~= "number" then return esc(v) end
  if v ~= v then return "–" end
  if v == math.floor(v) and math.abs(v) < 1e6 then return string.format("%d", v) end
  return string.format("%." .. (digits or 4) .. "g", v)
end

local function pval(p)
  if p == nil then return "–" end
  if p < 0.0001 then return "&lt; 0.0001" end
  return string.format("%.4f", p)
end

local function pct(v) return v and string.format("%.2f %%", 100 * v) or "–" end

local function rel(path)
  local prefix = paddy.out_dir .. "/"
  if path and path:sub(1, #prefix) == prefix then return path:sub(#prefix + 1) end
  return path
end

local function table_html(header, rows, caption)
  local h = {"<table>"}
  if caption then h[#h + 1] = "<caption>" .. caption .. "</caption>" end
  h[#h + 1] = "<thead><tr>"
  for _, c in ipairs(header) do h[#h + 1] = "<th>" .. c .. "</th>" end
  h[#h + 1] = "</tr></thead><tbody>"
  for _, row in ipairs(rows) do
    h[#h + 1] = "<tr>"
    for _, c in ipairs(row) do h[#h + 1] = "<td>" .. c .. "</td>" end
    h[#h + 1] = "</tr>"
  end
  h[#h + 1] = "</tbody></table>"
  return table.concat(h)
end

local function figure(path, caption)
  if not path then return "" end
  return string.format('<figure><img src="%s" alt="%s"/><figcaption>%s</figcaption></figure>', esc(rel(path)), esc(caption), esc(caption))
end

local function figures_of(list, pattern)
  local out = {}
  for _, p in ipairs(list or {}) do
    if p:match("%.png$") and (not pattern or p:match(pattern)) then out[#out + 1] = p end
  end
  table.sort(out)
  return out
end

local function copy(src, dst)
  local a = io.open(src, "rb")
  if not a then return nil end
  local data = a:read("a")
  a:close()
  local b = assert(io.open(dst, "wb"))
  b:write(data)
  b:close()
  return dst
end

local function factor_label(input, sym)
  local f = input.by_symbol[sym]
  return f and string.format("%s %s%s", sym, f.parameter, f.unit ~= "" and " [" .. f.unit .. "]" or "") or sym
end

---------------------------------------------------------------------------- sections
local function anova_section(input, fit, responses, what)
  local h = {}
  for _, r in ipairs(responses) do
    local a = fit.responses[r]
    local rows = {}
    for _, e in ipairs(a.anova) do
      rows[#rows + 1] = {esc(e.source), num(e.ss, 6), num(e.df), num(e.ms, 6), num(e.F, 4), pval(e.p)}
    end
    h[#h + 1] = table_html({"Source", "Sum of squares", "df", "Mean square", "F", "p"}, rows,
                           string.format("ANOVA of %s (%s)", esc(r), what))
    h[#h + 1] = table_html({"R²", "adjusted R²", "predicted R²", "C.V. %", "Adequate precision", "std. dev.", "mean"},
                           {{num(a.r2), num(a.adj_r2), num(a.pred_r2), num(a.cv_percent, 3), num(a.adeq_precision), num(a.std_dev), num(a.mean)}})
  end
  return table.concat(h, "\n")
end

local function equation(coefficients, terms, response)
  local parts = {}
  for _, t in ipairs(terms) do
    local c = coefficients[t]
    if c then
      if t == "Intercept" then parts[#parts + 1] = string.format("%.6g", c)
      else parts[#parts + 1] = string.format("%s %.6g·%s", c < 0 and "−" or "+", math.abs(c), t:gsub(":", "·")) end
    end
  end
  return esc(response) .. " = " .. table.concat(parts, " ")
end

local function convergence_series(o)
  -- Best single-run worst error against the number of simulations each strategy has used.
  local series = {}
  local pb = #o.screening.runs
  local function add(name, list)
    local best, pts = math.huge, {}
    for i, w in ipairs(list) do
      best = math.min(best, w)
      pts[#pts + 1] = {i, 100 * best}
    end
    series[#series + 1] = {name = name, points = pts}
  end
  local scr = {}
  for i, row in ipairs(o.screening.runs) do
    local _, w = require("lib.calibration.jobs").errors(row.responses, o.measured)
    scr[i] = w
  end
  if o.reference then
    local list = {table.unpack(scr)}
    for _, s in ipairs(o.reference.steepest_ascent) do list[#list + 1] = s.worst end
    for _, r in ipairs(o.reference.runs) do
      for _, row in ipairs(r.rows) do
        local _, w = require("lib.calibration.jobs").errors(row.responses, o.measured)
        list[#list + 1] = w
      end
    end
    for _, row in ipairs(o.reference.verification.runs) do
      local _, w = require("lib.calibration.jobs").errors(row.responses, o.measured)
      list[#list + 1] = w
    end
    add("reference (PB, steepest ascent, Box-Behnken, verification)", list)
  end
  if o.surrogate then
    local list = {table.unpack(scr)}
    for _, ev in ipairs(o.surrogate.evaluations) do list[#list + 1] = ev.worst end
    add("surrogate (PB screening, then Gaussian process + EI)", list)
  end
  return series, pb
end

-- Simulations each strategy needed to reach the tolerance with a seed-averaged point.
function M.to_tolerance(o)
  local pb = #o.screening.runs
  local t = {}
  if o.reference then
    local r = o.reference
    local n = pb + #r.steepest_ascent
    for _, run in ipairs(r.runs) do n = n + #run.rows end
    n = n + #r.verification.runs
    t.reference = {simulations = n, reached = r.verification.worst <= o.tolerance, error = r.verification.worst,
                   seeds = #r.verification.runs}
  end
  if o.surrogate then
    local s = o.surrogate
    t.surrogate = {simulations = pb + (s.confirmed and s.confirmed.simulations or #s.evaluations), reached = s.success,
                   error = s.confirmed and s.confirmed.worst or s.best and s.best.worst, seeds = s.confirmed and s.confirmed.seeds or 1}
  end
  return t
end

---------------------------------------------------------------------------- writers
local function strip(rows, responses)
  local out = {}
  for i, r in ipairs(rows) do
    out[i] = {label = r.label, seed = r.seed, key = r.key, index = r.index, params = r.params, responses = r.responses}
  end
  return out
end

local function json_document(o)
  local doc = {measured = o.measured, tolerance = o.tolerance, input = o.input.path, responses = o.responses,
               wall_time_s = o.wall_time_s, simulations = o.simulations, to_tolerance = M.to_tolerance(o),
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
                                                  comparison = r.rheometer.result.comparison} or nil}
  end
  if o.surrogate then
    local s = o.surrogate
    doc.surrogate = {factors = s.factors, evaluations = s.evaluations, confirmed = s.confirmed, success = s.success,
                     budget = s.budget, rounds = s.rounds}
  end
  return doc
end

local function write_csvs(o, data)
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

local function charts(o, figures)
  local c = {}
  -- Convergence of both strategies.
  local series = convergence_series(o)
  local plot = {}
  for k, s in ipairs(series) do
    local name = "figures/convergence_" .. k .. ".dat"
    local rows = {}
    for i, p in ipairs(s.points) do rows[i] = p end
    util.write_columns(name, "simulations best_worst_error_percent", rows)
    plot[#plot + 1] = string.format("'%s' using 1:2 with steps lw 2 title '%s'", util.out(name), s.name)
  end
  plot[#plot + 1] = string.format("%g with lines dt 2 lc rgb 'black' title 'tolerance %g %%'", 100 * o.tolerance, 100 * o.tolerance)
  c.convergence = util.gnuplot("figures/convergence", string.format([[
set title 'Best worst-response error so far against simulations used'
set xlabel 'simulations'; set ylabel 'worst relative error [%%]'; set logscale y; set grid; set key top right
plot %s]], table.concat(plot, ", \\\n     ")))
  if o.reference then
    -- Simulated (verification mean ± sd) against measured.
    local rows = {}
    for i, r in ipairs(o.responses) do
      rows[i] = {i, o.measured[r], o.reference.verification.mean[r], o.reference.verification.sd[r]}
    end
    util.write_columns("figures/verification.dat", "index measured simulated_mean simulated_sd", rows)
    local tics = {}
    for i, r in ipairs(o.responses) do tics[i] = string.format("'%s' %d", r, i) end
    c.verification = util.gnuplot("figures/verification", string.format([[
set title 'Verification at the optimum: simulated (mean ± sd over seeds) and measured'
set style data histograms; set style histogram errorbars gap 2 lw 1; set style fill solid 0.6 border -1
set boxwidth 0.9; set ylabel '[mm]'; set grid ytics; set yrange [0:*]; set xtics (%s)
set xrange [0.3:%g]
plot '%s' using ($1-0.2):2:(0.35) with boxes lc rgb '#4477aa' title 'measured', \
     '' using ($1+0.2):3:(0.35) with boxes lc rgb '#8b5a2b' title 'simulated', \
     '' using ($1+0.2):3:4 with yerrorbars lc rgb 'black' pt 0 notitle]],
      table.concat(tics, ", "), #o.responses + 0.7, util.out("figures/verification.dat")))
    -- Responses along the steepest-ascent path.
    local sa = {}
    for i, s in ipairs(o.reference.steepest_ascent) do
      sa[i] = {s.step}
      for _, r in ipairs(o.responses) do sa[i][#sa[i] + 1] = s.responses[r] end
    end
    util.write_columns("figures/steepest_ascent.dat", "step " .. table.concat(o.responses, " "), sa)
    local lines = {}
    for k, r in ipairs(o.responses) do
      lines[#lines + 1] = string.format("'%s' using 1:%d with linespoints pt 7 lw 2 title '%s', %g with lines dt 2 title 'measured %s'",
                                        util.out("figures/steepest_ascent.dat"), k + 1, r, o.measured[r], r)
    end
    c.steepest_ascent = util.gnuplot("figures/steepest_ascent", string.format([[
set title 'Steepest ascent: responses along the path'
set xlabel 'step'; set ylabel '[mm]'; set grid; set key outside bottom center horizontal
plot %s]], table.concat(lines, ", ")))
  end
  return c
end

---------------------------------------------------------------------------- the page
local function html_page(o, files, ch, pics)
  local input, resp, sel = o.input, o.responses, o.screening.selected
  local h = {}
  local function add(s) h[#h + 1] = s end
  add('<!DOCTYPE html>')
  add('<html xmlns="http://www.w3.org/1999/xhtml" lang="en"><head><meta charset="utf-8"/>')
  add('<title>Paddy calibration report</title>')
  add([[<style>
body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}
table{border-collapse:collapse;margin:0.8em 0}td,th{border:1px solid #bbb;padding:0.2em 0.5em;text-align:right}
th{background:#eee}caption{font-weight:bold;text-align:left;padding:0.3em 0}
figure{display:inline-block;margin:0.5em;vertical-align:top}figure img{max-width:560px;border:1px solid #ddd}
figcaption{font-size:0.9em;color:#555;max-width:560px}.eq{font-family:monospace;margin:0.3em 0}
.ok{color:#070}.bad{color:#a00}</style></head><body>]])
  add('<h1>Calibration report</h1>')
  add('<p>' .. esc(input.description) .. '</p>')
  add(string.format('<p>Input file <code>%s</code>; experiment <code>%s</code>; particle diameter %s m; strategy %s; %d distinct simulations; wall time %s s. Paddy %s.</p>',
                    esc(input.path), esc(input.experiment), num(o.particle_diameter), esc(o.parameters.strategy),
                    #o.simulations, num(o.wall_time_s), esc(paddy.version)))

  -- Summary.
  add('<h2>Summary</h2>')
  local tt = M.to_tolerance(o)
  local rows = {}
  for _, name in ipairs({"reference", "surrogate"}) do
    local t = tt[name]
    if t then
      rows[#rows + 1] = {name, num(t.simulations), string.format('<span class="%s">%s</span>', t.reached and "ok" or "bad",
                         t.reached and "yes" or "no"), pct(t.error), num(t.seeds)}
    end
  end
  add(table_html({"strategy", "simulations", string.format("within %g %%", 100 * o.tolerance), "worst error of the result", "seeds averaged"}, rows,
                 "Simulations used by each strategy (screening included) until its result; the result is the mean over its seeds"))
  if o.reference then
    local r = o.reference
    rows = {}
    for _, x in ipairs(resp) do
      rows[#rows + 1] = {esc(x), num(o.measured[x]), num(r.optimum.predicted[x]), num(r.verification.mean[x]) .. " ± " .. num(r.verification.sd[x], 3),
                         pct(r.verification.errors[x])}
    end
    add(table_html({"response", "measured", "regression at optimum", "simulated (verification)", "relative error"}, rows,
                   "Reference procedure: verification at the optimum"))
  end
  rows = {}
  for _, f in ipairs(input.factors) do
    local ref = o.reference and o.reference.optimum.factors[f.symbol]
    local sur = o.surrogate and o.surrogate.confirmed and o.surrogate.confirmed.values[f.symbol]
    rows[#rows + 1] = {esc(f.symbol), esc(f.parameter), num(ref or f.center), num(o.surrogate and (sur or (o.surrogate.best and o.surrogate.best.values[f.symbol])) or nil),
                       ref and "optimised" or "fixed at centre"}
  end
  add(table_html({"symbol", "parameter", "reference optimum", "surrogate result", "note"}, rows, "Calibrated parameters (at the reference 2 mm particle size)"))
  add(figure(ch.convergence, "Best worst-response relative error so far against the simulations used, both strategies"))

  -- 1. Screening.
  add('<h2>1. Plackett-Burman screening</h2>')
  local header = {"run", "type"}
  for _, f in ipairs(input.factors) do header[#header + 1] = esc(f.symbol) end
  for k = 1, input.screening.dummy_columns do header[#header + 1] = "D" .. k end
  for _, x in ipairs(resp) do header[#header + 1] = esc(x) end
  rows = {}
  for i, run in ipairs(o.screening.design.runs) do
    local row = {num(run.run), esc(run.type)}
    for _, f in ipairs(input.factors) do row[#row + 1] = num(run.real[f.symbol]) end
    for k = 1, input.screening.dummy_columns do row[#row + 1] = num(run.coded["D" .. k]) end
    for _, x in ipairs(resp) do row[#row + 1] = num(o.screening.runs[i].responses[x]) end
    rows[#rows + 1] = row
  end
  add(table_html(header, rows, "Design (real units; dummy columns coded) and simulated responses"))
  add(anova_section(input, o.screening.fit, resp, "main effects + curvature; dummy columns form the residual"))
  rows = {}
  for _, f in ipairs(o.screening.ranking) do
    local row = {esc(factor_label(input, f.symbol))}
    for _, x in ipairs(resp) do row[#row + 1] = pval(f.p_by_response[x]) end
    row[#row + 1] = f.selected and ("selected (" .. esc(f.reason) .. ")") or "fixed at centre"
    rows[#rows + 1] = row
  end
  header = {"factor"}
  for _, x in ipairs(resp) do header[#header + 1] = "p (" .. esc(x) .. ")" end
  header[#header + 1] = string.format("decision (alpha = %g)", input.screening.alpha)
  add(table_html(header, rows, "Factors ranked by p-value"))
  for _, p in ipairs(figures_of(o.screening.fit.plots, "pareto_")) do add(figure(p, "Pareto chart of standardised effects: " .. p:match("([^/]*)%.png$"))) end

  if o.reference then
    local r = o.reference
    add('<h2>2. Steepest ascent</h2>')
    header = {"step"}
    for _, s in ipairs(sel) do header[#header + 1] = esc(factor_label(input, s)) end
    for _, x in ipairs(resp) do header[#header + 1] = esc(x); header[#header + 1] = "δ " .. esc(x) end
    rows = {}
    for _, s in ipairs(r.steepest_ascent) do
      local row = {num(s.step)}
      for _, sym in ipairs(sel) do row[#row + 1] = num(s.values[sym]) end
      for _, x in ipairs(resp) do row[#row + 1] = num(s.responses[x]); row[#row + 1] = pct(s.errors[x]) end
      rows[#rows + 1] = row
    end
    add(table_html(header, rows, string.format("Path (δ = |measured − simulated| / measured); best step %d becomes the centre", r.best_step.step)))
    add(figure(ch.steepest_ascent, "Responses along the steepest-ascent path"))

    add('<h2>3. Box-Behnken design</h2>')
    rows = {}
    for _, s in ipairs(sel) do rows[#rows + 1] = {esc(factor_label(input, s)), num(r.box[s][1]), num((r.box[s][1] + r.box[s][2]) / 2), num(r.box[s][2])} end
    add(table_html({"factor", "−1", "0", "+1"}, rows, "Levels"))
    header = {"run", "type"}
    for _, s in ipairs(sel) do header[#header + 1] = esc(s) end
    for _, x in ipairs(resp) do header[#header + 1] = esc(x) .. " (mean ± sd)" end
    header[#header + 1] = "replicates"
    rows = {}
    for _, run in ipairs(r.runs) do
      local row = {num(run.run.run), esc(run.run.type)}
      for _, s in ipairs(sel) do row[#row + 1] = num(run.run.real[s]) end
      for _, x in ipairs(resp) do row[#row + 1] = num(run.mean[x]) .. " ± " .. num(run.sd[x], 3) end
      row[#row + 1] = num(#run.rows)
      rows[#rows + 1] = row
    end
    add(table_html(header, rows, "Design and responses (replicates with different seeds, averaged)"))
    add(anova_section(input, r.fit, resp, "quadratic model; lack of fit against pure error from the centre points"))
    for _, x in ipairs(resp) do
      local a = r.fit.responses[x]
      add('<p class="eq">coded: ' .. equation(a.coefficients, r.fit.terms, x) .. '</p>')
      add('<p class="eq">actual: ' .. equation(a.coefficients_actual, r.fit.terms, x) .. '</p>')
    end
    for _, p in ipairs(figures_of(r.fit.plots, "surface_")) do add(figure(p, "Response surface " .. p:match("([^/]*)%.png$"))) end
    for _, p in ipairs(figures_of(r.fit.plots, "contour_")) do add(figure(p, "Contours " .. p:match("([^/]*)%.png$"))) end
    for _, p in ipairs(figures_of(r.fit.plots, "pred_actual_")) do add(figure(p, "Predicted against actual " .. p:match("([^/]*)%.png$"))) end

    add('<h2>4. Desirability optimum</h2>')
    rows = {}
    for k, s in ipairs(r.optimization.solutions) do
      if k > 5 then break end
      local row = {num(k)}
      for _, sym in ipairs(sel) do row[#row + 1] = num(s.factors[sym]) end
      for _, x in ipairs(resp) do row[#row + 1] = num(s.predicted[x]) end
      row[#row + 1] = num(s.desirability, 4)
      rows[#rows + 1] = row
    end
    header = {"solution"}
    for _, s in ipairs(sel) do header[#header + 1] = esc(s) end
    for _, x in ipairs(resp) do header[#header + 1] = "predicted " .. esc(x) end
    header[#header + 1] = "desirability"
    add(table_html(header, rows, "Solutions (targets: " .. (function()
      local t = {}
      for _, g in ipairs(r.goals) do t[#t + 1] = string.format("%s = %g in [%g, %g]", g.response, g.target, g.lower, g.upper) end
      return esc(table.concat(t, "; "))
    end)() .. ")"))
    for _, p in ipairs(figures_of(r.optimization.plots)) do add(figure(p, "Desirability ramp " .. p:match("([^/]*)%.png$"))) end

    add('<h2>5. Verification</h2>')
    header = {"seed"}
    for _, x in ipairs(resp) do header[#header + 1] = esc(x) end
    rows = {}
    for _, v in ipairs(r.verification.runs) do
      local row = {num(v.seed)}
      for _, x in ipairs(resp) do row[#row + 1] = num(v.responses[x]) end
      rows[#rows + 1] = row
    end
    add(table_html(header, rows, "Simulations at the optimum"))
    add(figure(ch.verification, "Simulated against measured"))
    for _, p in ipairs(pics.verification or {}) do add(figure(p.path, p.caption)) end
    if r.rheometer then
      local res = r.rheometer.result
      rows = {}
      for _, s in ipairs(res.steps or {}) do
        rows[#rows + 1] = {num(s.speed_rpm), num(s.torque_Nm, 4), num(s.shear_rate, 4), num(s.shear_stress_Pa, 4)}
      end
      add('<h3>Vane rheometer at the optimum</h3>')
      add(table_html({"speed [rpm]", "steady torque [N m]", "shear rate [1/s]", "shear stress [Pa]"}, rows, "Steady torque per speed"))
      local hb = res.herschel_bulkley
      if hb then add(string.format("<p>Herschel–Bulkley fit: τ0 = %s Pa, K = %s Pa·sⁿ, n = %s.</p>", num(hb.tau0), num(hb.K), num(hb.n))) end
      if res.comparison then
        add(string.format("<p>Against the measured torque curve <code>%s</code>: mean relative error %s, largest %s.</p>",
                          esc(res.comparison.file), pct(res.comparison.mean_relative_error), pct(res.comparison.max_relative_error)))
      else
        add("<p>No measured torque curve is given in the input file (rheometer.measured_torque_csv), so the torque is reported without errors.</p>")
      end
      for _, p in ipairs(pics.rheometer or {}) do add(figure(p.path, p.caption)) end
    end
  end

  if o.surrogate then
    local s = o.surrogate
    add('<h2>Surrogate-based strategy</h2>')
    local box = {}
    for _, f in ipairs(s.factors) do box[#box + 1] = string.format("%s ∈ [%g, %g]", f.name, f.low, f.high) end
    add(string.format("<p>Gaussian process per response, expected improvement of the worst relative error; search box %s; budget %d simulations after screening. %s</p>",
                      esc(table.concat(box, ", ")), s.budget,
                      s.success and string.format("Confirmed within tolerance after %d own simulations (mean of %d seeds: worst error %s).",
                                                  s.confirmed.simulations, s.confirmed.seeds, pct(s.confirmed.worst))
                        or "No point was confirmed within the tolerance inside the budget."))
    header = {"n", "kind"}
    for _, f in ipairs(s.factors) do header[#header + 1] = esc(f.name) end
    for _, x in ipairs(resp) do header[#header + 1] = esc(x); header[#header + 1] = "predicted " .. esc(x) end
    header[#header + 1] = "worst error"
    rows = {}
    for _, ev in ipairs(s.evaluations) do
      local row = {num(ev.n), esc(ev.kind)}
      for _, f in ipairs(s.factors) do row[#row + 1] = num(ev.values[f.name]) end
      for _, x in ipairs(resp) do
        row[#row + 1] = num(ev.responses[x])
        local pr = ev.predicted and ev.predicted.predicted and ev.predicted.predicted[x]
        row[#row + 1] = pr and (num(pr.mean) .. " ± " .. num(pr.sd, 3)) or "–"
      end
      row[#row + 1] = pct(ev.worst)
      rows[#rows + 1] = row
    end
    add(table_html(header, rows, "Simulations of the surrogate strategy (predictions are the surrogate's before the run)"))
  end

  add('<h2>Data</h2><ul>')
  add(string.format('<li><a href="%s">calibration.json</a> — every number of this report</li>', esc(rel(files.json))))
  for _, f in ipairs(files.csv) do add(string.format('<li><a href="%s">%s</a></li>', esc(rel(f)), esc(rel(f)))) end
  add('</ul></body></html>')
  return table.concat(h, "\n") .. "\n"
end

-- Writes everything; returns {html =, json =, csv = {...}, figures = {...}}.
function M.write(a)
  local o = a.outcome
  os.execute("mkdir -p '" .. util.out("data"):gsub("'", "'\\''") .. "'")
  local files = {csv = {}}
  files.json = paddy.write_json("calibration.json", json_document(o))
  files.csv = write_csvs(o)
  local ch, pics = {}, {}
  if a.pictures then
    ch = charts(o, a.figures)
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
  local html = html_page(o, files, ch, pics)
  local path = util.out("report.html")
  local tmp = path .. ".tmp"
  local f = assert(io.open(tmp, "w"))
  f:write(html)
  f:close()
  assert(os.rename(tmp, path))
  files.html = path
  return files
end

-- The experiment's result.json entries.
function M.summary(o, files)
  local s = {measured = o.measured, tolerance = o.tolerance, simulations = #o.simulations, wall_time_s = o.wall_time_s,
             selected_factors = o.screening.selected, to_tolerance = M.to_tolerance(o),
             report = files.html, calibration_json = files.json, csv = files.csv}
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
