-- The spread of a refitted parameter over specimens (discover.lua, step 4: the strength's
-- se_specimen). The measurements y are one specimen (or the mean of n), whose seed scatter moves
-- a whole curve together (a tack test's 24 bins, a profile); the shrunk covariance in the
-- misfit's weights counts those bins as many independent readings, so the linearised se of the
-- refit is too small. Each run of a group simulated at the refit point (the confirmation runs, whose
-- scatter the effect itself sets) stands for another specimen: the quadratic response surface
-- through the refit's design is solved again for y + d_k and y - d_k, d_k the run's deviation from
-- the group's mean, and
--   se_specimen = sqrt( sum over the 2K solutions of (x_j - mean)^2 / (2K) * K / (K - 1) )
-- which for a linear model x_j = x0 + g . (y - y0) is exactly the sample sd of g . d_k over the K
-- runs (K - 1 degrees of freedom; the antithetic pair keeps the draws' mean at y). A parametric
-- bootstrap over specimens: B. Efron and R. J. Tibshirani, An Introduction to the Bootstrap,
-- Chapman & Hall 1993, ch. 6.
local doe = require("paddy.doe")

local M = {}

-- design = {points, values, lower, upper} (doe.response_surface's), weights the misfit's
-- covariance, j the coordinate, runs the group's stacked vectors, y the measurements. nil when
-- fewer than two runs or fewer than two surfaces can be solved.
function M.se(design, weights, j, runs, y)
  if not design or #runs < 2 then return nil end
  local m = #y
  local mean = {}
  for i = 1, m do
    local s = 0
    for _, f in ipairs(runs) do s = s + f[i] end
    mean[i] = s / #runs
  end
  local xs = {}
  for _, f in ipairs(runs) do
    for _, sign in ipairs({1, -1}) do
      local yk = {}
      for i = 1, m do yk[i] = y[i] + sign * (f[i] - mean[i]) end
      local ok, rs = pcall(doe.response_surface, {points = design.points, values = design.values, measured = yk,
                                                  covariance = weights, lower = design.lower, upper = design.upper})
      if ok then xs[#xs + 1] = rs.x[j] end
    end
  end
  if #xs < 2 then return nil end
  local mx, ss = 0, 0
  for _, x in ipairs(xs) do mx = mx + x / #xs end
  for _, x in ipairs(xs) do ss = ss + (x - mx) ^ 2 end
  return math.sqrt(ss / #xs * #runs / (#runs - 1))
end

return M
