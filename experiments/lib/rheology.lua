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

return M
