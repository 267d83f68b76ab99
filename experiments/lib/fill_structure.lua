-- Structure of a settled fill, away from the walls: is it a random packing or a crystal?
--
-- For the spheres whose centres lie in a core region (a frustum, axis +z) it reports
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
local M = {}

M.crystal_share = 0.1

-- Volume of the frustum {radius_bottom, radius_top, z_min, z_max}.
local function frustum_volume(c)
  local a, b = c.radius_bottom, c.radius_top
  return math.pi * (c.z_max - c.z_min) / 3 * (a * a + a * b + b * b)
end

-- sim: a simulation; core: {radius_bottom =, radius_top =, z_min =, z_max =} (radii at z_min and
-- z_max, axis x = y = 0). Returns the table described above, or nil and a reason when the core
-- holds fewer than 20 centres.
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
  local function inside(i)
    local z = zs[i]
    if z < core.z_min or z > core.z_max then return false end
    local R = core.radius_bottom + (core.radius_top - core.radius_bottom) * (z - core.z_min) / (core.z_max - core.z_min)
    return xs[i] * xs[i] + ys[i] * ys[i] < R * R
  end
  -- Cell grid (cell ≥ the largest distance looked at) over all spheres.
  local reach = math.max(2.2 * r_max * 1.05, 1.6 * d_mean)
  local cell = reach
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
  local pairs = {}
  for b = 1, bins do pairs[b] = 0 end
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
                    local b = math.floor((r - lo) / width) + 1
                    pairs[b] = pairs[b] + 1
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
  local volume = frustum_volume(core)
  local density = core_n / volume
  local g = 0
  for b = 1, bins do
    local r1, r2 = lo + (b - 1) * width, lo + b * width
    g = math.max(g, pairs[b] / (core_n * density * 4 / 3 * math.pi * (r2 ^ 3 - r1 ^ 3)))
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

-- Warns on stderr when a measured fill is crystalline; `who` names the script.
function M.warn_if_crystalline(who, structure)
  if structure and structure.crystalline then
    io.stderr:write(string.format("warning: %s: the fill is crystalline (%.0f %% of the core's spheres have 10 or more "
                                  .. "neighbours, solid fraction %.3f): it resists shear like no mud; use packing = poured\n",
                                  who, 100 * structure.neighbours_10_or_more, structure.solid_fraction))
  end
end

return M
