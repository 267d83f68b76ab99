-- Writes a tiny ASCII STL in millimetres (a 100 mm square in two triangles), imports it with
-- scale = 0.001 and a placement, and rests a sphere on it.
local C = require("common")
local path = paddy.out_dir .. "/square_mm.stl"
local f = assert(io.open(path, "w"))
f:write([[
solid square
facet normal 0 0 1
 outer loop
  vertex -50 -50 0
  vertex 50 -50 0
  vertex 50 50 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex -50 -50 0
  vertex 50 50 0
  vertex -50 50 0
 endloop
endfacet
endsolid square
]])
f:close()
local sim = paddy.simulation{gravity = {0, 0, -9.81}, threads = paddy.threads}
local mud, steel = C.setup(sim)
-- Rotated by 90 degrees about z (still the same square) and lifted to z = 0.01.
local w = sim:add_mesh_wall{file = path, scale = 0.001, material = steel, name = "square",
                            rotate = {axis = {0, 0, 1}, angle = 90}, translate = {0, 0, 0.01}}
local r = 0.002
sim:add_particle{pos = {0.03, 0.02, 0.01 + r + 0.0005}, radius = r, material = mud}
sim:timestep{fraction = 0.25}
sim:run{duration = 0.15, progress = false}
local z = sim:positions()[1][3]
C.check(z > 0.01 + 0.9 * r and z < 0.01 + r, "sphere at z = %g", z)
local weight = 1680 * 4 / 3 * math.pi * r ^ 3 * 9.81
local fz = sim:wall_force(w)[3]
C.check(math.abs(fz + weight) < 0.05 * weight, "wall force %g N, weight %g N", fz, weight)
local parts = paddy.parts()
local names = {}
for _, p in ipairs(parts) do names[#names + 1] = p.name end
C.check(table.concat(names, ",") == "cup,plate,slump_cone,vane", "parts: %s", table.concat(names, ","))
paddy.result{z = z, fz = fz, parts = names}
