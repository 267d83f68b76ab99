-- The damping-aware time step of the mud experiments (lib/mud.lua timestep_fraction): the
-- explicit-integration limit ω Δt ≤ 2(√(1+ζ²) − ζ) of a contact with damping ratio
-- ζ = √(5/6)|ln e| / √(ln²e + π²) (Hertz-Mindlin damping), relative to the reference damping.
local mud = require("lib.mud")
local check = require("checks").check
local P = {timestep_fraction = 0.2}
local function c(e_mm, e_ms) return {mud_mud_restitution = e_mm, mud_steel_restitution = e_ms} end

-- The reference mud and anything less damped keep the step exactly.
for _, e in ipairs({{0.13, 0.3}, {0.5, 0.9}, {0.13, 0.13}, {1.0, 1.0}}) do
  local f, k = mud.timestep_fraction(P, c(e[1], e[2]))
  check(f == 0.2 and k == 1, "e = %g/%g: fraction %.17g (factor %.17g), expected exactly 0.2", e[1], e[2], f, k)
end
-- Damping ratios by hand: e = 0.13 → |ln e| = 2.0402208, ζ = √(5/6)·|ln e|/√(ln²e + π²) = 0.4971931;
-- e = 0.01 → |ln e| = 4.6051702, ζ = 0.7541090.
check(math.abs(mud.damping_ratio(0.13) - 0.4971931) < 1e-6, "zeta(0.13) = %.7f", mud.damping_ratio(0.13))
check(math.abs(mud.damping_ratio(0.01) - 0.7541090) < 1e-6, "zeta(0.01) = %.7f", mud.damping_ratio(0.01))
check(mud.damping_ratio(1) == 0, "no damping at e = 1")
-- g(ζ) = √(1+ζ²) − ζ: g(0.4971931) = 0.6195884, g(0.7541090) = 0.4983607 → factor 0.8043416.
local f, k = mud.timestep_fraction(P, c(0.01, 0.3))
check(math.abs(k - 0.8043416) < 1e-6, "factor at e = 0.01: %.7f", k)
check(math.abs(f - 0.2 * k) < 1e-15, "fraction = 0.2 x factor")
-- The smaller of the two restitutions decides, and the factor falls with e.
local _, k2 = mud.timestep_fraction(P, c(0.3, 0.01))
check(k2 == k, "mud-steel restitution 0.01 counts like mud-mud")
local last = 1
for _, e in ipairs({0.12, 0.08, 0.04, 0.02, 0.01, 0.001}) do
  local _, ke = mud.timestep_fraction(P, c(e, 0.5))
  check(ke < last, "factor must fall with the restitution (e = %g: %g)", e, ke)
  last = ke
end
paddy.result{ok = true, factor_at_0_01 = k}
