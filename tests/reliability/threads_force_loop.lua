-- A small wet-mud pile for the thread checks (scripts/sanitize.sh thread, docs/reliability.md):
-- JKR cohesion + constant-torque rolling friction on a floor, so the OpenMP force loop sees
-- many contacts, history updates, neighbour-list rebuilds and re-sorting with two threads.
local P = paddy.parameters{
  steps = {default = 300, type = "integer", min = 1, max = 100000, description = "time steps"},
}
local sim = paddy.simulation{threads = paddy.threads}
local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
sim:interaction(m, m, {normal = "jkr", rolling = "constant_torque", restitution = 0.5, friction = 0.3,
                       rolling_friction = 0.1, surface_energy = 0.1})
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = m}
sim:fill{region = {type = "box", min = {0, 0, 0}, max = {0.02, 0.02, 0.03}},
         radius = {dist = "normal", mean = 0.001, std = 0.0001}, material = m,
         volume_fraction = 0.35, seed = paddy.seed}
sim:run{steps = P.steps, progress = false}
paddy.result{n = sim:count(), hash = sim:state_hash()}
