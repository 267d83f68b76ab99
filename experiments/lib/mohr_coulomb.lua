-- The vane depth series of validation/yield_stress.lua: the Mohr–Coulomb line of the vane's peak
-- stress against the overburden at the blades' mid-height. A module of its own (not lib/rheology.lua,
-- which rheometer.lua requires) so that a change here does not change the rheometer's job keys
-- (docs/campaign.md: a job's key hashes the modules its script requires).
local M = {}

-- Mohr–Coulomb line τ = c + σ·tanφ through (σ, τ) points by ordinary least squares: the vane's
-- peak stress at several overburdens σ (the depth series of validation/yield_stress.lua). c is the
-- pressure-independent (cohesive) part, tanφ the friction coefficient of the sheared packing.
-- Standard errors from the residual variance s² = SSE/(n − 2) (nil for n = 2: an exact line):
--     se(tanφ) = s/√Sxx,  se(c) = s·√(1/n + σ̄²/Sxx).
-- Refuses fewer than 2 points, unequal lengths, a non-positive or non-finite σ, a non-finite τ and
-- fewer than 2 distinct σ (no line).
-- args: {sigma = {...}, tau = {...}}; returns {c=, tan_phi=, se_c=, se_tan_phi=, n=, dof=, r2=, residuals=}.
function M.fit(args)
  local x, y = args.sigma, args.tau
  if type(x) ~= "table" or type(y) ~= "table" then error("mohr_coulomb.fit: needs sigma = {...} and tau = {...}", 2) end
  local n = #x
  if n ~= #y then error(string.format("mohr_coulomb.fit: %d stresses but %d shear stresses", n, #y), 2) end
  if n < 2 then error(string.format("mohr_coulomb.fit: %d point(s): needs at least 2 overburdens", n), 2) end
  local sx, sy = 0, 0
  for k = 1, n do
    if type(x[k]) ~= "number" or not (x[k] > 0) or x[k] == math.huge then
      error(string.format("mohr_coulomb.fit: sigma[%d] = %s: the normal stress must be positive and finite", k, tostring(x[k])), 2)
    end
    if type(y[k]) ~= "number" or y[k] ~= y[k] or math.abs(y[k]) == math.huge then
      error(string.format("mohr_coulomb.fit: tau[%d] = %s is not a finite number", k, tostring(y[k])), 2)
    end
    sx, sy = sx + x[k], sy + y[k]
  end
  local xm, ym = sx / n, sy / n
  local sxx, sxy, syy = 0, 0, 0
  for k = 1, n do
    sxx = sxx + (x[k] - xm) ^ 2
    sxy = sxy + (x[k] - xm) * (y[k] - ym)
    syy = syy + (y[k] - ym) ^ 2
  end
  if not (sxx > 1e-12 * xm * xm * n) then
    error("mohr_coulomb.fit: all points at one normal stress: needs at least 2 distinct overburdens", 2)
  end
  local b = sxy / sxx
  local a = ym - b * xm
  local sse, residuals = 0, {}
  for k = 1, n do
    residuals[k] = y[k] - (a + b * x[k])
    sse = sse + residuals[k] ^ 2
  end
  local fit = {c = a, tan_phi = b, n = n, dof = n - 2, residuals = residuals, sigma_mean = xm,
               r2 = syy > 0 and 1 - sse / syy or 1}
  if n > 2 then
    local s = math.sqrt(sse / (n - 2))
    fit.se_tan_phi = s / math.sqrt(sxx)
    fit.se_c = s * math.sqrt(1 / n + xm * xm / sxx)
  end
  return fit
end

-- Mean vertical stress at depth `depth` below a free surface under the bulk density
-- particle_density × solid_fraction. Without `janssen` hydrostatic (no wall friction):
-- σ_v = ρ_bulk g z. With janssen = {lateral_ratio = K, wall_friction = μ_w, radius = R} the cup wall
-- carries part of the weight (Janssen 1895): σ_v = ρ_bulk g λ (1 − e^(−z/λ)), λ = R / (2 K μ_w),
-- which tends to ρ_bulk g z for K μ_w → 0.
function M.overburden(args)
  local rho, phi, z, g = args.particle_density, args.solid_fraction, args.depth, args.gravity or 9.81
  for name, v in pairs({particle_density = rho, solid_fraction = phi, depth = z}) do
    if type(v) ~= "number" or not (v > 0) then error(string.format("overburden: %s = %s must be positive", name, tostring(v)), 2) end
  end
  if phi >= 1 then error(string.format("overburden: solid_fraction = %g must be below 1", phi), 2) end
  local j = args.janssen
  if j then
    for _, name in ipairs({"lateral_ratio", "wall_friction", "radius"}) do
      if type(j[name]) ~= "number" or not (j[name] >= 0) then
        error(string.format("overburden: janssen.%s = %s must be a number >= 0", name, tostring(j[name])), 2)
      end
    end
    if not (j.radius > 0) then error("overburden: janssen.radius must be positive", 2) end
    local km = j.lateral_ratio * j.wall_friction
    if km > 0 then
      local lambda = j.radius / (2 * km)
      return rho * phi * g * lambda * (1 - math.exp(-z / lambda))
    end
  end
  return rho * phi * g * z
end

return M
