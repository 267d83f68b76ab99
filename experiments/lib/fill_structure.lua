-- Structure of a settled fill, away from the walls: is it a random packing or a crystal?
--
-- For the spheres whose centres lie in a core region (a sim:fill cone or cylinder region) it reports
--   solid_fraction  Σ (π/6) d_i³ of the core centres / core volume (random packings of
--                   frictional spheres 0.55–0.64, Scott & Kilgour 1969, J. Phys. D 2:863; the FCC
--                   crystal 0.74). Centres near the core's surface count whole, so a core only a
--                   few diameters across reads a few per cent high;
--   neighbours      mean number of spheres closer than 1.05 (r_i + r_j): a random dense packing
--                   has about 7 (Aste, Saadatfar & Senden 2005, Phys. Rev. E 71:061302), a crystal
--                   12;
--   neighbours_10_or_more  the share of core spheres with 10 or more of them: about 0–2 % in a
--                   random packing, most of them in a crystal;
--   g_sqrt2         the highest value of the radial distribution g(r), in bins of 0.02 d (d the
--                   mean diameter), between 1.33 d and 1.51 d: around the FCC/HCP second-neighbour
--                   distance √2·d (times the lattice spacing), a sharp peak (g > 2) in a crystal and
--                   the dip before the split second peak (g ≈ 0.5–0.9) in a random packing
--                   (Finney 1970, Proc. R. Soc. A 319:479).
-- `crystalline` is neighbours_10_or_more > crystal_share (default 0.1).
local util = require("lib.util")

local M = {}

M.crystal_share = 0.1

-- sim: a simulation; core: a cone or cylinder region as sim:fill takes it (axis +z through base).
-- Returns the table described above, or nil and a reason when the core holds fewer than 20 centres.
function M.measure(sim, core)
  local xs, ys, zs = sim:xyz()
  local radii = sim:radii()
  local n = #xs
  if n == 0 then return nil, "no particles" end
  local d_mean, r_max = 0, 0
  for i = 1, n do
    d_mean = d_mean + 2 * radii[i]
    r_max = math.max(r_max, radii[i])
  end
  d_mean = d_mean / n
  local x0, y0, z0 = core.base[1], core.base[2], core.base[3]
  local function inside(i)
    local h = zs[i] - z0
    if h < 0 or h > core.height then return false end
    local R = util.region_radius_at(core, h)
    return (xs[i] - x0) ^ 2 + (ys[i] - y0) ^ 2 < R * R
  end
  -- Cell grid over all spheres; a cell is at least the largest distance looked at (a contact
  -- neighbour within 1.05 (r_i + r_j), the g(r) bins up to 1.51 d).
  local cell = math.max(2.2 * r_max * 1.05, 1.6 * d_mean)
  local grid = {}
  local function key(ix, iy, iz) return (ix * 4096 + iy) * 4096 + iz end
  local cx, cy, cz = {}, {}, {}
  for i = 1, n do
    cx[i], cy[i], cz[i] = math.floor(xs[i] / cell), math.floor(ys[i] / cell), math.floor(zs[i] / cell)
    local k = key(cx[i], cy[i], cz[i])
    local list = grid[k]
    if not list then list = {}; grid[k] = list end
    list[#list + 1] = i
  end
  local bins, width, lo = 9, 0.02 * d_mean, 1.33 * d_mean
  local hi = lo + bins * width
  local shell_pairs = {}
  for k = 1, bins do shell_pairs[k] = 0 end
  local core_n, solid, nb_sum, nb_many = 0, 0, 0, 0
  for i = 1, n do
    if inside(i) then
      core_n = core_n + 1
      solid = solid + 4 / 3 * math.pi * radii[i] ^ 3
      local nb = 0
      for a = -1, 1 do
        for b = -1, 1 do
          for c = -1, 1 do
            local list = grid[key(cx[i] + a, cy[i] + b, cz[i] + c)]
            if list then
              for _, j in ipairs(list) do
                if j ~= i then
                  local dx, dy, dz = xs[i] - xs[j], ys[i] - ys[j], zs[i] - zs[j]
                  local r = math.sqrt(dx * dx + dy * dy + dz * dz)
                  if r < 1.05 * (radii[i] + radii[j]) then nb = nb + 1 end
                  if r >= lo and r < hi then
                    local k = math.floor((r - lo) / width) + 1
                    shell_pairs[k] = shell_pairs[k] + 1
                  end
                end
              end
            end
          end
        end
      end
      nb_sum = nb_sum + nb
      if nb >= 10 then nb_many = nb_many + 1 end
    end
  end
  if core_n < 20 then return nil, string.format("only %d sphere centres in the core", core_n) end
  local volume = util.region_volume(core)
  local density = core_n / volume
  local g = 0
  for k = 1, bins do
    local r1, r2 = lo + (k - 1) * width, lo + k * width
    g = math.max(g, shell_pairs[k] / (core_n * density * 4 / 3 * math.pi * (r2 ^ 3 - r1 ^ 3)))
  end
  return {
    core_particles = core_n,
    core_volume_m3 = volume,
    solid_fraction = solid / volume,
    neighbours = nb_sum / core_n,
    neighbours_10_or_more = nb_many / core_n,
    g_sqrt2 = g,
    crystalline = nb_many / core_n > M.crystal_share,
    mean_diameter = d_mean,
  }
end

-- The fill of a container after the strike-off, as the experiments report it: the solid fraction
-- of the whole container (sphere volume / volume of `container`, a cone or cylinder region up to
-- the fill level) and the structure of its core, two diameters `d` inside the walls, floor and
-- top. Warns on stderr, naming `who`, when the core is crystalline. Returns the solid fraction and
-- the structure (or {note = why not measured}).
function M.measure_fill(who, sim, container, d)
  local solid = util.total_mass(sim, 1)   -- sphere volume
  local structure, note = M.measure(sim, util.inner_region(container, 2 * d))
  if structure and structure.crystalline then
    io.stderr:write(string.format("warning: %s: the fill is crystalline (%.0f %% of the core's spheres have 10 or more "
                                  .. "neighbours, solid fraction %.3f): it resists shear like no mud; use packing = poured\n",
                                  who, 100 * structure.neighbours_10_or_more, structure.solid_fraction))
  end
  return solid / util.region_volume(container), structure or {note = note}
end

return M
