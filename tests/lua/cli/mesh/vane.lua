-- A vane turning at a known speed in a cup of spheres: the torque the spheres exert about the
-- axis is finite and opposes the rotation.
local C = require("common")
local sim = paddy.simulation{gravity = {0, 0, -9.81}, threads = paddy.threads}
local mud, steel = C.setup(sim)
local Rc, Rv = 0.025, 0.0125   -- cup and vane radii
sim:add_mesh_wall{part = "cup", params = {diameter = 2 * Rc, height = 0.05, segments = 32}, material = steel}
local omega = 5.0              -- rad/s, reached by a ramp over 0.05 s
local vane = sim:add_mesh_wall{part = "vane", material = steel, translate = {0, 0, 0.003},
                               params = {diameter = 2 * Rv, height = 0.03, shaft_length = 0.03},
                               motion = {type = "rotate", axis = {0, 0, 1}, schedule = {{0, 0}, {0.05, omega}}}}
local r = 0.0015
sim:fill{region = {type = "cylinder", base = {0, 0, 0}, radius = Rc - 0.0015, height = 0.045},
         radius = r, material = mud, count = 1200, seed = 5}
-- Nothing may start inside the vane: clear the cylinder it sweeps (plus a margin).
sim:remove_if(function(i, x, y, z, rr) return x * x + y * y < (Rv + rr + 0.0002) ^ 2 end)
local n = sim:count()
C.check(n >= 400, "only %d particles", n)
sim:timestep{fraction = 0.25}
local samples = {}
sim:run{duration = 0.3, every = 0.005, progress = false, callback = function(s)
  s:record_wall_loads(vane)
  if s:time() > 0.1 then samples[#samples + 1] = s:wall_axial_torque(vane) end
end}
local mean = 0
for _, t in ipairs(samples) do
  C.check(t == t and math.abs(t) < math.huge, "non-finite torque %s", tostring(t))
  mean = mean + t / #samples
end
C.check(mean < 0, "mean axial torque %g N m does not oppose the rotation", mean)
local T = sim:wall_torque(vane)
C.check(math.abs(sim:wall_axial_torque(vane) - T[3]) < 1e-12 + 1e-9 * math.abs(T[3]), "axial torque is not T_z")
-- A new motion would restart from the placement: refused once the vane has turned; "fixed"
-- stops it where it is.
local ok, err = pcall(sim.set_motion, sim, vane, {type = "rotate", rpm = 10})
C.check(not ok and tostring(err):find("has moved"), "set_motion on a moved wall: %s", tostring(err))
sim:set_motion(vane, {type = "fixed"})
sim:run{steps = 5, progress = false}
paddy.result{n = n, mean_torque = mean, csv = sim:write_wall_loads(vane, "vane_torque.csv")}
