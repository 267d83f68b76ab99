-- Slump-cone lift on a plate, with wall loads recorded (a short example; docs/geometry.md
-- "Using parts from Lua"). A scaled-down slump cone stands on a meshed steel plate and is filled
-- with a few hundred mud spheres; once they have settled the cone is lifted at lift_speed and
-- the mud spreads. The cone's force (what the mud exerts on it) is sampled every 10 ms and
-- written to cone_loads.csv in the output directory.
--
--   paddy run experiments/examples/cone_lift.lua [--set n=150 --set lift_speed=0.1]

local P = paddy.parameters{
  n = {default = 200, type = "integer", min = 10, max = 100000, description = "number of particles"},
  scale = {default = 0.25, min = 0.05, max = 1, description = "cone size / GB/T 50080 cone (0.1/0.2/0.3 m)"},
  particle_diameter = {default = 0.005, unit = "m", min = 5e-4, max = 0.02, description = "sphere diameter"},
  settle = {default = 0.2, unit = "s", min = 0, max = 5, description = "settling time before the lift"},
  lift_speed = {default = 0.2, unit = "m/s", min = 0.001, max = 5, description = "cone lift speed"},
  flow = {default = 0.5, unit = "s", min = 0.01, max = 10, description = "time simulated after the lift starts"},
}

local sim = paddy.simulation{gravity = {0, 0, -9.81}, threads = paddy.threads}
local mud = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
local steel = sim:material{name = "steel", density = 7800, shear_modulus = 7e9, poisson = 0.3}
sim:interaction(mud, mud, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                           restitution = 0.13, friction = 0.15})
sim:interaction(mud, steel, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                             restitution = 0.3, friction = 0.6})

-- The parts come from the geometry plugin (paddy.parts() lists them with their parameters).
local Rb, Rt, H = 0.1 * P.scale, 0.05 * P.scale, 0.3 * P.scale
sim:add_mesh_wall{name = "plate", part = "plate", params = {side = 1.0}, material = steel}
local cone = sim:add_mesh_wall{name = "cone", part = "slump_cone", material = steel,
                               params = {bottom_diameter = 2 * Rb, top_diameter = 2 * Rt, height = H}}

local r = P.particle_diameter / 2
local placed = sim:fill{region = {type = "cone", base = {0, 0, 0}, radius_bottom = Rb - r,
                                  radius_top = Rt - r, height = H - r},
                        radius = r, material = mud, count = P.n}
sim:timestep{fraction = 0.2}

local function runout()
  local x, y = sim:xyz()
  local m = 0
  for i = 1, #x do m = math.max(m, math.sqrt(x[i] ^ 2 + y[i] ^ 2) + r) end
  return m
end

-- Settle inside the fixed cone, then lift it from the current time on.
sim:run{duration = P.settle, progress = false}
local runout0 = runout()
sim:set_motion(cone, {type = "translate", velocity = {0, 0, P.lift_speed}})
sim:run{duration = P.flow, every = 0.01, callback = function(s) s:record_wall_loads(cone) end}

paddy.result{placed = placed, runout_before = runout0, runout_after = runout(),
             cone_lift = sim:wall_position(cone)[3], cone_force_z = sim:wall_force(cone)[3],
             loads = sim:write_wall_loads(cone, "cone_loads.csv")}
