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
-- 3. Start-up test (startup_rpm > 0): from rest, turn at startup_rpm through startup_angle; the
--    peak of the smoothed torque gives the yield stress by the vane relation (Nguyen & Boger 1983;
--    measure.vane_startup). Then the speed steps speeds_rpm up (and down again, down_sweep), each
--    at constant speed until its torque is steady by the criterion of measure.steady_torque (batch
--    means over windows of window_angle, no significant trend, drift below drift_tolerance, at
--    least min_step_angle turned) or max_step_time has passed; step_time > 0 runs fixed steps
--    instead. Steady torque = mean of the compared windows; the torque is the resisting torque
--    −T·ẑ. Steps that did not become steady are reported so and left out of the fit.
-- 4. Convert torque → shear stress with the vane relation T = (π D³/2)(H/D + 1/3) τ, speed →
--    shear rate with the Couette analogy γ̇ = 2Ω / (n (1 − κ^{2/n})), κ = D/D_cup, n the local
--    flow index d ln T / d ln Ω (paddy.measure vane_flow_curve, docs/measurement.md), and fit
--    Herschel–Bulkley τ = τ0 + K γ̇ⁿ to the steady up-sweep steps.
-- 5. Optional measured_csv (columns speed_rpm,torque_Nm): relative error |T_meas − T_sim| / T_meas
--    per speed (simulated torque interpolated in ln Ω between the simulated speeds) and the mean.
local mud = require("lib.mud")
local pour = require("lib.pour")
local fill_structure = require("lib.fill_structure")
local util = require("lib.util")
local rheology = require("lib.rheology")
local sampler = require("lib.sampler")
local trigger = require("lib.trigger")
local phase = require("lib.phase")
local chart = require("lib.chart")
local measure = require("paddy.measure")
local vane_stress = require("lib.vane_stress")

local P = mud.resolve(paddy.parameters(mud.parameters{
  {name = "particle_diameter", default = 0.008, unit = "m", min = 0.001, max = 0.04,
   description = "mean sphere diameter (reference 0.002; coarse grained above); the gap between vane and cup must be at least one wide"},
  {name = "size_spread", default = 0.0, min = 0, max = 0.3, description = "relative std of the diameters (0: monodisperse)"},
  {name = "seed", default = 0, type = "integer", min = 0, max = 2147483647, description = "fill seed (0: --seed)"},
  {name = "packing", default = "poured", choices = {"poured", "lattice"},
   description = "fill: poured (random loose spheres in the cup and a hopper on its rim, settled under gravity: amorphous; lib/pour.lua) or lattice (FCC lattice: settles into a crystal, not a mud)"},
  {name = "speeds_rpm", default = "5,10,20,40,80", description = "vane speed steps [rpm], increasing"},
  {name = "down_sweep", default = true, description = "after the up-sweep, the same speeds down again (without the top one): hysteresis shows thixotropy"},
  {name = "step_time", default = 0.0, unit = "s", min = 0, max = 100, description = "0: each step runs until its torque is steady (criterion below) or max_step_time; > 0: every step this long (the criterion still says whether it became steady)"},
  {name = "max_step_time", default = 8.0, unit = "s", min = 0.01, max = 100, description = "longest step when step_time = 0"},
  {name = "min_step_angle", default = 60, unit = "deg", min = 0, max = 3600, description = "steady criterion: no step is steady before the vane turned this far in it"},
  {name = "window_angle", default = 10, unit = "deg", min = 0.1, max = 360, description = "steady criterion: torque means over windows of this rotation angle"},
  {name = "steady_windows", default = 6, type = "integer", min = 3, max = 100, description = "steady criterion: the last this many windows are compared; the steady torque is their mean"},
  {name = "trend_alpha", default = 0.05, min = 1e-6, max = 0.5, description = "steady criterion: level of the t test for a trend of the window means"},
  {name = "drift_tolerance", default = 0.05, min = 1e-4, max = 1, description = "steady criterion: largest fitted change over the compared windows, relative to their mean"},
  {name = "steady_confirm", default = false, description = "steady criterion: the stretch of steady_windows windows before the compared one must pass the criterion too, with a mean within 2 standard errors of it (a step cannot end in one chance quiet stretch of a stick-slip torque)"},
  {name = "fit_unsteady", default = false, description = "fit Herschel-Bulkley to the steps that did not become steady too (the fit then says so)"},
  {name = "startup_rpm", default = 5, unit = "rpm", min = 0, max = 100, description = "start-up (stress-growth) test before the sweep at this speed (0: none)"},
  {name = "startup_stress_every", default = 1, unit = "deg", min = 0, max = 360, description = "during the start-up, measure the stresses on the vane's sheared surface from the contact forces every this many degrees (lib/vane_stress.lua; 0: not)"},
  {name = "startup_angle", default = 90, unit = "deg", min = 1, max = 3600, description = "rotation of the start-up test"},
  {name = "sample_interval", default = 0.005, unit = "s", min = 1e-5, max = 1, description = "torque sampling interval (shorter at high speed: at least samples_per_window per window)"},
  {name = "samples_per_window", default = 10, type = "integer", min = 1, max = 1000, description = "torque samples per window at least"},
  {name = "fill_level", default = 0.12, unit = "m", min = 0.01, max = 1, description = "mud level in the cup"},
  {name = "cup_diameter", default = 0.1, unit = "m", min = 0.01, max = 1, description = "cup inner diameter"},
  {name = "cup_height", default = 0.12, unit = "m", min = 0.01, max = 1, description = "cup inner depth"},
  {name = "vane_diameter", default = 0.05, unit = "m", min = 0.005, max = 1, description = "vane diameter (blade tips)"},
  {name = "vane_height", default = 0.06, unit = "m", min = 0.005, max = 1, description = "blade height"},
  {name = "vane_bottom", default = 0.03, unit = "m", min = 0, max = 1, description = "height of the blades' lower edge above the cup bottom"},
  {name = "timestep_fraction", default = 0.1, min = 0.01, max = 0.5, description = "set by contact_conventions / material unless given (paddy 0.1, edem 0.2; paddy_calibrated: 0.0804 as calibrated); time step / Rayleigh time at the reference damping (the slump test is converged at 0.1, not at 0.2); shortened for restitutions below 0.13 (docs/physics.md)"},
  {name = "timestep_damping", default = true, description = "set by contact_conventions / material unless given; shorten the step for restitutions below 0.13 (false: timestep_fraction as given, e.g. one step for a whole calibration)"},
  {name = "settle_max_time", default = 1.0, unit = "s", min = 0, max = 20, description = "longest settling before the vane goes in (a poured fill needs at least its fall time plus min_rest_time)"},
  pour.rest_of_parameter(),
  {name = "rest_speed", default = 0.005, unit = "m/s", min = 1e-6, max = 1, description = "settled: RMS speed sqrt(2 KE / M) of the spheres below the strike-off level below this, once the pour has landed (lib/pour.lua settled)"},
  {name = "min_rest_time", default = 0.15, unit = "s", min = 0, max = 10, description = "shortest settling"},
  {name = "insert_time", default = 0.05, unit = "s", min = 0, max = 5, description = "settling after the vane is inserted"},
  {name = "fill_only", default = false, description = "stop once the vane is in: the fill and the stress state around the vane (fill_stress: lib/vane_stress.lua), no torque; the fill is the one a full run with the same parameters and seed starts from"},
  {name = "measured_csv", default = "", description = "measured torque CSV (speed_rpm,torque_Nm) for relative errors ('' = none)"},
  {name = "snapshot_interval", default = 0.25, unit = "s", min = 0, max = 10, description = "snapshots for ParaView (0: none)"},
  {name = "pictures", default = true, description = "draw PNG pictures with gnuplot"},
  {name = "progress", default = true, description = "progress line on stderr"},
}))

local wall_start = os.time()
local d = P.particle_diameter
local speeds = P.speeds_rpm:match("^%s*$") and {} or util.numbers(P.speeds_rpm, "speeds_rpm")  -- "": start-up only
for k = 2, #speeds do
  if not (speeds[k] > speeds[k - 1]) then error("speeds_rpm = " .. P.speeds_rpm .. ": the speeds must increase strictly") end
end
if #speeds > 0 and speeds[1] <= 0 then error(string.format("speeds_rpm = %s: every speed must be > 0 rpm", P.speeds_rpm)) end
if #speeds == 0 and P.startup_rpm == 0 and not P.fill_only then error("speeds_rpm is empty and startup_rpm = 0: nothing to measure (or fill_only = true)") end
local seed = P.seed > 0 and P.seed or paddy.seed
local R_cup, R_vane = P.cup_diameter / 2, P.vane_diameter / 2
local z_vane = P.vane_bottom
if z_vane + P.vane_height > P.fill_level then error("the vane's blades must be below fill_level") end
-- A sheared gap narrower than a sphere is no rheometer (the test runs use 20 mm spheres in the
-- standard cup's 25 mm gap; the benchmarks' scaled vane has a gap of 3 spheres and more).
if R_cup - R_vane < d then
  error(string.format("particle_diameter = %g m: the gap between vane and cup, (cup_diameter - vane_diameter)/2 = %g m, "
                      .. "must be at least one sphere wide: allowed particle_diameter <= %g m, or a larger cup_diameter", d, R_cup - R_vane,
                      R_cup - R_vane), 0)
end

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
local settle, struck = pour.settle_and_strike(sim, {who = "rheometer", poured = poured, level = P.fill_level,
  settle_max_time = P.settle_max_time, min_rest_time = P.min_rest_time, rest_speed = P.rest_speed, rest_of = P.settle_rest_of,
  snapshot_every = snapshot_every, progress = P.progress})
local settle_time = settle.duration
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

local vane = sim:add_mesh_wall{
  name = "vane", material = m_steel, part = "vane",
  params = {diameter = P.vane_diameter, height = P.vane_height, blade_thickness = blade_t, shaft_diameter = 2 * shaft_r},
  translate = {0, 0, z_vane},
  motion = {type = "rotate", point = {0, 0, z_vane}, axis = {0, 0, 1}, speed = 0},
}
local vane_geometry = {diameter = P.vane_diameter, height = P.vane_height, cup_diameter = P.cup_diameter, sheared_ends = 2}

-- 3. The vane at rest for insert_time, then the start-up test and the speed steps; each runs at a
-- constant speed (sim:set_motion) and samples the resisting torque −T·ẑ against the angle turned.
if P.insert_time > 0 then phase.run(sim, {duration = P.insert_time, snapshot_every = snapshot_every, progress = P.progress}) end
-- The stress state the vane starts in, from the contact forces (the overburden of its depth).
local vane_dims = {diameter = P.vane_diameter, height = P.vane_height, bottom = z_vane, shaft_radius = shaft_r,
                   cup_diameter = P.cup_diameter, sheared_ends = 2, wall = vane}
local STRESS_PEAK_WINDOW = 2  -- deg either side of the peak: the start-up's stresses there are averaged
local fill_stress = vane_stress.measure(sim, vane_dims)
-- What a run reports about its fill, with or without the torque measurements.
local fill_fields = {
  vane = {diameter = P.vane_diameter, height = P.vane_height, cup_diameter = P.cup_diameter, sheared_ends = 2,
          bottom = z_vane, torque_factor_m3 = measure.vane_torque_factor(vane_geometry)},
  fill_level = P.fill_level, cup_height = P.cup_height,
  mud_density = P.mud_density,        -- particle density; × fill_solid_fraction = bulk density of the fill
  particles = particles, filled = filled, struck_off = struck, removed_for_vane = removed, packing = P.packing,
  fill_solid_fraction = fill_solid,   -- sphere volume / cup volume below fill_level, before the vane goes in
  fill_stress = fill_stress,          -- around the vane as it starts (lib/vane_stress.lua)
  hopper_height_m = poured and poured.hopper_height or nil,
  fill_structure = structure,
  settle_time_s = settle_time, settle_stopped_by = settle.stopped_by, time_step = dt, time_step_fraction = dt_fraction, time_step_damping_factor = dt_damping_factor,
  material = P.material_info,  -- conventions and material set used, with their source (lib/mud.lua)
  coarse_graining = {alpha = cg.alpha, reference_diameter = mud.reference_diameter, particle_diameter = d,
                     scaled_params = cg.params, changed = cg.changed, rows = cg.rows},
}
-- The result: the fill's fields and `extra`.
local function result(extra)
  for k, v in pairs(extra) do fill_fields[k] = v end
  paddy.result(fill_fields)
end
if P.fill_only then
  result({simulated_time_s = sim:time(), wall_time_s = os.difftime(os.time(), wall_start)})
  print("model       " .. mud.describe(P))
  print(string.format("fill        %d spheres, solid fraction %.3f; around the vane: sigma_v %.1f Pa at mid-height, sigma_rr %.1f Pa "
                      .. "on the blade tips' cylinder (K = %.3f), sigma_zz %.1f / %.1f Pa at the top / bottom edge",
                      particles, fill_solid, fill_stress.sigma_v_Pa, fill_stress.sigma_rr_Pa, fill_stress.lateral_ratio or 0 / 0,
                      fill_stress.sigma_zz_top_Pa, fill_stress.sigma_zz_bottom_Pa))
  return
end
local t_start = sim:time()
local PHASE_CODE = {startup = 0, up = 1, down = 2}
local current_phase
local function resisting_torque(s) return -s:wall_axial_torque(vane) end
-- Every torque sample of the start-up and the steps against time from t_start (torque.dat).
local torque_log = sampler.new{
  {"t", function(s) return s:time() - t_start end},
  {"torque", resisting_torque},
  {"phase", function() return PHASE_CODE[current_phase] end},
}
local criterion = {window_angle = math.rad(P.window_angle), windows = P.steady_windows, min_angle = math.rad(P.min_step_angle),
                   alpha = P.trend_alpha, drift_tolerance = P.drift_tolerance}

-- Turns the vane at `rpm` for `duration`, sampling the angle [rad from the phase start] and the
-- torque every `every` seconds (stop_when(step sampler) → a trigger that ends it early; on_sample(s,
-- angle) → called at every sample); returns the angles, torques, start and end time.
local function turn(rpm, duration, every, phase_name, stop_when, on_sample)
  sim:set_motion(vane, {type = "rotate", point = {0, 0, z_vane}, axis = {0, 0, 1}, speed = measure.rpm_to_rad(rpm)})
  local a0 = sim:wall_pose(vane).angle
  local step = sampler.new{{"angle", function(s) return s:wall_pose(vane).angle - a0 end}, {"torque", resisting_torque}}
  current_phase = phase_name
  local run = phase.run(sim, {duration = duration, every = every, snapshot_every = snapshot_every, progress = P.progress,
                              before = function(s)
                                s:record_wall_loads(vane)
                                if on_sample then on_sample(s, s:wall_pose(vane).angle - a0) end
                              end, sample = {step, torque_log},
                              stop = stop_when and stop_when(step)})
  return step:column("angle"), step:column("torque"), run.t0 - t_start, run.t1 - t_start
end

-- 3a. Start-up (stress growth) at startup_rpm from rest: peak torque → yield stress (Nguyen & Boger).
local startup
if P.startup_rpm > 0 then
  local w = measure.rpm_to_rad(P.startup_rpm)
  local angle_max = math.rad(P.startup_angle)
  -- The stresses on the sheared surface every startup_stress_every degrees (side: σ_rr and the
  -- resisting shear −τ_rθ on the blade tips' cylinder; σ_n as lib/vane_stress.lua weights it).
  local stress_rows, next_deg = {}, 0
  local function on_sample(s, angle)
    if math.deg(angle) + 1e-9 < next_deg then return end
    local st = vane_stress.measure(s, vane_dims)
    stress_rows[#stress_rows + 1] = {math.deg(angle), st.sigma_rr_Pa, -st.shear_rtheta_Pa, st.sigma_zz_top_Pa, st.sigma_zz_bottom_Pa,
                                     st.sheared_normal_Pa}
    next_deg = next_deg + P.startup_stress_every
  end
  local angles, torques = turn(P.startup_rpm, angle_max / w, math.min(P.sample_interval, math.rad(0.25) / w), "startup", nil,
                               P.startup_stress_every > 0 and on_sample or nil)
  local su = measure.vane_startup{vane = vane_geometry, angle = angles, torque = torques}
  startup = {speed_rpm = P.startup_rpm, angle_deg = math.deg(angles[#angles]), peak_torque_Nm = su.peak_torque,
             peak_angle_deg = math.deg(su.peak_angle), peak_reached = su.peak_reached, final_torque_Nm = su.final_torque,
             yield_stress_Pa = su.yield_stress, samples = #angles}
  if #stress_rows > 0 then
    util.write_columns("startup_stress.dat", "angle_deg sigma_rr_Pa shear_side_Pa sigma_zz_top_Pa sigma_zz_bottom_Pa sigma_n_Pa", stress_rows)
    startup.stress_at_peak = vane_stress.at_peak(stress_rows, startup.peak_angle_deg, STRESS_PEAK_WINDOW, vane_dims, su.peak_torque)
  end
  local rows = {}
  for k = 1, #angles do rows[k] = {math.deg(angles[k]), torques[k], su.smoothed[k]} end
  util.write_columns("startup.dat", "angle_deg torque_Nm smoothed_torque_Nm (start-up at " .. P.startup_rpm .. " rpm)", rows)
  if not su.peak_reached then
    io.stderr:write(string.format("warning: rheometer: the start-up torque was still rising at %g deg: the peak %.4g N m "
                                  .. "is a lower bound (raise startup_angle)\n", P.startup_angle, su.peak_torque))
  end
end

-- 3b. Speed steps: each until steady (or max_step_time), or step_time long.
local window = math.rad(P.window_angle)
local function steady_torque(angles, torques)
  local c = {angle = angles, torque = torques}
  for k, v in pairs(criterion) do c[k] = v end
  return measure.steady_torque(c)
end
-- steady_confirm: the criterion on the steady_windows windows before the compared ones (the
-- samples up to their end), and whether its mean agrees with the compared windows' within two
-- combined standard errors. A step that ended in the first quiet stretch of a fluctuating torque
-- fails it. → confirmed, reason (nil when confirmed).
local function confirm(angles, torques, v)
  local cut = (math.floor(angles[#angles] / window) - P.steady_windows) * window
  local a, t = {}, {}
  for k = 1, #angles do
    if angles[k] <= cut + 1e-12 then a[#a + 1], t[#t + 1] = angles[k], torques[k] end
  end
  if #a < 2 then return false, "no stretch before the compared windows to confirm them" end
  local u = steady_torque(a, t)
  if not u.steady then return false, "the stretch before the compared windows is not steady (" .. u.reason .. ")" end
  local tol = 2 * math.sqrt(u.standard_error ^ 2 + v.standard_error ^ 2)
  if math.abs(u.mean - v.mean) > tol then
    return false, string.format("the stretch before has mean %.4g N m, the compared windows %.4g (more than 2 standard errors apart)", u.mean, v.mean)
  end
  return true, nil
end
-- The criterion on a step's samples, with the confirmation when asked for.
local function judged(angles, torques)
  local v = steady_torque(angles, torques)
  if v.steady and P.steady_confirm then
    local ok, why = confirm(angles, torques, v)
    if not ok then v.steady, v.reason = false, why end
    v.confirmed = ok
  end
  return v
end
-- step_time = 0: the step ends when its torque is steady, judged at each completed window.
local function steady_step(step)
  local function angle() return step:last().angle end
  return trigger.all{
    trigger.periodic(angle, window),
    trigger.named("steady", function()
      local a = angle()
      if math.floor(a / window) < P.steady_windows or a < criterion.min_angle then return false end
      return judged(step:column("angle"), step:column("torque")).steady
    end),
  }
end
local function speed_step(rpm, phase_name)
  local w = measure.rpm_to_rad(rpm)
  local every = math.min(P.sample_interval, window / w / P.samples_per_window)
  local angles, torques, t0, t1 = turn(rpm, P.step_time > 0 and P.step_time or P.max_step_time, every, phase_name,
                                       P.step_time == 0 and steady_step or nil)
  local v = judged(angles, torques)
  if not v.steady then
    io.stderr:write(string.format("warning: rheometer: %s %g rpm not steady after %.3g s (%.0f deg): %s\n", phase_name, rpm,
                                  t1 - t0, math.deg(v.angle), v.reason))
  end
  return {speed_rpm = rpm, omega = w, steady = v.steady, confirmed = v.confirmed, not_steady_because = v.steady and nil or v.reason,
          torque_Nm = v.mean, torque_se = v.standard_error, trend_Nm_per_rev = v.trend * 2 * math.pi,
          trend_se_Nm_per_rev = v.trend_standard_error * 2 * math.pi, trend_p = v.trend_p_value, drift = v.drift,
          windows = v.compared_windows, angle_deg = math.deg(v.angle), duration_s = t1 - t0, t_from = t1 - v.compared_windows * window / w,
          t_to = t1, samples = #angles, window_means_Nm = v.window_means}
end
local steps = {}
for k, rpm in ipairs(speeds) do steps[k] = speed_step(rpm, "up") end
local down = {}
if P.down_sweep then
  for k = #speeds - 1, 1, -1 do down[#down + 1] = speed_step(speeds[k], "down") end
end
sim:write_wall_loads(vane, "vane_loads.csv")

-- 4. Flow curve and Herschel–Bulkley fit of the up-sweep's steady steps (or all: fit_unsteady).
local omegas, torques, fitted = {}, {}, {}
for k, s in ipairs(steps) do
  s.shear_stress_Pa = measure.vane_shear_stress(vane_geometry, s.torque_Nm)
  if s.steady or P.fit_unsteady then
    omegas[#omegas + 1], torques[#torques + 1], fitted[#fitted + 1] = s.omega, s.torque_Nm, k
  end
end
local unsteady_in_fit = 0
for _, k in ipairs(fitted) do if not steps[k].steady then unsteady_in_fit = unsteady_in_fit + 1 end end
local ok, curve = false, "no speed steps (speeds_rpm is empty)"
if #speeds > 0 then ok, curve = pcall(measure.vane_flow_curve, {vane = vane_geometry, omega = omegas, torque = torques}) end
local fit, fit_error, fit_warning, rate_share = nil, nil, nil, nil
if ok then
  fit = curve.fit
  fit.steps = #fitted
  fit.unsteady_steps = unsteady_in_fit
  local fsteps = {}
  for i, k in ipairs(fitted) do
    local s = steps[k]
    s.shear_stress_Pa = curve.shear_stress[i]
    s.shear_rate = curve.shear_rate[i]
    s.n_local = curve.n_local[i]
    s.hb_torque_Nm = measure.vane_torque_hb(vane_geometry, {tau0 = fit.tau0, K = fit.K, n = fit.n}, s.omega)
    fsteps[i] = s
  end
  -- A flow curve only if the torque rises and the rate carries a share of the stress
  -- (lib/rheology.lua).
  fit_warning, rate_share = rheology.flow_curve_warning(fsteps, fit)
  if unsteady_in_fit > 0 then
    fit_warning = string.format("%s%d of the %d fitted steps did not become steady", fit_warning and (fit_warning .. "; ") or "",
                                unsteady_in_fit, #fitted)
  end
  if fit_warning then
    io.stderr:write("warning: rheometer: ", fit_warning, "\n")
  end
else
  fit_error = string.format("%d of %d steps steady%s: %s", #fitted - unsteady_in_fit, #steps,
                            P.fit_unsteady and " (all fitted)" or "", tostring(curve))
  if #speeds > 0 then io.stderr:write("warning: rheometer: no flow curve: ", fit_error, "\n") end
end
for _, s in ipairs(down) do s.shear_stress_Pa = measure.vane_shear_stress(vane_geometry, s.torque_Nm) end
-- Hysteresis: up against down at each speed of both sweeps, (T_up − T_down) / T_up.
local hysteresis = {}
for _, d in ipairs(down) do
  for _, u in ipairs(steps) do
    if u.speed_rpm == d.speed_rpm then
      hysteresis[#hysteresis + 1] = {speed_rpm = d.speed_rpm, up_Nm = u.torque_Nm, down_Nm = d.torque_Nm,
                                     relative = (u.torque_Nm - d.torque_Nm) / u.torque_Nm, both_steady = u.steady and d.steady}
    end
  end
end
local function column(list, key)
  local out = {}
  for k, s in ipairs(list) do out[k] = s[key] end
  return out
end

-- 5. Measured torques.
local comparison
if P.measured_csv ~= "" then
  local rows = util.read_csv(P.measured_csv)
  local lw = {}
  local omegas, torques = column(steps, "omega"), column(steps, "torque_Nm")  -- every up step, steady or not
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
  local torque_dat = torque_log:write("torque.dat", "t_s torque_Nm phase (resisting torque on the vane; phase 0 start-up, 1 up, 2 down)",
                                      {"t", "torque", "phase"})
  local st = {}
  for _, list in ipairs({steps, down}) do
    for _, s in ipairs(list) do st[#st + 1] = {s.t_from, s.t_to, s.torque_Nm, s.speed_rpm, s.steady and 1 or 0} end
  end
  local steps_dat = util.write_columns("torque_steps.dat", "t_from t_to steady_torque_Nm speed_rpm steady", st)
  pictures.torque = chart.plot("torque", {
    title = string.format("Vane torque against time (speed steps %s rpm%s)", P.speeds_rpm, P.down_sweep and ", up and down" or ""),
    xlabel = "t [s]", ylabel = "torque [N m]", settings = {"set key top left"},
    series = {
      {file = torque_dat, using = "1:2", with = "lines lc rgb '#8b5a2b'", title = "torque"},
      {file = steps_dat, using = "1:($5 > 0 ? $3 : 1/0):($2-$1):(0)", with = "vectors nohead lw 3 lc rgb 'blue'",
       title = "steady torque (mean of the compared windows)"},
      {file = steps_dat, using = "1:($5 > 0 ? 1/0 : $3):($2-$1):(0)", with = "vectors nohead lw 3 lc rgb 'red'", title = "not steady"},
    },
  })
  if startup then
    local startup_dat = util.out("startup.dat")
    pictures.startup = chart.plot("startup", {
      title = string.format("Vane start-up at %g rpm: peak %.4g N m at %.1f deg, yield stress %.4g Pa", startup.speed_rpm,
                            startup.peak_torque_Nm, startup.peak_angle_deg, startup.yield_stress_Pa),
      xlabel = "rotation angle [deg]", ylabel = "torque [N m]", settings = {"set key bottom right"},
      series = {
        {file = startup_dat, using = "1:2", with = "lines lc rgb '#c8a27a'", title = "torque"},
        {file = startup_dat, using = "1:3", with = "lines lw 2 lc rgb '#8b5a2b'", title = "smoothed"},
        {rows = {{startup.peak_angle_deg, startup.peak_torque_Nm}}, using = "1:2", with = "points pt 7 ps 1.5 lc rgb 'blue'",
         title = "peak"},
      },
    })
  end
  if fit then
    local fc = {}
    for _, s in ipairs(steps) do if s.shear_rate then fc[#fc + 1] = {s.shear_rate, s.shear_stress_Pa} end end
    local curve_dat = util.write_columns("flow_curve.dat", "shear_rate_1/s shear_stress_Pa", fc)
    pictures.flow_curve = chart.plot("flow_curve", {
      title = string.format("Flow curve: Herschel-Bulkley tau0 = %.3g Pa, K = %.3g Pa s^n, n = %.3f", fit.tau0, fit.K, fit.n),
      xlabel = "shear rate [1/s]", ylabel = "shear stress [Pa]", settings = {"set key top left", "set xrange [0:*]; set yrange [0:*]"},
      series = {
        {file = curve_dat, using = "1:2", with = "points pt 7 ps 1.2", title = "vane (simulated)"},
        {expr = string.format("%g + %g * x**%g", fit.tau0, fit.K, fit.n), with = "lines lw 2", title = "Herschel-Bulkley fit"},
      },
    })
  end
end

result({
  -- Up-sweep, aligned with speeds_rpm: the steady torque (mean of the compared windows) and
  -- whether the step became steady; details per step in steps (down_sweep likewise).
  speeds_rpm = speeds,
  torque_Nm = column(steps, "torque_Nm"),
  steady = column(steps, "steady"),
  steps = steps,
  down_sweep = P.down_sweep and {speeds_rpm = column(down, "speed_rpm"), torque_Nm = column(down, "torque_Nm"),
                                 steady = column(down, "steady"), steps = down} or nil,
  hysteresis = P.down_sweep and hysteresis or nil,
  steady_criterion = {step_time = P.step_time, max_step_time = P.max_step_time, min_step_angle_deg = P.min_step_angle,
                      window_angle_deg = P.window_angle, windows = P.steady_windows, trend_alpha = P.trend_alpha,
                      drift_tolerance = P.drift_tolerance, confirm = P.steady_confirm},
  startup = startup,
  yield_stress_Pa = startup and startup.yield_stress_Pa or nil,  -- vane start-up peak (Nguyen & Boger 1983)
  herschel_bulkley = fit,
  fit_error = fit_error,
  fit_warning = fit_warning,
  rate_dependent_share = rate_share,    -- K D_max^n / (tau0 + K D_max^n) of the fit (lib/rheology.lua)
  comparison = comparison,
  simulated_time_s = sim:time(),
  wall_time_s = os.difftime(os.time(), wall_start),
  pictures = pictures,
  torque_csv = util.out("vane_loads.csv"),
})

-- What the user sees on stdout at the end.
print("model       " .. mud.describe(P))
local function print_steps(title, list)
  print(title)
  print("speed [rpm]   steady torque [N m]   shear stress [Pa]   steady   angle [deg]   time [s]")
  for _, st in ipairs(list) do
    print(string.format("%11g   %8.4f +- %-8.4f   %10.1f   %6s   %11.0f   %8.3f", st.speed_rpm, st.torque_Nm, st.torque_se,
                        st.shear_stress_Pa, st.steady and "yes" or "NO", st.angle_deg, st.duration_s))
  end
end
if #steps > 0 then print_steps("up-sweep", steps) end
if #down > 0 then print_steps("down-sweep", down) end
if startup then
  print(string.format("start-up at %g rpm: peak torque %.4f N m at %.1f deg%s -> yield stress %.4g Pa (vane relation)",
                      startup.speed_rpm, startup.peak_torque_Nm, startup.peak_angle_deg,
                      startup.peak_reached and "" or " (still rising: a lower bound)", startup.yield_stress_Pa))
end
if fit then
  print(string.format("Herschel-Bulkley  tau0 = %.4g Pa, K = %.4g Pa s^n, n = %.3f, R^2 = %.3f, from %d steady steps%s", fit.tau0,
                      fit.K, fit.n, fit.r2, fit.steps - fit.unsteady_steps, fit_warning and "  (see the warning above)" or ""))
else
  print("Herschel-Bulkley: no fit (" .. tostring(fit_error) .. ")")
end
if comparison then
  print(string.format("against %s: mean relative error %.1f %%, largest %.1f %%", comparison.file,
                      100 * comparison.mean_relative_error, 100 * comparison.max_relative_error))
end
util.print_outputs(pictures, {"torque", "startup", "flow_curve"})
