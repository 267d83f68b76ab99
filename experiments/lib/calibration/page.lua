-- report.html: one page in the order of the procedure (summary, screening, steepest ascent,
-- Box-Behnken, optimum, verification and rheometer, surrogate strategy, data files).
local html = require("lib.calibration.html")
local compare = require("lib.calibration.compare")
local esc, num, pval, pct, rel = html.esc, html.num, html.pval, html.pct, html.rel
local table_html, figure, figures_of, factor_label = html.table_html, html.figure, html.figures_of, html.factor_label
local anova_section, equation = html.anova_section, html.equation
local M = {}

function M.render(o, files, ch, pics)
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
  add(string.format('<p>Input file <code>%s</code>; experiment <code>%s</code>; particle diameter %s m; time step %s × the Rayleigh time for every run (damping factor %s at the lowest restitution %s); strategy %s; %d distinct simulations; wall time %s s. Paddy %s.</p>',
                    esc(input.path), esc(input.experiment), num(o.particle_diameter), num(o.time_step.fraction), num(o.time_step.factor, 3),
                    num(o.time_step.lowest_restitution), esc(o.parameters.strategy), #o.simulations, num(o.wall_time_s), esc(paddy.version)))
  for _, r in ipairs(o.runs_at_shorter_step or {}) do
    add(string.format('<p class="bad">%s %s stopped at the calibration\'s step (too large for the velocities it reached) and ran at %s × the Rayleigh time (%d halving(s)).</p>',
                      esc(r.stage), esc(r.label or ""), num(r.timestep_fraction), r.step_halvings))
  end

  -- Summary.
  add('<h2>Summary</h2>')
  local tt = compare.to_tolerance(o)
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
  add(figure(ch.convergence, "Best single-run worst-response error so far against the simulations used, both strategies. One run can fall within the tolerance by chance, even in the screening; the table above counts results averaged over seeds"))

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

return M
