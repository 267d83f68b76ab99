-- lib/mud.lua's contact conventions and material sets (docs/physics.md "EDEM conventions"):
-- which values, sub-models and time step a run gets for each choice, what --set overrides, and
-- the refusals; the calibration input's "conventions" key.
local mud = require("lib.mud")
local input_file = require("lib.calibration.input")
local check = require("checks").check

-- The declared parameters as paddy.parameters would return them with no --set.
local function declared(overrides)
  local P = {}
  for _, e in ipairs(mud.parameters{
    {name = "timestep_fraction", default = 0.1, min = 0.01, max = 0.5},
    {name = "timestep_damping", default = true},
  }) do P[e.name] = e.default end
  for k, v in pairs(overrides or {}) do P[k] = v end
  return P
end
local function same(V, expected, what)
  for k, v in pairs(expected) do
    check(V[k] == v, "%s: %s = %s, expected %s", what, k, tostring(V[k]), tostring(v))
  end
end
-- Paddy's calibration (docs/calibration.md "Results": surrogate, 10 mm, 0.0804 T_R, no damping factor).
local calibrated = {jkr_surface_energy = 0.0077, mud_steel_friction = 0.693, mud_mud_friction = 0.183,
                    mud_mud_rolling_friction = 0.022, mud_mud_restitution = 0.055, mud_steel_restitution = 0.3,
                    mud_steel_rolling_friction = 0.055}
-- The reference's EDEM calibration (shared/reference/README.md, step 4).
local reference = {mud_mud_restitution = 0.13, mud_steel_friction = 0.6, jkr_surface_energy = 0.096,
                   mud_mud_friction = 0.15, mud_mud_rolling_friction = 0.125, mud_steel_restitution = 0.3,
                   mud_steel_rolling_friction = 0.055}

-- Defaults: paddy conventions, Paddy's calibration at its calibration step.
local V = mud.resolve(declared(), {})
same(V, calibrated, "default")
check(V.material_info.name == "paddy_calibrated" and V.material_info.conventions == "paddy", "default set %s", V.material_info.name)
check(V.timestep_fraction == 0.0804 and V.timestep_damping == false, "default step %g / %s", V.timestep_fraction, tostring(V.timestep_damping))
check(V.material_info.source:find("docs/calibration.md", 1, true), "the source names the calibration")
-- The declared defaults are the default set's, so --help and the run's metadata agree with it.
for _, e in ipairs(mud.contact) do check(e.default == calibrated[e.name], "declared default of %s", e.name) end

-- edem conventions: the reference's EDEM values at EDEM's recommended 0.2 T_R.
V = mud.resolve(declared{contact_conventions = "edem"}, {})
same(V, reference, "edem")
check(V.material_info.name == "reference_edem", "edem set %s", V.material_info.name)
check(V.timestep_fraction == 0.2, "edem step %g", V.timestep_fraction)

-- A set by name in the other conventions: its values, the conventions' step (it was calibrated elsewhere).
V = mud.resolve(declared{material = "reference_edem"}, {})
same(V, reference, "paddy + reference_edem")
check(V.timestep_fraction == 0.1 and V.timestep_damping == true, "paddy + reference_edem step %g", V.timestep_fraction)
V = mud.resolve(declared{contact_conventions = "edem", material = "paddy_calibrated"}, {})
same(V, calibrated, "edem + paddy_calibrated")
check(V.timestep_fraction == 0.2, "edem + paddy_calibrated step %g", V.timestep_fraction)

-- --set wins: a given contact parameter is kept, the rest from the set, and the set's
-- calibration step no longer applies (the set is not used as calibrated).
V = mud.resolve(declared{mud_mud_friction = 0.3}, {mud_mud_friction = "0.3"})
check(V.mud_mud_friction == 0.3 and V.jkr_surface_energy == 0.0077, "given friction %g, gamma %g", V.mud_mud_friction, V.jkr_surface_energy)
check(V.timestep_fraction == 0.1 and V.timestep_damping == true, "step with a given parameter %g", V.timestep_fraction)
check(#V.material_info.given == 1 and V.material_info.given[1] == "mud_mud_friction", "given list")
V = mud.resolve(declared{timestep_fraction = 0.05}, {timestep_fraction = "0.05"})
check(V.timestep_fraction == 0.05 and V.timestep_damping == false, "given step %g / %s", V.timestep_fraction, tostring(V.timestep_damping))

-- Refusals name the parameter, the value and the choices; the resolved table refuses typos.
local ok, msg = pcall(mud.resolve, declared{contact_conventions = "lammps"}, {})
check(not ok and msg:find("contact_conventions = 'lammps'", 1, true) and msg:find("paddy, edem", 1, true), "bad conventions: %s", tostring(msg))
ok, msg = pcall(mud.resolve, declared{material = "clay"}, {})
check(not ok and msg:find("material = 'clay'", 1, true) and msg:find("paddy_mud.json", 1, true), "bad material: %s", tostring(msg))
check(not pcall(function() return mud.resolve(declared(), {}).mud_mud_fricton end), "a typo must fail")

-- The sub-models each conventions selects (a stand-in simulation records the interactions).
-- A stand-in for a simulation that records into rec what mud.setup hands it: each pair's law under
-- "a-b", the integration scheme under `integration`.
local function recording_sim(rec)
  return {material = function(_, m) return m.name end,
          interaction = function(_, a, b, spec) rec[a .. "-" .. b] = spec end,
          integration = function(_, scheme) rec.integration = scheme end}
end
local function laws(conventions)
  local rec = {}
  local sim = recording_sim(rec)
  local P = mud.resolve(declared{contact_conventions = conventions}, {})
  mud.setup(sim, P, P)
  return rec
end
local p, e = laws("paddy"), laws("edem")
check(p["mud-mud"].rolling == "constant_torque" and p["mud-steel"].rolling == "constant_torque", "paddy rolling")
check(p["mud-mud"].jkr_overlap_stiffness == 0, "paddy JKR stiffness from the contact radius")
check(e["mud-mud"].rolling == "constant_torque_explicit" and e["mud-steel"].rolling == "constant_torque_explicit", "edem rolling")
check(e["mud-mud"].jkr_overlap_stiffness == 1, "edem JKR stiffness from the overlap")
check(e["mud-mud"].surface_energy == reference.jkr_surface_energy, "edem gamma %g", e["mud-mud"].surface_energy)

-- rolling_integration overrides the conventions' rolling sub-model on both pairs and nothing else;
-- set_interactions replaces the laws with the new choice (slump.lua's lift_rolling_integration).
local function laws_with(conventions, integration)
  local rec = {}
  local sim = recording_sim(rec)
  local P = mud.resolve(declared{contact_conventions = conventions, rolling_integration = integration}, {})
  mud.setup(sim, P, P)
  return rec, P, sim
end
local ei, Pi, sim_i = laws_with("edem", "implicit")
check(ei["mud-mud"].rolling == "constant_torque" and ei["mud-steel"].rolling == "constant_torque", "edem + implicit rolling")
check(ei["mud-mud"].jkr_overlap_stiffness == 1 and Pi.timestep_fraction == 0.2, "edem + implicit keeps the other edem choices")
check(Pi.material_info.rolling == "constant_torque" and mud.describe(Pi):find("(rolling constant_torque)", 1, true),
      "the override is recorded and printed: %s", mud.describe(Pi))
local pe = laws_with("paddy", "explicit")
check(pe["mud-mud"].rolling == "constant_torque_explicit" and pe["mud-steel"].rolling == "constant_torque_explicit", "paddy + explicit rolling")
check(pe["mud-mud"].jkr_overlap_stiffness == 0, "paddy + explicit keeps the paddy JKR stiffness")
local pc = laws_with("paddy", "conventions")
check(pc["mud-mud"].rolling == "constant_torque" and not mud.describe(mud.resolve(declared(), {})):find("(rolling", 1, true), "conventions: no override")
Pi.rolling_integration = "explicit"
mud.set_interactions(sim_i, Pi, Pi, "mud", "steel")
check(ei["mud-mud"].rolling == "constant_torque_explicit" and ei["mud-steel"].rolling == "constant_torque_explicit", "switched during the run")
ok, msg = pcall(mud.pair_specs, {contact_conventions = "paddy", rolling_integration = "halfway"}, Pi)
check(not ok and msg:find("rolling_integration = 'halfway'", 1, true), "bad rolling_integration: %s", tostring(msg))

-- time_integration: the conventions' scheme (velocity Verlet in both) unless given; setup hands it
-- to sim:integration, the run's record and printed line name an override.
check(ei.integration == "velocity_verlet" and pc.integration == "velocity_verlet", "conventions' scheme: %s, %s",
      tostring(ei.integration), tostring(pc.integration))
do
  local rec = {}
  local sim = recording_sim(rec)
  local P = mud.resolve(declared{contact_conventions = "edem", time_integration = "euler"}, {})
  mud.setup(sim, P, P)
  check(rec.integration == "euler" and P.material_info.integration == "euler", "edem + euler: %s", tostring(rec.integration))
  check(mud.describe(P):find("(integration euler)", 1, true), "the override is printed: %s", mud.describe(P))
  check(not mud.describe(mud.resolve(declared(), {})):find("(integration", 1, true), "no override printed by default")
  ok, msg = pcall(mud.resolve, declared{time_integration = "rk4"}, {})
  check(not ok and msg:find("time_integration = 'rk4'", 1, true), "bad time_integration: %s", tostring(msg))
end

-- The calibration input's conventions key: default paddy, edem accepted, anything else refused.
local t = paddy.read_json((mud.materials_file:gsub("materials/paddy_mud%.json$", "calibration/paddy_mud.json")))
check(input_file.read(paddy.write_json("cal_default.json", t)).conventions == "paddy", "input default")
t.conventions = "edem"
check(input_file.read(paddy.write_json("cal_edem.json", t)).conventions == "edem", "input edem")
t.conventions = "liggghts"
ok, msg = pcall(input_file.read, paddy.write_json("cal_bad.json", t))
check(not ok and msg:find("conventions = liggghts", 1, true) and msg:find("cal_bad.json", 1, true), "bad input conventions: %s", tostring(msg))

-- The shipped EDEM-conventions input (calibration/paddy_mud_edem.json) is paddy_mud.json with
-- conventions = edem: the same targets, tolerance, factors and designs.
local cal_dir = mud.materials_file:gsub("materials/paddy_mud%.json$", "calibration/")
local plain, edem = input_file.read(cal_dir .. "paddy_mud.json"), input_file.read(cal_dir .. "paddy_mud_edem.json")
check(plain.conventions == "paddy" and edem.conventions == "edem", "shipped inputs: conventions %s, %s", plain.conventions, edem.conventions)
local function same(a, b, path)
  if type(a) ~= type(b) then error(string.format("paddy_mud_edem.json differs from paddy_mud.json at %s", path)) end
  if type(a) ~= "table" then
    check(a == b, "paddy_mud_edem.json differs from paddy_mud.json at %s: %s against %s", path, tostring(b), tostring(a))
    return
  end
  for k, v in pairs(a) do same(v, b[k], path .. "." .. tostring(k)) end
  for k in pairs(b) do check(a[k] ~= nil, "paddy_mud_edem.json has %s.%s, paddy_mud.json not", path, tostring(k)) end
end
for _, key in ipairs({"measured", "tolerance", "factors", "screening", "steepest_ascent", "box_behnken", "verification",
                      "surrogate", "rheometer", "experiment"}) do
  check(plain[key] ~= nil, "paddy_mud.json has no %s", key)
  same(plain[key], edem[key], key)
end

paddy.result{ok = true}
