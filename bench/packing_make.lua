-- Paddy benchmark, settled-packing case: makes the settled random packing that
-- bench/packing.lua, bench/lammps/packing.in and bench/liggghts/packing.in all start from.
--
--   * n monodisperse mud spheres, d = 2 mm (the column collapse's mud), placed at random
--     (sim:fill packing = "random", seed `seed`, loose solid fraction 0.2: random addition
--     jams near 0.25 in the box) in a box of W x W base, W = (n v / 1.2)^(1/3) with v the
--     sphere volume, so that the settled packing (solid fraction ~0.6) stands about 2 W high,
--     like the column case;
--   * poured under gravity into that box: floor z = 0 (mud-steel, as in the column case) and
--     four frictionless side walls, mud-mud Hertz-Mindlin without cohesion or rolling
--     friction (restitution 0.13, friction 0.15), dt = 0.2 T_R as in the timed case;
--   * settled until at rest: after the free fall, until the rms speed sqrt(2 KE / M) is below
--     `rest_speed` (the fastest sphere is not used: a few spheres keep rolling on the free
--     surface, there being no rolling friction); at `max_time` the packing is written anyway
--     and result.json says at_rest = false;
--   * written to `data` as a LAMMPS/LIGGGHTS data file (atom_style sphere / granular: one line
--     "id type diameter density x y z" per sphere, 2 atom types for LIGGGHTS's wall material),
--     which bench/packing.lua also reads. Box: x, y in [-W, 2W], z in [0, 1.3 x top].
--
-- Deterministic for a given n, seed and thread count (bench/run.sh uses --threads 1):
--   build/bin/paddy run bench/packing_make.lua --set n=20000 --set data=bench/data/packing_20000.data \
--       --threads 1 --out /tmp/pm
-- result.json: particles, contacts (overlapping sphere pairs, walls not counted, as LAMMPS's
-- compute contact/atom), contacts_per_sphere (2 x contacts / particles),
-- solid_fraction (below 0.9 x the top), top, width, settle_time, at_rest.

local P = paddy.parameters{
  n          = {default = 20000, type = "integer", min = 100, max = 2000000, description = "spheres"},
  data       = {default = "packing.data", description = "data file to write"},
  seed       = {default = 1, type = "integer", min = 1, max = 1e9, description = "fill seed"},
  rest_speed = {default = 0.002, unit = "m/s", min = 0, max = 1, description = "at rest below this rms speed"},
  max_time   = {default = 1.5, unit = "s", min = 0.01, max = 10, description = "longest settling"},
}

local d, R, rho = 0.002, 0.001, 1680
local v = 4 / 3 * math.pi * R ^ 3
local W = (P.n * v / 1.2) ^ (1 / 3)
local H_loose = P.n * v / (0.2 * W * W)

local sim = paddy.simulation{gravity = {0, 0, -9.81}, skin = 0.4}
local mud   = sim:material{name = "mud",   density = rho,  shear_modulus = 1e6,    poisson = 0.5}
local steel = sim:material{name = "steel", density = 7800, shear_modulus = 7000e6, poisson = 0.3}
local glass = sim:material{name = "side",  density = 7800, shear_modulus = 7000e6, poisson = 0.3}
sim:interaction(mud, mud, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                           restitution = 0.13, friction = 0.15})
sim:interaction(mud, steel, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                             restitution = 0.3, friction = 0.6})
sim:interaction(mud, glass, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                             restitution = 0.3, friction = 0.0})

sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = steel, name = "floor"}
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {1, 0, 0}, material = glass, name = "x0"}
sim:add_wall{type = "plane", point = {W, 0, 0}, normal = {-1, 0, 0}, material = glass, name = "x1"}
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 1, 0}, material = glass, name = "y0"}
sim:add_wall{type = "plane", point = {0, W, 0}, normal = {0, -1, 0}, material = glass, name = "y1"}

local placed = sim:fill{region = {type = "box", min = {0, 0, 0}, max = {W, W, H_loose}}, radius = R,
                        material = mud, packing = "random", count = P.n, seed = P.seed}
if placed ~= P.n then error(string.format("packing_make.lua: placed %d of %d spheres", placed, P.n)) end

local dt = sim:timestep{fraction = 0.2}
local fall = math.sqrt(2 * H_loose / 9.81)
local mass = P.n * v * rho
local at_rest, rms = false, nil
sim:run{duration = P.max_time, every = 0.01, progress = false, callback = function(s)
  rms = math.sqrt(2 * s:kinetic_energy() / mass)
  if s:time() > fall and rms < P.rest_speed then at_rest = true; return false end
end}

-- Write the data file (ids in Paddy's order; all velocities zero).
local xs, ys, zs = sim:xyz()
local radii = sim:radii()
local top = 0
for i = 1, #zs do top = math.max(top, zs[i] + radii[i]) end
local f = assert(io.open(P.data, "w"))
f:write(string.format("Settled random packing of %d mud spheres (bench/packing_make.lua, seed %d, t = %.4f s)\n\n",
                      #xs, P.seed, sim:time()))
f:write(string.format("%d atoms\n2 atom types\n\n", #xs))
f:write(string.format("%.9g %.9g xlo xhi\n%.9g %.9g ylo yhi\n0 %.9g zlo zhi\n\nAtoms # sphere\n\n",
                      -W, 2 * W, -W, 2 * W, 1.3 * top))
for i = 1, #xs do
  f:write(string.format("%d 1 %.9g %.9g %.12g %.12g %.12g\n", i, 2 * radii[i], rho, xs[i], ys[i], zs[i]))
end
f:close()

-- Solid fraction of the bulk (below 0.9 x the top, away from the rough surface).
local vol = 0
for i = 1, #zs do if zs[i] < 0.9 * top then vol = vol + v end end
local contacts = require("packing_common").overlapping_pairs(sim)
paddy.result{particles = #xs, contacts = contacts, contacts_engine = sim:contact_count(),
             contacts_per_sphere = 2 * contacts / #xs,
             solid_fraction = vol / (W * W * 0.9 * top), top = top, width = W, dt = dt,
             settle_time = sim:time(), at_rest = at_rest, rms_speed = rms, max_speed = sim:max_speed(),
             data = P.data}
print(string.format("packing: %d spheres, %.2f contacts per sphere, top %.4f m, t = %.3f s, rms speed %.2g m/s, "
                    .. "at rest: %s -> %s", #xs, 2 * contacts / #xs, top, sim:time(), rms, tostring(at_rest), P.data))
