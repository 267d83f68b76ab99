-- The experiments' run helpers: lib/sampler.lua (rows, interpolation on a fixed grid, the steady
-- window that ends the slump test), lib/trigger.lua (combinations, elapsed time, periodic),
-- lib/phase.lua (a stop trigger ends sim:run early, an event acts once), lib/chart.lua (the gnuplot
-- script), lib/reference_measurement.lua (the measured slump from the calibration input) and the
-- slump test's end with the cone free (lib/slump_observables.lua).
local sampler = require("lib.sampler")
local trigger = require("lib.trigger")
local phase = require("lib.phase")
local chart = require("lib.chart")
local reference = require("lib.reference_measurement")
local check = require("checks").check

-- A fake simulation: time and one quantity, set by hand.
local clock = {t = 0, v = 0}
local fake = {time = function() return clock.t end}

-- Sampler: rows in order, columns, linear interpolation; before the first / after the last sample
-- the end values hold.
local smp = sampler.new{{"t", function(s) return s:time() end}, {"s", function() return clock.v end}}
for _, p in ipairs({{0, 0}, {0.5, 100}, {1.0, 150}}) do
  clock.t, clock.v = p[1], p[2]
  smp:record(fake)
end
check(#smp.rows == 3 and smp:last().s == 150 and smp:column("t")[2] == 0.5, "rows, last, column")
local at = smp:at("s", {-1, 0.25, 0.5, 0.75, 3})
check(at[1] == 0 and at[2] == 50 and at[3] == 100 and at[4] == 125 and at[5] == 150,
      "interpolation %g %g %g %g %g", at[1], at[2], at[3], at[4], at[5])
check(not pcall(sampler.interpolate, {}, "s", {1}), "interpolation of no samples must fail")
check(not pcall(sampler.new, {{"t"}}), "a quantity without a function must be refused")

-- Steady window: s(t) = 231 (1 − exp(−t / 0.2)) mm sampled every 0.05 s up to 2 s. Over the last
-- 0.5 s it changes by 231 (e^{−7.5} − e^{−10}) = 0.118 mm, over the last 1.5 s by 231 (e^{−2.5} −
-- e^{−10}) = 18.95 mm.
local rows = {}
for k = 0, 40 do
  local t = 0.05 * k
  rows[#rows + 1] = {t = t, s = 231 * (1 - math.exp(-t / 0.2))}
end
check(sampler.steady(rows, "s", 0.5, 0.2), "steady within 0.2 mm over 0.5 s")
check(not sampler.steady(rows, "s", 0.5, 0.1), "not steady within 0.1 mm over 0.5 s")
check(not sampler.steady(rows, "s", 1.5, 0.2), "not steady over 1.5 s")
check(sampler.steady(rows, "s", 1.5, 19), "steady within 19 mm over 1.5 s")
check(not sampler.steady(rows, "s", 0.5, 0), "tolerance 0 switches the window off")
check(not sampler.steady({rows[1], rows[2]}, "s", 0.5, 1e9), "0.05 s of samples do not span a 0.5 s window")
check(not sampler.steady({}, "s", 0.5, 1), "no samples: not steady")

-- Triggers: elapsed since the phase start or since a time known later; all / any give names.
local ph = {t0 = 1.0}
clock.t = 1.2
check(not trigger.elapsed(0.3)(fake, ph), "0.2 s elapsed is not 0.3 s")
clock.t = 1.3
check(trigger.elapsed(0.3)(fake, ph) == "elapsed", "0.3 s elapsed")
local later
check(not trigger.elapsed(0)(fake, {t0 = nil}) and not trigger.elapsed(0, function() return later end)(fake, ph),
      "elapsed since an unknown time never fires")
later = 1.25
check(not trigger.elapsed(0.1, function() return later end)(fake, ph), "0.05 s since a later time")
local yes, no = trigger.named("yes", function() return true end), trigger.named("no", function() return false end)
check(trigger.any{no, yes}(fake, ph) == "yes" and not trigger.any{no, no}(fake, ph), "any")
check(trigger.all{yes, trigger.named("last", function() return true end)}(fake, ph) == "last"
      and not trigger.all{yes, no}(fake, ph), "all")
clock.v = 0.004
check(trigger.below(smp, "s", 151, "low")(fake, ph) == "low" and not trigger.below(smp, "s", 150)(fake, ph), "below")
check(trigger.steady(smp, "s", 0.5, 50)(fake, ph) == "s_steady" and not trigger.steady(smp, "s", 0.5, 49)(fake, ph), "steady")
local angle = 0
local each_window = trigger.periodic(function() return angle end, 10)
local fired = {}
for k = 1, 12 do
  angle = 2.5 * k  -- 2.5 ... 30: windows complete at 10, 20, 30
  if each_window(fake, ph) then fired[#fired + 1] = angle end
end
check(#fired == 3 and fired[1] == 10 and fired[2] == 20 and fired[3] == 30, "periodic fired %d times", #fired)

-- Phase runner on a real simulation: spheres falling onto a floor; the stop trigger ends the run
-- early, an event acts once and at its sample the stop trigger is not checked.
local sim = paddy.simulation{threads = 1, gravity = {0, 0, -9.81}}
local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
sim:interaction(m, m, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin", restitution = 0.5, friction = 0.3})
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = m}
sim:fill{region = {type = "box", min = {0, 0, 0.01}, max = {0.02, 0.02, 0.03}}, radius = 0.002, material = m, count = 5, seed = 1}
sim:timestep{fraction = 0.1}
local times = sampler.new{{"t", function(s) return s:time() end}}
local acted = 0
local run = phase.run(sim, {
  duration = 1.0, every = 0.01, sample = times,
  events = {{when = trigger.elapsed(0.025), act = function() acted = acted + 1 end}},
  stop = trigger.elapsed(0.025),
})
check(acted == 1, "the event acted %d times", acted)
check(run.stopped_by == "elapsed" and math.abs(run.duration - 0.04) < 1e-3,
      "stopped by %s after %g s (0.04 s: at 0.03 s the event acted)", tostring(run.stopped_by), run.duration)
check(#times.rows == 4 and math.abs(run.t1 - times:last().t) < 1e-12, "%d samples", #times.rows)
local plain = phase.run(sim, {duration = 0.01})
check(plain.stopped_by == nil and math.abs(plain.duration - 0.01) < 1e-3, "a phase without callback runs its duration")
check(not pcall(phase.run, sim, {duration = 0.01, stop = trigger.elapsed(0)}), "a stop trigger without every must be refused")

-- Chart: titles quoted (quotes doubled), one plot command, inline rows after it.
local gp = chart.script{title = "the mud's slump", xlabel = "t [s]", settings = {"set key top left"},
                        series = {{file = "/o/h.dat", using = "1:2", with = "lines", title = "slump"},
                                  {expr = "231", with = "lines dt 3"},
                                  {rows = {{1, 2}, {3, 4.5}}, using = "1:2", with = "points", title = "peak"}}}
check(gp == "set title 'the mud''s slump'\nset xlabel 't [s]'\nset grid\nset key top left\n"
      .. "plot '/o/h.dat' using 1:2 with lines title 'slump', \\\n     231 with lines dt 3 notitle, \\\n"
      .. "     '-' using 1:2 with points title 'peak'\n1 2\n3 4.5\ne", "chart script:\n%s", gp)
check(not pcall(chart.script, {title = "x", series = {}}), "a chart without series must be refused")

-- The slump test's end before the lift has cleared the pile (lib/slump_observables.lua): rows every
-- 0.05 s; the pile at rest and the cone free over the last 0.1 s (three rows) ends the run, and each
-- single condition broken in one row of that window keeps it going.
local obs = require("lib.slump_observables")
local function rest_rows(edit)
  local out = {}
  for k = 0, 10 do
    out[#out + 1] = {t = 0.05 * k, rms_speed = k < 8 and 0.2 or 0.004, slump_mm = k < 8 and 20 * k or 228.3,
                     cone_load_N = k < 8 and 3.5 or 0}
  end
  if edit then edit(out) end
  return out
end
check(obs.at_rest_cone_free(rest_rows(), 0.1, 0.01, 1), "at rest and free over the last three rows")
check(not obs.at_rest_cone_free(rest_rows(), 0.2, 0.01, 1), "0.2 s reaches back into the collapse")
check(not obs.at_rest_cone_free(rest_rows(function(r) r[10].cone_load_N = 1e-9 end), 0.1, 0.01, 1),
      "a load on the cone in the window keeps the run going")
check(not obs.at_rest_cone_free(rest_rows(function(r) r[11].rms_speed = 0.01 end), 0.1, 0.01, 1),
      "an RMS speed not below rest_speed keeps the run going")
check(not obs.at_rest_cone_free(rest_rows(function(r) r[9].slump_mm = 226.9 end), 0.1, 0.01, 1),
      "a slump that moved by more than the tolerance keeps the run going")
check(obs.at_rest_cone_free(rest_rows(function(r) r[9].slump_mm = 226.9 end), 0.1, 0.01, 0),
      "tolerance 0: the slump is not checked")
check(not obs.at_rest_cone_free({{t = 1, rms_speed = 0, slump_mm = 1, cone_load_N = 0}}, 0.1, 0.01, 1),
      "one row does not span the window")
-- Sample times rounded to whole steps (0.0501 s apart here): the window starts at the last row at
-- or before t_last − 0.1 s, so three such rows still end the run.
local drift = {{t = 2.0508, rms_speed = 0.5, slump_mm = 200, cone_load_N = 0}}
for _, t in ipairs({2.1008, 2.1509, 2.2010}) do
  drift[#drift + 1] = {t = t, rms_speed = 0.007, slump_mm = 239.48, cone_load_N = 0}
end
check(not obs.at_rest_cone_free({drift[1], drift[2], drift[3]}, 0.1, 0.01, 1), "2.0508 s is in the window and moving")
check(obs.at_rest_cone_free(drift, 0.1, 0.01, 1), "rows 2.1008-2.2010 s span the window")
check(not obs.at_rest_cone_free(rest_rows(), 0, 0.01, 1), "window 0: off")
-- The largest load since the last look: an exact zero when nothing touched the wall.
local seen = 0
local function set_seen(n) seen = n end
local loads = {{force = {0, 0, 0}}, {force = {3, 0, -4}}, {force = {0, 0, 0}}}
check(obs.largest_load(loads, seen, set_seen) == 5 and seen == 3, "largest load 5 N over three samples")
loads[4], loads[5] = {force = {0, 0, 0}}, {force = {0, 0, 0}}
check(obs.largest_load(loads, seen, set_seen) == 0 and seen == 5, "no load in the two new samples")
check(obs.largest_load(loads, seen, set_seen) == 0 and seen == 5, "no new sample: no load")

-- The measured slump test: the calibration input's targets.
local measured = reference.slump()
local input = paddy.read_json(reference.file()).measured
check(measured.slump_mm == input.slump_mm and measured.slump_flow_mm == input.slump_flow_mm,
      "measured %g / %g mm", measured.slump_mm, measured.slump_flow_mm)

paddy.result{ok = true}
