-- A vane translated, then rotated, then translated again by sim:set_motion: each motion continues
-- from the pose the wall has reached, and the final pose is the closed form (no time-stepping
-- error). One far-away particle only sets the time scale.
local C = require("common")
local sim = paddy.simulation{gravity = {0, 0, 0}, threads = paddy.threads}
local mud, steel = C.setup(sim)
sim:add_particle{pos = {5, 5, 5}, radius = 0.01, material = mud}
sim:timestep{dt = 1e-3}
-- Placement: turned 90 degrees about x, at x0. A: 0.2 m/s along +x from t = 0.
local x0 = {0.1, 0, 0.02}
local vane = sim:add_mesh_wall{part = "vane", material = steel, rotate = {axis = {1, 0, 0}, angle = 90},
                               translate = x0, motion = {type = "translate", velocity = {0.2, 0, 0}}}
sim:run{duration = 0.5, progress = false}
local t1 = sim:time()
-- B: 2 rad/s about +z through p, from now on.
local p = {0.3, 0.1, 0}
sim:set_motion(vane, {type = "rotate", point = p, axis = {0, 0, 1}, speed = 2})
sim:run{duration = 0.75, progress = false}
local t2 = sim:time()
-- C: along -z, the speed ramping 0 -> 0.2 m/s over 1 s (absolute times), i.e. 0.1 (t - t2)^2.
sim:set_motion(vane, {type = "translate", direction = {0, 0, -1}, schedule = {{t2, 0}, {t2 + 1, 0.2}}})
sim:run{duration = 0.75, progress = false}
local t3 = sim:time()

local th = 2 * (t2 - t1)
local c, s = math.cos(th), math.sin(th)
local dc = 0.1 * (t3 - t2) ^ 2
-- Origin: x0 moved by A, turned about p by B, moved down by C.
local y = {x0[1] + 0.2 * t1 - p[1], x0[2] - p[2], x0[3] - p[3]}
local origin = {c * y[1] - s * y[2] + p[1], s * y[1] + c * y[2] + p[2], y[3] + p[3] - dc}
-- Rotation: Rz(th) * Rx(90 deg) = {{c, 0, s}, {s, 0, -c}, {0, 1, 0}}.
local R = {{c, 0, s}, {s, 0, -c}, {0, 1, 0}}
local pose = sim:wall_pose(vane)
for i = 1, 3 do
  C.check(math.abs(pose.origin[i] - origin[i]) < 1e-12, "origin[%d] = %.17g, expected %.17g", i, pose.origin[i], origin[i])
  for j = 1, 3 do
    C.check(math.abs(pose.rotation[i][j] - R[i][j]) < 1e-12, "rotation[%d][%d] = %.17g, expected %.17g",
            i, j, pose.rotation[i][j], R[i][j])
  end
end
C.check(math.abs(pose.angle - th) < 1e-12, "angle %.17g, expected %.17g", pose.angle, th)
C.check(math.abs(pose.distance - (0.2 * t1 + dc)) < 1e-12, "distance %.17g", pose.distance)
local u = sim:wall_position(vane)
C.check(math.abs(u[1] - 0.2 * t1) < 1e-12 and math.abs(u[2]) < 1e-12 and math.abs(u[3] + dc) < 1e-12,
        "translation travelled {%g, %g, %g}", u[1], u[2], u[3])
-- "fixed" stops it where it is.
sim:set_motion(vane, {type = "fixed"})
sim:run{duration = 0.1, progress = false}
local after = sim:wall_pose(vane)
for i = 1, 3 do
  C.check(after.origin[i] == pose.origin[i], "moved after fixed: origin[%d] %.17g -> %.17g", i, pose.origin[i], after.origin[i])
end
paddy.result{t1 = t1, t2 = t2, t3 = t3, origin = pose.origin, angle = pose.angle}
