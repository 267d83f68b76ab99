-- Virtual vane rheometer with the reference paddy mud (shared/reference/README.md: Brookfield
-- R/S plus with a vane; the mud is fitted with Herschel–Bulkley). Documentation: docs/experiments.md.
--
--   paddy run experiments/rheometer.lua --out results/rheometer [--set speeds_rpm=5,10,20 ...]
--
-- 1. Fill the steel cup (100 mm inner diameter, 120 mm deep; geometry part "cup") with mud
--    spheres: poured (random loose in the cup and in a hopper on its rim; lib/pour.lua), let them
--    settle (kinetic-energy criterion), strike off above fill_level.
-- 2. Insert the vane (part "vane": 4 blades, 50 mm diameter, 60 mm high, blades from vane_bottom):
--    the particles overlapping a blade or the shaft are removed, the rest settles briefly.
-- 3. Turn the vane through the speed steps speeds_rpm, each step_time long; record the axial
--    torque every sample_interval. The steady torque of a step is the mean over its last
--    average_fraction (the resisting torque: −T·ẑ for a positive speed).
-- 4. Convert torque → shear stress with the vane relation T = (π D³/2)(H/D + 1/3) τ, speed →
--    shear rate with the Couette analogy γ̇ = 2Ω / (n (1 − κ^{2/n})), κ = D/D_cup, n the local
--    flow index d ln T / d ln Ω (paddy.measure vane_flow_curve, docs/measurement.md), and fit
--    Herschel–Bulkley τ = τ0 + K γ̇ⁿ.
-- 5. Optional measured_csv (columns speed_rpm,torque_Nm): relative error |T_meas − T_sim| / T_meas
--    per speed (simulated torque interpolated in ln Ω between the simulated speeds) and the mean.
local mud = require("lib.mud")
local pour = require("lib.pour")
local fill_structure = require("lib.fill_structure")
local util = require("lib.util")
local rheology = require("lib.rheology")
local measure = require("paddy.measure")

local P = mud.resolve(paddy.parameters(mud.parameters{
  {name = "particle_diameter", default = 0.008, unit = "m", min = 0.001, max = 0.02,
   description = "mean sphere diameter (reference 0.002; coarse grained above)"},
  {name = "size_spread", default = 0.0, min = 0, max = 0.3, description = "relative std of the diameters (0: monodisperse)"},
  {name = "seed", default = 0, type = "integer", min = 0, max = 2147483647, description = "fill seed (0: --seed)"},
  {name = "packing", default = "poured", choices = {"poured", "lattice"},
   description = "fill: poured (random loose spheres in the cup and a hopper on its rim, settled under gravity: amorphous; lib/pour.lua) or lattice (FCC lattice: settles into a crystal, not a mud)"},
  {name = "speeds_rpm", default = "5,10,20,40,80", description = "vane speed steps [rpm], increasing"},
  {name = "step_time", default = 0.5, unit = "s", min = 0.01, max = 100, description = "duration of each speed step"},
  {name = "average_fraction", default = 0.5, min = 0.05, max = 1, description = "steady torque: mean over this last fraction of a step"},
  {name = "sample_interval", default = 0.005, unit = "s", min = 1e-5, max = 1, description = "torque sampling interval"},
  {name = "fill_level", default = 0.12, unit = "m", min = 0.01, max = 1, description = "mud level in the cup"},
  {name = "cup_diameter", default = 0.1, unit = "m", min = 0.01, max = 1, description = "cup inner diameter"},
  {name = "cup_height", default = 0.12, unit = "m", min = 0.01, max = 1, description = "cup inner depth"},
  {name = "vane_diameter", default = 0.05, unit = "m", min = 0.005, max = 1, description = "vane diameter (blade tips)"},
  {name = "vane_height", default = 0.06, unit = "m", min = 0.005, max = 1, description = "blade height"},
  {name = "vane_bottom", default = 0.03, unit = "m", min = 0, max = 1, description = "height of the blades' lower edge above the cup bottom"},
  {name = "timestep_fraction", default = 0.1, min = 0.01, max = 0.5, description = "set by contact_conventions / material unless given (paddy 0.1, edem 0.2; paddy_calibrated: 0.0804 as calibrated); time step / Rayleigh time at the reference damping (the slump test is converged at 0.1, not at 0.2); shortened for restitutions below 0.13 (docs/physics.md)"},
  {name = "timestep_damping", default = true, description = "set by contact_conventions / material unless given; shorten the step for restitutions below 0.13 (false: timestep_fraction as given, e.g. one step for a whole calibration)"},
  {name = "settle_max_time", default = 1.0, unit = "s", min = 0, max = 20, description = "longest settling before the vane goes in (a poured fill needs at least its fall time plus min_rest_time)"},
  {name = "rest_speed", default = 0.005, unit = "m/s", min = 1e-6, max = 1, description = "at rest: RMS speed sqrt(2 KE / M) below this"},
  {name = "min_rest_time", default = 0.15, unit = "s", min = 0, max = 10, description = "shortest settling"},
  {name = "insert_time", default = 0.05, unit = "s", min = 0, max = 5, description = "settling after the vane is inserted"},
  {name = "measured_csv", default = "", description = "measured torque CSV (speed_rpm,torque_Nm) for relative errors ('' = none)"},
  {name = "snapshot_interval", default = 0.25, unit = "s", min = 0, max = 10, description = "snapshots for ParaView (0: none)"},
  {name = "pictures", default = true, description = "draw PNG pictures with gnuplot"},
  {name = "progress", default = true, description = "progress line on stderr"},
}))

local wall_start = os.time()
local d = P.particle_diameter
local speeds = util.numbers(P.speeds_rpm, "speeds_rpm")
for k = 2, #speeds do
  if not (speeds[k] > speeds[k - 1]) then error("speeds_rpm must be increasing: " .. P.speeds_rpm) end
end
if speeds[1] <= 0 then error("speeds_rpm must be positive") end
local seed = P.seed > 0 and P.seed or paddy.seed
local R_cup, R_vane = P.cup_diameter / 2, P.vane_diameter / 2
local z_vane = P.vane_bottom
if z_vane + P.vane_height > P.fill_level then error("the vane's blades must be below fill_level") end

local cg = mud.coarse_grain(P, d)
local sim = paddy.simulation{gravity = {0, 0, -9.81}, threads = paddy.threads}
local m_mud, m_steel = mud.setup(sim, P, cg.params)
sim:add_mesh_wall{name = "cup", material = m_steel, part = "cup",
                  params = {diameter = P.cup_diameter, height = P.cup_height}, motion = {type = "fixed"}}

-- 1. Fill, settle, strike off.
-- poured: random loose spheres in the cup and a hopper on its rim (lib/pour.lua); lattice: FCC
-- lattice up to 1.1 fill_level. Both are struck off at fill_level after settling.
if P.fill_level > P.cup_height then
  error(string.format("fill_level = %g m is above the cup: allowed fill_level <= cup_height = %g m", P.fill_level, P.cup_height))
end
local filled, poured
if P.packing == "poured" then
  poured = pour.fill(sim, {
    region = {type = "cylinder", base = {0, 0, 0}, radius = R_cup, height = P.cup_height},
    rim_radius = R_cup, radius = mud.radius(d, P.size_spread), material = m_mud, seed = seed, wall_material = m_steel,
  })
  filled = poured.filled
  pour.check_settle_time("rheometer", poured, P.settle_max_time, P.min_rest_time)
else
  filled = sim:fill{
    region = {type = "cylinder", base = {0, 0, 0}, radius = R_cup, height = math.min(P.fill_level * 1.1, P.cup_height)},
    radius = mud.radius(d, P.size_spread), material = m_mud, seed = seed,
    packing = "lattice", spacing = 1.02, jitter = 0.5,
  }
end
local dt_fraction, dt_damping_factor = P.timestep_fraction, 1
if P.timestep_damping then dt_fraction, dt_damping_factor = mud.timestep_fraction(P, cg.params) end
local dt = sim:timestep{fraction = dt_fraction}
local snapshot_every = P.snapshot_interval > 0 and P.snapshot_interval or nil
io.stderr:write(string.format("rheometer: %d particles of %.1f mm (alpha = %.2f), dt = %.3g s\n", filled, d * 1000, cg.alpha, dt))
local t0 = sim:time()
sim:run{duration = P.settle_max_time, every = 0.02, snapshot_every = snapshot_every, progress = P.progress,
        callback = function(s) return not (s:time() - t0 >= P.min_rest_time and util.rms_speed(s) < P.rest_speed) end}
local settle_time = sim:time() - t0
local struck = sim:remove_if(function(i, x, y, z, r) return z + r > P.fill_level end)
if poured then
  pour.check_full("rheometer", struck, P.fill_level)
  pour.remove_hopper(sim, poured)
end
local fill_solid, structure = fill_structure.measure_fill("rheometer", sim,
  {type = "cylinder", base = {0, 0, 0}, radius = R_cup, height = P.fill_level}, d)

-- 2. The vane: remove the particles overlapping its blades (slabs along 0°, 90°, ... from the
-- shaft to the tips) or its shaft, then add it.
local blades, blade_t, shaft_r = 4, 0.002, 0.004
local z_top = z_vane + P.vane_height
local function overlaps_vane(x, y, z, r)
  if z + r < z_vane then return false end
  if math.sqrt(x * x + y * y) < shaft_r + r then return true end  -- shaft (continues above the blades)
  if z - r > z_top then return false end
  for k = 0, blades - 1 do
    local phi = 2 * math.pi * k / blades
    local u = x * math.cos(phi) + y * math.sin(phi)
    local w = -x * math.sin(phi) + y * math.cos(phi)
    local du = math.max(0, -u, u - R_vane)
    local dw = math.max(0, math.abs(w) - blade_t / 2)
    local dz = math.max(0, z_vane - z, z - z_top)
    if du * du + dw * dw + dz * dz < r * r then return true end
  end
  return false
end
local removed = sim:remove_if(function(i, x, y, z, r) return overlaps_vane(x, y, z, r) end)
local particles = sim:count()

-- Speed schedule (absolute times): steps at t_start + k·step_time.
local t_start = sim:time() + P.insert_time
local schedule = {{t_start, 0}}
for k, rpm in ipairs(speeds) do
  local w = measure.rpm_to_rad(rpm)
  schedule[#schedule + 1] = {t_start + (k - 1) * P.step_time, w}
  schedule[#schedule + 1] = {t_start + k * P.step_time, w}
end
local vane = sim:add_mesh_wall{
  name = "vane", material = m_steel, part = "vane",
  params = {diameter = P.vane_diameter, height = P.vane_height, blade_thickness = blade_t, shaft_diameter = 2 * shaft_r},
  translate = {0, 0, z_vane},
  motion = {type = "rotate", point = {0, 0, z_vane}, axis = {0, 0, 1}, schedule = schedule},
}

-- 3. Run and sample the torque.
local samples = {}  -- {t, torque} with t from t_start, torque = resisting torque −T·ẑ
local total = P.insert_time + #speeds * P.step_time
sim:run{duration = total, every = P.sample_interval, snapshot_every = snapshot_every, progress = P.progress,
        callback = function(s)
          if s:time() >= t_start - 1e-12 then
            s:record_wall_loads(vane)
            samples[#samples + 1] = {t = s:time() - t_start, torque = -s:wall_axial_torque(vane)}
          end
          return true
        end}
sim:write_wall_loads(vane, "vane_loads.csv")

-- Steady torque per step.
local steps = {}
local omegas, torques = {}, {}
for k, rpm in ipairs(speeds) do
  local a, b = (k - P.average_fraction) * P.step_time, k * P.step_time
  local values = {}
  for _, s in ipairs(samples) do
    if s.t >= a - 1e-9 and s.t <= b + 1e-9 then values[#values + 1] = s.torque end
  end
  local mean = util.mean(values)
  steps[k] = {speed_rpm = rpm, omega = measure.rpm_to_rad(rpm), torque_Nm = mean, torque_std = util.std(values),
              samples = #values}
  omegas[k], torques[k] = steps[k].omega, mean
end

-- 4. Flow curve and Herschel–Bulkley fit.
local vane_geometry = {diameter = P.vane_diameter, height = P.vane_height, cup_diameter = P.cup_diameter, sheared_ends = 2}
local ok, curve = pcall(measure.vane_flow_curve, {vane = vane_geometry, omega = omegas, torque = torques})
local fit, fit_error, fit_warning, rate_share = nil, nil, nil, nil
if ok then
  fit = curve.fit
  for k, s in ipairs(steps) do
    s.shear_stress_Pa = curve.shear_stress[k]
    s.shear_rate = curve.shear_rate[k]
    s.n_local = curve.n_local[k]
    s.hb_torque_Nm = measure.vane_torque_hb(vane_geometry, fit, s.omega)
  end
  -- A flow curve only if the torque rises and the rate carries a share of the stress
  -- (lib/rheology.lua).
  fit_warning, rate_share = rheology.flow_curve_warning(steps, fit)
  if fit_warning then
    io.stderr:write("warning: rheometer: ", fit_warning, "\n")
  end
else
  fit_error = tostring(curve)
  io.stderr:write("warning: rheometer: no flow curve: ", fit_error, "\n")
  for _, s in ipairs(steps) do s.shear_stress_Pa = measure.vane_shear_stress(vane_geometry, s.torque_Nm) end
end

-- 5. Measured torques.
local comparison
if P.measured_csv ~= "" then
  local rows = util.read_csv(P.measured_csv)
  local lw = {}
  for k, w in ipairs(omegas) do lw[k] = math.log(w) end
  local function simulated_at(rpm)  -- linear in ln Ω between the simulated speeds
    local x = math.log(measure.rpm_to_rad(rpm))
    for k = 1, #lw do
      if math.abs(x - lw[k]) < 1e-9 then return torques[k] end
      if k > 1 and x > lw[k - 1] and x < lw[k] then
        local f = (x - lw[k - 1]) / (lw[k] - lw[k - 1])
        return torques[k - 1] + f * (torques[k] - torques[k - 1])
      end
    end
    return nil
  end
  local meas, sims, points = {}, {}, {}
  for _, row in ipairs(rows) do
    if type(row.speed_rpm) ~= "number" or type(row.torque_Nm) ~= "number" then
      error(P.measured_csv .. ":" .. row._line .. ": needs numeric columns speed_rpm,torque_Nm")
    end
    local t = simulated_at(row.speed_rpm)
    if t then
      meas[#meas + 1], sims[#sims + 1] = row.torque_Nm, t
      points[#points + 1] = {speed_rpm = row.speed_rpm, measured_Nm = row.torque_Nm, simulated_Nm = t}
    else
      io.stderr:write(string.format("warning: rheometer: measured speed %g rpm is outside the simulated range, skipped\n", row.speed_rpm))
    end
  end
  if #meas > 0 then
    local e = measure.relative_errors(meas, sims)
    for k, p in ipairs(points) do p.relative_error = e.per_point[k] end
    comparison = {file = P.measured_csv, points = points, mean_relative_error = e.mean, max_relative_error = e.max}
  end
end

-- Pictures.
local pictures = {}
if P.pictures then
  local rows = {}
  for k, s in ipairs(samples) do rows[k] = {s.t, s.torque} end
  util.write_columns("torque.dat", "t_s torque_Nm (resisting torque on the vane)", rows)
  local st = {}
  for k, s in ipairs(steps) do st[k] = {(k - P.average_fraction) * P.step_time, k * P.step_time, s.torque_Nm, s.speed_rpm} end
  util.write_columns("torque_steps.dat", "t_from t_to steady_torque_Nm speed_rpm", st)
  pictures.torque = util.gnuplot("torque", string.format([[
set title 'Vane torque against time (speed steps %s rpm)'
set xlabel 't [s]'; set ylabel 'torque [N m]'; set grid; set key top left
plot '%s' using 1:2 with lines lc rgb '#8b5a2b' title 'torque', \
     '%s' using 1:3:($2-$1):(0) with vectors nohead lw 3 lc rgb 'blue' title 'steady torque (mean)']],
    P.speeds_rpm, util.out("torque.dat"), util.out("torque_steps.dat")))
  if fit then
    local fc = {}
    for k, s in ipairs(steps) do fc[k] = {s.shear_rate, s.shear_stress_Pa} end
    util.write_columns("flow_curve.dat", "shear_rate_1/s shear_stress_Pa", fc)
    pictures.flow_curve = util.gnuplot("flow_curve", string.format([[
set title sprintf('Flow curve: Herschel-Bulkley tau0 = %%.3g Pa, K = %%.3g Pa s^n, n = %%.3f', %g, %g, %g)
set xlabel 'shear rate [1/s]'; set ylabel 'shear stress [Pa]'; set grid; set key top left
set xrange [0:*]; set yrange [0:*]
plot '%s' using 1:2 with points pt 7 ps 1.2 title 'vane (simulated)', \
     %g + %g * x**%g with lines lw 2 title 'Herschel-Bulkley fit']],
      fit.tau0, fit.K, fit.n, util.out("flow_curve.dat"), fit.tau0, fit.K, fit.n))
  end
end

paddy.result{
  steps = steps,
  herschel_bulkley = fit,
  fit_error = fit_error,
  fit_warning = fit_warning,
  rate_dependent_share = rate_share,    -- K D_max^n / (tau0 + K D_max^n) of the fit (lib/rheology.lua)
  comparison = comparison,
  vane = {diameter = P.vane_diameter, height = P.vane_height, cup_diameter = P.cup_diameter, sheared_ends = 2,
          bottom = z_vane, torque_factor_m3 = measure.vane_torque_factor(vane_geometry)},
  particles = particles, filled = filled, struck_off = struck, removed_for_vane = removed, packing = P.packing,
  fill_solid_fraction = fill_solid,   -- sphere volume / cup volume below fill_level, before the vane goes in
  hopper_height_m = poured and poured.hopper_height or nil,
  fill_structure = structure,
  settle_time_s = settle_time, time_step = dt, time_step_fraction = dt_fraction, time_step_damping_factor = dt_damping_factor,
  simulated_time_s = sim:time(),
  wall_time_s = os.difftime(os.time(), wall_start),
  material = P.material_info,  -- conventions and material set used, with their source (lib/mud.lua)
  coarse_graining = {alpha = cg.alpha, reference_diameter = mud.reference_diameter, particle_diameter = d,
                     scaled_params = cg.params, changed = cg.changed, rows = cg.rows},
  pictures = pictures,
  torque_csv = util.out("vane_loads.csv"),
}

-- What the user sees on stdout at the end.
print("model       " .. mud.describe(P))
print("speed [rpm]   steady torque [N m]   shear stress [Pa]")
for _, st in ipairs(steps) do
  print(string.format("%11g   %8.4f +- %-8.4f   %10.1f", st.speed_rpm, st.torque_Nm, st.torque_std, st.shear_stress_Pa))
end
if fit then
  print(string.format("Herschel-Bulkley  tau0 = %.4g Pa, K = %.4g Pa s^n, n = %.3f, R^2 = %.3f%s", fit.tau0, fit.K, fit.n,
                      fit.r2, fit_warning and "  (see the warning above)" or ""))
end
if comparison then
  print(string.format("against %s: mean relative error %.1f %%, largest %.1f %%", comparison.file,
                      100 * comparison.mean_relative_error, 100 * comparison.max_relative_error))
end
util.print_outputs(pictures, {"torque", "flow_curve"})
