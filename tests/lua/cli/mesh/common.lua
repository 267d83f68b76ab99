-- Shared set-up of the mesh-wall CLI cases: a soft mud (large time step, fast tests) and steel.
local M = {}

function M.setup(sim)
  local mud = sim:material{name = "mud", density = 1680, shear_modulus = 2e5, poisson = 0.4}
  local steel = sim:material{name = "steel", density = 7800, shear_modulus = 7e9, poisson = 0.3}
  sim:interaction(mud, mud, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                             restitution = 0.3, friction = 0.3})
  sim:interaction(mud, steel, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                               restitution = 0.3, friction = 0.5})
  return mud, steel
end

function M.check(cond, ...)
  if not cond then error(string.format(...), 2) end
end

return M
