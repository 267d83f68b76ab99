-- The reference paddy mud (shared/reference/README.md) for the Lua experiments: parameter
-- declarations with the reference's names and calibrated defaults, the materials (Table 2), the
-- contact laws, and coarse graining of the contact parameters (paddy.coarse_grain).
--
--   local mud = require("lib.mud")
--   local P = mud.resolve(paddy.parameters(mud.parameters{ {name = "lift_speed", ...}, ... }))
--   local cg = mud.coarse_grain(P, P.particle_diameter)   -- scaled parameters + rows
--   local m, steel = mud.setup(sim, P, cg.params)
local M = {}

-- Particle diameter of the reference simulation (the real 0.2 mm grains scaled up 10×).
M.reference_diameter = 0.002

-- Named material sets (experiments/materials/paddy_mud.json): the contact parameters with their
-- source and the conventions, sphere size and time step they were calibrated at.
local function materials_path()
  local here = package.searchpath("lib.mud", package.path)
  if not here then error("lib/mud.lua: cannot locate itself on package.path to find experiments/materials/") end
  return (here:gsub("lib[/\\]mud%.lua$", "materials/paddy_mud.json"))
end
M.materials_file = materials_path()
M.materials = paddy.read_json(M.materials_file).sets
M.material_names = {"auto"}
for name in pairs(M.materials) do M.material_names[#M.material_names + 1] = name end
table.sort(M.material_names)

-- Named contact conventions (docs/physics.md "EDEM conventions"). paddy: Paddy's converged physics
-- (implicit type A rolling torque, JKR damping and tangential stiffness from the contact radius a,
-- 0.1 T_R). edem: EDEM as its documentation describes it (type A torque applied explicitly from
-- the step's angular velocity, JKR damping and tangential stiffness from sqrt(R* delta) as in
-- Hertz-Mindlin, zero in a gap, EDEM's recommended 0.2 T_R). Both: JKR friction and rolling
-- torque from the repulsive part of the JKR force; contact lever R_i - delta/2.
-- default_material: the material set `material = auto` picks.
M.conventions = {
  paddy = {rolling = "constant_torque", jkr_overlap_stiffness = 0, timestep_fraction = 0.1, timestep_damping = true,
           default_material = "paddy_calibrated",
           description = "Paddy: implicit type A rolling torque, JKR stiffness from the contact radius, 0.1 T_R"},
  edem = {rolling = "constant_torque_explicit", jkr_overlap_stiffness = 1, timestep_fraction = 0.2, timestep_damping = true,
          default_material = "reference_edem",
          description = "EDEM: explicit type A rolling torque, JKR damping/tangential stiffness from sqrt(R* delta), 0.2 T_R (EDEM's recommended step)"},
}
M.convention_names = {"paddy", "edem"}
M.default_conventions = "paddy"

-- The calibrated contact parameters and Table 2 intrinsic properties. The contact parameters'
-- declared defaults are the default material set's (conventions paddy, material auto); with
-- another `material` the set's values replace every contact parameter not given with --set.
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
local default_set = M.materials[M.conventions[M.default_conventions].default_material].values
for _, e in ipairs(M.contact) do
  e.default = default_set[e.name] or e.default
  e.description = e.description .. "; default: the `material` set's value"
end
M.selection = {
  {name = "contact_conventions", default = M.default_conventions, choices = M.convention_names,
   description = "contact conventions: paddy (Paddy's converged physics) or edem (EDEM as documented: explicit type A rolling torque, JKR stiffness from the overlap, 0.2 T_R); docs/physics.md \"EDEM conventions\""},
  {name = "material", default = "auto", choices = M.material_names,
   description = "named contact-parameter set (experiments/materials/paddy_mud.json); auto: paddy_calibrated under paddy conventions, reference_edem under edem"},
}

function M.parameters(own)
  local list = {}
  for _, e in ipairs(own) do list[#list + 1] = e end
  for _, e in ipairs(M.selection) do list[#list + 1] = e end
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
-- The rolling sub-model and the JKR stiffness option follow P.contact_conventions (M.conventions).
function M.setup(sim, P, c)
  local conv = M.conventions[P.contact_conventions or M.default_conventions]
  local mud = sim:material{name = "mud", density = P.mud_density, shear_modulus = P.mud_shear_modulus,
                           poisson = P.mud_poisson}
  local steel = sim:material{name = "steel", density = P.steel_density, shear_modulus = P.steel_shear_modulus,
                             poisson = P.steel_poisson}
  sim:interaction(mud, mud, {
    normal = "jkr", damping = "hertz_mindlin", tangential = "mindlin", rolling = conv.rolling,
    restitution = c.mud_mud_restitution, friction = c.mud_mud_friction,
    rolling_friction = c.mud_mud_rolling_friction, surface_energy = c.jkr_surface_energy,
    jkr_overlap_stiffness = conv.jkr_overlap_stiffness,
  })
  sim:interaction(mud, steel, {
    normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin", rolling = conv.rolling,
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

-- The parameters with the conventions and the material set applied: a plain table holding every
-- value of P (unknown names still fail), where each contact parameter and the time step not
-- given with --set (paddy.set_parameters) come from the material set / conventions:
--   contact parameters: the set's values;
--   timestep_fraction, timestep_damping: the set's calibration step when the set was calibrated
--     in these conventions, gives one, and all its values are used (no contact parameter given;
--     paddy_calibrated: 0.0804 T_R, no damping factor, as the calibration ran), else the
--     conventions' step (paddy 0.1 T_R, edem 0.2 T_R).
-- Adds V.material_info = {name, conventions, source, values, given, timestep_from} for result.json.
function M.resolve(P, given)
  given = given or paddy.set_parameters or {}
  local V = {}
  for k, v in pairs(P) do V[k] = v end
  local conv_name = V.contact_conventions or M.default_conventions
  local conv = M.conventions[conv_name]
  if not conv then
    error(string.format("contact_conventions = '%s': choose one of %s", tostring(conv_name), table.concat(M.convention_names, ", ")), 0)
  end
  local name = V.material or "auto"
  if name == "auto" then name = conv.default_material end
  local set = M.materials[name]
  if not set then
    error(string.format("material = '%s' is not a set of %s (sets: %s)", tostring(name), M.materials_file,
                        table.concat(M.material_names, ", ")), 0)
  end
  local info = {name = name, conventions = conv_name, conventions_description = conv.description,
                source = set.source, calibrated_with = set.calibrated_with, file = M.materials_file, given = {}}
  for _, e in ipairs(M.contact) do
    if given[e.name] ~= nil then
      info.given[#info.given + 1] = e.name
    elseif set.values[e.name] ~= nil then
      V[e.name] = set.values[e.name]
    end
  end
  local cal = set.calibrated_with or {}
  local step = conv
  info.timestep_from = "conventions " .. conv_name
  if cal.conventions == conv_name and cal.timestep_fraction and #info.given == 0 then
    step = {timestep_fraction = cal.timestep_fraction, timestep_damping = cal.timestep_damping}
    info.timestep_from = "material " .. name .. " (its calibration step)"
  end
  if V.timestep_fraction ~= nil and given.timestep_fraction == nil then V.timestep_fraction = step.timestep_fraction end
  if V.timestep_damping ~= nil and given.timestep_damping == nil and step.timestep_damping ~= nil then
    V.timestep_damping = step.timestep_damping
  end
  if given.timestep_fraction ~= nil or given.timestep_damping ~= nil then info.timestep_from = "--set" end
  info.values = {}
  for _, e in ipairs(M.contact) do info.values[e.name] = V[e.name] end
  V.material_info = info
  return setmetatable(V, {__index = function(_, k) error("unknown parameter '" .. tostring(k) .. "'", 2) end})
end

-- One line for stdout: which conventions and which contact values a run used, and their source.
function M.describe(P)
  local i = P.material_info
  local v = i.values
  return string.format("conventions %s; material %s (%s): e %.3g/%.3g, mu %.3g/%.3g, mu_r %.3g/%.3g (mud-mud/mud-steel), gamma %.3g J/m^2 at 2 mm%s\n            step %.3g T_R%s from %s",
    i.conventions, i.name, (i.source:match("^[^(,;]+"):gsub("%s+$", "")), v.mud_mud_restitution, v.mud_steel_restitution,
    v.mud_mud_friction, v.mud_steel_friction, v.mud_mud_rolling_friction, v.mud_steel_rolling_friction,
    v.jkr_surface_energy, #i.given > 0 and ("; given with --set: " .. table.concat(i.given, ", ")) or "",
    P.timestep_fraction, P.timestep_damping and " (shortened below e = 0.13)" or "", i.timestep_from)
end

-- Particle radius option of sim:fill: monodisperse, or a normal distribution of diameters with
-- relative standard deviation `spread`, truncated at ±2 std.
function M.radius(d, spread)
  if spread <= 0 then return d / 2 end
  local r, s = d / 2, spread * d / 2
  return {dist = "normal", mean = r, std = s, min = math.max(r - 2 * s, 0.2 * r), max = r + 2 * s}
end

return M
