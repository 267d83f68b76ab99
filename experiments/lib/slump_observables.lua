-- Observables of the slump test on grids that do not depend on the run, so that runs can be
-- stacked into one vector (experiments/discover.lua, docs/discovery.md): the pile profile h(r)
-- at fixed radii, the slump history s(t) at fixed times after the lift starts, the vertical
-- force of the mud on the cone during the lift, and the mud carried up by the cone.
--
--   local obs = require("lib.slump_observables")
--   local p = obs.profile(sim)                         --> {radii_mm = {...}, h_mm = {...}}
--   local s = obs.history_at(history, obs.HISTORY_TIMES) --> slump [mm] at each time
--   local f = obs.cone_force(sim:wall_load_history(cone), t_lift, t_stop) --> {mean =, peak =, samples =}
--   local m = obs.carried_by_cone(sim, {...})          --> {mass_g =, count =}
--   obs.at_rest_cone_free(history.rows, 0.1, 0.01, 1)  --> whether the run can end (slump.lua step 3)
local sampler = require("lib.sampler")
local util = require("lib.util")

local M = {}

-- Profile: bins of PROFILE_BIN from the axis to PROFILE_R_MAX (12 bins, centres 12.5 ... 287.5 mm);
-- the height of a bin is the median over its angular cells of the highest sphere top (0 where no
-- sphere is: the plate), sim:measure_profile (docs/experiments.md); h_mean_mm is the mean over the
-- cells instead (volume per area of the ring), which moves continuously as the pile's edge crosses
-- a ring where the median jumps between 0 and a sphere's height.
M.PROFILE_BIN = 0.025
M.PROFILE_R_MAX = 0.3
-- Slump history: seconds after the start of the lift. After the run stopped (pile at rest) the
-- last sample holds.
M.HISTORY_TIMES = {0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0}

function M.profile(sim)
  local bins = sim:measure_profile{axis = {0, 0}, base_z = 0, bin_width = M.PROFILE_BIN, r_max = M.PROFILE_R_MAX,
                                   largest_cluster = true}
  local radii, h, h_mean = {}, {}, {}
  for k, b in ipairs(bins) do
    radii[k], h[k], h_mean[k] = b.r * 1000, b.h * 1000, b.h_mean * 1000
  end
  return {radii_mm = radii, h_mm = h, h_mean_mm = h_mean}
end

-- Slump [mm] of history rows ({t =, slump_mm =}, t ascending) at each of `times`, linearly
-- interpolated (lib/sampler.lua); before the first sample the first value, after the last the last.
function M.history_at(history, times)
  assert(#history > 0, "slump_observables.history_at: empty history")
  return sampler.interpolate(history, "slump_mm", times)
end

-- Vertical force of the mud on the cone, positive downward (the mud holds the cone back), over
-- the load samples with t0 <= t <= t1 (absolute times) up to the last one with a load: mean and
-- peak while the mud loads the cone. The samples after the last load (the cone free, an exact zero
-- force) are left out, so that the mean does not depend on how long the cone rose, or the run
-- went on, after the mud let go of it (slump.lua's two ways to end the lift). `samples` as
-- sim:wall_load_history returns them ({t =, force = {fx, fy, fz}}, the force the particles exert).
function M.cone_force(samples, t0, t1)
  local window = {}
  for _, s in ipairs(samples) do
    if s.t >= t0 - 1e-12 and s.t <= t1 + 1e-12 then window[#window + 1] = s end
  end
  local last = #window
  while last > 0 and window[last].force[1] == 0 and window[last].force[2] == 0 and window[last].force[3] == 0 do
    last = last - 1
  end
  if last == 0 then return {mean = 0, peak = 0, samples = 0} end
  local sum, peak = 0, -math.huge
  for k = 1, last do
    local down = -window[k].force[3]
    sum, peak = sum + down, math.max(peak, down)
  end
  return {mean = sum / last, peak = peak, samples = last}
end

-- Mud carried by the cone: spheres whose centre lies above the cone's bottom edge (z_bottom) and
-- inside its inner surface plus one radius, moving with it (util.moving_with: stuck to its inside).
-- o = {lift_speed =, z_bottom =, radius_bottom =, radius_top =, height =, density =}. → util.carried's
-- {mass_g =, count =}
function M.carried_by_cone(sim, o)
  return util.carried(sim, function(x, y, z, r)
    local h = z - o.z_bottom
    if h < 0 or h > o.height then return false end
    local R = o.radius_bottom + (o.radius_top - o.radius_bottom) * h / o.height
    return x ^ 2 + y ^ 2 <= (R + r) ^ 2
  end, o.lift_speed, o.density)
end

-- Largest magnitude of the force in the load samples after the first `seen` ones (0 when there
-- are none, or when no sphere touched the wall in any of them: the engine records an exact zero
-- then), and tells `set_seen` how many samples it has looked at.
function M.largest_load(samples, seen, set_seen)
  local largest = 0
  for k = seen + 1, #samples do
    local f = samples[k].force
    largest = math.max(largest, math.sqrt(f[1] ^ 2 + f[2] ^ 2 + f[3] ^ 2))
  end
  set_seen(#samples)
  return largest
end

-- The pile at rest and the cone free of mud over the last `window` seconds of history rows
-- ({t =, rms_speed =, slump_mm =, cone_load_N =}, t ascending): the rows from the last one at or
-- before t_last − window (so that they span the window whatever the rounding of the sample times
-- to whole steps) to the last all have their RMS speed below `speed` and no load on the cone, and
-- their slumps differ by at most `tolerance` mm (0: not checked). After such a window nothing can
-- move the pile again: the cone, the only moving wall, touches no sphere, and the spheres are at rest.
function M.at_rest_cone_free(rows, window, speed, tolerance)
  if not (window > 0) or #rows == 0 then return false end
  local start = rows[#rows].t - window + 1e-9
  local lo, hi = math.huge, -math.huge
  for k = #rows, 1, -1 do
    local row = rows[k]
    if not (row.rms_speed < speed) or row.cone_load_N ~= 0 then return false end
    lo, hi = math.min(lo, row.slump_mm), math.max(hi, row.slump_mm)
    if row.t <= start then return not (tolerance > 0) or hi - lo <= tolerance end
  end
  return false  -- the rows do not reach back a whole window
end

-- Whether sphere i moves with the rising cone (see carried_by_cone): used to leave such spheres
-- out of "the highest particle under the cone" that decides when the lift stops.
function M.moving_with_cone(vz, lift_speed)
  return util.moving_with(vz, lift_speed)
end

return M
