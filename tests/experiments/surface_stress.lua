-- Test of sim:measure_stress (engine/lua/src/lua_surface_stress.cpp, paddy/measure/surface_stress.hpp)
-- on the engine's own contact forces, against closed forms; each check raises an error naming
-- what failed (run by run_case.cmake).
local function near(what, got, want, tol)
  if not (math.abs(got - want) <= tol) then
    error(string.format("%s = %.10g, expected %.10g ± %.3g", what, got, want, tol), 2)
  end
end
local function check(what, cond) if not cond then error(what, 2) end end

local rho, r, g = 1680, 0.005, 9.81
local function new_sim(gravity)
  local sim = paddy.simulation{threads = 1, gravity = gravity}
  local m = sim:material{name = "mud", density = rho, shear_modulus = 1e6, poisson = 0.5}
  local s = sim:material{name = "steel", density = 7800, shear_modulus = 7e9, poisson = 0.3}
  sim:interaction(m, m, {restitution = 0.1, friction = 0.3})
  sim:interaction(m, s, {restitution = 0.1, friction = 0.3})
  return sim, m, s
end

-- 1. A vertical chain of 5 spheres standing on a steel floor, at rest: the plane between sphere k
-- and k + 1 carries the weight of the 5 − k spheres above it, all of it through the one contact
-- that crosses it (the method of planes is exact at rest). The plane between the floor and the
-- first sphere crosses only a wall contact, which the measure leaves out: nothing.
do
  local sim, m, s = new_sim({0, 0, -g})
  sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = s, name = "floor"}
  local N = 5
  for k = 1, N do sim:add_particle{pos = {0, 0, (2 * k - 1) * r * 1.001}, radius = r, material = m} end
  sim:timestep{fraction = 0.1}
  sim:run{duration = 1.0}
  local _, _, z = sim:xyz()
  table.sort(z)
  local weight = rho * 4 / 3 * math.pi * r ^ 3 * g
  for k = 1, N - 1 do
    local st = sim:measure_stress{surface = "disc", z = 0.5 * (z[k] + z[k + 1]), r_max = 2 * r}
    check("one contact crosses the plane above sphere " .. k, st.crossings == 1)
    near("force across the plane above sphere " .. k .. " [N]", st.normal * st.area, (N - k) * weight, 1e-6 * N * weight)
    near("no shear above sphere " .. k, st.shear, 0, 1e-9)
  end
  local floor = sim:measure_stress{surface = "disc", z = 0.5 * z[1], r_max = 2 * r}
  check("the floor contact is not counted", floor.crossings == 0 and floor.normal == 0)
  -- Off-axis disc that the chain does not cross: nothing.
  local off = sim:measure_stress{surface = "disc", z = 0.5 * (z[1] + z[2]), r_min = r, r_max = 3 * r}
  check("an annulus around the chain carries nothing", off.crossings == 0)
end

-- 2. Two spheres pressed together across a vertical cylinder, no gravity, at rest: the cylinder
-- carries the Hertz force F = (4/3) E* sqrt(R*) δ^(3/2) as compression over its area, whatever the
-- azimuth of the pair; a pair pulled apart (spheres not touching) carries nothing.
do
  local G, nu = 1e6, 0.5
  local E_star = 2 * G * (1 + nu) / (2 * (1 - nu ^ 2))
  local delta, R_cyl, H = 0.002, 0.025, 0.06
  local F = 4 / 3 * E_star * math.sqrt(r / 2) * delta ^ 1.5
  for _, angle in ipairs({0, 0.7, 2.5}) do
    local sim, m = new_sim({0, 0, 0})
    local c, sn = math.cos(angle), math.sin(angle)
    local half = r - delta / 2
    sim:add_particle{pos = {(R_cyl - half) * c, (R_cyl - half) * sn, 0.05}, radius = r, material = m}
    sim:add_particle{pos = {(R_cyl + half) * c, (R_cyl + half) * sn, 0.05}, radius = r, material = m}
    local st = sim:measure_stress{surface = "cylinder", radius = R_cyl, z_min = 0.02, z_max = 0.02 + H}
    check("one contact crosses the cylinder", st.crossings == 1)
    near("area", st.area, 2 * math.pi * R_cyl * H, 1e-15)
    near(string.format("normal force across the cylinder at azimuth %g [N]", angle), st.normal * st.area, F, 1e-9 * F)
    near("no shear", st.shear, 0, 1e-9)
    -- The same pair below the height range: not counted.
    local below = sim:measure_stress{surface = "cylinder", radius = R_cyl, z_min = 0.06, z_max = 0.1}
    check("a crossing below z_min is not counted", below.crossings == 0)
  end
end

-- 2b. Several surfaces in one call (one reading of the contacts) give what one call each gives.
do
  local sim, m, s = new_sim({0, 0, -g})
  sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = s, name = "floor"}
  for k = 1, 3 do sim:add_particle{pos = {0.001 * k, 0, (2 * k - 1) * r * 1.001}, radius = r, material = m} end
  sim:timestep{fraction = 0.1}
  sim:run{duration = 0.05}
  local specs = {{surface = "disc", z = 2 * r, r_max = 3 * r}, {surface = "cylinder", radius = 0.0015, z_min = 0, z_max = 6 * r},
                 {surface = "disc", z = 0.5 * r, r_max = 3 * r}}
  local all = sim:measure_stress{surfaces = specs, walls = "floor"}
  check("one result per surface", #all == #specs)
  for k, spec in ipairs(specs) do
    local one = {walls = "floor"}
    for key, v in pairs(spec) do one[key] = v end
    local st = sim:measure_stress(one)
    for _, key in ipairs({"normal", "shear", "area", "crossings"}) do
      check(string.format("surface %d: %s %s in the list, %s alone", k, key, tostring(all[k][key]), tostring(st[key])), all[k][key] == st[key])
    end
  end
  check("the floor's contact counts when listed", all[3].crossings == 1 and all[3].normal > 0)
end

-- 3. Bad input names the option.
do
  local sim = new_sim({0, 0, 0})
  local ok, err = pcall(function() return sim:measure_stress{surface = "sphere", z = 0} end)
  check("unknown surface refused: " .. tostring(err), not ok and tostring(err):match("not one of disc, cylinder"))
  ok, err = pcall(function() return sim:measure_stress{surface = "disc", z = 0, r_max = -1} end)
  check("bad radii refused: " .. tostring(err), not ok and tostring(err):match("r_min < r_max"))
  ok, err = pcall(function() return sim:measure_stress{surface = "disc", z = 0, r_max = 1, height = 2} end)
  check("unknown option refused: " .. tostring(err), not ok and tostring(err):match("height"))
  ok, err = pcall(function() return sim:measure_stress{surfaces = {}} end)
  check("an empty surface list refused: " .. tostring(err), not ok and tostring(err):match("non%-empty list"))
  ok, err = pcall(function() return sim:measure_stress{surfaces = {{surface = "disc", z = 0, r_max = 1}, {surface = "cone"}}} end)
  check("a bad surface named by its place: " .. tostring(err), not ok and tostring(err):match("surface 2: surface 'cone'"))
  ok, err = pcall(function() return sim:measure_stress{surfaces = {{surface = "disc", z = 0, r_max = 1}}, z = 1} end)
  check("a list with surface options beside it refused: " .. tostring(err), not ok and tostring(err):match("'z'"))
end
paddy.result{ok = true}
