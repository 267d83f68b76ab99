-- Column collapse of the reference paddy mud (docs/scripting.md; shared/reference/README.md).
--
-- A cylindrical column of cohesive mud spheres stands on a steel floor and is released at
-- t = 0 (no container yet: the slump cone, lifted at lift_speed, comes with the geometry module
-- -- see the HOOK below). The pile spreads and comes to rest; we report its run-out (radius of
-- the spread) and final height.
--
--   paddy run experiments/column_collapse.lua [--set n=3000 --set duration=0.4 ...]

local P = paddy.parameters{
  n = {default = 3000, type = "integer", min = 10, max = 2000000, description = "number of particles"},
  particle_diameter = {default = 0.002, unit = "m", min = 1e-4, max = 0.02, description = "sphere diameter"},
  aspect_ratio = {default = 1.0, min = 0.2, max = 5, description = "column height / column diameter"},
  duration = {default = 0.3, unit = "s", min = 0.001, max = 10, description = "simulated time"},
  restitution = {default = 0.13, min = 0.01, max = 1, description = "mud-mud coefficient of restitution"},
  friction = {default = 0.15, min = 0, max = 2, description = "mud-mud static friction"},
  rolling_friction = {default = 0.125, min = 0, max = 1, description = "mud-mud rolling friction"},
  surface_energy = {default = 0.096, unit = "J/m^2", min = 0, max = 10, description = "JKR surface energy (mud-mud)"},
  steel_friction = {default = 0.6, min = 0, max = 2, description = "mud-steel static friction"},
  steel_restitution = {default = 0.3, min = 0.01, max = 1, description = "mud-steel coefficient of restitution"},
  steel_rolling_friction = {default = 0.055, min = 0, max = 1, description = "mud-steel rolling friction"},
  timestep_fraction = {default = 0.3, min = 0.01, max = 0.5, description = "time step / Rayleigh time"},
  snapshots = {default = 10, type = "integer", min = 0, max = 1000, description = "number of snapshots (0: none)"},
}

local r = P.particle_diameter / 2
local sim = paddy.simulation{gravity = {0, 0, -9.81}, threads = paddy.threads}

-- Reference Table 2 (intrinsic properties).
local mud = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
local steel = sim:material{name = "steel", density = 7800, shear_modulus = 7e9, poisson = 0.3}

sim:interaction(mud, mud, {
  normal = "jkr", damping = "hertz_mindlin", tangential = "mindlin", rolling = "constant_torque",
  restitution = P.restitution, friction = P.friction, rolling_friction = P.rolling_friction,
  surface_energy = P.surface_energy,
})
sim:interaction(mud, steel, {
  normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin", rolling = "constant_torque",
  restitution = P.steel_restitution, friction = P.steel_friction, rolling_friction = P.steel_rolling_friction,
})

-- Floor: an infinite steel plane at z = 0.
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = steel, name = "floor"}
-- HOOK: the slump cone (paddy.mesh / geometry plugin "slump_cone") goes here, lifted at a
-- constant speed; until then the column stands free and collapses at t = 0.

-- Column size for n spheres on a jittered hexagonal lattice (solid fraction ~0.6).
local solid = P.n * (4 / 3) * math.pi * r ^ 3
local radius = (solid / 0.6 / (2 * math.pi * P.aspect_ratio)) ^ (1 / 3)
local height = 2 * radius * P.aspect_ratio
local placed = sim:fill{
  region = {type = "cylinder", base = {0, 0, 0}, radius = radius, height = 3 * height},
  radius = r, material = mud, packing = "lattice", spacing = 1.02, jitter = 0.5,
  count = P.n, seed = paddy.seed,
}

local dt = sim:timestep{fraction = P.timestep_fraction}
local function pile()
  local x, y, z = sim:xyz()
  local runout, top = 0, 0
  for i = 1, #x do
    runout = math.max(runout, math.sqrt(x[i] ^ 2 + y[i] ^ 2) + r)
    top = math.max(top, z[i] + r)
  end
  return runout, top
end
local runout0, height0 = pile()

local history = {}
sim:run{
  duration = P.duration,
  every = P.duration / 20,
  snapshot_every = P.snapshots > 0 and P.duration / P.snapshots or nil,
  callback = function(s)
    local runout, top = pile()
    history[#history + 1] = {t = s:time(), runout = runout, height = top, kinetic_energy = s:kinetic_energy()}
    return true
  end,
}

local runout, top = pile()
paddy.result{
  particles = placed,
  time_step = dt,
  initial_radius = runout0,
  initial_height = height0,
  runout = runout,                       -- radius of the spread [m]
  spread_diameter = 2 * runout,          -- slump-flow analogue [m]
  final_height = top,                    -- [m]
  slump = height0 - top,                 -- [m]
  kinetic_energy = sim:kinetic_energy(), -- [J]
  history = history,
}
