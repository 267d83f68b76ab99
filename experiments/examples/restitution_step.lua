-- The restitution a contact law gives through the whole engine, against the step and the time
-- integration scheme: a mud sphere (R = 1 mm, Table 2's intrinsic values) hits a steel plane at
-- 0.5 m/s without gravity under Hertz + Hertz-Mindlin damping (no friction), and rebounds at
-- e_measured · 0.5 m/s. Where the contact begins within a step moves one impact's result by up to
-- ±2 % at 0.1 T_R, so each value is the mean over `gaps` starting gaps between 10 and 20 µm
-- (their spread is written beside it). docs/physics.md §3 "Measured restitution".
--
--   paddy run experiments/examples/restitution_step.lua --out results/restitution_step
-- writes restitution_step.csv (scheme, e, step / T_R, mean, min, max, relative error) and
-- restitution_step.png (the error against the step, log-log; `pictures = false` skips it).

local util = require("lib.util")

local P = paddy.parameters{
  {name = "restitutions", default = "0.1,0.13,0.3,0.5,0.9", description = "set restitutions, comma-separated"},
  {name = "fractions", default = "0.2,0.1,0.05,0.02,0.01", description = "steps as fractions of the Rayleigh time"},
  {name = "schemes", default = "velocity_verlet,euler", description = "time integration schemes (sim:integration)"},
  {name = "gaps", default = 16, type = "integer", min = 1, max = 1000, description = "starting gaps per value (10 to 20 um)"},
  {name = "speed", default = 0.5, unit = "m/s", min = 1e-3, max = 10, description = "impact speed"},
  {name = "pictures", default = true, description = "draw restitution_step.png with gnuplot"},
}

local R = 1e-3
local function rebound(scheme, e, fraction, gap)
  local sim = paddy.simulation{gravity = {0, 0, 0}, threads = 1}
  local mud = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
  local steel = sim:material{name = "steel", density = 7800, shear_modulus = 7e9, poisson = 0.3}
  sim:interaction(mud, steel, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                               restitution = e, friction = 0})
  sim:interaction(mud, mud, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                             restitution = e, friction = 0})
  sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = steel, name = "plane"}
  sim:add_particle{pos = {0, 0, R + gap}, radius = R, material = mud, vel = {0, 0, -P.speed}}
  sim:integration(scheme)
  sim:timestep{fraction = fraction}
  sim:run{duration = 2e-3 + 2 * gap / P.speed, progress = false}
  if sim:contact_count() ~= 0 then error(string.format("%s, e = %g, %g T_R: still in contact at the end", scheme, e, fraction)) end
  return sim:velocities()[1][3] / P.speed
end

local schemes = {}
for s in tostring(P.schemes):gmatch("[^,%s]+") do schemes[#schemes + 1] = s end
local restitutions, fractions = util.numbers(P.restitutions, "restitutions"), util.numbers(P.fractions, "fractions")
-- rows for the CSV, table_out for result.json; blocks and plots for the picture (one line per
-- scheme and restitution: |relative error| against the step).
local rows, table_out, blocks, plots = {}, {}, {}, {}
for _, scheme in ipairs(schemes) do
  for _, e in ipairs(restitutions) do
    local lines = {}
    for _, f in ipairs(fractions) do
      local sum, lo, hi = 0, math.huge, -math.huge
      for k = 0, P.gaps - 1 do
        local r = rebound(scheme, e, f, 1e-5 * (1 + k / P.gaps))
        sum, lo, hi = sum + r, math.min(lo, r), math.max(hi, r)
      end
      local mean = sum / P.gaps
      local err = mean / e - 1
      rows[#rows + 1] = {scheme, e, f, mean, lo, hi, err}
      table_out[#table_out + 1] = {scheme = scheme, restitution = e, step_fraction = f, measured = mean,
                                   min = lo, max = hi, relative_error = err}
      lines[#lines + 1] = string.format("%.9g %.9g", f, math.max(1e-6, 100 * math.abs(err)))
      print(string.format("%-16s e %-5g step %-5g T_R   measured %.5f (%.5f-%.5f)   %+6.2f %%", scheme, e, f, mean,
                          lo, hi, 100 * err))
    end
    blocks[#blocks + 1] = table.concat(lines, "\n")
    plots[#plots + 1] = string.format("'restitution_step.dat' index %d using 1:2 with linespoints dt %d lw 2 title '%s, e = %g'",
                                      #blocks - 1, scheme == "euler" and 2 or 1, scheme, e)
  end
end
util.write_csv("restitution_step.csv", {"scheme", "restitution", "step_fraction", "measured_mean", "measured_min",
                                         "measured_max", "relative_error"}, rows)

-- The picture (a first-order scheme's lines have slope 1, a second-order one's 2).
local picture
if P.pictures then
  util.write_file(util.out("restitution_step.dat"), table.concat(blocks, "\n\n\n") .. "\n")
  picture = util.gnuplot("restitution_step", "set logscale xy\nset xrange [0.008:0.3]\nset xlabel 'time step / Rayleigh time'\n" ..
    "set ylabel '|measured / set restitution - 1| [%], mean of " .. P.gaps .. " impacts'\nset key left top\nset grid\n" ..
    "cd " .. util.gnuplot_text(paddy.out_dir) .. "\nplot " .. table.concat(plots, ", \\\n  "))
end
paddy.result{gaps = P.gaps, speed = P.speed, radius = R, values = table_out, picture = picture}
if picture then print("picture  " .. picture) end
