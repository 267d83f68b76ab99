-- The report's own charts (gnuplot, PNG): best error so far of both strategies, verification
-- against measurement, responses along the steepest-ascent path. The statistics plots (Pareto,
-- surfaces, contours, desirability) come from paddy.doe.
local util = require("lib.util")
local compare = require("lib.calibration.compare")
local M = {}

function M.draw(o)
  local c = {}
  -- Convergence of both strategies.
  local series = compare.convergence(o)
  local plot = {}
  for k, s in ipairs(series) do
    local name = "figures/convergence_" .. k .. ".dat"
    local rows = {}
    for i, p in ipairs(s.points) do rows[i] = p end
    util.write_columns(name, "simulations best_worst_error_percent", rows)
    plot[#plot + 1] = string.format("%s using 1:2 with steps lw 2 title %s", util.gnuplot_text(util.out(name)), util.gnuplot_text(s.name))
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
    for i, r in ipairs(o.responses) do tics[i] = string.format("%s %d", util.gnuplot_text(r), i) end
    c.verification = util.gnuplot("figures/verification", string.format([[
set title 'Verification at the optimum: simulated (mean ± sd over seeds) and measured'
set style data histograms; set style histogram errorbars gap 2 lw 1; set style fill solid 0.6 border -1
set boxwidth 0.9; set ylabel '[mm]'; set grid ytics; set yrange [0:*]; set xtics (%s)
set xrange [0.3:%g]
plot %s using ($1-0.2):2:(0.35) with boxes lc rgb '#4477aa' title 'measured', \
     '' using ($1+0.2):3:(0.35) with boxes lc rgb '#8b5a2b' title 'simulated', \
     '' using ($1+0.2):3:4 with yerrorbars lc rgb 'black' pt 0 notitle]],
      table.concat(tics, ", "), #o.responses + 0.7, util.gnuplot_text(util.out("figures/verification.dat"))))
    -- Responses along the steepest-ascent path.
    local sa = {}
    for i, s in ipairs(o.reference.steepest_ascent) do
      sa[i] = {s.step}
      for _, r in ipairs(o.responses) do sa[i][#sa[i] + 1] = s.responses[r] end
    end
    util.write_columns("figures/steepest_ascent.dat", "step " .. table.concat(o.responses, " "), sa)
    local lines = {}
    for k, r in ipairs(o.responses) do
      lines[#lines + 1] = string.format("%s using 1:%d with linespoints pt 7 lw 2 title %s, %g with lines dt 2 title %s",
                                        util.gnuplot_text(util.out("figures/steepest_ascent.dat")), k + 1, util.gnuplot_text(r), o.measured[r],
                                        util.gnuplot_text("measured " .. r))
    end
    c.steepest_ascent = util.gnuplot("figures/steepest_ascent", string.format([[
set title 'Steepest ascent: responses along the path'
set xlabel 'step'; set ylabel '[mm]'; set grid; set key outside bottom center horizontal
plot %s]], table.concat(lines, ", ")))
  end
  return c
end

return M
