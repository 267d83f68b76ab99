-- Paddy benchmark, settled-packing case: the settled random packing released on its floor.
--
-- The problem must stay identical to bench/lammps/packing.in and bench/liggghts/packing.in
-- (bench/run.sh -p packing compares the three codes):
--   * the spheres of `data` (written once by bench/packing_make.lua: n mud spheres, d = 2 mm,
--     poured and settled at rest in a W x W box, ~2 W high), all at rest at t = 0;
--   * the box's side walls are gone at t = 0: the packing stands on the floor z = 0
--     (mud-steel, as in the column case) and slumps under gravity (0, 0, -9.81);
--   * law = "cohesive": the column case's mud-mud law (JKR gamma = 0.096 J/m^2, Hertz-Mindlin
--     damping e = 0.13, Mindlin friction 0.15, constant-torque rolling mu_r = 0.125);
--     law = "cohesionless": plain Hertz-Mindlin (e = 0.13, friction 0.15; no cohesion, no
--     rolling friction); the floor: the column case's mud-steel law (cohesionless: no rolling);
--   * dt = 0.2 x Rayleigh time = 2.6868e-5 s, skin 0.4 R; `steps` timed steps (default 2000).
--
-- Run by bench/run.sh as:
--   build/bin/paddy run bench/packing.lua --set data=bench/data/packing_20000.data \
--       --set law=cohesive --set steps=2000 --threads T --out DIR
-- DIR/result.json: particle_steps_per_second (from the engine's run statistics: particles x
-- timed steps / wall seconds of the timed sim:run), particles, contacts (overlapping sphere
-- pairs at the end, counted as LAMMPS's compute contact/atom does; after the timed run),
-- contacts_engine (Paddy's active contacts: floor contacts and JKR's tensile ones included).

local P = paddy.parameters{
  data  = {default = "bench/data/packing_20000.data", description = "packing (bench/packing_make.lua)"},
  law   = {default = "cohesive", choices = {"cohesive", "cohesionless"}, description = "contact law"},
  steps = {default = 2000, type = "integer", min = 1, max = 10000000, description = "timed steps"},
}
local common = require("packing_common")

local sim = paddy.simulation{gravity = {0, 0, -9.81}, skin = 0.4}
local mud   = sim:material{name = "mud",   density = 1680, shear_modulus = 1e6,    poisson = 0.5}
local steel = sim:material{name = "steel", density = 7800, shear_modulus = 7000e6, poisson = 0.3}

if P.law == "cohesive" then
  sim:interaction(mud, mud, {
    normal = "jkr", damping = "hertz_mindlin", tangential = "mindlin", rolling = "constant_torque",
    restitution = 0.13, friction = 0.15, rolling_friction = 0.125, surface_energy = 0.096,
  })
  sim:interaction(mud, steel, {
    normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin", rolling = "constant_torque",
    restitution = 0.3, friction = 0.6, rolling_friction = 0.055,
  })
else
  sim:interaction(mud, mud, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                             restitution = 0.13, friction = 0.15})
  sim:interaction(mud, steel, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                               restitution = 0.3, friction = 0.6})
end
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = steel, name = "floor"}

for _, a in ipairs(common.read_data(P.data)) do
  sim:add_particle{pos = {a[4], a[5], a[6]}, radius = a[2] / 2, material = mud, vel = {0, 0, 0}}
end

-- dt = 0.2 T_R of the mud (2 mm spheres) = 2.6868e-5 s, as in the column case.
local dt = sim:timestep{fraction = 0.2}
sim:run{steps = P.steps, progress = false}

local contacts = common.overlapping_pairs(sim)
paddy.result{particles = sim:count(), contacts = contacts, contacts_engine = sim:contact_count(),
             contacts_per_sphere = 2 * contacts / sim:count(), law = P.law, dt = dt}
