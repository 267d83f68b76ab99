local sim = paddy.simulation{}
local steel = sim:material{name = "steel", density = 7800, shear_modulus = 7e9, poisson = 0.3}
sim:add_mesh_wall{part = "slump_kone", material = steel}
