-- The experiments, observables, candidates and free parameter that the discovery benchmarks share
-- (experiments/validation/discovery_blind.lua, the blind benchmark; discovery_sensitivity.lua, the
-- measured sensitivities and confusabilities; docs/discovery.md).
--
--   local bench = require("lib.discovery.benchmark")
--   local exps = bench.experiments{variant = "small", lift_speeds = "", cone_scales = "1,1.5", vane_scale = 4}
--   -- exps[i] = {name =, script =, set = {...}, observables = {{key =, abs =, rel =}, ...}}
--   local sd = bench.noise_sd(o, value)     -- measurement sd of one observable entry
local util = require("lib.util")

local M = {}

-- The candidate lists. Each strength runs from 0 (off) to high (2 mm values: mud.lua coarse grains
-- them; docs/physics.md §2.7); `outside` are effects the workflow is not told about: a parameter
-- moved from its default by a factor.
M.CANDIDATE_SETS = {
  stand_in = {
    candidates = {{name = "wall_friction", parameter = "mud_steel_friction", low = 0, high = 1.0},
                  {name = "rolling_resistance", parameter = "mud_mud_rolling_friction", low = 0, high = 0.3}},
    outside = {{parameter = "mud_mud_friction", default = 0.15, factor = {2.5, 4}}},
  },
  effects = {
    -- bridge volume as a fraction of the sphere volume; viscosity up to 0.02 Pa s (20 x water),
    -- where the film is still resolved by the step; wall JKR energy up to 0.3 J/m^2; pull-off up to
    -- 0.1 of the largest load (0.05 already lowers the 20 mm slump by 95 mm, 0.3 makes the pile stand).
    candidates = {{name = "liquid_bridges", parameter = "liquid_bridge_volume", low = 0, high = 0.05},
                  {name = "lubrication", parameter = "lubrication_viscosity", low = 0, high = 0.02},
                  {name = "wall_adhesion", parameter = "mud_steel_surface_energy", low = 0, high = 0.3},
                  {name = "plastic_adhesion", parameter = "plastic_adhesion", low = 0, high = 0.1}},
    outside = {{parameter = "mud_mud_friction", default = 0.15, factor = {2.5, 4}}},
  },
}

-- The free parameter of every benchmark trial.
M.FREE = {{parameter = "jkr_surface_energy", low = 0.05, high = 0.3}}

-- Observables with their measurement sd: sd = max(abs, rel |value|), abs in the key's unit.
-- The slump's profile is the ring-mean height (profile_mean_mm): the median height of a ring
-- (profile_mm) jumps from 0 to a sphere's height as the pile's edge crosses it, a step no seed
-- scatter of the replicates measures.
M.SLUMP_OBSERVABLES = {{key = "slump_mm", abs = 3}, {key = "slump_flow_mm", abs = 6}, {key = "profile_mean_mm", abs = 4},
                       {key = "history_mm", abs = 4}, {key = "cone_force_N.mean", abs = 0.3, rel = 0.1}}
-- The vane: the steady torque at each speed and the start-up test's peak torque, 5 % (a
-- rheometer's torque is read far better; 5 % is the scatter of repeated fills of a real mud).
M.VANE_OBSERVABLES = {{key = "torque_Nm", abs = 0.001, rel = 0.05}, {key = "startup.peak_torque_Nm", abs = 0.001, rel = 0.05}}

-- The vane read as a rheometer reads one specimen (o.vane_shared_sd > 0): the scatter between fills
-- (5 %) is one factor 1 + eps that every torque of the sweep and the start-up peak share (the
-- input's shared_error), and each torque keeps only its own reading error, VANE_READING_SD.
M.VANE_READING_SD = 0.015
function M.vane_observables(reading_sd)
  return {{key = "torque_Nm", abs = 0.001, rel = reading_sd}, {key = "startup.peak_torque_Nm", abs = 0.001, rel = reading_sd}}
end

-- The plate tack test (tack.lua) scaled by `scale` from its default (cup 80 mm wide and 30 mm
-- deep, plate 50 mm, pressed 2 mm and pulled 12 mm; for 5 mm spheres), pulled at `speed` m/s.
-- Its observables: the peak pull, the tension profile over the pull and the mud carried, each
-- with 10 % error and at least one sphere's weight (mass) at the benchmark's 25 mm spheres (a
-- balance and a load cell read far better; the floor is the coarse mud's own graininess). The
-- approach and press at `press_speed` (default 0.01 m/s, the test's own default).
M.TACK_SPEED = 0.04
M.TACK_OBSERVABLES = {{key = "tack_peak_force_N", abs = 0.135, rel = 0.1}, {key = "tack_tension_profile_N", abs = 0.135, rel = 0.1},
                      {key = "tack_mass_on_plate_g", abs = 13.7, rel = 0.1}}
M.TACK_PRESS_SPEED = 0.01
function M.tack_set(scale, speed, press_speed)
  return {cup_diameter = 0.08 * scale, cup_depth = 0.03 * scale, plate_diameter = 0.05 * scale, approach_gap = 0.001 * scale,
          press_depth = 0.002 * scale, pull_distance = 0.012 * scale, smoothing = 0.0002 * scale, sample_spacing = 2e-5 * scale,
          pull_speed = speed or M.TACK_SPEED, press_speed = press_speed or M.TACK_PRESS_SPEED}
end

function M.noise_sd(o, value)
  return math.max(o.abs, (o.rel or 0) * math.abs(value))
end

-- Settings every slump experiment of the benchmarks shares (shorter settling and rest than the
-- main job's: the benchmark runs hundreds of them).
M.SLUMP_COMMON = {settle_max_time = 1.5, min_rest_time = 0.2, max_time = 4}

-- The vane rheometer scaled by `scale` from the standard one (cup 100 mm wide and 120 mm deep,
-- vane 50 mm by 60 mm, blades from 30 mm): a coarse-grained mud needs a cup many spheres wide (a
-- field vane is this size). Two speeds (the steady torque at each) after a start-up test (its peak
-- torque): a static strength and a flowing one.
M.VANE_SPEEDS_RPM = "10,40"
function M.vane_set(scale, speeds, startup_rpm)
  return {cup_diameter = 0.1 * scale, cup_height = 0.12 * scale, fill_level = 0.12 * scale, vane_diameter = 0.05 * scale,
          vane_height = 0.06 * scale, vane_bottom = 0.03 * scale, speeds_rpm = speeds or M.VANE_SPEEDS_RPM, down_sweep = false,
          startup_rpm = startup_rpm or 5, startup_angle = 60, max_step_time = 3, settle_max_time = 1.5}
end

-- The experiments of a variant: `full` (slump lifted at 0.1 and 0.4 m/s) or `small` (one slump at
-- 0.3 m/s); o.lift_speeds ('' = the variant's) replaces the slump experiments by one per speed;
-- o.cone_scales ('' = the standard cone) runs each in cones of the given sizes (a scale other than
-- 1 appends _cone<percent> to the name and scales the cone's three dimensions); o.vane_scale > 0
-- adds the vane rheometer at that scale, its start-up test at o.vane_startup_rpm (default 5; 60 degrees
-- at 5 rpm take 2 s of simulated time, at 10 rpm 1 s), at o.vane_speeds (rpm, comma-separated; '' = 10,40), its
-- torques each with 5 % error (o.vane_shared_sd = 0) or sharing a fill's error of vane_shared_sd
-- with their own reading error o.vane_reading_sd (default VANE_READING_SD) beside it; o.tack_scale > 0
-- adds the plate tack test at that scale (M.tack_set), pulled at o.tack_speed (default TACK_SPEED), or one
-- tack test per speed of o.tack_speeds (m/s, comma-separated; '' = o.tack_speed alone), each pressed at
-- o.tack_press_speed (default TACK_PRESS_SPEED).
function M.experiments(o)
  local exps
  if o.variant == "small" then
    exps = {{name = "slump", set = {lift_speed = 0.3}}}
  else
    exps = {{name = "slump_slow", set = {lift_speed = 0.1}}, {name = "slump_fast", set = {lift_speed = 0.4}}}
  end
  if (o.lift_speeds or "") ~= "" then
    local speeds = util.numbers(o.lift_speeds, "lift_speeds")
    for _, v in ipairs(speeds) do
      if v <= 0 or v > 2 then error(string.format("discovery benchmark: lift_speeds = %s: each speed must be in (0, 2] m/s", o.lift_speeds), 0) end
    end
    exps = {}
    for _, v in ipairs(speeds) do
      exps[#exps + 1] = {name = string.format("slump_%dmm_per_s", math.floor(v * 1000 + 0.5)), set = {lift_speed = v}}  -- a plain name: no dot
    end
  end
  if (o.cone_scales or "") ~= "" then
    local scales, sized = util.numbers(o.cone_scales, "cone_scales"), {}
    for _, sc in ipairs(scales) do
      if sc < 0.5 or sc > 2 then error(string.format("discovery benchmark: cone_scales = %s: each scale must be in [0.5, 2]", o.cone_scales), 0) end
    end
    for _, e in ipairs(exps) do
      for _, sc in ipairs(scales) do
        local set = {}
        for k, v in pairs(e.set) do set[k] = v end
        local name = e.name
        if sc ~= 1 then
          name = string.format("%s_cone%d", e.name, math.floor(sc * 100 + 0.5))
          set.cone_height, set.cone_top_diameter, set.cone_bottom_diameter = 0.3 * sc, 0.1 * sc, 0.2 * sc
        end
        sized[#sized + 1] = {name = name, set = set}
      end
    end
    exps = sized
  end
  for _, e in ipairs(exps) do
    e.script, e.observables = "slump.lua", M.SLUMP_OBSERVABLES
    for k, v in pairs(M.SLUMP_COMMON) do e.set[k] = v end
  end
  local vs = o.vane_scale or 0
  if vs ~= 0 then
    if vs < 1 or vs > 8 then error(string.format("discovery benchmark: vane_scale = %g: must be 0 (no vane) or in [1, 8]", vs), 0) end
    local speeds = (o.vane_speeds or "") ~= "" and o.vane_speeds or nil
    if speeds then
      for _, v in ipairs(util.numbers(speeds, "vane_speeds")) do
        if v <= 0 or v > 300 then error(string.format("discovery benchmark: vane_speeds = %s: each speed must be in (0, 300] rpm", speeds), 0) end
      end
    end
    local su = o.vane_startup_rpm or 5
    if su <= 0 or su > 20 then error(string.format("discovery benchmark: vane_startup_rpm = %g: must be in (0, 20] rpm", su), 0) end
    local e = {name = string.format("vane_x%g", vs):gsub("%.", "_"), script = "rheometer.lua", set = M.vane_set(vs, speeds, su),
               observables = M.VANE_OBSERVABLES}
    local shared = o.vane_shared_sd or 0
    if shared > 0 then
      local reading = o.vane_reading_sd or M.VANE_READING_SD
      if shared > 0.5 or not (reading > 0 and reading <= 0.5) then
        error(string.format("discovery benchmark: vane_shared_sd = %g and vane_reading_sd = %g: each must be in (0, 0.5]", shared, reading), 0)
      end
      e.observables = M.vane_observables(reading)
      e.shared_error = {rel_sd = shared, keys = {"torque_Nm", "startup.peak_torque_Nm"}}
    end
    exps[#exps + 1] = e
  end
  local ts = o.tack_scale or 0
  if ts ~= 0 then
    if ts < 1 or ts > 10 then error(string.format("discovery benchmark: tack_scale = %g: must be 0 (no tack test) or in [1, 10]", ts), 0) end
    local name = string.format("tack_x%g", ts):gsub("%.", "_")
    local press = o.tack_press_speed or M.TACK_PRESS_SPEED
    if not (press > 0 and press <= 1) then error(string.format("discovery benchmark: tack_press_speed = %g: must be in (0, 1] m/s", press), 0) end
    -- one tack test per pull speed (a viscous pull grows with the speed, a static one does not);
    -- one speed keeps the plain name
    local single = (o.tack_speeds or "") == ""
    local speeds = single and {o.tack_speed or M.TACK_SPEED} or util.numbers(o.tack_speeds, "tack_speeds")
    for _, v in ipairs(speeds) do
      if not (v > 0 and v <= 1) then
        error(single and string.format("discovery benchmark: tack_speed = %g: must be in (0, 1] m/s", v)
              or string.format("discovery benchmark: tack_speeds = %s: each speed must be in (0, 1] m/s", o.tack_speeds), 0)
      end
    end
    for _, v in ipairs(speeds) do
      exps[#exps + 1] = {name = single and name or string.format("%s_%dmm_per_s", name, math.floor(v * 1000 + 0.5)), script = "tack.lua",
                         set = M.tack_set(ts, v, press), observables = M.TACK_OBSERVABLES}
    end
  end
  return exps
end

return M
