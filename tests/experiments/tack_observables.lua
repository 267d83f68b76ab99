-- The plate tack test's observables (lib/tack_observables.lua) on force curves with known answers:
-- the moving average, the peak, the work of separation (trapezoids on the positive part, a sign
-- change inside an interval), the range, the detachment, the release and the bin means on a fixed
-- grid.
local obs = require("lib.tack_observables")
local check = require("checks").check
local function near(a, b, tol) return math.abs(a - b) <= (tol or 1e-12) * math.max(1, math.abs(b)) end

-- Moving average: a straight line is its own average away from the ends (the window is
-- symmetric); at the ends the window is cut (mean of the samples inside it); exact zeros stay zero.
local u, F = {}, {}
for k = 0, 20 do u[#u + 1], F[#F + 1] = 0.125 * k, 3 * (0.125 * k) - 1 end
local Fs = obs.smooth(u, F, 0.5)   -- 5 samples per window (steps exact in binary)
for k = 3, 19 do check(near(Fs[k], F[k]), "smoothed line at u = %g: %g, expected %g", u[k], Fs[k], F[k]) end
check(near(Fs[1], (F[1] + F[2] + F[3]) / 3), "smoothed first sample %g", Fs[1])
-- (a running sum would leave 0.1 + 0.2 − 0.1 − 0.2 = 2.8e-17 there, and a spurious peak)
local zeros = obs.smooth({0, 1, 2, 3, 4, 5}, {0.1, 0.2, 0, 0, 0, 0}, 2.5)
check(zeros[5] == 0 and zeros[6] == 0, "a stretch of zeros after a force must stay exactly 0: %g %g", zeros[5], zeros[6])
local same = obs.smooth(u, F, 0)
for k = 1, #F do check(same[k] == F[k], "width 0 must copy the force") end
check(not pcall(obs.smooth, {0, 1}, {0}, 1), "arrays of different lengths must be refused")

-- Peak: the largest value and where it is first reached.
local peak, at = obs.peak({0, 1, 2, 3}, {-2, 5, 5, 1})
check(peak == 5 and at == 1, "peak %g at %g, expected 5 at 1", peak, at)

-- Work: F = u − 2 on [0, 4] has ∫ max(F, 0) du = 2 (the trapezoids are exact on a line); F from −1
-- to 3 over [0, 1] crosses zero at 0.25: the triangle above zero has area 0.5 · 0.75 · 3 = 1.125.
check(near(obs.work({0, 1, 2, 3, 4}, {-2, -1, 0, 1, 2}), 2), "work of u - 2")
check(near(obs.work({0, 1}, {-1, 3}), 1.125), "work across a sign change: %g", obs.work({0, 1}, {-1, 3}))
check(near(obs.work({0, 1}, {3, -1}), 1.125), "work across a sign change, falling")
check(obs.work({0, 1, 2}, {-3, -1, 0}) == 0, "compression alone does no work of separation")

-- Range: the last displacement with the force above 0.1 of the peak; 0 without a positive peak.
check(obs.range({0, 1, 2, 3, 4}, {-1, 10, 2, 1.5, 0.5}, 10, 0.1) == 3, "range")
check(obs.range({0, 1, 2}, {-1, 0, 0}, 0, 0.1) == 0, "range without a pull")
-- Detachment: the last displacement with the force above final + 0.1 (peak − final); with a
-- final force of 0 it is the range.
check(obs.detach({0, 1, 2, 3, 4, 5}, {-1, 10, 6, 2.5, 2, 2}, 10, 2, 0.1) == 2, "detach above a carried weight")
check(obs.detach({0, 1, 2, 3, 4}, {-1, 10, 2, 1.5, 0}, 10, 0, 0.1) == obs.range({0, 1, 2, 3, 4}, {-1, 10, 2, 1.5, 0}, 10, 0.1),
      "detach with nothing carried is the range")
-- Release: the first displacement where the force is no longer negative.
check(obs.release({0, 1, 2, 3}, {-3, -1, 0, 2}) == 2, "release")
check(obs.release({0, 1}, {-3, -1}) == nil, "no release while the mud pushes to the end")

-- Profile: 4 bins of [0, 2]; samples every 0.125 of F = u: each bin's mean is the mean of its
-- samples (u = 0, 0.125, 0.25, 0.375 in the first: 0.1875; a sample on a boundary belongs to the
-- upper bin, the last bin keeps u = 2: 1.5, 1.625, ..., 2.0 → 1.75).
local uu, ff = {}, {}
for k = 0, 16 do uu[#uu + 1], ff[#ff + 1] = 0.125 * k, 0.125 * k end
local grid = obs.profile(uu, ff, 2, 4)
check(#grid.centres == 4 and #grid.means == 4, "4 bins")
local expect_c, expect_m, expect_n = {0.25, 0.75, 1.25, 1.75}, {0.1875, 0.6875, 1.1875, 1.75}, {4, 4, 4, 5}
for b = 1, 4 do
  check(near(grid.centres[b], expect_c[b]) and near(grid.means[b], expect_m[b], 1e-9) and grid.counts[b] == expect_n[b],
        "bin %d: centre %g mean %g count %d", b, grid.centres[b], grid.means[b], grid.counts[b])
end
check(not pcall(obs.profile, {0, 0.1, 1.9}, {0, 0, 0}, 2, 4), "a bin without a sample must be refused")

paddy.result{ok = true}
