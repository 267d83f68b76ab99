-- Observables of the plate tack test (experiments/tack.lua) from the samples of the pull: the
-- plate's displacement u (from the start of the pull, upward) and the pull force F (the downward
-- force of the mud on the plate, positive in tension) at each sample, u ascending. Pure functions
-- of the arrays, except carried(), which reads the spheres.
--
--   local obs = require("lib.tack_observables")
--   local Fs = obs.smooth(u, F, 0.2e-3)            -- moving average over 0.2 mm of travel
--   local peak, at = obs.peak(u, Fs)               -- largest smoothed pull force, where
--   local W = obs.work(u, F)                       -- ∫ max(F, 0) du
--   local range = obs.range(u, Fs, peak, 0.1)      -- last u where Fs > 0.1 peak
--   local release = obs.release(u, Fs)             -- first u where Fs >= 0 (the pre-load released)
--   local detach = obs.detach(u, Fs, peak, final, 0.1) -- last u where Fs > final + 0.1 (peak - final)
--   local grid = obs.profile(u, F, 0.012, 12)      -- {centres =, means =}: bin means on a fixed grid
--   local m = obs.carried(sim, {...})              -- {mass_g =, count =}: mud going up with the plate
local util = require("lib.util")

local M = {}

-- Moving average over a window of travel: Fs_k = mean of F_j over the samples with
-- |u_j − u_k| ≤ width/2 (u ascending). Each window is summed afresh, so a stretch of exact zeros
-- (no contact) stays exactly zero. width 0 returns F unchanged (for distinct u).
function M.smooth(u, F, width)
  local n = #u
  if #F ~= n then error("tack_observables.smooth: u and F differ in length", 2) end
  local out = {}
  local half = math.max(width, 0) / 2
  local lo = 1
  for k = 1, n do
    while u[lo] < u[k] - half do lo = lo + 1 end
    local sum, count, j = 0, 0, lo
    while j <= n and u[j] <= u[k] + half do
      sum, count, j = sum + F[j], count + 1, j + 1
    end
    out[k] = sum / count
  end
  return out
end

-- Largest value of Fs and its displacement (the first where it is reached). Empty: nil.
function M.peak(u, Fs)
  local best, at = nil, nil
  for k = 1, #Fs do
    if best == nil or Fs[k] > best then best, at = Fs[k], u[k] end
  end
  return best, at
end

-- Work of separation W = ∫ max(F, 0) du: the trapezoidal rule on the positive part of the
-- piecewise-linear force (where F changes sign inside an interval only the triangle above zero
-- counts). Compression (the release of the pre-load) does not count.
function M.work(u, F)
  local w = 0
  for k = 2, #u do
    local a, b, du = F[k - 1], F[k], u[k] - u[k - 1]
    if a >= 0 and b >= 0 then
      w = w + 0.5 * (a + b) * du
    elseif a > 0 or b > 0 then
      local p, q = math.max(a, b), math.min(a, b)  -- p > 0 > q
      w = w + 0.5 * p * p / (p - q) * du
    end
  end
  return w
end

-- Release: the first displacement at which Fs is no longer negative (the mud has stopped pushing
-- the plate: the pre-load is released); nil when it pushes to the end.
function M.release(u, Fs)
  for k = 1, #Fs do
    if Fs[k] >= 0 then return u[k] end
  end
  return nil
end

-- Range: the largest displacement at which Fs exceeds `fraction` × peak (0 when the peak is not
-- positive: nothing pulled).
function M.range(u, Fs, peak, fraction)
  if not (peak and peak > 0) then return 0 end
  local limit = fraction * peak
  for k = #Fs, 1, -1 do
    if Fs[k] > limit then return u[k] end
  end
  return 0
end

-- Detachment: the largest displacement at which Fs exceeds the final force by more than
-- `fraction` × (peak − final): where the pull beyond the weight of what the plate carries away
-- ends (the range counts that weight; this does not).
function M.detach(u, Fs, peak, final, fraction)
  local limit = final + fraction * (peak - final)
  for k = #Fs, 1, -1 do
    if Fs[k] > limit then return u[k] end
  end
  return 0
end

-- Force on a fixed grid: `bins` equal bins of [0, distance]; each value the mean of the F
-- samples in its bin (a sample on a boundary belongs to the upper bin, the last bin includes
-- `distance`). Returns {centres = {...}, means = {...}, counts = {...}} in the units of u and F. A
-- bin without a sample is an error (the sampling is too coarse for the grid).
function M.profile(u, F, distance, bins)
  local width = distance / bins
  local sums, counts, centres, means = {}, {}, {}, {}
  for b = 1, bins do sums[b], counts[b] = 0, 0 end
  for k = 1, #u do
    if u[k] >= -1e-12 and u[k] <= distance + 1e-12 then
      local b = math.min(bins, math.floor(u[k] / width + 1e-9) + 1)
      if b >= 1 then
        sums[b], counts[b] = sums[b] + F[k], counts[b] + 1
      end
    end
  end
  for b = 1, bins do
    if counts[b] == 0 then
      error(string.format("tack_observables.profile: no sample in bin %d of %d (%g-%g): sample more densely", b, bins,
                          (b - 1) * width, b * width), 2)
    end
    centres[b], means[b] = (b - 0.5) * width, sums[b] / counts[b]
  end
  return {centres = centres, means = means, counts = counts}
end

-- Mud carried by the plate: spheres within the plate's footprint (centre less than plate_radius
-- + its radius from the axis) moving with it (util.moving_with: faster than half the pull speed).
-- o = {pull_speed =, plate_radius =, density =, axis = {x, y} (default {0, 0})}. → util.carried's
-- {mass_g =, count =}
function M.carried(sim, o)
  local ax, ay = (o.axis or {0, 0})[1], (o.axis or {0, 0})[2]
  return util.carried(sim, function(x, y, z, r) return (x - ax) ^ 2 + (y - ay) ^ 2 <= (o.plate_radius + r) ^ 2 end,
                      o.pull_speed, o.density)
end

return M
