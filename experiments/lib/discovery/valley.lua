-- The valley points of the refit's start scan (experiments/discover.lua, step 4; docs/discovery.md
-- "Steps"): the calibration moved the free parameters θ by β·λ to absorb an effect of strength λ,
-- β = (JᵀΣ⁻¹J)⁻¹JᵀΣ⁻¹g the least-squares fit of the effect's signature g by the free parameters'
-- Jacobian J, so the truth lies near the line θ(λ) = θ̂ − β·λ. Point k = 0…n puts λ at
-- λ̂ + k/n·(high − λ̂) (the score test's λ̂ is linear and underestimates a strong effect) and θ at
-- θ(λ), clipped to the box; each point k ≥ 1 has a twin with θ moved half a stratum (1/(2n) of
-- each range), up for odd k and down for even k, for the curvature of the valley. A λ̂ at or above
-- the range's top (`whole_range`) is no guide: a response that rises in a step and saturates (the
-- layer of mud a strongly adhering tack plate carries) makes the linear estimate overshoot, so λ
-- then runs over low + k/n·(high − low), k = 1…n.
--
--   local valley = require("lib.discovery.valley")
--   local pts = valley.points{theta = {0.14}, beta = {0.2}, lambda = 0.3, n = 5, whole_range = true,
--                             theta_low = {0.05}, theta_high = {0.3}, lambda_low = 0, lambda_high = 0.3}
--   -- pts[i] = {theta = {...}, lambda = value}
local M = {}

-- Whether a linear estimate says nothing of where the strength lies: at or above the range's top.
function M.whole_range(estimate, high)
  return estimate ~= nil and estimate >= high
end

function M.points(v)
  local n = v.n
  if not (type(n) == "number" and n >= 1 and n == math.floor(n)) then error(string.format("valley: n = %s must be a positive integer", tostring(n)), 0) end
  if not (v.lambda_high > v.lambda_low) then
    error(string.format("valley: the strength's range [%g, %g] is empty", v.lambda_low, v.lambda_high), 0)
  end
  local function clip(x, lo, hi) return math.min(hi, math.max(lo, x)) end
  local from = v.whole_range and v.lambda_low or v.lambda
  local pts = {}
  for k = v.whole_range and 1 or 0, n do
    local lam = from + k / n * (v.lambda_high - from)
    for side = 0, (k > 0 and 1 or 0) do
      local theta = {}
      for j = 1, #v.theta do
        local lo, hi = v.theta_low[j], v.theta_high[j]
        local offset = side == 1 and (k % 2 == 1 and 1 or -1) * (hi - lo) / (2 * n) or 0
        theta[j] = clip(v.theta[j] - v.beta[j] * lam + offset, lo, hi)
      end
      pts[#pts + 1] = {theta = theta, lambda = lam}
    end
  end
  return pts
end

return M
