-- Load samples recorded by the engine (sim:run{record_loads_every = T}, no callback) at the
-- instants t0 + k n dt (n = round(T / dt)) and at the end of the run; a subset of walls with
-- record_loads; a run stopped early by its callback; bad options. The histories are written to
-- one HDF5 file (a group per wall), to a single-wall HDF5 file and to CSV.
local C = require("common")
local sim = paddy.simulation{gravity = {0, 0, -9.81}, threads = paddy.threads}
local mud, steel = C.setup(sim)
local cup = sim:add_mesh_wall{part = "cup", params = {diameter = 0.05, height = 0.05, segments = 32}, material = steel}
local vane = sim:add_mesh_wall{part = "vane", material = steel, translate = {0, 0, 0.003},
                               params = {diameter = 0.025, height = 0.03, shaft_length = 0.03},
                               motion = {type = "rotate", axis = {0, 0, 1}, speed = 3}}
local floor = sim:add_wall{type = "plane", point = {0, 0, -0.01}, normal = {0, 0, 1}, material = steel, name = "floor"}
sim:fill{region = {type = "cylinder", base = {0, 0, 0}, radius = 0.022, height = 0.02},
         radius = 0.0015, material = mud, count = 150, seed = 2}
sim:remove_if(function(i, x, y, z, r) return x * x + y * y < (0.0125 + r + 0.0002) ^ 2 end)
local dt = 1e-4
sim:timestep{dt = dt}

local function near(a, b) return math.abs(a - b) < 1e-12 end
-- Samples of `h` from index `first` are at t0 + k n dt (k = 1..m) and then at t_end if off-grid.
local function check_times(h, first, t0, n, steps, label)
  local k, expected = 0, {}
  for j = n, steps, n do expected[#expected + 1] = t0 + j * dt end
  if steps % n ~= 0 then expected[#expected + 1] = t0 + steps * dt end
  C.check(#h - first + 1 == #expected, "%s: %d samples, expected %d", label, #h - first + 1, #expected)
  for i, t in ipairs(expected) do
    k = first + i - 1
    C.check(near(h[k].t, t), "%s: sample %d at t = %.17g, expected %.17g", label, i, h[k].t, t)
  end
end

-- Every mesh wall, every 0.01 s (100 steps) over 0.05 s: 5 samples each, at 0.01 .. 0.05.
local t0 = sim:time()
sim:run{duration = 0.05, record_loads_every = 0.01, progress = false}
check_times(sim:wall_load_history(vane), 1, t0, 100, 500, "vane, run 1")
check_times(sim:wall_load_history(cup), 1, t0, 100, 500, "cup, run 1")
local h = sim:wall_load_history(vane)
C.check(near(h[#h].angle, 3 * h[#h].t), "vane angle %.17g at t = %g", h[#h].angle, h[#h].t)
C.check(#h[1].force == 3 and #h[1].torque == 3, "force/torque are vectors")

-- Only the vane, every 0.004 s (40 steps) over 0.025 s (250 steps): 6 on the grid + the end.
t0 = sim:time()
sim:run{duration = 0.025, record_loads_every = 0.004, record_loads = {vane}, progress = false}
check_times(sim:wall_load_history(vane), 6, t0, 40, 250, "vane, run 2")
C.check(#sim:wall_load_history(cup) == 5, "the cup recorded in run 2")

-- Stopped early by the callback at 0.015 s: samples at 0.01 and at the stop, once each.
t0 = sim:time()
local calls = 0
sim:run{duration = 0.05, record_loads_every = 0.01, record_loads = "vane", every = 0.015, progress = false,
        callback = function(s) calls = calls + 1; return false end}
check_times(sim:wall_load_history(vane), 13, t0, 100, 150, "vane, run 3")
C.check(calls == 1, "callback called %d times", calls)

-- Bad options name the option and what is allowed.
local function refused(opts, pattern)
  opts.duration = 0.001
  opts.progress = false
  local ok, err = pcall(sim.run, sim, opts)
  C.check(not ok and tostring(err):find(pattern), "expected an error matching '%s', got: %s", pattern, tostring(err))
end
refused({record_loads_every = 0}, "record_loads_every = 0 s must be a positive number of seconds")
refused({record_loads_every = -1}, "record_loads_every = %-1 s must be a positive")
refused({record_loads = {vane}}, "record_loads needs record_loads_every")
refused({record_loads_every = 0.01, record_loads = {vane, "nope"}}, "record_loads entry 2: no wall named 'nope'")
refused({record_loads_every = 0.01, record_loads = {floor}}, "record_loads entry 1: wall 'floor' is not a mesh wall")
refused({record_loads_every = 0.01, record_loads = {}}, "record_loads is an empty list")
local ok, err = pcall(sim.write_wall_loads, sim, "loads.csv")
C.check(not ok and tostring(err):find("must end in .h5 or .hdf5"), "all walls to CSV: %s", tostring(err))

local n_vane, n_cup = #sim:wall_load_history(vane), #sim:wall_load_history(cup)
local all = sim:write_wall_loads("loads.h5")             -- every mesh wall, a group each
local one = sim:write_wall_loads(vane, "vane_loads.hdf5")
local csv = sim:write_wall_loads("vane", "vane_loads.csv")
paddy.result{vane_samples = n_vane, cup_samples = n_cup, all = all, one = one, csv = csv}
