-- The named strength extrapolated to a finer model (experiments/discover.lua, step 4;
-- docs/discovery.md "Steps"). The refit found x̂ = (θ̂, λ̂) where the model at sphere diameter d fits
-- the measurements, f_d(x̂) ≈ y; the resolution runs at x̂ give b = f_cd(x̂) − f_d(x̂) (standardised
-- observables). With G = ∂f/∂x at x̂ (natural units of x), f_cd(x̂ + Δ) ≈ y gives, by weighted least
-- squares with the refit's weights W = Σ⁻¹ (the Gauss–Newton normal equations, paddy.doe.gauss_newton),
--   Δ = −(GᵀWG)⁻¹GᵀW b,
-- and the corrected strength λ̂ + Δ_λ (λ the last coordinate): a first-order extrapolation of the
-- fitted strength toward the finer model. Δ is linear in b, whose noise is one seed's scatter ×
-- (1/resolution_seeds + 1/K) (b is the mean of the resolution runs minus the mean of K confirmation
-- runs); that scatter of Δ_λ is measured by applying the same map to each confirmation run's
-- deviation from their mean (K − 1 degrees of freedom), so
--   se_shift² = Σ_k (A d_k)_λ² / (K − 1) · (1/resolution_seeds + 1/K),   A = −(GᵀWG)⁻¹GᵀW,
-- and the corrected value's se is √(se² + se_shift²), se the refit's.
--
--   local resolution = require("lib.discovery.resolution")
--   local rc = resolution.corrected{jacobian = G, shift = b, deviations = {d1, d2, ...}, weights = Sigma,
--                                   lambda = 0.25, se = 0.01, low = 0, high = 0.3, resolution_seeds = 2}
local doe = require("paddy.doe")
local M = {}

-- The λ coordinate of A v, or nil when G is rank-deficient.
local function mapped(G, W, v)
  local d = #G[1]
  local zeros, neg = {}, {}
  for j = 1, d do zeros[j] = 0 end
  for i = 1, #v do neg[i] = -v[i] end
  local ok, gn = pcall(doe.gauss_newton, {theta = zeros, residual = neg, jacobian = G, covariance = W, damping = 0})
  if not ok or (gn.rank and gn.rank < d) then return nil end
  return gn.step[d]
end

-- Returns {value, low, high, se, shift, se_shift, clipped} (value and interval clipped to [low, high]),
-- or nil with fewer than two deviations or a degenerate G.
function M.corrected(a)
  local K = #a.deviations
  if K < 2 then return nil end
  if not (a.resolution_seeds and a.resolution_seeds >= 1) then error("resolution.corrected: resolution_seeds must be >= 1", 0) end
  local delta = mapped(a.jacobian, a.weights, a.shift)
  if not delta then return nil end
  local ss = 0
  for k = 1, K do
    local s_k = mapped(a.jacobian, a.weights, a.deviations[k])
    if not s_k then return nil end
    ss = ss + s_k ^ 2
  end
  local se_shift = math.sqrt(ss / (K - 1) * (1 / a.resolution_seeds + 1 / K))
  local raw = a.lambda + delta
  local value = math.min(a.high, math.max(a.low, raw))
  local se = math.sqrt(a.se ^ 2 + se_shift ^ 2)
  return {value = value, low = math.max(a.low, value - 1.96 * se), high = math.min(a.high, value + 1.96 * se), se = se,
          shift = delta, se_shift = se_shift, clipped = value ~= raw}
end

return M
