-- A broken STL (a zero-area triangle): the reader's message names the file and the problem.
local path = paddy.out_dir .. "/broken.stl"
local f = assert(io.open(path, "w"))
f:write("solid broken\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 2 0 0\n endloop\nendfacet\nendsolid broken\n")
f:close()
local sim = paddy.simulation{}
local steel = sim:material{name = "steel", density = 7800, shear_modulus = 7e9, poisson = 0.3}
sim:add_mesh_wall{file = path, material = steel}
