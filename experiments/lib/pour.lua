-- Poured fill of a container (the slump cone, the rheometer cup): spheres placed at random, loose,
-- in the container and in an open tube (hopper) standing on its rim, then left to fall and settle
-- under gravity; the script strikes off what stands above the rim. The result is an amorphous
-- packing, like the particle factories of EDEM and LIGGGHTS fill a container.
--
-- Why not a lattice: spheres placed on a face-centred cubic lattice (sim:fill packing="lattice",
-- spacing 1.02) settle by less than their 2 % gap and stay a crystal. In the slump cone its core
-- packs at solid fraction 0.71 with the √2·d peak of the FCC lattice in g(r) (10 mm spheres); a
-- random packing of frictional spheres cannot exceed 0.64 (random close packing; Scott & Kilgour
-- 1969, J. Phys. D 2:863), and a crystal resists shear like no mud does. docs/physics.md, "Fill".
--
-- Loose placement: random sequential addition (sim:fill packing="random") reaches a solid fraction
-- of about 0.3 before it jams (the limit is 0.38; Feder 1980, J. Theor. Biol. 87:237). The settled
-- packing holds at most `solid_fraction` (default 0.64), so the hopper is made tall enough that
-- `margin` more than a fill at that fraction lands in the container: it is always full to the rim.
local util = require("lib.util")
local phase = require("lib.phase")
local trigger = require("lib.trigger")

local M = {}

M.loose_fraction = 0.35   -- asked of the random placement (it jams near 0.3)
M.solid_fraction = 0.64   -- the densest the settled fill can be (random close packing)
M.margin = 0.1            -- extra loose spheres beyond a fill at solid_fraction

-- Free-fall time of the highest loose sphere onto the floor of the container: a lower bound of the
-- settling time.
function M.fall_time(top_z, g)
  return math.sqrt(2 * top_z / (g or 9.81))
end

-- spec: region (the container's inside up to its rim, base at z = base_z), rim_radius (radius of
-- the opening at the rim), radius (sim:fill radius option), material, seed, wall_material (the
-- hopper), part ("slump_cone": an open tube when both diameters are equal), optional
-- solid_fraction, margin, loose_fraction.
-- Returns {filled =, loose_fraction = (placed in the container), hopper = wall or nil,
--          hopper_height =, top_z = (top of the loose spheres)}.
function M.fill(sim, spec)
  local region = spec.region
  local base_z = region.base[3]
  local rim_z = base_z + region.height
  local phi_solid = spec.solid_fraction or M.solid_fraction
  local margin = spec.margin or M.margin
  local loose = spec.loose_fraction or M.loose_fraction
  local n, phi0 = sim:fill{region = region, radius = spec.radius, material = spec.material, seed = spec.seed,
                           packing = "random", volume_fraction = loose}
  if not (phi0 > 0) then error("lib/pour.lua: no sphere fits in the container", 2) end
  -- The settled fill needs (1 + margin)·phi_solid·V of solid; the container holds phi0·V loose.
  local V = util.region_volume(region)
  local missing = ((1 + margin) * phi_solid - phi0) * V
  local out = {filled = n, loose_fraction = phi0, hopper_height = 0, top_z = rim_z}
  if missing <= 0 then return out end
  local area = math.pi * spec.rim_radius ^ 2
  local h = missing / (phi0 * area)
  out.hopper = sim:add_mesh_wall{
    name = "hopper", material = spec.wall_material, part = spec.part or "slump_cone",
    params = {top_diameter = 2 * spec.rim_radius, bottom_diameter = 2 * spec.rim_radius, height = h},
    translate = {region.base[1], region.base[2], rim_z}, motion = {type = "fixed"},
  }
  local n2 = sim:fill{region = {type = "cylinder", base = {region.base[1], region.base[2], rim_z}, radius = spec.rim_radius,
                                height = h},
                      radius = spec.radius, material = spec.material, seed = spec.seed + 1, packing = "random",
                      volume_fraction = loose}
  out.filled, out.hopper_height, out.top_z = n + n2, h, rim_z + h
  return out
end

-- Earliest time the settled fill can count as at rest: the free fall of the highest loose sphere
-- down to the strike-off level (0 for a fill placed without a pour). Before it the stream may
-- still be landing on the fill, which the fill's own RMS speed does not see between two samples.
function M.landing_time(fill, level)
  if not fill or not (fill.top_z > level) then return 0 end
  return M.fall_time(fill.top_z - level)
end

-- The settling's stop rule: at least min_rest_time and the landing time (M.landing_time) after the
-- start, then the spheres the strike-off at `level` keeps (wholly below it) at rest: their RMS
-- speed below rest_speed (util.rms_speed). The excess above the level is not waited for: it is
-- removed, and what it still does after the stream has landed (the hopper's column compacting,
-- spheres bouncing on top) does not move the fill below (docs/experiments.md, "Fill"). `extra`: more
-- triggers, any of which may stand in for the fill at rest (slump.lua: the top steady).
-- rest_of = "all": every sphere at rest, the excess included, after min_rest_time only (the rule
-- before 7 Dec 2026, kept to repeat earlier runs); default "fill".
local REST_OF = {"fill", "all"}

-- The scripts' parameter for rest_of (slump.lua, rheometer.lua, tack.lua declare it alike).
function M.rest_of_parameter()
  return {name = "settle_rest_of", default = REST_OF[1], choices = {table.unpack(REST_OF)},
          description = "the settling ends when these spheres are at rest: fill (those the strike-off keeps, once the pour has landed) or all (the excess too: the rule before 7 Dec 2026, to repeat earlier runs); lib/pour.lua settled"}
end

function M.settled(fill, level, min_rest_time, rest_speed, extra, rest_of)
  local all = rest_of == "all"
  if rest_of ~= nil and not all and rest_of ~= "fill" then
    error(string.format("lib/pour.lua: settle_rest_of = %s; allowed: %s", tostring(rest_of), table.concat(REST_OF, ", ")), 2)
  end
  local rest = {all and trigger.at_rest(rest_speed) or trigger.at_rest(rest_speed, level)}
  for _, t in ipairs(extra or {}) do rest[#rest + 1] = t end
  local wait = all and min_rest_time or math.max(min_rest_time, M.landing_time(fill, level))
  return trigger.all{trigger.elapsed(wait), trigger.any(rest)}
end

-- Refuses a settling time too short for the pour to land: the free fall from the top of the
-- loose spheres plus the shortest settling (min_rest_time). `who` names the script.
function M.check_settle_time(who, fill, settle_max_time, min_rest_time)
  local fall = M.fall_time(fill.top_z)
  if settle_max_time < fall + min_rest_time then
    error(string.format("%s: settle_max_time = %g s is too short for the poured fill: the spheres fall from %.2f m "
                        .. "(%.2f s) and settling needs min_rest_time = %g s more; allowed: settle_max_time >= %.2f s",
                        who, settle_max_time, fill.top_z, fall, min_rest_time, fall + min_rest_time), 2)
  end
end

-- After settling, a full container has spheres above its rim (the strike-off removes them). None
-- means the pour fell short and the container is not full: refuse to go on.
function M.check_full(who, struck, level)
  if struck == 0 then
    error(string.format("%s: the poured fill settled below the rim (z = %g m): nothing to strike off, so the "
                        .. "container is not full; raise lib/pour.lua's margin", who, level), 2)
  end
end

-- After the strike-off nothing is left in the hopper: send it up and away from the experiment (the
-- engine has no wall removal; a wall far away costs nothing).
function M.remove_hopper(sim, fill)
  if fill.hopper then sim:set_motion(fill.hopper, {type = "translate", velocity = {0, 0, 2.0}}) end
end

-- Settles a fill in its container and strikes it off at `level`: runs until the fill below the
-- level is at rest (M.settled; at most settle_max_time), removes every sphere
-- standing above the level, and for a poured fill (`poured`, from M.fill) checks that it was full
-- (M.check_full) and sends its hopper away. o: who (the script's name), poured (nil for a fill
-- placed without a hopper), level, settle_max_time, min_rest_time, rest_speed, rest_of (M.settled),
-- snapshot_every, progress; optional: every (the sampling interval, default 0.02 s), sample (lib/
-- sampler.lua samplers recorded at each sample), also (more stop triggers, M.settled's `extra`).
-- → the settling phase (phase.run's result, stopped_by = the trigger's name or "settle_max_time"),
-- spheres struck off
function M.settle_and_strike(sim, o)
  local settle = phase.run(sim, {duration = o.settle_max_time, every = o.every or 0.02, snapshot_every = o.snapshot_every,
                                 progress = o.progress, sample = o.sample,
                                 stop = M.settled(o.poured, o.level, o.min_rest_time, o.rest_speed, o.also, o.rest_of)})
  settle.stopped_by = settle.stopped_by or "settle_max_time"
  local struck = sim:remove_if(function(i, x, y, z, r) return z + r > o.level end)
  if o.poured then
    M.check_full(o.who, struck, o.level)
    M.remove_hopper(sim, o.poured)
  end
  return settle, struck
end

return M
