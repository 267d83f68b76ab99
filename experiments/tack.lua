-- Virtual plate tack (pull-off) test of the paddy mud. Documentation: docs/experiments.md, "Plate
-- tack test".
--
--   paddy run experiments/tack.lua --out results/tack [--set pull_speed=0.04 --set mud_steel_surface_energy=0.15 ...]
--
-- What it is. A flat steel probe is pressed onto the material, held, and pulled straight off at a
-- constant speed while the force on it is recorded against its displacement: the probe tack test
-- of adhesives (inverted-probe tack, ASTM D2979; the force-displacement curve and its area, the
-- tack energy: Zosel 1985, Colloid Polym. Sci. 263:541; practice: Duncan, Abbott & Roberts 1999,
-- NPL Measurement Good Practice Guide No. 26 "Adhesive Tack") and the normal-loading adhesion test
-- of soil on tool materials (Fountaine 1954, J. Soil Sci. 5:251: a plate pressed on wet soil and
-- pulled off normally; the adhesion is the tension of the water film times its area). Its point
-- here: once the plate has left the mud's surface, the force on it can only come from an
-- attraction acting across a gap (liquid bridges, up to their rupture distance), from mud held on
-- the plate (wall adhesion: the mud it carries weighs on it) or from a rate-dependent film
-- (lubrication; Stefan 1874, Sitzungsber. Akad. Wiss. Wien 69:713: the viscous pull
-- F = 3πμR⁴ḣ/(2h³) between separating discs grows with the pull speed). Mud-mud cohesion alone
-- holds nothing to a plate it does not stick to. docs/discovery.md: the slump and the vane could
-- not tell these effects apart; docs/experiments.md has what this test tells apart (measured).
--
-- Procedure.
-- 1. Fill the steel cup (cup_diameter × cup_depth; part "cup") with mud spheres poured and
--    settled as in the rheometer (lib/pour.lua: loose in the cup and a hopper on its rim, settled
--    to rest), strike off at the rim, rest for relax_time (the unloaded surface springs back).
-- 2. The plate: a steel disc of plate_diameter, axis on the cup's axis (the flat bottom of a
--    "cup" part with a rim of PLATE_RIM pointing up, away from the mud: the "plate" part is a
--    square). It starts approach_gap above the highest point of the mud under it, z_touch (the
--    highest sphere top under the disc, or where a sphere outside it meets its edge), and moves
--    down at press_speed until it is press_depth below z_touch.
-- 3. Held there for hold_time.
-- 4. Pulled straight up at pull_speed through pull_distance. Samples every sample_spacing of
--    travel: u = plate height − its height at the start of the pull, F = −F_z, the pull force (the
--    mud's vertical force on the plate, positive when the mud holds the plate down; the plate is
--    a kinematic wall, so its own weight never enters). At u = press_depth the plate is back at
--    the level it first touched.
--
-- Observables (lib/tack_observables.lua), F̄ = F averaged over `smoothing` of travel:
--   tack_peak_force_N     F_peak = max_u F̄(u)           (tack_peak_mm: the u where it is reached)
--   tack_work_J           W = ∫₀^{pull_distance} max(F, 0) du          (work of separation)
--   tack_range_mm         the largest u with F̄(u) > 0.1 F_peak; 0 when F_peak is below the weight
--                         of one mean sphere, tack_floor_N = ρ g π d³/6 (no tack); pull_distance
--                         when the weight of carried mud stays above 0.1 F_peak
--   tack_release_mm       the first u with F̄(u) ≥ 0: the mud has stopped pushing the plate
--   tack_detach_mm        the largest u with F̄(u) − F_final > 0.1 (F_peak − F_final): where the
--                         pull beyond the weight of the mud carried away ends (0 without tack)
--   tack_force_profile_N  mean F over each of profile_points equal bins of [0, pull_distance],
--                         at the bin centres tack_profile_mm
--   tack_tension_profile_N  the same of max(F, 0): the pull alone, without the release of the
--                         pre-load that dominates the first bins of the force profile
--   tack_final_force_N    the last bin's mean: the weight of carried mud plus any pull left
--   tack_mass_on_plate_g  Σ ρ π d_i³/6 over the spheres in the plate's footprint moving up faster
--                         than pull_speed / 2 at the end of the pull (carried by the plate)
--   tack_preload_N        mean push F_z over the last `smoothing` of the press (the pre-load)
--   tack_hold_end_N       mean push over the last fifth of the hold (after relaxation)
-- The mud: lib/mud.lua as in slump.lua and rheometer.lua (material, conventions, the candidate
-- effects, coarse graining of the contact parameters from 2 mm).
local mud = require("lib.mud")
local pour = require("lib.pour")
local fill_structure = require("lib.fill_structure")
local util = require("lib.util")
local sampler = require("lib.sampler")
local phase = require("lib.phase")
local chart = require("lib.chart")
local obs = require("lib.tack_observables")

local P = mud.resolve(paddy.parameters(mud.parameters{
  {name = "particle_diameter", default = 0.005, unit = "m", min = 0.001, max = 0.04,
   description = "mean sphere diameter (reference 0.002; coarse grained above)"},
  {name = "size_spread", default = 0.0, min = 0, max = 0.3, description = "relative std of the diameters (0: monodisperse)"},
  {name = "seed", default = 0, type = "integer", min = 0, max = 2147483647, description = "fill seed (0: --seed)"},
  {name = "cup_diameter", default = 0.08, unit = "m", min = 0.01, max = 1, description = "cup inner diameter"},
  {name = "cup_depth", default = 0.03, unit = "m", min = 0.005, max = 1, description = "cup inner depth = mud depth (struck off at the rim)"},
  {name = "plate_diameter", default = 0.05, unit = "m", min = 0.005, max = 1,
   description = "plate (disc) diameter; at most cup_diameter minus two sphere diameters"},
  {name = "approach_gap", default = 0.001, unit = "m", min = 0, max = 0.1, description = "the plate starts this far above the mud under it"},
  {name = "press_depth", default = 0.002, unit = "m", min = 0, max = 0.05,
   description = "the plate is pressed this far below the level where it first touches the mud (0.4 of the default sphere)"},
  {name = "press_speed", default = 0.01, unit = "m/s", min = 1e-4, max = 1, description = "speed of the approach and the press"},
  {name = "hold_time", default = 0.1, unit = "s", min = 0, max = 10, description = "the plate rests at the press depth this long"},
  {name = "pull_speed", default = 0.01, unit = "m/s", min = 1e-4, max = 1, description = "speed of the pull"},
  {name = "pull_distance", default = 0.012, unit = "m", min = 1e-4, max = 0.5, description = "travel of the pull (from the press depth)"},
  {name = "profile_points", default = 24, type = "integer", min = 1, max = 1000,
   description = "bins of tack_force_profile_N and tack_tension_profile_N over [0, pull_distance]"},
  {name = "smoothing", default = 0.0002, unit = "m", min = 0, max = 0.05,
   description = "window of travel of the moving average for the peak, the range and the pre-load (0: none)"},
  {name = "sample_spacing", default = 2e-5, unit = "m", min = 1e-7, max = 0.01,
   description = "force samples every this much plate travel (press and pull)"},
  {name = "timestep_fraction", default = 0.1, min = 0.01, max = 0.5, description = "set by contact_conventions / material unless given (paddy 0.1, edem 0.2; paddy_calibrated: 0.0804 as calibrated); time step / Rayleigh time at the reference damping; shortened for restitutions below 0.13 (docs/physics.md)"},
  {name = "timestep_damping", default = true, description = "set by contact_conventions / material unless given; shorten the step for restitutions below 0.13"},
  {name = "settle_max_time", default = 0.6, unit = "s", min = 0, max = 20, description = "longest settling of the poured fill (at least its fall time plus min_rest_time)"},
  pour.rest_of_parameter(),
  {name = "rest_speed", default = 0.005, unit = "m/s", min = 1e-6, max = 1, description = "settled: RMS speed sqrt(2 KE / M) of the spheres below the strike-off level below this, once the pour has landed (lib/pour.lua settled)"},
  {name = "min_rest_time", default = 0.15, unit = "s", min = 0, max = 10, description = "shortest settling"},
  {name = "relax_time", default = 0.05, unit = "s", min = 0, max = 5,
   description = "the mud rests this long after the strike-off before the plate is placed (the unloaded surface springs back ~0.1 mm)"},
  {name = "snapshot_interval", default = 0.1, unit = "s", min = 0, max = 10, description = "snapshots for ParaView (0: none)"},
  {name = "pictures", default = true, description = "draw PNG pictures with gnuplot"},
  {name = "progress", default = true, description = "progress line on stderr"},
}))

local PLATE_RIM = 1e-4   -- m: the disc's rim (the smallest "cup" height), pointing up
local RANGE_FRACTION = 0.1   -- tack_range_mm: where the smoothed force last exceeds this share of the peak
local G = 9.81

local wall_start = os.time()
local d = P.particle_diameter
local seed = P.seed > 0 and P.seed or paddy.seed
local R_cup, R_plate = P.cup_diameter / 2, P.plate_diameter / 2
if P.plate_diameter > P.cup_diameter - 2 * d then
  error(string.format("plate_diameter = %g m: the plate must clear the cup wall by a sphere on each side: allowed "
                      .. "plate_diameter <= cup_diameter - 2 particle_diameter = %g m", P.plate_diameter,
                      P.cup_diameter - 2 * d), 0)
end
if P.cup_depth < 3 * d then
  error(string.format("cup_depth = %g m: the mud must be at least three spheres deep: allowed cup_depth >= %g m "
                      .. "(or a smaller particle_diameter)", P.cup_depth, 3 * d), 0)
end
if P.pull_distance <= P.press_depth then
  error(string.format("pull_distance = %g m must exceed press_depth = %g m: the plate has to leave the surface", P.pull_distance,
                      P.press_depth), 0)
end
if P.pull_distance / P.profile_points < 2 * P.sample_spacing then
  error(string.format("profile_points = %d: each of its bins (pull_distance / profile_points = %g m) needs two samples at "
                      .. "least: allowed profile_points <= %d, or a smaller sample_spacing", P.profile_points,
                      P.pull_distance / P.profile_points, math.floor(P.pull_distance / (2 * P.sample_spacing))), 0)
end

local cg = mud.coarse_grain(P, d)
local sim = paddy.simulation{gravity = {0, 0, -G}, threads = paddy.threads}
local m_mud, m_steel = mud.setup(sim, P, cg.params)
sim:add_mesh_wall{name = "cup", material = m_steel, part = "cup",
                  params = {diameter = P.cup_diameter, height = P.cup_depth}, motion = {type = "fixed"}}

-- 1. Fill, settle, strike off at the rim (as the rheometer's cup).
local poured = pour.fill(sim, {
  region = {type = "cylinder", base = {0, 0, 0}, radius = R_cup, height = P.cup_depth},
  rim_radius = R_cup, radius = mud.radius(d, P.size_spread), material = m_mud, seed = seed, wall_material = m_steel,
})
pour.check_settle_time("tack", poured, P.settle_max_time, P.min_rest_time)
local dt_fraction, dt_damping_factor = P.timestep_fraction, 1
if P.timestep_damping then dt_fraction, dt_damping_factor = mud.timestep_fraction(P, cg.params) end
local dt = sim:timestep{fraction = dt_fraction}
local snapshot_every = P.snapshot_interval > 0 and P.snapshot_interval or nil
io.stderr:write(string.format("tack: %d particles of %.1f mm (alpha = %.2f), dt = %.3g s\n", poured.filled, d * 1000, cg.alpha, dt))
local settle, struck = pour.settle_and_strike(sim, {who = "tack", poured = poured, level = P.cup_depth,
  settle_max_time = P.settle_max_time, min_rest_time = P.min_rest_time, rest_speed = P.rest_speed, rest_of = P.settle_rest_of,
  snapshot_every = snapshot_every, progress = P.progress})
local fill_solid, structure = fill_structure.measure_fill("tack", sim,
  {type = "cylinder", base = {0, 0, 0}, radius = R_cup, height = P.cup_depth}, d)
local particles = sim:count()
if P.relax_time > 0 then phase.run(sim, {duration = P.relax_time, snapshot_every = snapshot_every, progress = P.progress}) end

-- 2. The plate. z_touch: the height at which a disc of R_plate on the axis first touches a sphere
-- coming down (its underside on a sphere top, or its edge on a sphere beside it).
local function touch_height()
  local xs, ys, zs = sim:xyz()
  local radii = sim:radii()
  local top = -math.huge
  for i = 1, #xs do
    local r, rho = radii[i], math.sqrt(xs[i] ^ 2 + ys[i] ^ 2)
    if rho <= R_plate then
      top = math.max(top, zs[i] + r)
    elseif rho < R_plate + r then
      top = math.max(top, zs[i] + math.sqrt(r * r - (rho - R_plate) ^ 2))
    end
  end
  return top
end
local z_touch = touch_height()
local z_start = z_touch + P.approach_gap
local plate = sim:add_mesh_wall{name = "plate", material = m_steel, part = "cup",
                                params = {diameter = P.plate_diameter, height = PLATE_RIM},
                                translate = {0, 0, z_start}, motion = {type = "fixed"}}
local function plate_z(s) return s:wall_pose(plate).origin[3] end
local t_test = sim:time()
local current_phase
local PHASE_CODE = {press = 1, hold = 2, pull = 3}
-- Every sample of the test: time, phase, plate height above z_touch, the mud's upward force.
local test_log = sampler.new{
  {"t", function(s) return s:time() - t_test end},
  {"phase", function() return PHASE_CODE[current_phase] end},
  {"height_mm", function(s) return (plate_z(s) - z_touch) * 1000 end},
  {"push_N", function(s) return s:wall_force(plate)[3] end},
}
local function run_phase(name, motion, duration, every, more)
  current_phase = name
  sim:set_motion(plate, motion)
  local samplers = {test_log}
  for _, smp in ipairs(more or {}) do samplers[#samplers + 1] = smp end
  return phase.run(sim, {duration = duration, every = every, sample = samplers, snapshot_every = snapshot_every,
                         progress = P.progress})
end

-- 2.–3. Approach and press, hold.
local press_travel = P.approach_gap + P.press_depth
io.stderr:write(string.format("tack: mud surface under the plate at %.2f mm; pressing %.2f mm at %g m/s\n", z_touch * 1000,
                              P.press_depth * 1000, P.press_speed))
if press_travel > 0 then
  run_phase("press", {type = "translate", velocity = {0, 0, -P.press_speed}}, press_travel / P.press_speed,
            P.sample_spacing / P.press_speed)
end
local press_end = #test_log.rows
if P.hold_time > 0 then run_phase("hold", {type = "fixed"}, P.hold_time, P.hold_time / 50) end
local hold_end = #test_log.rows

-- 4. Pull.
local z_pull = plate_z(sim)
local pull_log = sampler.new{
  {"u", function(s) return plate_z(s) - z_pull end},
  {"F", function(s) return -s:wall_force(plate)[3] end},
}
pull_log:record(sim)
io.stderr:write(string.format("tack: pulling %.1f mm at %g m/s\n", P.pull_distance * 1000, P.pull_speed))
run_phase("pull", {type = "translate", velocity = {0, 0, P.pull_speed}}, P.pull_distance / P.pull_speed,
          P.sample_spacing / P.pull_speed, {pull_log})
local carried = obs.carried(sim, {pull_speed = P.pull_speed, plate_radius = R_plate, density = P.mud_density})

-- Observables.
local u, F = pull_log:column("u"), pull_log:column("F")
local Fs = obs.smooth(u, F, P.smoothing)
local peak, peak_at = obs.peak(u, Fs)
local work = obs.work(u, F)
local release = obs.release(u, Fs)
local grid = obs.profile(u, F, P.pull_distance, P.profile_points)
local tension = {}
for k = 1, #F do tension[k] = math.max(F[k], 0) end
local tension_grid = obs.profile(u, tension, P.pull_distance, P.profile_points)
local final_force = grid.means[#grid.means]
-- A peak below the weight of one mean sphere is no tack (without any attraction the damping of the
-- unloading contacts alone pulls about 1e-5 N): its range and detachment are 0.
local tack_floor = P.mud_density * math.pi / 6 * d ^ 3 * G
local range = peak > tack_floor and obs.range(u, Fs, peak, RANGE_FRACTION) or 0
local detach = peak > tack_floor and obs.detach(u, Fs, peak, final_force, RANGE_FRACTION) or 0
local profile_mm = {}
for k, c in ipairs(grid.centres) do profile_mm[k] = c * 1000 end
-- Pre-load: the mean push over the last `smoothing` of the press; after the hold: its last fifth.
local function mean_push(first, last, keep)
  local sum, n = 0, 0
  for k = first, last do
    if keep(test_log.rows[k]) then sum, n = sum + test_log.rows[k].push_N, n + 1 end
  end
  return n > 0 and sum / n or nil
end
local preload, hold_force
if press_end > 0 then
  local h_end = test_log.rows[press_end].height_mm
  preload = mean_push(1, press_end, function(row) return row.height_mm <= h_end + P.smoothing * 1000 + 1e-9 end)
end
if hold_end > press_end then
  local t_end = test_log.rows[hold_end].t
  hold_force = mean_push(press_end + 1, hold_end, function(row) return row.t >= t_end - P.hold_time / 5 - 1e-12 end)
end

-- Outputs: the pull curve (CSV), the whole test (columns for the chart), pictures.
local curve_rows = {}
for k = 1, #u do curve_rows[k] = {u[k] * 1000, F[k], Fs[k]} end
local curve_csv = util.write_csv("tack_curve.csv", {"displacement_mm", "pull_force_N", "smoothed_pull_force_N"}, curve_rows)
local test_rows = {}
for k, row in ipairs(test_log.rows) do test_rows[k] = {row.t, row.phase, row.height_mm, row.push_N} end
local test_csv = util.write_csv("tack_test.csv", {"t_s", "phase", "plate_height_mm", "push_force_N"}, test_rows)
local pictures = {}
if P.pictures then
  local dat = util.write_columns("tack_curve.dat", "displacement_mm pull_force_N smoothed_pull_force_N", curve_rows)
  local bins = {}
  for k = 1, #profile_mm do bins[k] = {profile_mm[k], grid.means[k]} end
  -- The tension in view when there is a tack; the release of the pre-load then goes below the frame.
  local clipped = peak > tack_floor and -peak > F[1]
  local y_lo, y_hi = clipped and -peak or math.min(F[1], 0), peak > tack_floor and 1.4 * peak or 0.1 * math.max(-F[1], 1e-6)
  local settings = {clipped and "set key top right" or "set key bottom right", "set xzeroaxis lt -1",
                    string.format("set xrange [0:%g]", P.pull_distance * 1000), string.format("set yrange [%g:%g]", y_lo, y_hi)}
  local function vertical(x) return {{x, y_lo}, {x, y_hi}} end
  local series = {
    {file = dat, using = "1:2", with = "lines lc rgb '#c8a27a'",
     title = clipped and string.format("pull force (from %.3g N at u = 0, below the frame)", F[1]) or "pull force"},
    {file = dat, using = "1:3", with = "lines lw 2 lc rgb '#8b5a2b'", title = string.format("smoothed over %g mm", P.smoothing * 1000)},
    {rows = bins, using = "1:2", with = "points pt 7 ps 1.2 lc rgb 'blue'", title = "profile (bin means)"},
    {rows = {{peak_at * 1000, peak}}, using = "1:2", with = "points pt 6 ps 2 lc rgb 'red'", title = "peak"},
    {rows = vertical(P.press_depth * 1000), using = "1:2", with = "lines dt 3 lc rgb 'black'", title = "back at the first touch"},
  }
  if range > 0 then
    series[#series + 1] = {rows = vertical(range * 1000), using = "1:2", with = "lines dt 2 lc rgb 'gray'", title = "range"}
  end
  if detach > 0 then
    series[#series + 1] = {rows = vertical(detach * 1000), using = "1:2", with = "lines dt 4 lc rgb 'red'",
                           title = "detached (pull beyond the carried weight ends)"}
  end
  pictures.tack_curve = chart.plot("tack_curve", {
    title = string.format("Plate tack at %g m/s: peak %.4g N at %.2f mm, work %.3g mJ, range %.2f mm, %.2f g carried",
                          P.pull_speed, peak, peak_at * 1000, work * 1000, range * 1000, carried.mass_g),
    xlabel = "plate displacement u from the press depth [mm]", ylabel = "pull force of the mud on the plate [N]",
    settings = settings, series = series,
  })
  local test_dat = util.write_columns("tack_test.dat", "t_s phase plate_height_mm push_force_N", test_rows)
  pictures.tack_test = chart.plot("tack_test", {
    title = "Plate tack test: force and plate height against time (press, hold, pull)",
    xlabel = "t [s] from the start of the approach", ylabel = "upward force of the mud on the plate [N]",
    settings = {"set key top right", "set y2label 'plate height above first touch [mm]'", "set y2tics", "set ytics nomirror",
                "set xzeroaxis lt -1"},
    series = {
      {file = test_dat, using = "1:4", with = "lines lc rgb '#8b5a2b'", title = "force (push > 0, pull < 0)"},
      {file = test_dat, using = "1:3", with = "lines lw 2 lc rgb 'blue' axes x1y2", title = "plate height (right axis)"},
    },
  })
end

local reference_params = {}
for _, e in ipairs(mud.contact) do reference_params[e.name] = P[e.name] end
paddy.result{
  tack_peak_force_N = peak,               -- max of the smoothed pull force
  tack_peak_mm = peak_at * 1000,          -- displacement of the peak
  tack_work_J = work,                     -- ∫ max(F, 0) du over the pull
  tack_range_mm = range * 1000,           -- last displacement with smoothed F > 0.1 peak (0: peak below one sphere's weight)
  tack_release_mm = release and release * 1000 or nil,  -- first displacement with smoothed F >= 0
  tack_floor_N = tack_floor,              -- weight of one mean sphere
  tack_detach_mm = detach * 1000,         -- last displacement with smoothed F - final > 0.1 (peak - final)
  tack_force_profile_N = grid.means,      -- bin means of F at tack_profile_mm
  tack_tension_profile_N = tension_grid.means,  -- bin means of max(F, 0)
  tack_profile_mm = profile_mm,
  tack_final_force_N = final_force,       -- the last bin's mean
  tack_mass_on_plate_g = carried.mass_g,  -- mud moving up with the plate at the end of the pull
  tack_particles_on_plate = carried.count,
  tack_carried_weight_N = carried.mass_g / 1000 * G,
  tack_preload_N = preload,               -- push at the end of the press
  tack_hold_end_N = hold_force,           -- push at the end of the hold
  plate = {diameter = P.plate_diameter, area_m2 = math.pi * R_plate ^ 2, touch_height_mm = z_touch * 1000,
           start_height_mm = z_start * 1000, pull_start_height_mm = z_pull * 1000,
           press_depth_mm = (z_touch - z_pull) * 1000},
  test = {approach_gap = P.approach_gap, press_depth = P.press_depth, press_speed = P.press_speed, hold_time = P.hold_time,
          pull_speed = P.pull_speed, pull_distance = P.pull_distance, smoothing = P.smoothing,
          sample_spacing = P.sample_spacing, range_fraction = RANGE_FRACTION},
  pull_samples = #u,
  cup_diameter = P.cup_diameter, cup_depth = P.cup_depth, mud_density = P.mud_density,
  particles = particles, filled = poured.filled, struck_off = struck,
  fill_solid_fraction = fill_solid, hopper_height_m = poured.hopper_height, fill_structure = structure,
  settle_time_s = settle.duration, settle_stopped_by = settle.stopped_by, time_step = dt, time_step_fraction = dt_fraction,
  time_step_damping_factor = dt_damping_factor,
  simulated_time_s = sim:time(),
  wall_time_s = os.difftime(os.time(), wall_start),
  material = P.material_info,
  coarse_graining = {alpha = cg.alpha, reference_diameter = mud.reference_diameter, particle_diameter = d,
                     reference_params = reference_params, scaled_params = cg.params, changed = cg.changed, rows = cg.rows},
  pictures = pictures,
  curve_csv = curve_csv, test_csv = test_csv,
}

print("model       " .. mud.describe(P))
print(string.format("pre-load    %8.4f N  (press %.2f mm at %g m/s), %.4f N after the hold of %g s", preload or 0,
                    P.press_depth * 1000, P.press_speed, hold_force or 0, P.hold_time))
print(string.format("tack        peak %.4f N at %.2f mm, work %.4g mJ, range %.2f mm, detached at %.2f mm (pull %.1f mm at %g m/s)",
                    peak, peak_at * 1000, work * 1000, range * 1000, detach * 1000, P.pull_distance * 1000, P.pull_speed))
print(string.format("release     the push ends at %s", release and string.format("%.2f mm", release * 1000) or "no point (pushed to the end)"))
print(string.format("carried     %.2f g of mud (%d spheres, weight %.4f N); final force %.4f N", carried.mass_g, carried.count,
                    carried.mass_g / 1000 * G, final_force))
util.print_outputs(pictures, {"tack_curve", "tack_test"})
if snapshot_every then print("ParaView    " .. util.out("snapshots/particles.xmf")) end
