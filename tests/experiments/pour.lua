-- lib/pour.lua (and lib/util.lua's region volume and inner region): closed forms; the hopper is as tall as the formula
-- says and every loose sphere starts inside the container or the hopper; a fill that settled below
-- the rim, or a settling time shorter than the fall, is refused; the settling stops on the fill
-- below the level at rest, not before the pour has landed.
local pour = require("lib.pour")
local util = require("lib.util")
local check = require("checks").check
local function near(a, b, tol) return math.abs(a - b) <= tol * math.abs(b) end

-- Slump cone 100/200/300 mm: V = π h/3 (R² + R r + r²) = 5.4978 L; a cylinder π r² h.
local cone = {type = "cone", base = {0, 0, 0}, radius_bottom = 0.1, radius_top = 0.05, height = 0.3}
check(near(util.region_volume(cone), math.pi * 0.3 / 3 * (0.01 + 0.005 + 0.0025), 1e-14), "cone volume")
check(near(util.region_volume{type = "cylinder", radius = 0.05, height = 0.12}, math.pi * 0.0025 * 0.12, 1e-14), "cylinder volume")
check(not pcall(util.region_volume, {type = "box"}), "a box region must be refused")
-- 20 mm inside the cone: from z = 0.02 to 0.28, radius R(z) − 0.02 with R(z) = 0.1 − z/6.
local inner = util.inner_region(cone, 0.02)
check(inner.type == "cone" and near(inner.base[3], 0.02, 1e-15) and near(inner.height, 0.26, 1e-14), "inner cone: base and height")
check(near(inner.radius_bottom, 0.1 - 0.02 / 6 - 0.02, 1e-14) and near(inner.radius_top, 0.1 - 0.28 / 6 - 0.02, 1e-14),
      "inner cone radii %.6f, %.6f", inner.radius_bottom, inner.radius_top)
local cup = util.inner_region({type = "cylinder", base = {0, 0, 0}, radius = 0.05, height = 0.12}, 0.016)
check(near(cup.radius, 0.034, 1e-14) and near(cup.base[3], 0.016, 1e-15) and near(cup.height, 0.088, 1e-14), "inner cylinder")
check(near(pour.fall_time(1.2), math.sqrt(2 * 1.2 / 9.81), 1e-14), "fall time")

local sim = paddy.simulation{threads = 1, gravity = {0, 0, -9.81}}
local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
local s = sim:material{name = "steel", density = 7800, shear_modulus = 7e9, poisson = 0.3}
local d = 0.02
local f = pour.fill(sim, {region = cone, rim_radius = 0.05, radius = d / 2, material = m, seed = 3, wall_material = s})
check(f.hopper ~= nil and f.filled == sim:count(), "hopper and count")
-- (1 + margin)·φ_max·V of solid must be placed: the hopper holds the rest at the container's loose fraction.
local V = util.region_volume(cone)
local h = ((1 + pour.margin) * pour.solid_fraction - f.loose_fraction) * V / (f.loose_fraction * math.pi * 0.05 ^ 2)
check(near(f.hopper_height, h, 1e-12), "hopper height %.6f, formula %.6f", f.hopper_height, h)
check(f.loose_fraction > 0.15 and f.loose_fraction < 0.38, "loose fraction %.3f (random sequential addition jams below 0.38)", f.loose_fraction)
check(near(f.top_z, 0.3 + h, 1e-12), "top_z")
local xs, ys, zs = sim:xyz()
local solid = 0
for i = 1, #xs do
  local rr = math.sqrt(xs[i] ^ 2 + ys[i] ^ 2)
  local inside = (zs[i] <= 0.3 and rr <= 0.1 - 0.05 * zs[i] / 0.3) or (zs[i] > 0.3 - d / 2 and zs[i] <= f.top_z and rr <= 0.05)
  check(inside, "sphere %d at r = %.4f, z = %.4f is outside the cone and the hopper", i, rr, zs[i])
  solid = solid + math.pi / 6 * d ^ 3
end
-- At least the planned solid was placed (the hopper fills at about the container's loose fraction).
check(solid > 0.9 * (1 + pour.margin) * pour.solid_fraction * V, "placed %.4g m^3 of solid, planned %.4g", solid,
      (1 + pour.margin) * pour.solid_fraction * V)

-- Refusals name the script and the allowed value.
local ok, msg = pcall(pour.check_settle_time, "slump", f, 0.2, 0.3)
check(not ok and msg:find("settle_max_time >= ", 1, true), "short settling accepted: %s", tostring(msg))
check(pcall(pour.check_settle_time, "slump", f, pour.fall_time(f.top_z) + 0.31, 0.3), "a long enough settling refused")
ok, msg = pcall(pour.check_full, "slump", 0, 0.3)
check(not ok and msg:find("settled below the rim", 1, true), "an unfilled container accepted: %s", tostring(msg))
check(pcall(pour.check_full, "slump", 5, 0.3), "a full container refused")

-- The settling's stop rule (pour.settled): the RMS speed of the spheres wholly below the level only
-- (util.rms_speed with top), and not before the pour's landing time √(2 (top_z − level) / g).
check(near(pour.landing_time(f, 0.3), math.sqrt(2 * (f.top_z - 0.3) / 9.81), 1e-14), "landing time %.6f", pour.landing_time(f, 0.3))
check(pour.landing_time(nil, 0.3) == 0 and pour.landing_time({top_z = 0.3}, 0.3) == 0, "landing time without a pour above the level")
local function spheres(v_kept)
  local g = paddy.simulation{threads = 1}
  local mm = g:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
  g:add_particle{pos = {0, 0, 0.1}, radius = 0.01, material = mm, vel = {0.003, 0, 0}}     -- kept
  g:add_particle{pos = {0, 0.05, 0.2}, radius = 0.02, material = mm, vel = {0, 0, -v_kept}} -- kept
  g:add_particle{pos = {0.05, 0, 0.29}, radius = 0.01, material = mm, vel = {0, 0, -2}}    -- z + r = 0.3: kept
  g:add_particle{pos = {0.1, 0, 0.295}, radius = 0.01, material = mm, vel = {0, 0, -2}}    -- straddles the level: struck off
  return g
end
local g = spheres(0.004)
local w1, w2 = 0.01 ^ 3, 0.02 ^ 3
local kept = math.sqrt((w1 * (0.003 ^ 2 + 4) + w2 * 0.004 ^ 2) / (2 * w1 + w2))
local all = math.sqrt((w1 * (0.003 ^ 2 + 8) + w2 * 0.004 ^ 2) / (3 * w1 + w2))
check(near(util.rms_speed(g, 0.3), kept, 1e-12), "RMS speed below the level %.6g, closed form %.6g", util.rms_speed(g, 0.3), kept)
check(near(util.rms_speed(g), all, 1e-12), "RMS speed of all %.6g, closed form %.6g", util.rms_speed(g), all)
g = spheres(0.004)
g:remove_if(function(i, x, y, z, r) return z + r >= 0.3 - 1e-12 end)  -- leaves the two slow spheres
local rest = pour.settled(f, 0.3, 0.1, 0.01)
local t_land = pour.landing_time(f, 0.3)
check(t_land > 0.1, "the landing time %.3f s is the binding one here", t_land)
check(not rest(g, {t0 = -(t_land - 0.01)}), "the fill counted as at rest before the pour could have landed")
check(rest(g, {t0 = -(t_land + 0.01)}) == "fill_kinetic_energy", "the fill at rest after the landing not seen")
check(not pour.settled(nil, 0.3, 0.1, 0.01)(g, {t0 = -0.09}), "at rest before min_rest_time")
check(pour.settled(nil, 0.3, 0.1, 0.01)(g, {t0 = -0.11}) == "fill_kinetic_energy", "without a pour min_rest_time alone is waited for")
-- A sphere above the level moving fast does not hold the rule up; the kept ones moving do.
g = spheres(0.004)
g:remove_if(function(i, x, y, z, r) return math.abs(z - 0.29) < 1e-9 end)  -- the fast kept sphere out, the straddler in
check(rest(g, {t0 = -(t_land + 0.01)}) == "fill_kinetic_energy", "a fast sphere above the level held the settling up")
g = spheres(0.05)
check(not rest(g, {t0 = -(t_land + 0.01)}), "the fill counted as at rest while it moves at 0.05 m/s")
check(pour.settled(f, 0.3, 0.1, 0.01, {function() return "top_steady" end})(g, {t0 = -(t_land + 0.01)}) == "top_steady",
      "an extra trigger does not stand in for the fill at rest")
check(not pour.settled(f, 0.3, 0.1, 0.01, {function() return "top_steady" end})(g, {t0 = 0}), "an extra trigger fired before the landing")
-- rest_of = "all" is the rule before 7 Dec 2026: every sphere at rest, after min_rest_time only.
g = spheres(0.004)
check(not pour.settled(f, 0.3, 0.1, 0.01, nil, "all")(g, {t0 = -(t_land + 0.01)}), "rest_of = all: a fast sphere above the level ignored")
g:remove_if(function(i, x, y, z, r) return z > 0.25 end)
check(pour.settled(f, 0.3, 0.1, 0.01, nil, "all")(g, {t0 = -0.11}) == "kinetic_energy", "rest_of = all waited for the landing")
check(pour.settled(f, 0.3, 0.1, 0.01, nil, "fill")(g, {t0 = -(t_land + 0.01)}) == "fill_kinetic_energy", "rest_of = fill is the default rule")
ok, msg = pcall(pour.settled, f, 0.3, 0.1, 0.01, nil, "some")
check(not ok and msg:find("allowed: fill, all", 1, true), "an unknown rest_of accepted: %s", tostring(msg))
paddy.result{ok = true, hopper_height = f.hopper_height, loose_fraction = f.loose_fraction}
