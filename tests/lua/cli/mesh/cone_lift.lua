-- A slump cone (scaled-down part) on a meshed plate, filled with ~300 spheres: they stay inside
-- while the cone is fixed and spread beyond its bottom radius once it is lifted.
local C = require("common")
local sim = paddy.simulation{gravity = {0, 0, -9.81}, threads = paddy.threads}
local mud, steel = C.setup(sim)
local R1, R2, H = 0.025, 0.015, 0.05   -- cone inner radii (bottom, top) and height
local plate = sim:add_mesh_wall{part = "plate", params = {side = 0.3, divisions = 4}, material = steel}
local cone = sim:add_mesh_wall{name = "cone", part = "slump_cone", material = steel,
                               params = {bottom_diameter = 2 * R1, top_diameter = 2 * R2, height = H, segments = 32},
                               motion = {type = "fixed"}}
local r = 0.002
local placed = sim:fill{region = {type = "cone", base = {0, 0, 0}, radius_bottom = R1 - 0.002,
                                  radius_top = R2 - 0.002, height = H - 0.002},
                        radius = r, material = mud, count = 300, seed = 3}
C.check(placed >= 250, "only %d particles placed", placed)
sim:timestep{fraction = 0.25}

local function inside_cone()
  local x, y, z = sim:xyz()
  local worst = -1
  for i = 1, #x do
    local allowed = R1 - (R1 - R2) * z[i] / H      -- inner radius at the centre's height
    worst = math.max(worst, math.sqrt(x[i] ^ 2 + y[i] ^ 2) - allowed)
  end
  return worst
end
local function runout()
  local x, y = sim:xyz()
  local m = 0
  for i = 1, #x do m = math.max(m, math.sqrt(x[i] ^ 2 + y[i] ^ 2)) end
  return m
end

sim:run{duration = 0.2, every = 0.02, progress = false, callback = function(s) s:record_wall_loads() end}
local excess = inside_cone()
C.check(excess < 0, "a particle left the fixed cone by %g m", excess)
local weight = placed * 1680 * 4 / 3 * math.pi * r ^ 3 * 9.81
local fz = sim:wall_force(plate)[3] + sim:wall_force(cone)[3]
C.check(fz < -0.5 * weight and fz > -1.5 * weight, "plate + cone carry %g N, weight %g N", -fz, weight)

local t0 = sim:time()
sim:set_motion(cone, {type = "translate", velocity = {0, 0, 0.5}})   -- starts now
sim:run{duration = 0.3, every = 0.02, progress = false, callback = function(s) s:record_wall_loads(cone) end}
local lift = sim:wall_position(cone)[3]
C.check(math.abs(lift - 0.5 * (sim:time() - t0)) < 1e-9, "cone lifted %g m", lift)
local spread = runout()
C.check(spread > R1 + r, "no spread after the lift: run-out %g m", spread)
local csv = sim:write_wall_loads(cone, "cone_loads.csv")
paddy.result{placed = placed, excess = excess, spread = spread, lift = lift, csv = csv,
             axial = sim:wall_axial_torque("cone")}
