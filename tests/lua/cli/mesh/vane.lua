-- A vane turning at a known speed in a cup of spheres: the torque the spheres exert about the
-- axis is finite and opposes the rotation. Its speed is then changed by sim:set_motion: the
-- angle is continuous and the pose is the closed form.
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
-- Change the speed mid-run: the new motion continues from the vane's current pose, so the angle
-- is continuous; theta(t) = 0.125 + omega (t - 0.05) before the switch, + 2 rad/s (t - ts) after.
local ts = sim:time()
local theta_s = 0.5 * 0.05 * omega + omega * (ts - 0.05)
local before = sim:wall_pose(vane)
C.check(math.abs(before.angle - theta_s) < 1e-12, "angle %.17g before the switch, expected %.17g", before.angle, theta_s)
sim:record_wall_loads(vane)
sim:set_motion(vane, {type = "rotate", axis = {0, 0, 1}, speed = 2})
sim:record_wall_loads(vane)
local h = sim:wall_load_history(vane)
C.check(h[#h].t == ts and h[#h].angle == h[#h - 1].angle, "angle jumps at the switch: %.17g -> %.17g",
        h[#h - 1].angle, h[#h].angle)
C.check(sim:wall_pose(vane).rotation[1][1] == before.rotation[1][1], "the pose jumps at the switch")
sim:run{duration = 0.05, progress = false, record_loads_every = 0.005}
local theta = theta_s + 2 * (sim:time() - ts)
local pose = sim:wall_pose(vane)
C.check(math.abs(pose.angle - theta) < 1e-12, "angle %.17g after the switch, expected %.17g", pose.angle, theta)
local R = pose.rotation
C.check(math.abs(R[1][1] - math.cos(theta)) < 1e-12 and math.abs(R[2][1] - math.sin(theta)) < 1e-12 and
        math.abs(R[1][2] + math.sin(theta)) < 1e-12 and math.abs(R[3][3] - 1) < 1e-12,
        "rotation {{%g, %g}, {%g, ...}} is not Rz(%g)", R[1][1], R[1][2], R[2][1], theta)
C.check(math.abs(pose.origin[1]) < 1e-15 and math.abs(pose.origin[2]) < 1e-15 and math.abs(pose.origin[3] - 0.003) < 1e-15,
        "the vane's origin moved to {%g, %g, %g}", pose.origin[1], pose.origin[2], pose.origin[3])
h = sim:wall_load_history(vane)
for k = 2, #h do
  local dtk = h[k].t - h[k - 1].t
  C.check(h[k].angle - h[k - 1].angle <= omega * dtk + 1e-12 and h[k].angle >= h[k - 1].angle,
          "angle not continuous between samples %d and %d: %.17g -> %.17g", k - 1, k, h[k - 1].angle, h[k].angle)
end
-- "fixed" stops it where it is, keeping the axis: the axial torque is still T_z.
sim:set_motion(vane, {type = "fixed"})
sim:run{steps = 5, progress = false}
C.check(sim:wall_pose(vane).angle == pose.angle, "the vane turned after fixed")
T = sim:wall_torque(vane)
C.check(math.abs(sim:wall_axial_torque(vane) - T[3]) < 1e-12 + 1e-9 * math.abs(T[3]), "axial torque is not T_z after fixed")
paddy.result{n = n, mean_torque = mean, theta = theta, csv = sim:write_wall_loads(vane, "vane_torque.csv")}
