-- Checks of the miniature plate tack runs of experiments.tack_mini (run_case.cmake): four runs of
-- experiments/tack.lua at the same seed, read from their result.json:
--   base  no mud–steel attraction;   wall  mud_steel_surface_energy > 0;
--   slow, fast  lubrication_viscosity > 0 at two pull speeds, fast = 4 x slow.
-- Each check says what a broken experiment would get wrong. Bounds are in units the run reports
-- itself (the weight of one sphere, tack_floor_N; the pull distance), not numbers of a past run.
local P = paddy.parameters{
  {name = "dir", default = "", description = "directory holding base/, wall/, slow/, fast/"},
  {name = "profile_points", default = 8, type = "integer", min = 1, max = 1000, description = "profile_points of the runs"},
}
local check = require("checks").check
local function load(name) return paddy.read_json(P.dir .. "/" .. name .. "/result.json").results end
local base, wall, slow, fast = load("base"), load("wall"), load("slow"), load("fast")

for name, r in pairs({base = base, wall = wall, slow = slow, fast = fast}) do
  -- The profile has its documented length, on the documented grid: the bin centres of
  -- [0, pull_distance] in mm.
  local n, width = P.profile_points, r.test.pull_distance * 1000 / P.profile_points
  check(#r.tack_force_profile_N == n and #r.tack_tension_profile_N == n and #r.tack_profile_mm == n,
        "%s: profile lengths %d / %d / %d, expected %d", name, #r.tack_force_profile_N, #r.tack_tension_profile_N,
        #r.tack_profile_mm, n)
  for k = 1, n do
    check(r.tack_tension_profile_N[k] >= 0 and r.tack_tension_profile_N[k] >= r.tack_force_profile_N[k] - 1e-12,
          "%s: tension profile bin %d = %g must be >= 0 and >= the force profile's %g", name, k, r.tack_tension_profile_N[k],
          r.tack_force_profile_N[k])
  end
  for k = 1, n do
    check(math.abs(r.tack_profile_mm[k] - (k - 0.5) * width) < 1e-9, "%s: tack_profile_mm[%d] = %g, expected %g", name, k,
          r.tack_profile_mm[k], (k - 0.5) * width)
  end
  -- The plate pressed the mud (a plate that never reached it, or a sign error, gives <= 0), and the
  -- first bin, which starts at the press depth, is the release of that push (negative pull).
  check(r.tack_preload_N > 0, "%s: pre-load %g N must be > 0", name, r.tack_preload_N)
  check(r.tack_force_profile_N[1] < 0, "%s: the first profile bin %g N must be the released push (< 0)", name, r.tack_force_profile_N[1])
  -- The mud stops pushing before the plate is back at the level it first touched (u = press_depth).
  check(r.tack_release_mm and r.tack_release_mm > 0 and r.tack_release_mm <= r.test.press_depth * 1000,
        "%s: release at %s mm, expected in (0, press_depth = %g mm]", name, tostring(r.tack_release_mm), r.test.press_depth * 1000)
end

-- Without any mud–steel attraction nothing holds the plate: the peak pull is below the weight of
-- one sphere, nothing is carried, the range is 0 and the work is negligible (1 % of one sphere's
-- weight over the pull).
local floor = base.tack_floor_N
check(base.tack_peak_force_N < floor, "base: peak pull %g N, expected below one sphere's weight %g N", base.tack_peak_force_N, floor)
check(base.tack_mass_on_plate_g == 0 and base.tack_range_mm == 0 and base.tack_detach_mm == 0,
      "base: %g g carried, range %g mm, detached at %g mm; expected none", base.tack_mass_on_plate_g, base.tack_range_mm,
      base.tack_detach_mm)
for k, v in ipairs(base.tack_tension_profile_N) do
  check(v < floor, "base: tension profile bin %d = %g N, expected below one sphere's weight", k, v)
end
check(base.tack_work_J < 0.01 * floor * base.test.pull_distance, "base: work %g J", base.tack_work_J)

-- Wall adhesion makes the mud stick: a pull of several spheres' weight, mud carried up, and the
-- force at the end of the pull is the weight of that mud (the force and the mass are measured
-- independently: a wrong sign, unit or footprint fails here).
check(wall.tack_peak_force_N > 3 * floor, "wall: peak pull %g N, expected above 3 spheres' weight %g N", wall.tack_peak_force_N,
      3 * floor)
check(wall.tack_particles_on_plate >= 3, "wall: %d spheres carried, expected 3 or more", wall.tack_particles_on_plate)
local weight = wall.tack_carried_weight_N
check(math.abs(wall.tack_final_force_N - weight) <= 0.25 * weight, "wall: final force %g N against the carried weight %g N",
      wall.tack_final_force_N, weight)
check(wall.tack_range_mm > wall.test.press_depth * 1000, "wall: range %g mm, expected beyond the press depth", wall.tack_range_mm)
check(wall.tack_work_J > 0.5 * wall.tack_final_force_N * (wall.test.pull_distance - wall.tack_release_mm / 1000),
      "wall: work %g J is less than half the carried weight over the pull", wall.tack_work_J)

-- Lubrication pulls only while the plate moves (Stefan): a pull above one sphere's weight, no mud
-- carried, and a faster pull pulls harder (a speed that is not applied, or a static force, fails).
check(slow.test.pull_speed * 3.99 < fast.test.pull_speed, "the fast run must pull 4 times faster")
check(slow.tack_peak_force_N > floor, "lubrication, slow: peak %g N, expected above one sphere's weight %g N",
      slow.tack_peak_force_N, floor)
check(fast.tack_peak_force_N > 2 * slow.tack_peak_force_N, "lubrication: peak %g N at 4x the speed, %g N slow; expected twice or more",
      fast.tack_peak_force_N, slow.tack_peak_force_N)
check(slow.tack_mass_on_plate_g == 0 and fast.tack_mass_on_plate_g == 0, "lubrication carried mud: %g / %g g",
      slow.tack_mass_on_plate_g, fast.tack_mass_on_plate_g)
-- Nothing is carried, so the force at the end is 0 and the detachment is the range.
check(fast.tack_final_force_N == 0 and fast.tack_detach_mm == fast.tack_range_mm,
      "lubrication, fast: final force %g N, detached at %g mm, range %g mm", fast.tack_final_force_N, fast.tack_detach_mm,
      fast.tack_range_mm)

paddy.result{ok = true}
