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
           integration = "velocity_verlet", default_material = "paddy_calibrated",
           description = "Paddy: implicit type A rolling torque, JKR stiffness from the contact radius, 0.1 T_R"},
  edem = {rolling = "constant_torque_explicit", jkr_overlap_stiffness = 1, timestep_fraction = 0.2, timestep_damping = true,
          integration = "velocity_verlet", default_material = "reference_edem",
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
-- For each contact parameter, the contact sub-model parameter whose coarse-graining law (declared
-- in its ParamSpec, beside the model) it follows.
M.contact_laws = {
  mud_mud_restitution = "restitution",
  mud_mud_friction = "friction",
  mud_mud_rolling_friction = "rolling_friction",
  mud_steel_restitution = "restitution",
  mud_steel_friction = "friction",
  mud_steel_rolling_friction = "rolling_friction",
  jkr_surface_energy = "surface_energy",
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
  {name = "rolling_integration", default = "conventions", choices = {"conventions", "implicit", "explicit"},
   description = "integration of the type A rolling torque: conventions (paddy implicit, edem explicit), implicit (constant_torque: a rotation stops instead of reversing) or explicit (constant_torque_explicit: the torque from the step's angular velocity); docs/physics.md §2.5, §6"},
  {name = "time_integration", default = "conventions", choices = {"conventions", "velocity_verlet", "euler"},
   description = "time integration scheme: conventions (both: velocity_verlet), velocity_verlet (second order) or euler (semi-implicit Euler, first order: EDEM's default scheme); docs/physics.md §3, §6"},
  {name = "material", default = "auto", choices = M.material_names,
   description = "named contact-parameter set (experiments/materials/paddy_mud.json); auto: paddy_calibrated under paddy conventions, reference_edem under edem"},
}

-- Candidate physical effects (docs/physics.md "Physical effects"): each is off at its default 0,
-- and then the run is exactly the run without it (the effect is not even added to the chain).
-- A descriptor:
--   name        what the effect is (discovery's candidate name)
--   strength    the parameter whose value 0 turns it off
--   parameters  its declarations (values for 2 mm grains, scaled when coarse grained)
--   reference(P) → {name = {value at 2 mm, law}}: the values mud.coarse_grain scales, each with the
--               contact sub-model parameter whose declared law it follows
--   pairs       which interactions it joins: "mud_mud", "mud_steel"
--   extra       contact sub-model added to those interactions' extras (optional)
--   normal      normal sub-model replacing the pair's own (optional)
--   contact(c, conv) → {sub-model parameter = value} from the scaled values c
-- An experiment can pass more descriptors to mud.parameters / mud.coarse_grain / mud.setup
-- (argument `effects`), or append to M.effects before calling them.
local function sphere_volume(d) return math.pi * d ^ 3 / 6 end
M.effects = {
  {name = "liquid_bridges", strength = "liquid_bridge_volume", extra = "liquid_bridge", pairs = {"mud_mud", "mud_steel"},
   parameters = {
     {name = "liquid_bridge_volume", default = 0, min = 0, max = 0.2, description = "liquid volume of one capillary bridge as a fraction of the mean sphere volume (0: no bridges; Willett et al. 2000, rupture at (1 + theta/2) V^(1/3), Lian et al. 1993)"},
     {name = "liquid_surface_tension", default = 0.072, unit = "N/m", min = 0, max = 10, description = "surface tension of the bridging liquid at 2 mm (water 0.072; scaled like the JKR surface energy when coarse grained)"},
     {name = "liquid_contact_angle", default = 0, unit = "deg", min = 0, max = 90, description = "contact angle of the bridging liquid"},
   },
   reference = function(P)
     return {liquid_bridge_volume_m3 = {P.liquid_bridge_volume * sphere_volume(M.reference_diameter), "bridge_volume"},
             liquid_surface_tension = {P.liquid_surface_tension, "surface_tension"},
             liquid_contact_angle = {P.liquid_contact_angle, "contact_angle"}}
   end,
   contact = function(c)
     return {bridge_volume = c.liquid_bridge_volume_m3, surface_tension = c.liquid_surface_tension,
             contact_angle = c.liquid_contact_angle}
   end},
  {name = "lubrication", strength = "lubrication_viscosity", extra = "lubrication", pairs = {"mud_mud", "mud_steel"},
   parameters = {
     {name = "lubrication_viscosity", default = 0, unit = "Pa s", min = 0, max = 1000, description = "viscosity of the interstitial fluid at 2 mm: squeeze-film force 6 pi mu R*^2 v_n/h and tangential log force (0: off; water 0.001; resolved by the step up to about 0.02, above it the force saturates at m*/(12 dt); scaled like the JKR surface energy when coarse grained)"},
     {name = "lubrication_min_gap", default = 0.01, unit = "R*", min = 1e-6, max = 1, description = "minimum film thickness (regularisation) as a fraction of R*"},
     {name = "lubrication_cutoff", default = 0.1, unit = "R*", min = 1e-6, max = 1, description = "gap beyond which the film force is 0, as a fraction of R*"},
   },
   reference = function(P)
     return {lubrication_viscosity = {P.lubrication_viscosity, "lubrication_viscosity"},
             lubrication_min_gap = {P.lubrication_min_gap, "lubrication_min_gap"},
             lubrication_cutoff = {P.lubrication_cutoff, "lubrication_cutoff"}}
   end,
   contact = function(c)
     return {lubrication_viscosity = c.lubrication_viscosity, lubrication_min_gap = c.lubrication_min_gap,
             lubrication_cutoff = c.lubrication_cutoff}
   end},
  {name = "wall_adhesion", strength = "mud_steel_surface_energy", normal = "jkr", pairs = {"mud_steel"},
   parameters = {
     {name = "mud_steel_surface_energy", default = 0, unit = "J/m^2", min = 0, max = 10, description = "JKR surface energy of the mud-steel pair (cone, plate, cup, vane) at 2 mm (0: Hertz, as the reference; scaled when coarse grained)"},
   },
   reference = function(P) return {mud_steel_surface_energy = {P.mud_steel_surface_energy, "surface_energy"}} end,
   contact = function(c, conv)
     return {surface_energy = c.mud_steel_surface_energy, jkr_overlap_stiffness = conv.jkr_overlap_stiffness}
   end},
  {name = "plastic_adhesion", strength = "plastic_adhesion", extra = "plastic_adhesion", pairs = {"mud_mud"},
   parameters = {
     {name = "plastic_adhesion", default = 0, min = 0, max = 0.9, description = "mud-mud adhesion growing with the largest load a contact carried: pull-off = this x largest load (0: off; Luding 2008, Thakur et al. 2014 EEPA)"},
     {name = "plastic_adhesion_range", default = 0.05, unit = "R*", min = 1e-6, max = 0.5, description = "largest bonded gap of the plastic adhesion as a fraction of R* (the range is min(largest overlap, this R*))"},
   },
   reference = function(P)
     return {plastic_adhesion = {P.plastic_adhesion, "plastic_adhesion"},
             plastic_adhesion_range = {P.plastic_adhesion_range, "plastic_adhesion_range"}}
   end,
   contact = function(c)
     return {plastic_adhesion = c.plastic_adhesion, plastic_adhesion_range = c.plastic_adhesion_range}
   end},
}
local function all_effects(more)
  local list = {}
  for _, e in ipairs(M.effects) do list[#list + 1] = e end
  for _, e in ipairs(more or {}) do list[#list + 1] = e end
  return list
end
-- The effects whose strength is > 0 in P (a P without the strength parameter: off).
function M.active_effects(P, more)
  local on = {}
  for _, e in ipairs(all_effects(more)) do
    local ok, v = pcall(function() return P[e.strength] end)
    if ok and type(v) == "number" and v > 0 then on[#on + 1] = e end
  end
  return on
end

function M.parameters(own, effects)
  local list = {}
  for _, e in ipairs(own) do list[#list + 1] = e end
  for _, e in ipairs(M.selection) do list[#list + 1] = e end
  for _, e in ipairs(M.contact) do list[#list + 1] = e end
  for _, fx in ipairs(all_effects(effects)) do
    for _, e in ipairs(fx.parameters) do list[#list + 1] = e end
  end
  for _, e in ipairs(M.intrinsic) do list[#list + 1] = e end
  return list
end

-- Coarse graining from the reference 2 mm to diameter d: α = d / 2 mm. Each contact parameter
-- follows the law its contact sub-model declares (ParamSpec, beside the model; the `law` field
-- above names it; docs/measurement.md): the JKR surface energies, the bridges' surface tension and
-- the lubrication viscosity ∝ α, the bridge volume ∝ α³ (the same fraction of the sphere), the
-- rest unchanged. Only the effects that are on are scaled (and listed). Returns
--   {alpha =, params = {name = scaled value}, rows = {...what changed and why...}}.
function M.coarse_grain(P, d, effects)
  local ref = {particle_diameter = M.reference_diameter}
  local laws = {particle_diameter = "diameter"}
  for _, e in ipairs(M.contact) do
    ref[e.name] = P[e.name]
    laws[e.name] = M.contact_laws[e.name]
  end
  for _, fx in ipairs(M.active_effects(P, effects)) do
    for name, v in pairs(fx.reference(P)) do
      ref[name], laws[name] = v[1], v[2]
    end
  end
  local alpha = d / M.reference_diameter
  local scaled, rows = paddy.coarse_grain{alpha = alpha, params = ref, laws = laws}
  local changed = {}
  for _, row in ipairs(rows) do
    if row.changed then changed[#changed + 1] = row.name end
  end
  return {alpha = alpha, params = scaled, rows = rows, changed = changed}
end

-- Materials and contact laws. `c` holds the (scaled) contact parameters. The two pairs' base
-- chains: mud–mud JKR + Hertz–Mindlin damping + Mindlin + constant-torque rolling; mud–steel Hertz
-- + Hertz–Mindlin damping + Mindlin + constant-torque rolling (the reference's Hertz–Mindlin "no
-- slip"). The rolling sub-model and the JKR stiffness option follow P.contact_conventions
-- (M.conventions). Then every effect that is on (M.effects, plus `effects` passed in) joins its
-- pairs: its extra is appended, its normal model replaces the pair's, its parameters are added.
M.rolling_models = {implicit = "constant_torque", explicit = "constant_torque_explicit"}

-- The type A rolling sub-model: the conventions' one unless rolling_integration overrides it.
function M.rolling_model(P, conv)
  local how = rawget(P, "rolling_integration")
  if how == nil or how == "conventions" then return conv.rolling end
  local model = M.rolling_models[how]
  if not model then
    error(string.format("rolling_integration = '%s': choose conventions, implicit or explicit", tostring(how)), 0)
  end
  return model
end

-- The time integration scheme (sim:integration): the conventions' one unless time_integration
-- overrides it.
M.integration_schemes = {velocity_verlet = true, euler = true}
function M.integration(P, conv)
  conv = conv or M.conventions[rawget(P, "contact_conventions") or M.default_conventions]
  local how = rawget(P, "time_integration")
  if how == nil or how == "conventions" then return conv.integration end
  if not M.integration_schemes[how] then
    error(string.format("time_integration = '%s': choose conventions, velocity_verlet or euler", tostring(how)), 0)
  end
  return how
end

function M.pair_specs(P, c, effects)
  local conv = M.conventions[P.contact_conventions or M.default_conventions]
  local rolling = M.rolling_model(P, conv)
  local specs = {
    mud_mud = {
      normal = "jkr", damping = "hertz_mindlin", tangential = "mindlin", rolling = rolling,
      restitution = c.mud_mud_restitution, friction = c.mud_mud_friction,
      rolling_friction = c.mud_mud_rolling_friction, surface_energy = c.jkr_surface_energy,
      jkr_overlap_stiffness = conv.jkr_overlap_stiffness,
    },
    mud_steel = {
      normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin", rolling = rolling,
      restitution = c.mud_steel_restitution, friction = c.mud_steel_friction,
      rolling_friction = c.mud_steel_rolling_friction,
    },
  }
  for _, fx in ipairs(M.active_effects(P, effects)) do
    for _, pair in ipairs(fx.pairs) do
      local spec = specs[pair]
      if not spec then error("effect '" .. fx.name .. "': unknown pair '" .. tostring(pair) .. "' (mud_mud, mud_steel)", 0) end
      if fx.normal then spec.normal = fx.normal end
      if fx.extra then
        spec.extras = spec.extras or {}
        spec.extras[#spec.extras + 1] = fx.extra
      end
      for k, v in pairs(fx.contact(c, conv)) do
        if v == nil then error("effect '" .. fx.name .. "': no value for " .. k, 0) end
        spec[k] = v
      end
    end
  end
  return specs
end

function M.setup(sim, P, c, effects)
  local mud = sim:material{name = "mud", density = P.mud_density, shear_modulus = P.mud_shear_modulus,
                           poisson = P.mud_poisson}
  local steel = sim:material{name = "steel", density = P.steel_density, shear_modulus = P.steel_shear_modulus,
                             poisson = P.steel_poisson}
  M.set_interactions(sim, P, c, mud, steel, effects)
  sim:integration(M.integration(P))
  return mud, steel
end

-- Sets (or replaces, during a run) the two pairs' contact laws.
function M.set_interactions(sim, P, c, mud, steel, effects)
  local specs = M.pair_specs(P, c, effects)
  sim:interaction(mud, mud, specs.mud_mud)
  sim:interaction(mud, steel, specs.mud_steel)
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
                rolling = M.rolling_model(V, conv), integration = M.integration(V, conv),
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
  local conv = M.conventions[i.conventions]
  -- what the run chose apart from its conventions
  local overrides = i.rolling ~= conv.rolling and string.format(" (rolling %s)", i.rolling) or ""
  if i.lift_rolling and i.lift_rolling ~= i.rolling then overrides = overrides .. string.format(" (from the lift on: rolling %s)", i.lift_rolling) end
  if i.integration and i.integration ~= conv.integration then overrides = overrides .. string.format(" (integration %s)", i.integration) end
  return string.format("conventions %s%s; material %s (%s): e %.3g/%.3g, mu %.3g/%.3g, mu_r %.3g/%.3g (mud-mud/mud-steel), gamma %.3g J/m^2 at 2 mm%s\n            step %.3g T_R%s from %s",
    i.conventions, overrides, i.name, (i.source:match("^[^(,;]+"):gsub("%s+$", "")), v.mud_mud_restitution, v.mud_steel_restitution,
    v.mud_mud_friction, v.mud_steel_friction, v.mud_mud_rolling_friction, v.mud_steel_rolling_friction,
    v.jkr_surface_energy, #i.given > 0 and ("; given with --set: " .. table.concat(i.given, ", ")) or "",
    P.timestep_fraction, P.timestep_damping and " (shortened below e = 0.13)" or "", i.timestep_from)
    .. M.describe_effects(P)
end

-- "; effects: liquid_bridges (liquid_bridge_volume = 0.05), ..." or "" when every effect is off.
function M.describe_effects(P, effects)
  local on = {}
  for _, fx in ipairs(M.active_effects(P, effects)) do
    on[#on + 1] = string.format("%s (%s = %g)", fx.name, fx.strength, P[fx.strength])
  end
  return #on > 0 and ("\n            effects: " .. table.concat(on, ", ")) or ""
end

-- Particle radius option of sim:fill: monodisperse, or a normal distribution of diameters with
-- relative standard deviation `spread`, truncated at ±2 std.
function M.radius(d, spread)
  if spread <= 0 then return d / 2 end
  local r, s = d / 2, spread * d / 2
  return {dist = "normal", mean = r, std = s, min = math.max(r - 2 * s, 0.2 * r), max = r + 2 * s}
end

return M
