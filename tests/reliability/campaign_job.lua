-- One job of campaign_stages.lua: a small pile of spheres settling on a floor, with HDF5
-- snapshots, a JSON file and result.json; deterministic for a given seed and parameters.
local P = paddy.parameters{
  steps = {default = 3000, type = "integer", min = 1, max = 1000000, description = "time steps"},
  friction = {default = 0.3, min = 0, max = 2, description = "sliding friction (differs between jobs)"},
  snapshots = {default = 3, type = "integer", min = 0, max = 100, description = "snapshots during the run"},
}
local sim = paddy.simulation{threads = paddy.threads}
local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
sim:interaction(m, m, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin", restitution = 0.5,
                       friction = P.friction})
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = m}
sim:fill{region = {type = "box", min = {0, 0, 0}, max = {0.012, 0.012, 0.02}},
         radius = {dist = "normal", mean = 0.001, std = 0.0001}, material = m, volume_fraction = 0.3, seed = paddy.seed}
local opts = {steps = P.steps, progress = false}
if P.snapshots > 0 then opts.snapshot_every = P.steps * sim:timestep() / P.snapshots end
sim:run(opts)
local z = 0
for _, x in ipairs(sim:positions()) do z = math.max(z, x[3]) end
paddy.write_json("pile.json", {n = sim:count(), height = z, friction = P.friction})
paddy.result{n = sim:count(), hash = sim:state_hash(), height = z}
