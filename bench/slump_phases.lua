-- bench/slump_phases.lua -- runs experiments/slump.lua unchanged, with a marker line on stderr
-- before and after every sim:run, strike-off (sim:remove_if) and measurement call, so that
-- bench/slump_phases.py can time the experiment's phases by the wall clock.
-- Run from the repository root (the experiment's modules are found under experiments/):
--   paddy run bench/slump_phases.lua --out DIR [--set name=value ...]   (slump.lua's parameters)
package.path = "experiments/?.lua;" .. package.path

local timed = {"run", "remove_if", "measure_slump", "measure_slump_flow", "measure_profile"}
local make_simulation = paddy.simulation
local wrapped = false
paddy.simulation = function(...)
  local sim = make_simulation(...)
  if not wrapped then
    -- The methods live in the shared metatable of all simulations: wrap them once.
    local methods = getmetatable(sim).__index
    for _, name in ipairs(timed) do
      local f = methods[name]
      if f then
        methods[name] = function(...)
          io.stderr:write("PHASE begin " .. name .. "\n")
          local r = table.pack(f(...))
          io.stderr:write("PHASE end " .. name .. "\n")
          return table.unpack(r, 1, r.n)
        end
      end
    end
    wrapped = true
  end
  return sim
end

dofile("experiments/slump.lua")
