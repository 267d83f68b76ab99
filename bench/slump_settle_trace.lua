-- bench/slump_settle_trace.lua -- runs experiments/slump.lua unchanged and, at every sample of its
-- settling (its first sim:run: the pour falling and settling inside the fixed cone), prints one
-- line: the time since the settling started, the RMS speed sqrt(2 KE / M) of all spheres, of those
-- wholly below the rim (z + r <= 300 mm: what the strike-off keeps), and the excess above the rim
-- (its count, mean vertical speed, fastest sphere, highest centre). It shows where the settling's
-- time goes and what the rule that ends it (lib/pour.lua settled) waits for.
-- Run from the repository root (the experiment's modules are found under experiments/):
--   paddy run bench/slump_settle_trace.lua --threads 1 --seed 1 --set settle_rest_of=all --out DIR
-- Lines: "SETTLE t_s rms_all rms_kept n_above vz_above vmax_above zmax_above" on stdout.
package.path = "experiments/?.lua;" .. package.path
local util = require("lib.util")

local RIM = 0.3  -- the slump cone's height (slump.lua: H)
local make_simulation = paddy.simulation
local wrapped = false
paddy.simulation = function(...)
  local sim = make_simulation(...)
  if wrapped then return sim end
  wrapped = true
  local methods = getmetatable(sim).__index
  local run, traced = methods.run, false
  methods.run = function(s, args)
    if traced or type(args) ~= "table" or not args.callback then return run(s, args) end
    traced = true
    local t0, callback = s:time(), args.callback
    print("SETTLE t_s rms_all rms_kept n_above vz_above vmax_above zmax_above")
    args.callback = function(ss)
      local zs = select(3, ss:xyz())
      local v, r = ss:velocities(), ss:radii()
      local n, vz, vmax, zmax = 0, 0, 0, -math.huge
      for i = 1, #zs do
        if zs[i] + r[i] > RIM then
          local w = v[i]
          n, vz = n + 1, vz + w[3]
          vmax = math.max(vmax, math.sqrt(w[1] ^ 2 + w[2] ^ 2 + w[3] ^ 2))
          zmax = math.max(zmax, zs[i])
        end
      end
      print(string.format("SETTLE %.3f %.5f %.5f %d %.4f %.3f %.3f", ss:time() - t0, util.rms_speed(ss),
                          util.rms_speed(ss, RIM), n, n > 0 and vz / n or 0, vmax, n > 0 and zmax or 0))
      return callback(ss)
    end
    return run(s, args)
  end
  return sim
end

dofile("experiments/slump.lua")
