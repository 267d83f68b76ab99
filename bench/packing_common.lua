-- Helpers of the settled-packing benchmark (bench/packing_make.lua, bench/packing.lua):
-- reading the packing's data file and counting overlapping sphere pairs the way LAMMPS's and
-- LIGGGHTS's `compute contact/atom` does (centre distance < r_i + r_j; walls not counted).
local M = {}

-- read_data(path) -> array of {id, diameter, density, x, y, z}, box {xlo, xhi, ylo, yhi, zlo, zhi}
-- Reads the "Atoms" section of the LAMMPS data file written by bench/packing_make.lua
-- (atom_style sphere: id type diameter density x y z).
function M.read_data(path)
  local f = assert(io.open(path, "r"))
  local atoms, box, in_atoms = {}, {}, false
  for line in f:lines() do
    local body = line:gsub("#.*", "")
    local lo, hi, axis = body:match("^%s*(%S+)%s+(%S+)%s+([xyz])lo%s+[xyz]hi")
    if lo then
      box[axis .. "lo"], box[axis .. "hi"] = tonumber(lo), tonumber(hi)
    elseif body:match("^%s*Atoms%s*$") then
      in_atoms = true
    elseif in_atoms then
      local id, _, dia, dens, x, y, z = body:match(
        "^%s*(%d+)%s+(%d+)%s+(%S+)%s+(%S+)%s+(%S+)%s+(%S+)%s+(%S+)")
      if id then
        atoms[#atoms + 1] = {tonumber(id), tonumber(dia), tonumber(dens), tonumber(x), tonumber(y), tonumber(z)}
      elseif body:match("%a") then
        break  -- the next section
      end
    end
  end
  f:close()
  if #atoms == 0 then error("packing_common.lua: no atoms in " .. path, 2) end
  return atoms, box
end

-- overlapping_pairs(sim) -> number of sphere pairs with centre distance < r_i + r_j
function M.overlapping_pairs(sim)
  local xs, ys, zs = sim:xyz()
  local r = sim:radii()
  local rmax = 0
  for i = 1, #r do rmax = math.max(rmax, r[i]) end
  local h = 2 * rmax
  local cells = {}
  local function key(i, j, k) return (i * 73856093) ~ (j * 19349663) ~ (k * 83492791) end
  local ci, cj, ck = {}, {}, {}
  for n = 1, #xs do
    ci[n], cj[n], ck[n] = math.floor(xs[n] / h), math.floor(ys[n] / h), math.floor(zs[n] / h)
    local kk = key(ci[n], cj[n], ck[n])
    local c = cells[kk]
    if not c then c = {}; cells[kk] = c end
    c[#c + 1] = n
  end
  local count = 0
  for n = 1, #xs do
    for di = -1, 1 do for dj = -1, 1 do for dk = -1, 1 do
      local c = cells[key(ci[n] + di, cj[n] + dj, ck[n] + dk)]
      if c then
        for _, m in ipairs(c) do
          if m > n and ci[m] == ci[n] + di and cj[m] == cj[n] + dj and ck[m] == ck[n] + dk then
            local dx, dy, dz = xs[m] - xs[n], ys[m] - ys[n], zs[m] - zs[n]
            local s = r[m] + r[n]
            if dx * dx + dy * dy + dz * dz < s * s then count = count + 1 end
          end
        end
      end
    end end end
  end
  return count
end

return M
