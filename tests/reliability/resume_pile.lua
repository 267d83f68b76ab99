-- A JKR pile run with a periodic checkpoint (sim:run{checkpoint, checkpoint_every}); killed and
-- started again by kill_resume.sh, it must end in the state of an uninterrupted run.
local P = paddy.parameters{
  run_steps = {default = 2000, type = "integer", min = 1, max = 1000000, description = "time steps"},
  checkpoint_steps = {default = 200, type = "integer", min = 0, max = 1000000,
                      description = "steps between checkpoints (0 = none)"},
}
local sim = paddy.simulation{threads = paddy.threads}
local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
sim:interaction(m, m, {normal = "jkr", rolling = "constant_torque", restitution = 0.5, friction = 0.3,
                       rolling_friction = 0.1, surface_energy = 0.1})
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = m}
sim:fill{region = {type = "box", min = {0, 0, 0}, max = {0.02, 0.02, 0.03}},
         radius = {dist = "normal", mean = 0.001, std = 0.0001}, material = m,
         volume_fraction = 0.35, seed = paddy.seed}
local opts = {steps = P.run_steps, progress = false}
if P.checkpoint_steps > 0 then
  opts.checkpoint = "pile.h5"
  opts.checkpoint_every = P.checkpoint_steps * sim:timestep()
end
local taken = sim:run(opts)
paddy.result{n = sim:count(), hash = sim:state_hash(), run_returned = taken, step_count = sim:steps()}
