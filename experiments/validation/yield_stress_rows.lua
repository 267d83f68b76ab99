-- The rows of validation/yield_stress.lua: one per set and seed (ys_runs.csv, the study's "runs")
-- and, with a vane depth series, one per set, seed and fill level (ys_depth_runs.csv,
-- "depth_runs"), built from the campaign's finished runs or read back from a finished study's
-- yield_stress_study.json (with_studies), so that more seeds can be added to a study without
-- running its seeds again. The statistics of the study read only these rows.
local mohr_coulomb = require("lib.mohr_coulomb")

local M = {}

-- The row of set `level` ({label, value}) and seed s from its slump and its vane at the reference
-- fill level (entries {result, wall} of finished runs, or nil).
function M.run_row(level, s, slump, vane)
  local sl, va = slump and slump.result, vane and vane.result
  local row = {set = level.label, value = level.value, seed = s,
               slump_mm = sl and sl.slump_mm, slump_flow_mm = sl and sl.slump_flow_mm,
               fill_solid_fraction = sl and sl.fill_solid_fraction,
               slump_yield_stress_Pa = sl and sl.yield_stress_Pa, slump_at_rest = sl and sl.at_rest,
               vane_peak_torque_Nm = va and va.startup and va.startup.peak_torque_Nm,
               vane_peak_angle_deg = va and va.startup and va.startup.peak_angle_deg,
               vane_peak_reached = va and va.startup and va.startup.peak_reached,
               vane_yield_stress_Pa = va and va.yield_stress_Pa,
               slump_wall_s = slump and slump.wall, vane_wall_s = vane and vane.wall}
  if row.slump_yield_stress_Pa and row.vane_yield_stress_Pa then row.ratio = row.vane_yield_stress_Pa / row.slump_yield_stress_Pa end
  return row
end

-- The row of the vane of set `level` and seed s at fill level f (the fi-th, shallowest first) from
-- its finished run (nil: a row with the set, seed and level only). The overburden at the blades'
-- mid-height: hydrostatic ρ_p φ g z and, with P.janssen_lateral_ratio > 0, Janssen's; with the
-- stresses measured on the sheared surface (rheometer.lua startup_stress_every), those as the vane
-- starts and at its peak. The shallowest level's vane over its seed's slump as ratio_to_slump.
function M.depth_row(level, s, f, fi, vane, slump, P)
  local row = {set = level.label, value = level.value, seed = s, fill_level = f}
  local v = vane and vane.result
  if not (v and v.yield_stress_Pa) then return row end
  local z = v.fill_level - (v.vane.bottom + v.vane.height / 2)
  row.depth_mid_m = z
  row.cup_height = v.cup_height
  row.fill_solid_fraction = v.fill_solid_fraction
  row.bulk_density = v.mud_density * v.fill_solid_fraction
  row.sigma_v_Pa = mohr_coulomb.overburden{particle_density = v.mud_density, solid_fraction = v.fill_solid_fraction, depth = z}
  if P.janssen_lateral_ratio > 0 then
    row.sigma_janssen_Pa = mohr_coulomb.overburden{particle_density = v.mud_density, solid_fraction = v.fill_solid_fraction,
      depth = z, janssen = {lateral_ratio = P.janssen_lateral_ratio, wall_friction = P.janssen_wall_friction,
                            radius = v.vane.cup_diameter / 2}}
  end
  local at_peak = v.startup.stress_at_peak  -- measured on the sheared surface at the peak
  if at_peak then
    row.sigma_n_start_Pa = v.fill_stress and v.fill_stress.sheared_normal_Pa
    row.sigma_v_measured_Pa = v.fill_stress and v.fill_stress.sigma_v_Pa
    row.sigma_n_peak_Pa, row.sigma_rr_peak_Pa = at_peak.sigma_n_Pa, at_peak.sigma_rr_Pa
    row.shear_side_peak_Pa, row.side_torque_share = at_peak.shear_side_Pa, at_peak.side_torque_share
  end
  row.particles = v.particles
  row.peak_torque_Nm = v.startup.peak_torque_Nm
  row.peak_angle_deg = v.startup.peak_angle_deg
  row.peak_reached = v.startup.peak_reached
  row.vane_yield_stress_Pa = v.yield_stress_Pa
  row.wall_s = vane.wall
  local tau_slump = slump and slump.result.yield_stress_Pa
  if fi == 1 and tau_slump then row.ratio_to_slump = row.vane_yield_stress_Pa / tau_slump end
  return row
end

local function same_number(a, b)
  return type(a) == "number" and type(b) == "number" and math.abs(a - b) <= 1e-9 * math.max(1, math.abs(a), math.abs(b))
end

-- The index of the set of `levels` whose value is `value` (nil: none).
local function level_of(levels, value)
  for li, l in ipairs(levels) do if same_number(l.value, value) then return li end end
end

local function list_text(v)
  if type(v) ~= "table" then return tostring(v) end
  local t = {}
  for k, x in ipairs(v) do t[k] = string.format("%g", x) end
  return table.concat(t, ",")
end

-- Reads the finished studies named in P.with_studies (comma-separated output directories of
-- yield_stress.lua, or their yield_stress_study.json), before anything runs. A study must have the
-- same design as this one (st: levels, seeds, fill_levels; P: the parameter, both sphere sizes, the
-- extra settings of both tests, Janssen's K and wall friction) and none of this study's or another
-- pooled study's seeds; anything else is refused, naming the study and the setting. Returns the
-- list of {file, doc} for M.pool.
function M.load_studies(P, st)
  local paths = {}
  for item in P.with_studies:gmatch("[^,]+") do
    local p = item:match("^%s*(.-)%s*$")
    if p ~= "" then paths[#paths + 1] = p end
  end
  local taken, loaded = {}, {}
  for _, s in ipairs(st.seeds) do taken[s] = "this study" end
  for _, path in ipairs(paths) do
    local file = path:match("%.json$") and path or (path .. "/yield_stress_study.json")
    local f = io.open(file, "r")
    if not f then error("with_studies: " .. path .. ": no yield_stress_study.json there (a finished yield_stress.lua study)", 0) end
    f:close()
    local doc = paddy.read_json(file)
    local function refuse(what, theirs, ours)
      error(string.format("with_studies: %s: %s is %s there, %s here: only a study of the same design can be pooled",
                          file, what, tostring(theirs), tostring(ours)), 0)
    end
    if doc.parameter ~= P.parameter then refuse("parameter", doc.parameter, P.parameter) end
    if not same_number(doc.slump_diameter, P.slump_diameter) then refuse("slump_diameter", doc.slump_diameter, P.slump_diameter) end
    if not same_number(doc.rheometer_diameter, P.rheometer_diameter) then refuse("rheometer_diameter", doc.rheometer_diameter, P.rheometer_diameter) end
    if (doc.slump_set or "") ~= P.slump_set then refuse("slump_set", "'" .. tostring(doc.slump_set) .. "'", "'" .. P.slump_set .. "'") end
    if (doc.rheometer_set or "") ~= P.rheometer_set then refuse("rheometer_set", "'" .. tostring(doc.rheometer_set) .. "'", "'" .. P.rheometer_set .. "'") end
    -- The sets: the same values, in any order.
    local theirs = {}
    for _, s in ipairs(doc.summary or {}) do theirs[#theirs + 1] = s.value end
    local ours = {}
    for k, l in ipairs(st.levels) do ours[k] = l.value end
    local matched = #theirs == #ours
    for _, v in ipairs(theirs) do matched = matched and level_of(st.levels, v) ~= nil end
    if not matched then refuse("the sets' values", list_text(theirs), list_text(ours)) end
    -- The depth series: the same fill levels and the same Janssen overburden.
    local ds = doc.depth_series
    local their_fills = ds and ds.fill_levels
    local same_fills = (their_fills == nil) == (st.fill_levels == false)
    if same_fills and their_fills then
      same_fills = #their_fills == #st.fill_levels
      for k, fl in ipairs(st.fill_levels) do same_fills = same_fills and same_number(their_fills[k], fl) end
    end
    if not same_fills then refuse("vane_fill_levels", their_fills and list_text(their_fills) or "none",
                                  st.fill_levels and list_text(st.fill_levels) or "none") end
    if their_fills then
      for _, set in ipairs(ds.sets or {}) do
        local j = set.janssen
        local k, mu = j and j.lateral_ratio or 0, j and j.wall_friction
        if not same_number(k, P.janssen_lateral_ratio) then
          refuse("janssen_lateral_ratio", k, P.janssen_lateral_ratio)
        end
        if k > 0 and not same_number(mu, P.janssen_wall_friction) then refuse("janssen_wall_friction", mu, P.janssen_wall_friction) end
      end
    end
    -- The seeds: none twice.
    for _, s in ipairs(doc.seeds or {}) do
      if taken[s] then
        error(string.format("with_studies: %s: seed %d is also in %s (a seed pooled twice would count twice)", file, s, taken[s]), 0)
      end
      taken[s] = file
    end
    loaded[#loaded + 1] = {file = file, doc = doc}
  end
  return loaded
end

-- Adds the rows of the studies M.load_studies read to st.run_of and st.depth_of, under this
-- study's set labels (a run a study lacks becomes an empty row). Returns the seeds to report (st's
-- as given when nothing is pooled, else the union in increasing order) and a list describing the
-- pooled studies (nil when none).
function M.pool(loaded, st)
  if #loaded == 0 then return st.seeds, nil end
  local all, pooled = {}, {}
  for _, s in ipairs(st.seeds) do all[#all + 1] = s end
  for _, study in ipairs(loaded) do
    local doc, mine = study.doc, {}
    for _, s in ipairs(doc.seeds) do
      mine[s] = true
      all[#all + 1] = s
      for li, l in ipairs(st.levels) do
        st.run_of[li][s] = {set = l.label, value = l.value, seed = s}
        if st.fill_levels then
          st.depth_of[li][s] = {}
          for fi, fl in ipairs(st.fill_levels) do st.depth_of[li][s][fi] = {set = l.label, value = l.value, seed = s, fill_level = fl} end
        end
      end
    end
    for _, r in ipairs(doc.runs or {}) do
      local li = level_of(st.levels, r.value)
      if li and mine[r.seed] then
        r.set = st.levels[li].label
        st.run_of[li][r.seed] = r
      end
    end
    for _, r in ipairs(doc.depth_runs or {}) do
      local li = level_of(st.levels, r.value)
      if li and mine[r.seed] and st.fill_levels then
        for fi, fl in ipairs(st.fill_levels) do
          if same_number(r.fill_level, fl) then
            r.set = st.levels[li].label
            st.depth_of[li][r.seed][fi] = r
          end
        end
      end
    end
    pooled[#pooled + 1] = {study = study.file, seeds = doc.seeds, failed = doc.failed, finished = doc.finished}
  end
  table.sort(all)
  return all, pooled
end

return M
