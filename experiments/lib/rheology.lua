-- Is a Herschel-Bulkley fit τ = τ0 + K·D^n a flow curve, or only a yield stress?
--
-- A material that flows has a stress that grows with the shear rate. The part of the stress that
-- depends on the rate, at the highest shear rate D_max of the test, is
--     share = K·D_max^n / (τ0 + K·D_max^n)        (0: a pure yield stress; 1: no yield stress).
-- When it is below `min_share` the fit has nothing to say about K and n: with K → 0 the exponent n
-- is arbitrary and an optimiser leaves it anywhere in its bounds, so neither n nor K can be the
-- test. The torque must also rise from the lowest to the highest speed.
local M = {}

-- Rate-dependent share of the fitted stress at shear rate D (> 0).
function M.rate_dependent_share(fit, D)
  local rate_part = fit.K * D ^ fit.n
  local total = fit.tau0 + rate_part
  if not (total > 0) then return 0 end
  return math.max(0, rate_part / total)
end

-- Default threshold: the rate explains less than 5 % of the stress at the highest rate.
M.min_share = 0.05

-- nil when the steps describe a flow curve; otherwise a sentence saying why not.
-- steps: {speed_rpm=, torque_Nm=, shear_rate=} in the order run; fit: {tau0=, K=, n=, r2=}.
function M.flow_curve_warning(steps, fit, min_share)
  min_share = min_share or M.min_share
  local first, last, d_max = steps[1], steps[#steps], 0
  for _, s in ipairs(steps) do d_max = math.max(d_max, s.shear_rate or 0) end
  local rising = last.torque_Nm > first.torque_Nm
  local share = d_max > 0 and M.rate_dependent_share(fit, d_max) or 0
  if rising and share >= min_share then return nil, share end
  return string.format("the steady torque %s with the speed (%.3g N m at %g rpm, %.3g N m at %g rpm); the "
                       .. "Herschel-Bulkley fit (tau0 = %.3g Pa, K = %.3g Pa s^n, n = %.3g) puts %.1f %% of the stress "
                       .. "at %.3g 1/s on the shear rate (below %g %%): it describes a yield stress, not a flow curve",
                       rising and "barely grows" or "does not grow", first.torque_Nm, first.speed_rpm, last.torque_Nm,
                       last.speed_rpm, fit.tau0, fit.K, fit.n, 100 * share, d_max, 100 * min_share), share
end

-- Mohr–Coulomb line τ = c + σ·tanφ through (σ, τ) points by ordinary least squares: the vane's
-- peak stress at several overburdens σ (the depth series of validation/yield_stress.lua). c is the
-- pressure-independent (cohesive) part, tanφ the friction coefficient of the sheared packing.
-- Standard errors from the residual variance s² = SSE/(n − 2) (nil for n = 2: an exact line):
--     se(tanφ) = s/√Sxx,  se(c) = s·√(1/n + σ̄²/Sxx).
-- Refuses fewer than 2 points, unequal lengths, a non-positive or non-finite σ, a non-finite τ and
-- fewer than 2 distinct σ (no line).
-- args: {sigma = {...}, tau = {...}}; returns {c=, tan_phi=, se_c=, se_tan_phi=, n=, dof=, r2=, residuals=}.
function M.mohr_coulomb_fit(args)
  local x, y = args.sigma, args.tau
  if type(x) ~= "table" or type(y) ~= "table" then error("mohr_coulomb_fit: needs sigma = {...} and tau = {...}", 2) end
  local n = #x
  if n ~= #y then error(string.format("mohr_coulomb_fit: %d stresses but %d shear stresses", n, #y), 2) end
  if n < 2 then error(string.format("mohr_coulomb_fit: %d point(s): needs at least 2 overburdens", n), 2) end
  local sx, sy = 0, 0
  for k = 1, n do
    if type(x[k]) ~= "number" or not (x[k] > 0) or x[k] == math.huge then
      error(string.format("mohr_coulomb_fit: sigma[%d] = %s: the normal stress must be positive and finite", k, tostring(x[k])), 2)
    end
    if type(y[k]) ~= "number" or y[k] ~= y[k] or math.abs(y[k]) == math.huge then
      error(string.format("mohr_coulomb_fit: tau[%d] = %s is not a finite number", k, tostring(y[k])), 2)
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
    error("mohr_coulomb_fit: all points at one normal stress: needs at least 2 distinct overburdens", 2)
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
-- particle_density × solid_fraction (hydrostatic, no wall friction): σ_v = ρ_bulk g z.
function M.overburden(args)
  local rho, phi, z, g = args.particle_density, args.solid_fraction, args.depth, args.gravity or 9.81
  for name, v in pairs({particle_density = rho, solid_fraction = phi, depth = z}) do
    if type(v) ~= "number" or not (v > 0) then error(string.format("overburden: %s = %s must be positive", name, tostring(v)), 2) end
  end
  if phi >= 1 then error(string.format("overburden: solid_fraction = %g must be below 1", phi), 2) end
  return rho * phi * g * z
end

return M
