-- Test of the measurement bindings (engine/lua/src/lua_measure.cpp) on particle sets with known
-- answers; every check raises an error naming what failed (run by run_case.cmake, exit code 0 = pass).
local measure = require("paddy.measure")

local function near(what, got, want, tol)
  if not (math.abs(got - want) <= tol) then
    error(string.format("%s = %.6g, expected %.6g ± %.3g", what, got, want, tol), 2)
  end
end
local function check(what, cond) if not cond then error(what, 2) end end

local sim = paddy.simulation{threads = 1}
local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
local s = sim:material{name = "steel", density = 7800, shear_modulus = 7e9, poisson = 0.3}
sim:interaction(m, m, {restitution = 0.5, friction = 0.3})
sim:interaction(m, s, {restitution = 0.5, friction = 0.3})

-- A lattice cone of 2 mm spheres, 40 mm high, bottom radius 30 mm, top radius 10 mm.
local r = 0.001
sim:fill{region = {type = "cone", radius_bottom = 0.03, radius_top = 0.01, height = 0.04},
         radius = r, material = m, packing = "lattice"}
local n = sim:count()
check("cone filled", n > 500)
-- A far-away particle of another material: ignored with material = "mud".
sim:add_particle{pos = {0.5, 0.5, 0.2}, radius = r, material = s}

local sl = sim:measure_slump{cone_height = 0.05, material = "mud"}
near("pile height", sl.pile_height, 0.04, 2 * r)       -- the apex within one lattice step
near("slump", sl.slump, 0.05 - sl.pile_height, 1e-12)
check("cluster = all mud particles", sl.cluster == n and sl.ignored == 0)
-- The module function takes the simulation as its first argument.
near("measure.slump_height", measure.slump_height(sim, {cone_height = 0.05, material = "mud"}).pile_height, sl.pile_height, 0)
near("measure.slump", measure.slump(0.3, 0.069), 0.231, 1e-12)

-- Top view of the cone: the footprint is the 60 mm bottom disc (edge spheres reach the rim).
local flow = sim:measure_slump_flow{material = m, pixel = 2.5e-4, png = "pics/top.png", pgm = "pics/top.pgm",
                                    title = "test cone", ruler = "max_perpendicular"}
near("slump-flow circle fit", flow.diameter_fit, 0.06, 5 * r)
near("slump-flow ruler", flow.ruler.mean, 0.06, 5 * r)
near("circle centre x", flow.circle.x, 0, r)
check("png written", io.open(flow.png) ~= nil)
check("pgm written", io.open(flow.pgm) ~= nil)
check("png inside out_dir", flow.png:sub(1, #paddy.out_dir) == paddy.out_dir)

-- Profile: h(r) falls along the cone's side, 40 mm at the axis to ~0 at 30 mm.
local prof = sim:measure_profile{material = m, bin_width = 0.005}
check("profile bins", #prof >= 6)
near("profile at the axis", prof[1].h, 0.04 - 0.0025 * 2, 0.006)
for k = 2, 5 do check("profile decreasing at bin " .. k, prof[k].h < prof[k - 1].h + 1e-9) end

-- Herschel–Bulkley: exact data τ = 25 + 6 D^0.55.
local rates, stress = {}, {}
for k = 1, 12 do
  rates[k] = 0.1 * 2 ^ (k - 1)
  stress[k] = 25 + 6 * rates[k] ^ 0.55
end
local fit = measure.herschel_bulkley{shear_rate = rates, stress = stress}
near("HB tau0", fit.tau0, 25, 1e-3)
near("HB K", fit.K, 6, 1e-3)
near("HB n", fit.n, 0.55, 1e-4)
near("HB r2", fit.r2, 1, 1e-9)
near("HB stress", measure.herschel_bulkley_stress(fit, 2.0), 25 + 6 * 2 ^ 0.55, 1e-3)

-- Vane relations (hand check of docs/measurement.md): D = 20 mm, H = 40 mm.
local vane = {diameter = 0.02, height = 0.04}
near("vane torque factor", measure.vane_torque_factor(vane), 2.93215e-5, 1e-9)
near("vane stress", measure.vane_shear_stress(vane, 0.01), 341.05, 0.01)
near("vane torque", measure.vane_torque(vane, 341.05), 0.01, 1e-6)
near("vane rate, infinite cup, Newtonian", measure.vane_shear_rate(vane, 1.0), 2.0, 1e-12)
near("vane rate, kappa 0.5", measure.vane_shear_rate({diameter = 0.02, height = 0.04, cup_diameter = 0.04}, 1.0, 1.0), 2 / 0.75, 1e-12)
near("rpm", measure.rpm_to_rad(60), 2 * math.pi, 1e-12)
-- Forward model → flow curve → fit, round trip.
local hb = {tau0 = 30, K = 8, n = 0.5}
local cupvane = {diameter = 0.05, height = 0.06, cup_diameter = 0.1}
local om, tq = {}, {}
for k = 1, 10 do
  om[k] = 0.2 * 1.6 ^ (k - 1)
  tq[k] = measure.vane_torque_hb(cupvane, hb, om[k])
end
local curve = measure.vane_flow_curve{vane = cupvane, omega = om, torque = tq}
check("flow curve sizes", #curve.shear_rate == 10 and #curve.shear_stress == 10 and #curve.n_local == 10)
near("flow curve tau0", curve.fit.tau0, 30, 3)
near("flow curve n", curve.fit.n, 0.5, 0.06)

-- Relative errors (δ = |meas − sim| / meas).
near("relative error", measure.relative_error(231, 258), 27 / 231, 1e-12)
local e = measure.relative_errors({100, 200}, {110, 190})
near("relative errors mean", e.mean, 0.075, 1e-12)
near("relative errors max", e.max, 0.1, 1e-12)

-- Coarse graining α = 5 (10 mm from 2 mm): only the surface energy (and sizes) change.
local scaled, rows = paddy.coarse_grain{alpha = 5, params = {jkr_surface_energy = 0.096, mud_mud_friction = 0.15,
  mud_mud_rolling_friction = 0.125, mud_steel_restitution = 0.3, particle_diameter = 0.002, lift_speed = 0.05},
  laws = {jkr_surface_energy = "surface_energy", mud_mud_friction = "friction",
          mud_mud_rolling_friction = "rolling_friction", mud_steel_restitution = "restitution",
          particle_diameter = "diameter", lift_speed = 0}}
near("scaled surface energy", scaled.jkr_surface_energy, 0.48, 1e-12)
near("scaled friction", scaled.mud_mud_friction, 0.15, 0)
near("scaled rolling friction", scaled.mud_mud_rolling_friction, 0.125, 0)
near("scaled diameter", scaled.particle_diameter, 0.01, 1e-15)
local changed = {}
for _, row in ipairs(rows) do if row.changed then changed[#changed + 1] = row.name .. ":" .. row.law end end
table.sort(changed)
check("changed rows: " .. table.concat(changed, ","),
      table.concat(changed, ",") == "jkr_surface_energy:surface_energy,particle_diameter:diameter")
check("same table from require", measure.coarse_grain ~= nil and #measure.scaling_laws() >= 10)
local unknown_ok, unknown_msg = pcall(paddy.coarse_grain, {alpha = 2, params = {lift_speed = 1}})
check("unknown parameter refused", not unknown_ok and tostring(unknown_msg):find("lift_speed", 1, true))
-- No law is guessed from a name: a parameter ending in a law's name still needs its law declared.
local undeclared_ok, undeclared_msg = pcall(paddy.coarse_grain, {alpha = 2, params = {mud_mud_friction = 0.15}})
check("undeclared law refused: " .. tostring(undeclared_msg), not undeclared_ok and
      tostring(undeclared_msg):find("parameter 'mud_mud_friction' has no scaling law", 1, true) and
      tostring(undeclared_msg):find("laws = {mud_mud_friction = ...}", 1, true))
near("rayleigh time ratio", measure.rayleigh_time(0.005, 1680, 1e6, 0.5) / measure.rayleigh_time(0.001, 1680, 1e6, 0.5), 5, 1e-12)

-- Rheometer criteria and yield stresses through Lua (closed forms in tests/measure/).
local ang, ramp, flat = {}, {}, {}
for k = 0, 200 do ang[#ang + 1] = math.rad(k * 0.5); ramp[#ramp + 1] = 0.1 * math.rad(k * 0.5); flat[#flat + 1] = 0.2 end
local st = measure.steady_torque{angle = ang, torque = ramp}
check("ramp not steady", st.steady == false and st.reason:find("trend", 1, true) and st.compared_windows == 6)
near("ramp trend", st.trend, 0.1, 1e-9)
st = measure.steady_torque{angle = ang, torque = flat, min_angle = math.rad(30)}
check("constant steady", st.steady == true and st.reason == "" and #st.window_means == 6)
near("constant mean", st.mean, 0.2, 1e-15)
local bad_ok, bad_msg = pcall(measure.steady_torque, {angle = ang, torque = flat, windows = 2})
check("windows = 2 refused", not bad_ok and tostring(bad_msg):find("windows = 2", 1, true))
local vane = {diameter = 0.05, height = 0.06, cup_diameter = 0.1}
local su = measure.vane_startup{vane = vane, angle = ang, torque = ramp, smoothing_angle = 0}
check("rising start-up: peak not reached", su.peak_reached == false)
near("start-up yield stress", su.yield_stress, ramp[#ramp] / measure.vane_torque_factor(vane), 1e-12)
-- Pashias cylinder: τ' = 0.1 → s/H = 0.478112; the cone inverts its own forward model.
near("Pashias slump", measure.slump_of_yield_stress{yield_stress = 0.1 * 1500 * 9.81 * 0.2, density = 1500, height = 0.2,
     top_diameter = 0.1, bottom_diameter = 0.1} / 0.2, 0.4781122, 1e-6)
local s_cone = measure.slump_of_yield_stress{yield_stress = 400, density = 1000}
near("cone round trip", measure.slump_yield_stress{slump = s_cone, density = 1000}, 400, 1e-6)
local s_ok, s_msg = pcall(measure.slump_yield_stress, {slump = 0.35, density = 1000})
check("slump above the cone refused", not s_ok and tostring(s_msg):find("0 < slump < 0.3", 1, true))

paddy.result{ok = true, particles = n, pile_height = sl.pile_height, slump_flow = flow.diameter_fit,
             ruler = flow.ruler.mean, hb = fit, scaled = scaled}
