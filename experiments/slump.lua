-- Virtual slump test of the reference paddy mud (GB/T 50080-2016; shared/reference/README.md),
-- measured like the physical test. Documentation: docs/experiments.md.
--
--   paddy run experiments/slump.lua --out results/slump [--set particle_diameter=0.008 ...]
--
-- 1. Fill the steel cone (inner diameters 100/200 mm, 300 mm high) standing on a steel plate
--    with mud spheres (seeded; monodisperse or normal sizes), poured: placed at random, loose, in
--    the cone and in a hopper on its rim (lib/pour.lua); let them settle inside the fixed cone
--    until the fill below the rim is at rest (its kinetic energy, once the pour has landed:
--    lib/pour.lua settled); strike off the excess above the rim, as the standard prescribes.
-- 2. Lift the cone at lift_speed. The lift stops when the cone's bottom edge is `clearance`
--    above the highest particle under it (the cone is then free of the pile; lifting it further
--    would only cost time: 300 mm at 0.05 m/s = 6 s).
-- 3. Run until the pile is at rest (RMS speed from the kinetic energy below rest_speed, at least
--    min_rest_time after the lift) or max_time after the start of the lift. The run also ends,
--    before the lift has cleared the pile, once the pile has been at rest and the cone free of mud
--    (no load on it) over free_rest_window: from then on nothing can move the pile, and lifting
--    the cone further would only cost time (the cone stops there).
-- 4. Measure slump (300 mm − pile height at the axis), slump-flow (top-view image + circle fit,
--    and ruler diameters), the pile profile h(r) and the slump history s(t).
-- Coarse graining: spheres of particle_diameter d instead of the reference's 2 mm; the contact
-- parameters are scaled with α = d / 2 mm (paddy.coarse_grain: γ_JKR ∝ α, the others unchanged)
-- and both the reference and the scaled values go to result.json.
--
-- cone = "none" releases the cone-shaped column at once (no cone wall, no settling): the limit of
-- an infinitely fast lift, and a test of the measurements without mesh walls.
local mud = require("lib.mud")
local pour = require("lib.pour")
local fill_structure = require("lib.fill_structure")
local util = require("lib.util")
local observables = require("lib.slump_observables")
local reference = require("lib.reference_measurement")
local sampler = require("lib.sampler")
local trigger = require("lib.trigger")
local phase = require("lib.phase")
local chart = require("lib.chart")

local P = mud.resolve(paddy.parameters(mud.parameters{
  {name = "particle_diameter", default = 0.010, unit = "m", min = 0.001, max = 0.04,
   description = "mean sphere diameter (reference 0.002; coarse grained above)"},
  {name = "size_spread", default = 0.0, min = 0, max = 0.3, description = "relative std of the diameters, normal, truncated at 2 std (0: monodisperse)"},
  {name = "packing", default = "poured", choices = {"poured", "lattice", "random"},
   description = "fill: poured (random loose spheres in the cone and a hopper on its rim, settled under gravity: amorphous; lib/pour.lua), lattice (FCC lattice: settles into a crystal, not a mud), random (random loose, cone=none only)"},
  {name = "seed", default = 0, type = "integer", min = 0, max = 2147483647, description = "fill seed (0: --seed)"},
  {name = "lift_speed", default = 0.05, unit = "m/s", min = 0.001, max = 2, description = "cone lift speed"},
  {name = "cone", default = "mesh", choices = {"mesh", "none"}, description = "mesh: lift the steel cone; none: release the column at once"},
  {name = "cone_height", default = 0.3, unit = "m", min = 0.01, max = 1, description = "cone height (GB/T 50080: 0.3)"},
  {name = "cone_top_diameter", default = 0.1, unit = "m", min = 0.01, max = 1, description = "cone top inner diameter"},
  {name = "cone_bottom_diameter", default = 0.2, unit = "m", min = 0.01, max = 1, description = "cone bottom inner diameter"},
  {name = "overfill", default = 0.35, min = 0, max = 0.5, description = "packing=lattice: fill this fraction of the height above the rim, struck off after settling"},
  {name = "timestep_fraction", default = 0.1, min = 0.01, max = 0.5, description = "set by contact_conventions / material unless given (paddy 0.1, edem 0.2; paddy_calibrated: 0.0804 as calibrated); time step / Rayleigh time at the reference damping (converged at 0.1; 0.2 is stable but not converged with this JKR mud, 0.3 unstable); shortened for restitutions below 0.13 (docs/physics.md)"},
  {name = "timestep_damping", default = true, description = "set by contact_conventions / material unless given; shorten the step for restitutions below 0.13 (false: timestep_fraction as given, e.g. one step for a whole calibration)"},
  {name = "lift_rolling_integration", default = "same", choices = {"same", "implicit", "explicit"},
   description = "integration of the type A rolling torque from the strike-off on (same: as during the fill; implicit or explicit: switch the contact laws before the lift): separates the torque's effect on the fill from its effect on the collapse"},
  {name = "settle_max_time", default = 2.0, unit = "s", min = 0, max = 20, description = "longest settling inside the cone (a poured fill needs at least its fall time plus min_rest_time)"},
  pour.rest_of_parameter(),
  {name = "rest_speed", default = 0.01, unit = "m/s", min = 1e-6, max = 1, description = "at rest: RMS speed sqrt(2 KE / M) below this ..."},
  {name = "rest_window", default = 0.5, unit = "s", min = 0.01, max = 10, description = "... or the slump changed by less than slump_tolerance over this window"},
  {name = "slump_tolerance", default = 0.001, unit = "m", min = 0, max = 0.1, description = "see rest_window (0: KE criterion only)"},
  {name = "min_rest_time", default = 0.3, unit = "s", min = 0, max = 10, description = "shortest run after settling start / after the lift before 'at rest' counts"},
  {name = "clearance", default = 0.02, unit = "m", min = 0, max = 0.3, description = "the lift stops this far above the pile top"},
  {name = "free_rest_window", default = 0.1, unit = "s", min = 0, max = 10, description = "the run also ends once, over this window, the pile has been at rest (RMS speed below rest_speed at every history sample, slump steady within slump_tolerance) and no sphere has loaded the cone, even before the lift has cleared the pile; the cone stops there (0: only the rule after the lift stop; at least one history_interval)"},
  {name = "max_time", default = 5.0, unit = "s", min = 0.01, max = 60, description = "time limit from the start of the lift"},
  {name = "history_interval", default = 0.05, unit = "s", min = 0.001, max = 1, description = "slump history sampling"},
  {name = "load_interval", default = 0.005, unit = "s", min = 1e-5, max = 1, description = "sampling of the force on the cone during the lift (cone_force_N)"},
  {name = "snapshot_interval", default = 0.25, unit = "s", min = 0, max = 10, description = "snapshots for ParaView (0: none)"},
  {name = "pixel", default = 0.001, unit = "m", min = 1e-5, max = 0.01, description = "pixel of the top-view image"},
  {name = "pictures", default = true, description = "draw PNG pictures with gnuplot"},
  {name = "progress", default = true, description = "progress line on stderr"},
  {name = "neighbour_skin", default = 0.4, min = 0.05, max = 2,
   description = "neighbour-list skin as a fraction of the largest sphere radius: speed only (a larger skin rebuilds the list less often and tests more pairs each step; another skin changes the results in the last bit, like another seed)"},
}))

if P.free_rest_window > 0 and P.free_rest_window < P.history_interval then
  error(string.format("slump.lua: free_rest_window = %g s is shorter than history_interval = %g s: the window must "
                      .. "span two history samples at least; allowed: 0 (off) or >= %g s", P.free_rest_window,
                      P.history_interval, P.history_interval))
end

local wall_start = os.time()
local d = P.particle_diameter
local R_bottom, R_top, H = P.cone_bottom_diameter / 2, P.cone_top_diameter / 2, P.cone_height
local seed = P.seed > 0 and P.seed or paddy.seed

-- Coarse graining of the contact parameters from the reference 2 mm spheres.
local cg = mud.coarse_grain(P, d)

local sim = paddy.simulation{gravity = {0, 0, -9.81}, threads = paddy.threads, skin = P.neighbour_skin}
local m_mud, m_steel = mud.setup(sim, P, cg.params)
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = m_steel, name = "plate"}

local cone
if P.cone == "mesh" then
  if not sim.add_mesh_wall then
    error("slump.lua: this build has no mesh walls (sim:add_mesh_wall); run with --set cone=none")
  end
  cone = sim:add_mesh_wall{
    name = "cone", material = m_steel, part = "slump_cone",
    params = {top_diameter = P.cone_top_diameter, bottom_diameter = P.cone_bottom_diameter, height = H},
    motion = {type = "fixed"},
  }
end

-- Fill. poured: random loose spheres in the cone and in a hopper on its rim, settled (lib/pour.lua);
-- lattice: the cone's inside, extended by `overfill` above the rim with the same taper; both are
-- struck off at the rim after settling. cone = none: the cone-shaped column itself.
if P.packing == "poured" and not cone then
  error("packing = poured needs the cone (cone = mesh); with cone = none use packing = lattice or random")
end
local radius = mud.radius(d, P.size_spread)
local cone_region = {type = "cone", base = {0, 0, 0}, radius_bottom = R_bottom, radius_top = R_top, height = H}
local filled, solid_fraction, poured
if P.packing == "poured" then
  poured = pour.fill(sim, {
    region = cone_region, rim_radius = R_top, radius = radius, material = m_mud, seed = seed, wall_material = m_steel,
  })
  filled, solid_fraction = poured.filled, poured.loose_fraction
  pour.check_settle_time("slump", poured, P.settle_max_time, P.min_rest_time)
else
  local fill_h = cone and H * (1 + P.overfill) or H
  local fill = {
    region = {type = "cone", base = {0, 0, 0}, radius_bottom = R_bottom,
              radius_top = R_bottom + (R_top - R_bottom) * fill_h / H, height = fill_h},
    radius = radius, material = m_mud, seed = seed,
  }
  if P.packing == "lattice" then
    fill.packing, fill.spacing, fill.jitter = "lattice", 1.02, 0.5
  else
    fill.packing, fill.volume_fraction = "random", 0.5
  end
  filled, solid_fraction = sim:fill(fill)
end
local dt_fraction, dt_damping_factor = P.timestep_fraction, 1
if P.timestep_damping then dt_fraction, dt_damping_factor = mud.timestep_fraction(P, cg.params) end
local dt = sim:timestep{fraction = dt_fraction}
io.stderr:write(string.format("slump: %d particles of %.1f mm (alpha = %.2f), dt = %.3g s%s\n",
                              filled, d * 1000, cg.alpha, dt,
                              poured and string.format(", poured from %.2f m", poured.top_z) or ""))

local snapshot_every = P.snapshot_interval > 0 and P.snapshot_interval or nil
local measured = reference.slump()  -- the reference's 231 / 480 mm (experiments/calibration/paddy_mud.json)

-- Highest particle top (z + r) under the cone's bottom ring (those the rising cone could touch).
-- During the lift (lifting = true) spheres that move up with the cone (stuck to its inside:
-- lib/slump_observables.lua) do not count: the cone carries them, the pile is below.
local function top_under_cone(lifting)
  local xs, ys, zs = sim:xyz()
  local radii = sim:radii()
  local v = lifting and sim:velocities() or nil
  local top = 0
  for i = 1, #xs do
    local r = radii[i]
    if xs[i] ^ 2 + ys[i] ^ 2 < (R_bottom + r) ^ 2 and not (v and observables.moving_with_cone(v[i][3], P.lift_speed)) then
      top = math.max(top, zs[i] + r)
    end
  end
  return top
end
local function measure_slump()
  return sim:measure_slump{cone_height = H, axis = {0, 0}, base_z = 0}
end

-- 1. Settle inside the fixed cone until the fill below the rim is at rest (its kinetic energy once
-- the pour has landed, lib/pour.lua settled; or the top under the cone steady within
-- slump_tolerance over rest_window), then strike off at the rim.
local settle_time, settle_stop, struck = 0, nil, 0
if cone then
  local t_settle = sim:time()
  local tops = sampler.new{
    {"t", function(s) return s:time() - t_settle end},
    {"top", function() return top_under_cone() end},
  }
  local settle
  settle, struck = pour.settle_and_strike(sim, {
    who = "slump", poured = poured, level = H, settle_max_time = P.settle_max_time, min_rest_time = P.min_rest_time,
    rest_speed = P.rest_speed, rest_of = P.settle_rest_of, every = P.history_interval, sample = tops,
    also = {trigger.steady(tops, "top", P.rest_window, P.slump_tolerance)}, snapshot_every = snapshot_every,
    progress = P.progress,
  })
  settle_time, settle_stop = settle.duration, settle.stopped_by
end
if P.lift_rolling_integration ~= "same" then
  P.rolling_integration = P.lift_rolling_integration
  mud.set_interactions(sim, P, cg.params, m_mud, m_steel)
  P.material_info.lift_rolling = mud.rolling_model(P, mud.conventions[P.contact_conventions])
end
local particles = sim:count()
-- The fill as the lift starts: solid fraction in the cone (the bulk density of the simulated mud is
-- this times the particle density) and the structure of its core, a random packing or a crystal
-- (which no mud is; lib/fill_structure.lua).
local fill_solid, structure = fill_structure.measure_fill("slump", sim, cone_region, d)
local initial = measure_slump()

-- 2. Lift the cone at lift_speed until its bottom edge is `clearance` above the pile under it.
-- 3. Run until the pile is at rest (RMS speed below rest_speed, or the slump steady within
-- slump_tolerance over rest_window), at least min_rest_time after the lift stopped, or max_time.
local t_lift = sim:time()
local lift_stop  -- absolute time the lift stopped (cone = none: the release, at once)
local carried    -- mud moving up with the cone as the lift stops (or at the end, if it never stops)
local function cone_bottom(t) return P.lift_speed * ((lift_stop or t) - t_lift) end
local function measure_carried(cone_z)
  return observables.carried_by_cone(sim, {lift_speed = P.lift_speed, z_bottom = cone_z, radius_bottom = R_bottom,
                                           radius_top = R_top, height = H, density = P.mud_density})
end
if cone then
  sim:set_motion(cone, {type = "translate", velocity = {0, 0, P.lift_speed}, start = t_lift})
else
  lift_stop = t_lift
end
-- Slump history, sampled every history_interval; the spread as the final measurement reads it
-- (image + circle fit; milliseconds per sample).
local load_seen = 0  -- cone load samples already looked at by the history
local function cone_load_since_last()
  if not cone then return nil end
  return observables.largest_load(sim:wall_load_history(cone), load_seen, function(n) load_seen = n end)
end
local history = sampler.new{
  {"t", function(s) return s:time() - t_lift end},
  {"slump_mm", function() return measure_slump().slump * 1000 end},
  {"slump_flow_mm", function() return sim:measure_slump_flow{axis = {0, 0}, base_z = 0, pixel = P.pixel}.diameter_fit * 1000 end},
  {"rms_speed", function(s) return util.rms_speed(s) end},
  {"cone_bottom_mm", function(s) return cone and cone_bottom(s:time()) * 1000 or nil end},
  {"cone_load_N", cone_load_since_last},  -- largest |force| on the cone since the previous sample
}
local cone_cleared = trigger.named("cone_cleared", function(s)
  return cone_bottom(s:time()) > top_under_cone(true) + P.clearance
end)
local STOP_REASONS = {cone_cleared = "the cone is clearance above the pile",
                      at_rest_cone_free = "the pile at rest and the cone free of mud over free_rest_window"}
local function stop_lift(s, why)
  local t = s:time()
  carried = measure_carried(cone_bottom(t))
  sim:set_motion(cone, {type = "fixed"})
  lift_stop = t
  io.stderr:write(string.format("slump: lift stopped at t = %.2f s, cone bottom %.0f mm: %s\n", t - t_lift,
                                cone_bottom(t) * 1000, STOP_REASONS[why] or why))
end
local function since_lift_stop() return lift_stop end
local at_rest_after_lift = trigger.all{
  trigger.elapsed(P.min_rest_time, since_lift_stop),
  trigger.any{
    trigger.below(history, "rms_speed", P.rest_speed, "kinetic_energy"),
    trigger.all{trigger.elapsed(P.rest_window, since_lift_stop),  -- the operator would read the ruler now
                trigger.steady(history, "slump_mm", P.rest_window, P.slump_tolerance * 1000, "slump_steady")},
  },
}
-- At rest with the cone free (free_rest_window > 0, with a cone): over the window every sample's
-- RMS speed is below rest_speed and the cone carried no load, and the slump is steady.
local at_rest_cone_free = trigger.all{
  trigger.elapsed(P.min_rest_time),
  trigger.named("at_rest_cone_free", function()
    return observables.at_rest_cone_free(history.rows, P.free_rest_window, P.rest_speed, P.slump_tolerance * 1000)
  end),
}
history:record(sim)
local lift_and_rest = phase.run(sim, {
  duration = P.max_time, every = P.history_interval, snapshot_every = snapshot_every, progress = P.progress,
  record_loads_every = cone and P.load_interval or nil, record_loads = cone and {cone} or nil,
  sample = history,
  events = cone and {{when = cone_cleared, act = stop_lift}} or nil,
  stop = (cone and P.free_rest_window > 0) and trigger.any{at_rest_after_lift, at_rest_cone_free} or at_rest_after_lift,
})
local at_rest, rest_criterion = lift_and_rest.stopped_by ~= nil, lift_and_rest.stopped_by
local rest_time = at_rest and history:last().t or nil
if rest_criterion == "at_rest_cone_free" and not lift_stop then
  stop_lift(sim, rest_criterion)  -- nothing touches the cone: where it stops changes nothing
end
if cone and not carried then carried = measure_carried(P.lift_speed * (sim:time() - t_lift)) end
if not at_rest then
  io.stderr:write(string.format("warning: slump: the pile is not at rest after max_time = %g s (RMS speed %.3g m/s)%s\n",
                                P.max_time, util.rms_speed(sim),
                                (cone and not lift_stop) and "; the lift never stopped: a sphere under the cone kept "
                                .. "rising with it (wedged in the cone); see slump_history for whether the pile was steady" or ""))
end

-- 4. Measurements.
local final = measure_slump()
local flow = sim:measure_slump_flow{
  axis = {0, 0}, base_z = 0, pixel = P.pixel, ruler = "max_perpendicular",
  png = P.pictures and "slump_flow_top.png" or nil,
  title = "Slump test: top view of the final pile",
  pgm = "slump_flow_top.pgm",
}
local profile = sim:measure_profile{axis = {0, 0}, base_z = 0, largest_cluster = true}
-- Observables on fixed grids (the same in every run; lib/slump_observables.lua).
local profile_grid = observables.profile(sim)
local history_grid = observables.history_at(history.rows, observables.HISTORY_TIMES)
local cone_force = cone and observables.cone_force(sim:wall_load_history(cone), t_lift, lift_stop or sim:time())
                   or {mean = 0, peak = 0, samples = 0}
local profile_out = {}
for k, b in ipairs(profile) do
  profile_out[k] = {r_mm = b.r * 1000, h_mm = b.h * 1000, coverage = b.coverage, particles = b.particles}
end

-- Pictures: side view of the pile, slump history (the top view comes from measure).
local pictures = {top_view = flow.png, top_view_pgm = flow.pgm}
if P.pictures then
  local xs, _, zs = sim:xyz()
  local radii = sim:radii()
  local rows, prof = {}, {}
  for i = 1, #xs do rows[i] = {xs[i] * 1000, zs[i] * 1000, radii[i] * 1000} end
  for k, b in ipairs(profile) do prof[k] = {b.r * 1000, b.h * 1000} end
  local particles_dat = util.write_columns("side_view.dat", "x_mm z_mm r_mm (all particles, projected on x-z)", rows)
  local profile_dat = util.write_columns("profile.dat", "r_mm h_mm", prof)
  local half_width = math.max(300, flow.diameter_fit * 600)
  pictures.side_view = chart.plot("side_view", {
    title = string.format("Slump test: final pile, side view (slump %.0f mm, slump-flow %.0f mm)",
                          final.slump * 1000, flow.diameter_fit * 1000),
    xlabel = "x [mm]", ylabel = "z [mm]",
    settings = {"set size ratio -1", string.format("set xrange [-%g:%g]; set yrange [0:%g]", half_width, half_width, H * 1000 * 1.1)},
    series = {
      {file = particles_dat, using = "1:2:3", with = "circles fill solid 0.5 noborder lc rgb '#8b5a2b'", title = "particles"},
      {file = profile_dat, using = "1:2", with = "lines lw 2 lc rgb 'blue'", title = "profile h(r)"},
      {file = profile_dat, using = "(-$1):2", with = "lines lw 2 lc rgb 'blue'"},
      {rows = {{-R_bottom * 1000, 0}, {-R_top * 1000, H * 1000}, {R_top * 1000, H * 1000}, {R_bottom * 1000, 0}},
       using = "1:2", with = "lines dt 2 lc rgb 'black'", title = "cone (initial)"},
    },
  })
  local dat = history:write("slump_history.dat", "t_s slump_mm cone_bottom_mm slump_flow_mm",
                            {"t", "slump_mm", "cone_bottom_mm", "slump_flow_mm"}, 0)
  pictures.slump_history = chart.plot("slump_history", {
    title = "Slump and slump-flow against time (t = 0: start of the lift)", xlabel = "t [s]", ylabel = "[mm]",
    settings = {"set key outside right",
                lift_stop and string.format("set arrow from %g, graph 0 to %g, graph 1 nohead lc rgb 'gray'",
                                            lift_stop - t_lift, lift_stop - t_lift) or nil},
    series = {
      {file = dat, using = "1:2", with = "linespoints pt 7 ps 0.5 lc rgb '#1f77b4'", title = "slump"},
      {file = dat, using = "1:4", with = "linespoints pt 5 ps 0.4 lc rgb '#8b5a2b'", title = "slump-flow (circle fit)"},
      {file = dat, using = "1:3", with = "lines dt 2 lc rgb 'black'", title = "cone bottom above the plate"},
      {expr = string.format("%g", measured.slump_mm), with = "lines lc rgb '#1f77b4' dt 3",
       title = string.format("measured slump %g mm", measured.slump_mm)},
      {expr = string.format("%g", measured.slump_flow_mm), with = "lines lc rgb '#8b5a2b' dt 3",
       title = string.format("measured slump-flow %g mm", measured.slump_flow_mm)},
    },
  })
end

local reference_params = {}
for _, e in ipairs(mud.contact) do reference_params[e.name] = P[e.name] end
-- Yield stress the slump implies (Schowalter & Christensen 1998 cone model, docs/measurement.md);
-- bulk density = particle density × solid fraction in the cone. nil when the slump is outside (0, H).
local tau_ok, yield_stress = pcall(require("paddy.measure").slump_yield_stress, {slump = final.slump, density = P.mud_density * fill_solid,
  height = H, top_diameter = P.cone_top_diameter, bottom_diameter = P.cone_bottom_diameter})
paddy.result{
  slump_mm = final.slump * 1000,
  yield_stress_Pa = tau_ok and yield_stress or nil,
  slump_flow_mm = flow.diameter_fit * 1000,          -- image + circle fit (as the reference study)
  slump_flow_ruler_mm = flow.ruler.mean * 1000,      -- two perpendicular diameters (GB/T 50080)
  slump_flow_ruler = {d1_mm = flow.ruler.d1 * 1000, d2_mm = flow.ruler.d2 * 1000, angle_deg = math.deg(flow.ruler.angle)},
  slump_flow_area_mm = flow.diameter_area * 1000,    -- area-equivalent diameter
  slump_flow_circle = {x_mm = flow.circle.x * 1000, y_mm = flow.circle.y * 1000, rms_mm = flow.circle.rms * 1000},
  pile_height_mm = final.pile_height * 1000,
  pile_particles = final.cluster, loose_particles = final.ignored,
  initial_slump_mm = initial.slump * 1000,
  profile = profile_out,
  history = history.rows,
  profile_mm = profile_grid.h_mm,                  -- h(r) at profile_radii_mm (fixed grid)
  profile_mean_mm = profile_grid.h_mean_mm,        -- ring-mean height at profile_radii_mm (continuous at the edge)
  profile_radii_mm = profile_grid.radii_mm,
  history_mm = history_grid,                       -- slump at history_times_s after the lift starts
  history_times_s = observables.HISTORY_TIMES,
  cone_force_N = {mean = cone_force.mean, peak = cone_force.peak, samples = cone_force.samples},  -- downward, during the lift
  mass_on_cone_g = carried and carried.mass_g or 0,  -- mud moving up with the cone as the lift stops
  particles_on_cone = carried and carried.count or 0,
  measured = {slump_mm = measured.slump_mm, slump_flow_mm = measured.slump_flow_mm},
  at_rest = at_rest,
  rest_time_s = rest_time,
  rest_criterion = rest_criterion,
  lift_stop_s = lift_stop and lift_stop - t_lift or nil,
  cone_lift_mm = cone and P.lift_speed * ((lift_stop or sim:time()) - t_lift) * 1000 or 0,
  settle_time_s = settle_time,
  settle_stopped_by = settle_stop,  -- fill_kinetic_energy, top_steady, kinetic_energy (settle_rest_of = all) or settle_max_time
  particles = particles, filled = filled, struck_off = struck, packing = P.packing,
  fill_solid_fraction = fill_solid,          -- in the cone as the lift starts
  fill_initial_solid_fraction = solid_fraction,  -- as placed (poured: the loose spheres in the cone)
  hopper_height_m = poured and poured.hopper_height or nil,
  fill_structure = structure,  -- core solid fraction, neighbours, g(sqrt2 d), crystalline (lib/fill_structure.lua)
  time_step = dt, time_step_fraction = dt_fraction, time_step_damping_factor = dt_damping_factor,
  simulated_time_s = sim:time(),
  wall_time_s = os.difftime(os.time(), wall_start),
  material = P.material_info,  -- conventions and material set used, with their source (lib/mud.lua)
  coarse_graining = {alpha = cg.alpha, reference_diameter = mud.reference_diameter, particle_diameter = d,
                     reference_params = reference_params, scaled_params = cg.params, changed = cg.changed,
                     rows = cg.rows, reference_particle_estimate = particles * cg.alpha ^ 3},
  pictures = pictures,
}

-- What the user sees on stdout at the end: both responses against the measurement, and where the
-- results and pictures are.
local function versus(v, m) return string.format("measured %g mm, %+.1f %%", m, 100 * (v - m) / m) end
print("model       " .. mud.describe(P))
print(string.format("slump       %6.1f mm   (%s)", final.slump * 1000, versus(final.slump * 1000, measured.slump_mm)))
print(string.format("slump-flow  %6.1f mm   circle fit; ruler %.1f mm   (%s)", flow.diameter_fit * 1000,
                    flow.ruler.mean * 1000, versus(flow.diameter_fit * 1000, measured.slump_flow_mm)))
if not at_rest then print("            (the pile was not at rest at max_time: see the warning above)") end
util.print_outputs(pictures, {"side_view", "top_view", "slump_history"})
if snapshot_every then print("ParaView    " .. util.out("snapshots/particles.xmf")) end
