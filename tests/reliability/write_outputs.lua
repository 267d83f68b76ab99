-- A small run that writes each kind of output Paddy produces: an HDF5 snapshot (sim:snapshot),
-- a checkpoint (sim:checkpoint), a JSON file (paddy.write_json), a CSV file through lib.util and
-- result.json (paddy.result). unwritable_output.sh runs it under `ulimit -f` and into directories
-- that cannot be written: `big` makes the chosen output larger than the limit.
local util = require("lib.util")
local P = paddy.parameters{
  outputs = {default = "all", type = "string",
             description = "what to write: all, snapshot, checkpoint, json, csv or result"},
  big = {default = 0, type = "integer", min = 0, max = 1, description = "1: the chosen output is large (160 kB or more)"},
  label = {default = "run", type = "string", description = "a text stored in the outputs"},
}
local function wants(what) return P.outputs == "all" or P.outputs == what end
local sim = paddy.simulation{threads = 1}
local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
sim:interaction(m, m, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin", restitution = 0.5, friction = 0.3})
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = m}
-- about 2000 spheres when big (a snapshot or checkpoint of some 300 kB), else about 40
local n_side = P.big == 1 and 13 or 3
for i = 1, n_side do
  for j = 1, n_side do
    for k = 1, (P.big == 1 and 12 or 4) do
      sim:add_particle{pos = {0.0025 * i, 0.0025 * j, 0.0025 * k}, radius = 0.001, material = m}
    end
  end
end
sim:run{steps = 20, progress = false}
local written = {}
if wants("snapshot") then written.snapshot = sim:snapshot() end
if wants("checkpoint") then written.checkpoint = sim:checkpoint("state.h5") end
local payload = string.rep(P.label .. " ", P.big == 1 and 40000 or 4)
if wants("json") then written.json = paddy.write_json("data.json", {label = P.label, payload = payload}) end
if wants("csv") then
  local rows = {}
  for i = 1, (P.big == 1 and 20000 or 5) do rows[i] = {i, i * 0.5, P.label} end
  written.csv = util.write_csv("table.csv", {"i", "half", "label"}, rows)
end
local result = {n = sim:count(), hash = sim:state_hash(), label = P.label}
if wants("result") then result.payload = payload end
paddy.result(result)
