-- The vane depth series of validation/yield_stress.lua: the Mohr–Coulomb line of the vane's peak
-- stress against the overburden at the blades' mid-height. A module of its own (not lib/rheology.lua,
-- which rheometer.lua requires) so that a change here does not change the rheometer's job keys
-- (docs/campaign.md: a job's key hashes the modules its script requires).
local line_fit = require("lib.line_fit")
local util = require("lib.util")

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

-- One parameter set's depth series as Mohr–Coulomb lines: per seed and pooled over the seeds, and
-- the intercept c against the slump's yield stress. args: points = {{seed =, sigma =, tau =}, ...},
-- slump_of = {[seed] = τ_slump} (may lack seeds), slump_mean = the set's mean τ_slump (or nil),
-- target = the agreement band (|c / τ_slump − 1| ≤ target). A fit that cannot be made (M.fit's
-- refusals) is reported as its error, not raised. c counts as determined when the pooled fit puts
-- it at least 2 standard errors above 0; only then can it be within the target.
-- args.seeds (optional): the seeds to report, in that order, with an entry (its fit's error) also
-- for a seed without points; default: the seeds that have points, ascending.
-- → {per_seed = {{seed, points, fit, fit_error, slump_yield_stress_Pa, c_over_slump}, ...},
--    pooled =, pooled_error =, c_Pa = {mean, std, values}, tan_phi = {mean, std, values},
--    c_over_slump = {mean, std, values}, pooled_c_over_slump =, c_determined =, c_within_target =}
function M.envelope(args)
  local function fit_or_error(sig, tau)
    local ok, f = pcall(M.fit, {sigma = sig, tau = tau})
    if ok then return f end
    return nil, tostring(f)
  end
  local function summary(v) return {mean = util.mean(v), std = util.std(v), values = v} end
  local by_seed, seeds, all_s, all_t = {}, {}, {}, {}
  for _, p in ipairs(args.points) do
    if not by_seed[p.seed] then
      by_seed[p.seed] = {sig = {}, tau = {}}
      seeds[#seeds + 1] = p.seed
    end
    local b = by_seed[p.seed]
    b.sig[#b.sig + 1], b.tau[#b.tau + 1] = p.sigma, p.tau
    all_s[#all_s + 1], all_t[#all_t + 1] = p.sigma, p.tau
  end
  table.sort(seeds)
  local out = {per_seed = {}}
  local cs, tans, ratios = {}, {}, {}
  for _, s in ipairs(args.seeds or seeds) do
    local b = by_seed[s] or {sig = {}, tau = {}}
    local f, why = fit_or_error(b.sig, b.tau)
    local tau_slump = args.slump_of and args.slump_of[s]
    local e = {seed = s, points = #b.sig, fit = f, fit_error = why, slump_yield_stress_Pa = tau_slump}
    if f then
      cs[#cs + 1], tans[#tans + 1] = f.c, f.tan_phi
      if tau_slump then
        e.c_over_slump = f.c / tau_slump
        ratios[#ratios + 1] = e.c_over_slump
      end
    end
    out.per_seed[#out.per_seed + 1] = e
  end
  out.pooled, out.pooled_error = fit_or_error(all_s, all_t)
  out.c_Pa, out.tan_phi, out.c_over_slump = summary(cs), summary(tans), summary(ratios)
  if out.pooled and args.slump_mean then out.pooled_c_over_slump = out.pooled.c / args.slump_mean end
  out.c_determined = out.pooled ~= nil and out.pooled.se_c ~= nil and out.pooled.c > 2 * out.pooled.se_c
  out.c_within_target = out.c_determined and #ratios > 0 and math.abs(out.c_over_slump.mean - 1) <= args.target
  return out
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
