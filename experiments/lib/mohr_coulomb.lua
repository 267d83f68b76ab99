-- The vane depth series of validation/yield_stress.lua: the Mohr–Coulomb line of the vane's peak
-- stress against the overburden at the blades' mid-height. A module of its own (not lib/rheology.lua,
-- which rheometer.lua requires) so that a change here does not change the rheometer's job keys
-- (docs/campaign.md: a job's key hashes the modules its script requires).
local line_fit = require("lib.line_fit")

local M = {}

-- Mohr–Coulomb line τ = c + σ·tanφ through (σ, τ) points by ordinary least squares: the vane's
-- peak stress at several overburdens σ (the depth series of validation/yield_stress.lua). c is the
-- pressure-independent (cohesive) part, tanφ the friction coefficient of the sheared packing.
-- Standard errors from the residual variance s² = SSE/(n − 2) (nil for n = 2: an exact line;
-- lib/line_fit.lua): se(tanφ) = s/√Sxx,  se(c) = s·√(1/n + σ̄²/Sxx).
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
  local xm = sx / n
  local sxx = 0
  for k = 1, n do sxx = sxx + (x[k] - xm) ^ 2 end
  if not (sxx > 1e-12 * xm * xm * n) then
    error("mohr_coulomb.fit: all points at one normal stress: needs at least 2 distinct overburdens", 2)
  end
  local line = line_fit.fit{x = x, y = y, what = "mohr_coulomb.fit"}
  return {c = line.a, tan_phi = line.b, n = n, dof = line.dof, residuals = line.residuals, sigma_mean = xm, r2 = line.r2,
          se_c = line.se_a, se_tan_phi = line.se_b}
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
