-- The design of the refit's zoom (experiments/discover.lua, step 4; docs/discovery.md): a
-- central composite design in a box of +-h of each range around a point, clipped to the ranges:
-- the centre, two axial points per dimension (on the box's faces) and every corner, 1 + 2d + 2^d
-- points — enough for the quadratic response surface (1 + d + d(d+1)/2 coefficients) that the
-- zoom fits (G. E. P. Box and K. B. Wilson, "On the experimental attainment of optimum
-- conditions", J. R. Stat. Soc. B 13, 1951; face-centred variant). Not paddy.doe.design's CCF:
-- that one is centred on its box, while here the centre and the axial points stay at the refit
-- point when the box is clipped by a range (a strength near the top of its range), so the point
-- the zoom starts from is always run. A centre on a bound of its range (a refit that ran into the
-- bound) would leave that dimension two levels (its axial point on the bound is the centre), too
-- few for its quadratic term: there the box reaches 2h of the range inward, and the axial points
-- lie at its far side and half-way, so the dimension has three levels (bound, half-way, far side).
--
--
-- When to zoom (M.reason): while the misfit the refit leaves at the confirmation seeds is
-- significant (the score test's Q0, which allows for the resolution shift), and also while its
-- RMS standardised residual stays above `above` noise sd even when the test does not call it
-- significant: the test projects out the resolution shift's direction, so a refit whose surface
-- has missed the valley floor along that direction (the step of wall adhesion's carried mass) can
-- pass it with an RMS well above the noise; a zoomed point is kept only when its RMS is smaller.
--
--   local zoom = require("lib.discovery.zoom")
--   local X, lo, hi = zoom.design({0.2, 0.05}, {0, 0}, {0.3, 0.1}, 0.15)
--   local why = zoom.reason(diagnosis.q0_significant, rms, 1.2)  -- nil: no zoom
local M = {}

-- significant: the misfit test's verdict; rms: the RMS standardised residual; above: the RMS
-- above which a zoom is tried anyway (0: only when significant). Returns why to zoom, or nil.
function M.reason(significant, rms, above)
  if significant then return "misfit left significant" end
  if above and above > 0 and rms and rms > above then
    return string.format("RMS standardised residual %.3g above %.3g noise sd", rms, above)
  end
  return nil
end

-- x0: the centre; lower, upper: the ranges; h: the half-width as a fraction of each range.
-- Returns the points (list of coordinate lists) and the zoom box (lo, hi).
function M.design(x0, lower, upper, h)
  local d = #x0
  if not (h > 0 and h <= 0.5) then error(string.format("zoom: half-width %g must be in (0, 0.5]", h), 0) end
  local lo, hi, axial = {}, {}, {}
  for j = 1, d do
    if not (upper[j] > lower[j]) then error(string.format("zoom: range %d is empty [%g, %g]", j, lower[j], upper[j]), 0) end
    if x0[j] < lower[j] or x0[j] > upper[j] then error(string.format("zoom: centre %g lies outside [%g, %g]", x0[j], lower[j], upper[j]), 0) end
    local w = h * (upper[j] - lower[j])
    lo[j], hi[j] = math.max(lower[j], x0[j] - w), math.min(upper[j], x0[j] + w)
    if x0[j] == upper[j] then
      lo[j] = math.max(lower[j], x0[j] - 2 * w)
      axial[j] = {lo[j], 0.5 * (lo[j] + x0[j])}
    elseif x0[j] == lower[j] then
      hi[j] = math.min(upper[j], x0[j] + 2 * w)
      axial[j] = {0.5 * (x0[j] + hi[j]), hi[j]}
    else
      axial[j] = {lo[j], hi[j]}
    end
  end
  local X = {{table.unpack(x0)}}
  for j = 1, d do
    for _, v in ipairs(axial[j]) do
      local x = {table.unpack(x0)}
      x[j] = v
      X[#X + 1] = x
    end
  end
  for corner = 0, (1 << d) - 1 do
    local x = {}
    for j = 1, d do x[j] = (corner >> (j - 1)) & 1 == 1 and hi[j] or lo[j] end
    X[#X + 1] = x
  end
  return X, lo, hi
end

return M
