-- lib/rheology.lua: the rate-dependent share K·D^n / (τ0 + K·D^n) of a Herschel-Bulkley fit and
-- the "not a flow curve" warning of the rheometer, on fits with known answers.
local rheology = require("lib.rheology")
local check = require("checks").check
local function near(a, b, tol) return math.abs(a - b) <= tol end

-- Closed form: τ0 = 30 Pa, K = 10 Pa s^0.5, D = 100 1/s → K D^n = 100 Pa, share = 100/130.
local s = rheology.rate_dependent_share({tau0 = 30, K = 10, n = 0.5}, 100)
check(near(s, 100 / 130, 1e-15), "share = %.17g, expected 100/130", s)
-- Bingham (n = 1): τ0 = 50, K = 2, D = 25 → 50/100.
s = rheology.rate_dependent_share({tau0 = 50, K = 2, n = 1}, 25)
check(near(s, 0.5, 1e-15), "Bingham share = %.17g", s)
-- No yield stress: all of it; no consistency: none of it (whatever n is).
check(rheology.rate_dependent_share({tau0 = 0, K = 3, n = 0.7}, 10) == 1, "power law: share 1")
for _, n in ipairs({0.05, 0.5, 1.5, 3}) do
  check(rheology.rate_dependent_share({tau0 = 961, K = 0, n = n}, 50) == 0, "K = 0, n = %g: share 0", n)
end

-- A flow curve: torque rising, the rate carries 77 % of the stress at the highest rate.
local steps = {{speed_rpm = 5, torque_Nm = 0.10, shear_rate = 4}, {speed_rpm = 20, torque_Nm = 0.18, shear_rate = 25},
               {speed_rpm = 80, torque_Nm = 0.31, shear_rate = 100}}
local w, share = rheology.flow_curve_warning(steps, {tau0 = 30, K = 10, n = 0.5})
check(w == nil, "rising, share 0.77: no warning, got %s", tostring(w))
check(near(share, 100 / 130, 1e-15), "reported share %.17g", share)

-- The converged mud at the reference parameters: torque falls, HB degenerates to τ0 = 961 Pa with
-- K ≈ 0 and n anywhere; also when n sits at the upper bound, which the old n-bound test missed.
local falling = {{speed_rpm = 5, torque_Nm = 0.34, shear_rate = 4}, {speed_rpm = 80, torque_Nm = 0.25, shear_rate = 100}}
for _, n in ipairs({0.05, 1.0, 3.0}) do
  local msg = rheology.flow_curve_warning(falling, {tau0 = 961, K = 1e-9, n = n})
  check(msg and msg:find("does not grow", 1, true), "falling torque, n = %g: warning expected, got %s", n, tostring(msg))
end
-- Rising, but the rate carries only 1 % of the stress (τ0 = 990, K D^n = 10 Pa) → warning "barely grows".
local flat = {{speed_rpm = 5, torque_Nm = 0.300, shear_rate = 4}, {speed_rpm = 80, torque_Nm = 0.303, shear_rate = 100}}
local msg, sh = rheology.flow_curve_warning(flat, {tau0 = 990, K = 1, n = 0.5})
check(msg and msg:find("barely grows", 1, true) and msg:find("1.0 %", 1, true), "flat curve: %s", tostring(msg))
check(near(sh, 10 / 1000, 1e-15), "flat share %.17g", sh)
-- The threshold is the caller's to choose: the same fit passes at 0.5 %.
check(rheology.flow_curve_warning(flat, {tau0 = 990, K = 1, n = 0.5}, 0.005) == nil, "threshold 0.005 passes 1 %%")

paddy.result{ok = true}
