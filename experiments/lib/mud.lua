-- The reference paddy mud (shared/reference/README.md) for the Lua experiments: parameter
-- declarations with the reference's names and calibrated defaults, the materials (Table 2), the
-- contact laws, and coarse graining of the contact parameters (paddy.coarse_grain).
--
--   local mud = require("lib.mud")
--   local P = paddy.parameters(mud.parameters{ {name = "lift_speed", ...}, ... })
--   local cg = mud.coarse_grain(P, P.particle_diameter)   -- scaled parameters + rows
--   local m, steel = mud.setup(sim, P, cg.params)
local M = {}

-- Particle diameter of the reference simulation (the real 0.2 mm grains scaled up 10×).
M.reference_diameter = 0.002

-- The calibrated contact parameters (reference step 4) and Table 2 intrinsic properties.
M.contact = {
  {name = "mud_mud_restitution", default = 0.13, min = 0.01, max = 1, description = "mud-mud coefficient of restitution (H1)"},
  {name = "mud_mud_friction", default = 0.15, min = 0, max = 2, description = "mud-mud static friction (H2)"},
  {name = "mud_mud_rolling_friction", default = 0.125, min = 0, max = 1, description = "mud-mud rolling friction (H3)"},
  {name = "mud_steel_restitution", default = 0.3, min = 0.01, max = 1, description = "mud-steel coefficient of restitution (H4)"},
  {name = "mud_steel_friction", default = 0.6, min = 0, max = 2, description = "mud-steel static friction (H5)"},
  {name = "mud_steel_rolling_friction", default = 0.055, min = 0, max = 1, description = "mud-steel rolling friction (H6)"},
  {name = "jkr_surface_energy", default = 0.096, unit = "J/m^2", min = 0, max = 10, description = "mud-mud JKR surface energy at 2 mm (H7; scaled when coarse grained)"},
}
M.intrinsic = {
  {name = "mud_poisson", default = 0.5, min = 0, max = 0.5, description = "mud Poisson ratio (Table 2)"},
  {name = "mud_density", default = 1680, unit = "kg/m^3", min = 1, max = 1e5, description = "mud particle density (Table 2)"},
  {name = "mud_shear_modulus", default = 1e6, unit = "Pa", min = 1e3, max = 1e12, description = "mud shear modulus (Table 2)"},
  {name = "steel_poisson", default = 0.3, min = 0, max = 0.5, description = "steel Poisson ratio (Table 2)"},
  {name = "steel_density", default = 7800, unit = "kg/m^3", min = 1, max = 1e5, description = "steel density (Table 2)"},
  {name = "steel_shear_modulus", default = 7e9, unit = "Pa", min = 1e3, max = 1e12, description = "steel shear modulus (Table 2)"},
}

-- The experiment's own entries followed by the mud's (list form keeps the order in --help).
function M.parameters(own)
  local list = {}
  for _, e in ipairs(own) do list[#list + 1] = e end
  for _, e in ipairs(M.contact) do list[#list + 1] = e end
  for _, e in ipairs(M.intrinsic) do list[#list + 1] = e end
  return list
end

-- Coarse graining from the reference 2 mm to diameter d: α = d / 2 mm. The contact parameters
-- follow the laws of paddy::measure::CoarseGraining (docs/measurement.md): only the JKR surface
-- energy changes (γ ∝ α); restitution, friction and rolling friction are dimensionless and the
-- intrinsic properties describe the same material. Returns
--   {alpha =, params = {name = scaled value}, rows = {...what changed and why...}}.
function M.coarse_grain(P, d)
  local ref = {particle_diameter = M.reference_diameter}
  for _, e in ipairs(M.contact) do ref[e.name] = P[e.name] end
  local alpha = d / M.reference_diameter
  local scaled, rows = paddy.coarse_grain{alpha = alpha, params = ref}
  local changed = {}
  for _, row in ipairs(rows) do
    if row.changed then changed[#changed + 1] = row.name end
  end
  return {alpha = alpha, params = scaled, rows = rows, changed = changed}
end

-- Materials and contact laws. `c` holds the (scaled) contact parameters. Mud–mud: JKR +
-- Hertz–Mindlin damping + Mindlin + constant-torque rolling; mud–steel: Hertz + Hertz–Mindlin
-- damping + Mindlin + constant-torque rolling (the reference's Hertz–Mindlin "no slip").
function M.setup(sim, P, c)
  local mud = sim:material{name = "mud", density = P.mud_density, shear_modulus = P.mud_shear_modulus,
                           poisson = P.mud_poisson}
  local steel = sim:material{name = "steel", density = P.steel_density, shear_modulus = P.steel_shear_modulus,
                             poisson = P.steel_poisson}
  sim:interaction(mud, mud, {
    normal = "jkr", damping = "hertz_mindlin", tangential = "mindlin", rolling = "constant_torque",
    restitution = c.mud_mud_restitution, friction = c.mud_mud_friction,
    rolling_friction = c.mud_mud_rolling_friction, surface_energy = c.jkr_surface_energy,
  })
  sim:interaction(mud, steel, {
    normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin", rolling = "constant_torque",
    restitution = c.mud_steel_restitution, friction = c.mud_steel_friction,
    rolling_friction = c.mud_steel_rolling_friction,
  })
  return mud, steel
end

-- Time step for the contact parameters c. timestep_fraction (of the Rayleigh time) is the step
-- found stable for the reference mud, whose strongest damping is the mud-mud restitution 0.13;
-- stronger damping shortens the stable step of an explicit integrator. For a contact with damping
-- ratio ζ the limit is ω Δt ≤ 2 (√(1+ζ²) − ζ) (central difference with damping: Hughes 2000,
-- §9.1; for DEM contacts: Otsubo, O'Sullivan & Shire 2017); Hertz-Mindlin damping has
-- ζ = √(5/6) |β|, β = ln e / √(ln²e + π²). The fraction is scaled by g(e_min) / g(0.13),
-- g(e) = √(1+ζ²) − ζ, where that is below 1 (a step is never lengthened; at e_min ≥ 0.13 it is
-- exactly timestep_fraction). e_min: the smallest restitution of the contact laws.
-- Returns the fraction to use and the factor.
M.stable_restitution = 0.13
function M.damping_ratio(e)
  local l = math.log(e)
  return math.sqrt(5 / 6) * math.abs(l) / math.sqrt(l * l + math.pi ^ 2)
end
function M.timestep_factor(e)
  local function g(r)
    local z = M.damping_ratio(r)
    return math.sqrt(1 + z * z) - z
  end
  return math.min(1, g(e) / g(M.stable_restitution))
end
function M.timestep_fraction(P, c)
  local factor = M.timestep_factor(math.min(c.mud_mud_restitution, c.mud_steel_restitution))
  return P.timestep_fraction * factor, factor
end

-- Particle radius option of sim:fill: monodisperse, or a normal distribution of diameters with
-- relative standard deviation `spread`, truncated at ±2 std.
function M.radius(d, spread)
  if spread <= 0 then return d / 2 end
  local r, s = d / 2, spread * d / 2
  return {dist = "normal", mean = r, std = s, min = math.max(r - 2 * s, 0.2 * r), max = r + 2 * s}
end

return M
