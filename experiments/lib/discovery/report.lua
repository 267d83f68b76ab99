-- The discovery workflow's outputs: result.json's summary (report.summary) and report.html with
-- its gnuplot figures (report.write): residual map before/after, each candidate's signature over
-- the residual, and the vector observables (profile, history, torques) measured against simulated
-- before and after. HTML building blocks from lib/calibration/html.lua.
local util = require("lib.util")
local html = require("lib.calibration.html")
local esc, num, pval, table_html, figure = html.esc, html.num, html.pval, html.table_html, html.figure
local M = {}

local function find(list, name)
  for _, c in ipairs(list or {}) do if c.name == name then return c end end
end

-- The keys result.json must have (docs/discovery.md): decision, named_effect, strength,
-- misfit_before/after (RMS of standardised residuals), candidates (statistic and p-value).
function M.summary(o, files)
  local d, a = o.diagnosis, o.after
  local cands = {}
  for k, c in ipairs(o.input.candidates) do
    local s = find(d.candidates, c.name) or {}
    cands[k] = {name = c.name, parameter = c.parameter, probe = c.probe, relevant = c.relevant, z = s.z, z_relevant = s.z_relevant,
                p = s.p, p_relevant = s.p_relevant, p_holm = s.p_holm,
                strength = s.strength, strength_se = s.strength_se, q_after = s.q_after, q_after_p = s.q_after_p,
                bayes_factor = s.bayes_factor, identifiable = s.identifiable,
                -- what these experiments can see of it, its signature's seed noise allowed for
                -- (doe detection.hpp; absent = infinite: not detectable at any strength)
                detection_limit = s.detection_limit, detectable = s.detectable, upper_limit = s.upper_limit,
                strength_corrected = s.strength_corrected, strength_corrected_se = s.strength_corrected_se,
                signature_noise_share = (s.a or 0) > 0 and s.a_noise / s.a or nil}
  end
  local theta = {}
  for j, f in ipairs(o.input.free_parameters) do theta[f.parameter] = o.calibration.theta[j] end
  local theta_after
  if a then
    theta_after = {}
    for j, f in ipairs(o.input.free_parameters) do theta_after[f.parameter] = a.theta[j] end
  end
  -- Signatures per observable (sigma units per unit strength) and the change a probe makes in
  -- seed standard deviations: which observable each candidate moves.
  local signatures = {}
  for _, c in ipairs(o.input.candidates) do
    local g, moved = o.signatures[c.name], {}
    for i, l in ipairs(o.layout) do
      moved[i] = {label = l.label, per_strength = g[i] * l.sigma,
                  probe_in_seed_sd = (o.located.noise.seed_sd and o.located.noise.seed_sd[i] or 0) > 0
                                     and g[i] * c.probe / o.located.noise.seed_sd[i] or nil}
    end
    signatures[c.name] = moved
  end
  local residuals = {}
  for i, r in ipairs(o.located.residuals) do
    residuals[i] = {label = r.label, experiment = r.block, key = r.key, index = r.index, axis = r.axis,
                    measured = r.measured, simulated = r.simulated, z_before = r.z,
                    simulated_after = a and a.simulated[i] * o.layout[i].sigma or nil, z_after = a and a.z[i] or nil}
  end
  return {
    decision = d.decision,
    named_effect = a and d.named or nil,
    ambiguous_with = d.ambiguous_with,
    separating_block = d.separating_block,
    strength = a and a.strength or nil,
    misfit_before = o.located.rms,
    misfit_after = a and a.rms or o.located.rms,
    q0 = d.q0, q0_df = d.q0_df, q0_p = d.q0_p,
    thresholds = d.thresholds and d.thresholds.method and d.thresholds
                 or {method = "tables", note = "chi^2 / normal tables with Holm"},
    misfit_statistic_before = d.misfit,
    misfit_statistic_after = a and a.diagnosis and a.diagnosis.misfit or nil,
    decision_after = a and a.diagnosis and a.diagnosis.decision or nil,
    screening_decision = o.screening and o.screening.decision or d.decision,
    reason = d.reason,
    tried_effect = o.tried and {name = d.best, strength = o.tried.strength, misfit_after = o.tried.rms,
                                q0_after = o.tried.diagnosis and o.tried.diagnosis.q0 or nil} or nil,
    comparison = a and a.comparison or nil,
    candidates = cands,
    signatures = signatures,
    confusability = d.confusability,
    calibrated = theta,
    recalibrated = theta_after,
    recalibration = a and {method = a.joint.method, surface = a.joint.surface, zooms = a.joint.zooms} or
                    (o.tried and {method = o.tried.joint.method, surface = o.tried.joint.surface, zooms = o.tried.joint.zooms}) or nil,
    residuals = residuals,
    ambiguous_refits = o.ambiguous_refits,
    noise = {shrinkage = o.located.noise.shrinkage, seed_sd = o.located.noise.seed_sd,
             measured_repeats = o.input.settings.measured_repeats},
    resolution = o.resolution,
    calibration = o.calibration.iterations,
    calibration_start = o.calibration.surface_start,
    simulations = #o.simulations,
    wall_time_s = o.wall_time_s,
    particle_diameter = o.parameters.particle_diameter,
    input = o.input.path,
    report = files.html,
  }
end

-- Figures -----------------------------------------------------------------------------------
local function residual_map(o)
  local rows = {}
  for i, r in ipairs(o.located.residuals) do
    rows[i] = {i, r.z, o.after and o.after.z[i] or 0}
  end
  util.write_columns("figures/residuals.dat", "index z_before z_after", rows)
  local tics, last = {}, nil
  for i, r in ipairs(o.located.residuals) do
    local id = r.block .. " " .. r.key
    if id ~= last then tics[#tics + 1] = string.format("%s %d", util.gnuplot_text(id), i); last = id end
  end
  return util.gnuplot("figures/residuals", string.format([[
set title 'Standardised residuals (measured - simulated) / sd, per observable'
set ylabel 'z'; set grid ytics; set xtics rotate by -40 (%s) font ',8'; set key top right
set style fill solid 0.6 border -1; set boxwidth 0.4; set xrange [0:%d]
plot %s using ($1-0.2):2 with boxes lc rgb '#a33' title 'before', \
     %s 2 with lines dt 2 lc rgb 'black' notitle, -2 with lines dt 2 lc rgb 'black' notitle]],
    table.concat(tics, ", "), #rows + 1, util.gnuplot_text(util.out("figures/residuals.dat")),
    o.after and string.format("'' using ($1+0.2):3 with boxes lc rgb '#36a' title 'after (effect added)',", o.after) or ""))
end

local function signature_chart(o, c, s)
  local rows = {}
  local lam = s.strength or 0
  for i, r in ipairs(o.residual) do rows[i] = {i, r, lam * o.signatures[c.name][i]} end
  local stem = "figures/signature_" .. c.name
  util.write_columns(stem .. ".dat", "index residual strength_times_signature (sigma units)", rows)
  return util.gnuplot(stem, string.format([[
set title %s
set xlabel 'observable'; set ylabel 'measured - simulated [sigma]'; set grid; set key top right
plot %s using 1:2 with impulses lw 4 lc rgb '#999' title 'residual', '' using 1:3 with linespoints pt 7 lc rgb '#a33' title 'signature x strength']],
    util.gnuplot_text(string.format("%s: residual and signature x estimated strength %.3g (sigma units; z = %.2f)", c.name, lam, s.z or 0)),
    util.gnuplot_text(util.out(stem .. ".dat"))))
end

-- Vector observables (more than one entry under one key): measured and simulated before/after.
local function curves(o)
  local groups, order = {}, {}
  for i, l in ipairs(o.layout) do
    if l.vector then
      local id = l.block .. " " .. l.key
      if not groups[id] then groups[id] = {}; order[#order + 1] = id end
      local g = groups[id]
      g[#g + 1] = {l.axis or l.index, l.measured, o.located.residuals[i].simulated,
                   o.after and o.after.simulated[i] * l.sigma or 0 / 0, l.sigma}
    end
  end
  local out = {}
  for k, id in ipairs(order) do
    local stem = "figures/curve_" .. k
    util.write_columns(stem .. ".dat", "axis measured simulated_before simulated_after sigma", groups[id])
    out[#out + 1] = {name = id, png = util.gnuplot(stem, string.format([[
set title %s
set xlabel 'grid (radius mm, time s, speed, or index)'; set grid; set key outside bottom center horizontal
plot %s using 1:2:5 with yerrorbars pt 7 lc rgb 'black' title 'measured +- sd', \
     '' using 1:3 with linespoints lw 2 lc rgb '#a33' title 'calibrated (before)'%s]],
      util.gnuplot_text(id .. ": measured and simulated"), util.gnuplot_text(util.out(stem .. ".dat")), o.after and ", '' using 1:4 with linespoints lw 2 lc rgb '#36a' title 'effect added (after)'" or ""))}
  end
  return out
end

function M.write(args)
  local o = args.outcome
  util.mkdir(util.out("figures"))
  local figs = {signatures = {}}
  if args.pictures then
    figs.residuals = residual_map(o)
    for _, c in ipairs(o.input.candidates) do
      figs.signatures[c.name] = signature_chart(o, c, find(o.diagnosis.candidates, c.name) or {})
    end
    figs.curves = curves(o)
  end
  local d, a = o.diagnosis, o.after
  local h = {}
  local function add(s) h[#h + 1] = s end
  add('<!DOCTYPE html>')
  add('<html xmlns="http://www.w3.org/1999/xhtml" lang="en"><head><meta charset="utf-8"/><title>Paddy discovery report</title>')
  add([[<style>body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}
table{border-collapse:collapse;margin:0.8em 0}td,th{border:1px solid #bbb;padding:0.2em 0.5em;text-align:right}
th{background:#eee}caption{font-weight:bold;text-align:left;padding:0.3em 0}
figure{display:inline-block;margin:0.5em;vertical-align:top}figure img{max-width:560px;border:1px solid #ddd}
figcaption{font-size:0.9em;color:#555;max-width:560px}</style></head><body>]])
  add('<h1>What is the model missing?</h1>')
  add('<p>' .. esc(o.input.description) .. '</p>')
  add(string.format('<p>Input <code>%s</code>; particle diameter %s m; %d distinct simulations; wall time %s s. Paddy %s.</p>',
                    esc(o.input.path), num(o.parameters.particle_diameter), #o.simulations, num(o.wall_time_s), esc(paddy.version)))
  add('<h2>Decision</h2>')
  local verdict = d.decision == "effect" and ("effect: <b>" .. esc(d.named) .. "</b>")
                  or d.decision == "ambiguous" and ("ambiguous between " .. esc(table.concat(d.ambiguous_with or {}, ", "))
                                                    .. (d.separating_block and ("; the experiment that separates them best: " .. esc(d.separating_block)) or ""))
                  or esc(d.decision)
  add('<p>' .. verdict .. '</p>')
  if d.reason then add('<p>Why: ' .. esc(d.reason) .. '.</p>') end
  if o.screening and o.screening.decision ~= d.decision then
    add('<p>The score test alone answered <b>' .. esc(o.screening.decision) .. '</b>: ' .. esc(o.screening.reason or "") ..
        '. The decision above was taken after adding the best candidate and recalibrating.</p>')
  end
  if o.tried then
    add(string.format('<p>Tried and not named: %s at %s, which left an RMS standardised residual of %s.</p>',
                      esc(d.best or "?"), num(o.tried.strength.value), num(o.tried.rms)))
  end
  local rows = {{"RMS standardised residual", num(o.located.rms), a and num(a.rms) or "–"},
                {"misfit statistic", num(d.misfit), a and a.diagnosis and num(a.diagnosis.misfit) or "–"},
                {"projected misfit Q0 (df, p)", string.format("%s (%s, %s)", num(d.q0), num(d.q0_df), pval(d.q0_p)),
                 a and a.diagnosis and string.format("%s (%s, %s)", num(a.diagnosis.q0), num(a.diagnosis.q0_df), pval(a.diagnosis.q0_p)) or "–"}}
  if a then
    rows[#rows + 1] = {"strength of " .. esc(d.named), "0", string.format("%s [%s, %s]", num(a.strength.value), num(a.strength.low), num(a.strength.high))}
    local rc = a.strength.resolution_corrected
    if rc then
      rows[#rows + 1] = {string.format("strength extrapolated to %s mm spheres", num(rc.diameter * 1000)), "",
                         string.format("%s [%s, %s] (shift %s ± %s)", num(rc.value), num(rc.low), num(rc.high), num(rc.shift), num(rc.se_shift))}
    end
    if a.comparison then
      rows[#rows + 1] = {"likelihood ratio (p), ΔBIC", "", string.format("%s (%s), %s", num(a.comparison.lr), pval(a.comparison.p), num(a.comparison.delta_bic))}
    end
  end
  add(table_html({"", "calibrated model", "effect added"}, rows, "Misfit before and after"))

  add('<h2>1. Calibration</h2>')
  rows = {}
  for _, it in ipairs(o.calibration.iterations) do
    local t = {}
    for j, f in ipairs(o.input.free_parameters) do t[#t + 1] = esc(f.parameter) .. " = " .. num(it.theta[j]) end
    rows[#rows + 1] = {num(it.iteration) .. ((it.backtrack or 0) > 0 and string.format(" (step halved %d×)", it.backtrack) or ""),
                       table.concat(t, ", "), num(it.rms_sigma), it.accepted == false and "rejected" or "accepted"}
  end
  local ss = o.calibration.surface_start
  local start_text = ""
  if ss then
    local t = {}
    for j, f in ipairs(o.input.free_parameters) do t[#t + 1] = esc(f.parameter) .. " = " .. num(ss.theta[j]) end
    start_text = string.format("; it starts at the best point of a quadratic response surface through %s scan points, %s (predicted RMS %s)",
                               num(ss.points), table.concat(t, ", "), num(ss.misfit_predicted))
  end
  add(table_html({"iteration", "parameters", "RMS residual [measurement sd], one seed", "step"}, rows,
                 "Gauss-Newton on forward differences, common random numbers; a step that raises the misfit is halved" .. start_text))
  if o.resolution then
    rows = {}
    for _, r in ipairs(o.resolution.shift) do rows[#rows + 1] = {esc(r.label), num(r.shift), num(r.z, 3)} end
    add(table_html({"observable", "shift", "shift [noise sd]"}, rows,
                   string.format("Resolution bias: the observables at %s m minus at the workflow's diameter (RMS %s noise sd), projected out like a free parameter",
                                 num(o.resolution.diameter), num(o.resolution.rms))))
  end

  add('<h2>2. Where the model misses</h2>')
  add(figure(figs.residuals, "Standardised residual of every observable before (calibrated) and after (named effect added and recalibrated); dashed: ±2"))
  rows = {}
  for i, r in ipairs(o.located.residuals) do
    rows[#rows + 1] = {esc(r.label), num(r.measured), num(r.simulated), num(r.z, 3), a and num(a.z[i], 3) or "–"}
  end
  add(table_html({"observable", "measured", "simulated", "z before", "z after"}, rows,
                 string.format("Residuals; noise = measurement sd + seed scatter of %d replicates", #o.replicates)))
  for _, c in ipairs(figs.curves or {}) do add(figure(c.png, c.name .. ": measured ± sd, simulated before and after")) end

  add('<h2>3. Candidates</h2>')
  rows = {}
  for _, c in ipairs(o.input.candidates) do
    local s = find(d.candidates, c.name) or {}
    rows[#rows + 1] = {esc(c.name), esc(c.parameter), num(c.probe), num(c.relevant or 0), num(s.z, 3), num(s.z_relevant or s.z, 3),
                       pval(s.p_relevant or s.p), pval(s.p_holm),
                       num(s.strength) .. " ± " .. num(s.strength_se, 3), num(s.q_after), pval(s.q_after_p), num(s.bayes_factor, 3),
                       s.identifiable == false and "no" or "yes",
                       (s.a or 0) > 0 and num(100 * s.a_noise / s.a, 3) .. " %" or "–",
                       s.detection_limit and num(s.detection_limit, 3) or "nowhere",
                       s.upper_limit and num(s.upper_limit, 3) or "unbounded"}
  end
  add(table_html({"candidate", "parameter", "probe", "smallest relevant", "z", "z above relevant", "p", "p (Holm)", "strength", "misfit left", "p", "Bayes factor", "identifiable",
                  "signature noise", "detectable from", "upper limit (95 %)"}, rows,
                 "Score test of each candidate on the residual that recalibration cannot absorb. Signature noise: the share of the "
                 .. "projected signature's size that is seed noise; detectable from: the strength named with 90 % power by the score "
                 .. "(docs/discovery.md, \"Detection limits\"); upper limit: the largest strength these data leave possible"))
  if d.confusability then
    local header, crow = {""}, {}
    for _, c in ipairs(o.input.candidates) do header[#header + 1] = esc(c.name) end
    for k, c in ipairs(o.input.candidates) do
      local row = {esc(c.name)}
      for l = 1, #o.input.candidates do row[#row + 1] = num((d.confusability[k] or {})[l], 3) end
      crow[#crow + 1] = row
    end
    add(table_html(header, crow, "Confusability |cos| of the projected signatures (above " .. num(o.input.settings.confusable) .. ": not separable)"))
  end
  for _, c in ipairs(o.input.candidates) do add(figure(figs.signatures[c.name], c.name .. ": signature × estimated strength over the residual")) end

  add('<h2>Simulations</h2>')
  rows = {}
  for _, s in ipairs(o.simulations) do
    rows[#rows + 1] = {num(s.index), esc(s.stage), esc(s.label or ""), num(s.seed), esc(s.key:sub(1, 12)), num(s.wall_time_s)}
  end
  add(table_html({"#", "step", "run", "seed", "job", "wall time [s]"}, rows, "Every distinct simulation (campaign jobs)"))
  add('</body></html>')
  -- written atomically (temporary file + rename); a failure names the file and the cause
  return {html = util.write_file(util.out("report.html"), table.concat(h, "\n"))}
end

return M
