-- lib/fill_structure.lua on packings with known structure: an FCC lattice (solid fraction
-- 0.74/s³ at spacing s, 12 neighbours, a g(r) peak at √2·d) and a random loose packing (random
-- sequential addition: no sphere with 10 neighbours, no peak at √2·d). A measure that cannot tell
-- them apart, or a wrong core volume, fails here.
local fill_structure = require("lib.fill_structure")
local check = require("checks").check
local d = 0.01
local function box_sim(packing, extra)
  local sim = paddy.simulation{threads = 1}
  local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
  local fill = {region = {type = "box", min = {-0.1, -0.1, 0}, max = {0.1, 0.1, 0.2}}, radius = d / 2, material = m,
                seed = 5, packing = packing}
  for k, v in pairs(extra) do fill[k] = v end
  sim:fill(fill)
  return sim
end
-- Core: a cylinder of radius 6 d, 6 d to 14 d high (well inside the 20 d box).
local core = {type = "cylinder", base = {0, 0, 0.06}, radius = 0.06, height = 0.08}
local core_volume = math.pi * 0.06 ^ 2 * 0.08

-- FCC ("lattice") at spacing 1.01: nearest neighbours at 1.01 d < 1.05 d.
local s = 1.01
local fcc = fill_structure.measure(box_sim("lattice", {spacing = s}), core)
check(math.abs(fcc.core_volume_m3 - core_volume) < 1e-15, "core volume %.17g, expected %.17g", fcc.core_volume_m3, core_volume)
local phi_fcc = math.pi / (3 * math.sqrt(2)) / s ^ 3
check(math.abs(fcc.solid_fraction - phi_fcc) < 0.03, "FCC solid fraction %.4f, expected %.4f", fcc.solid_fraction, phi_fcc)
check(fcc.neighbours > 11.9 and fcc.neighbours <= 12, "FCC neighbours %.3f, expected 12", fcc.neighbours)
check(fcc.neighbours_10_or_more > 0.99, "FCC share with >= 10 neighbours %.3f", fcc.neighbours_10_or_more)
check(fcc.g_sqrt2 > 2, "FCC g(sqrt2 d) = %.3f, expected a peak", fcc.g_sqrt2)
check(fcc.crystalline == true, "FCC not recognised as crystalline")

-- Random sequential addition at solid fraction 0.3 (loose, no order).
local rsa = fill_structure.measure(box_sim("random", {volume_fraction = 0.3}), core)
check(math.abs(rsa.solid_fraction - 0.3) < 0.03, "random solid fraction %.4f, expected 0.3", rsa.solid_fraction)
check(rsa.neighbours < 2, "random loose: %.3f neighbours", rsa.neighbours)
check(rsa.neighbours_10_or_more == 0, "random loose: share with >= 10 neighbours %.3f", rsa.neighbours_10_or_more)
check(rsa.g_sqrt2 < 1.5, "random loose: g(sqrt2 d) = %.3f", rsa.g_sqrt2)
check(rsa.crystalline == false, "random packing called crystalline")

-- A core with too few centres is refused with a reason, not measured.
local none, why = fill_structure.measure(box_sim("random", {volume_fraction = 0.3}),
                                         {type = "cylinder", base = {0, 0, 0.1}, radius = 0.004, height = 0.005})
check(none == nil and why:find("centres in the core", 1, true), "tiny core: %s", tostring(why))

paddy.result{ok = true, fcc = fcc, random = rsa}
