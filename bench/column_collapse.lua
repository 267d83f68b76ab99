-- Paddy performance benchmark: cohesive (JKR) column collapse of wet paddy mud.
--
-- The problem must stay identical to bench/lammps/column_collapse.in and
-- bench/liggghts/column_collapse.in, because bench/run.sh compares the three codes:
--
--   * N monodisperse spheres, d = 2 mm, mud: rho = 1680 kg/m^3, G = 1 MPa, nu = 0.5
--   * simple cubic lattice, spacing s = 1.02 d; m x m columns of nz layers with
--     m = round((N/2)^(1/3)), nz = round(N/m^2) (height ~ 2 x width):
--     N = 10000 -> 17x17x35 = 10115, 20000 -> 22x22x41 = 19844, 40000 -> 27x27x55 = 40095
--     sphere (i,j,k), 0-based, at ((i+0.5) s, (j+0.5) s, (k+0.5) s)
--   * flat floor z = 0 (mud-"steel" contact), no side walls, gravity (0, 0, -9.81)
--   * pseudo-random lateral velocity from a hash of the lattice indices (same numbers as the
--     LAMMPS/LIGGGHTS inputs, see lateral_velocity below), vz = 0
--   * dt = 0.2 x Rayleigh time (nu = 0.5) = 2.6868e-5 s; neighbour skin 0.4 R
--   * `steps` timed steps (default 2000 = 0.054 s of collapse)
--
-- Run by bench/run.sh as:
--   build/bin/paddy run bench/column_collapse.lua --set n=20000 --set steps=2000 \
--       --threads T --out DIR
-- and bench/run.sh reads DIR/result.json:
--   particle_steps_per_second  (REQUIRED; number) = particles x timed steps / wall seconds of
--                              the timed sim:run only (setup and output excluded), i.e. the
--                              analogue of N x steps / "Loop time" in LAMMPS and LIGGGHTS.
--                              Top level, or nested anywhere (e.g. under "stats"); run.sh
--                              takes the first key of that name it finds.
--   contacts                   (optional; integer) contacts at the end of the run
--   particles                  (optional; integer) particle count
-- The engine's run statistics give particle_steps_per_second in result.json's metadata.

local P = paddy.parameters{
  n     = {default = 20000, min = 1000, max = 2000000, description = "particles (requested; the lattice rounds it)"},
  steps = {default = 2000,  min = 1,    max = 10000000, description = "timed steps"},
}

local d     = 0.002          -- particle diameter [m]
local R     = d / 2
local s     = 1.02 * d       -- lattice spacing [m]
local m     = math.floor((P.n / 2) ^ (1 / 3) + 0.5)
local nz    = math.floor(P.n / (m * m) + 0.5)

-- Skin: Paddy's `skin` is a fraction of the largest radius (engine/core/src/integrator.cpp),
-- so 0.4 gives 0.4 R = 0.4 mm like `neighbor 0.0004 bin` in LAMMPS/LIGGGHTS.
-- threads: taken from --threads by default (paddy.simulation's `threads` option).
local sim = paddy.simulation{gravity = {0, 0, -9.81}, skin = 0.4}

local mud   = sim:material{name = "mud",   density = 1680, shear_modulus = 1e6,    poisson = 0.5}
local steel = sim:material{name = "steel", density = 7800, shear_modulus = 7000e6, poisson = 0.3}

-- Mud-mud: the reference's calibrated values (EDEM Hertz-Mindlin + JKR, rolling friction type A).
sim:interaction(mud, mud, {
  normal = "jkr", damping = "hertz_mindlin", tangential = "mindlin", rolling = "constant_torque",
  restitution = 0.13, friction = 0.15, rolling_friction = 0.125, surface_energy = 0.096,
})
-- Mud-floor: Hertz-Mindlin without cohesion, the reference's mud-steel values.
-- NOTE for comparability: LAMMPS and LIGGGHTS give the floor the MUD's stiffness (their wall
-- models take one material); with steel here the floor contact is slightly stiffer. Only the
-- bottom layer (m*m = 484 of 19844 spheres) touches the floor, so the cost is unaffected.
sim:interaction(mud, steel, {
  normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin", rolling = "constant_torque",
  restitution = 0.3, friction = 0.6, rolling_friction = 0.055,
})

-- The floor: an infinite steel plane.
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = steel, name = "floor"}

-- Same pseudo-random numbers as the LAMMPS/LIGGGHTS inputs (they compute the same formula
-- with floor(x/s) etc. on the created lattice; here we have the indices directly).
local function frac(x) return x - math.floor(x) end
local function lateral_velocity(i, j, k)
  local key = i + 97 * j + 9973 * k
  local ux = frac(math.sin(0.9137 * key + 0.25) * 31415.9265)
  local uy = frac(math.sin(0.9137 * key + 1.75) * 31415.9265)
  return 0.01 * (2 * ux - 1), 0.01 * (2 * uy - 1)
end

-- The lattice, one sphere at a time (each needs its own lateral velocity).
for k = 0, nz - 1 do
  for j = 0, m - 1 do
    for i = 0, m - 1 do
      local vx, vy = lateral_velocity(i, j, k)
      sim:add_particle{pos = {(i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s}, radius = R,
                       material = mud, vel = {vx, vy, 0}}
    end
  end
end

-- dt = 0.2 T_R with the MUD's Rayleigh time: T_R = pi R / (0.163 nu + 0.877) sqrt(rho/G)
-- = 1.3434e-4 s -> dt = 2.6868e-5 s. Today Simulation::rayleighTime() takes the minimum over
-- the materials that particles use, so the steel floor does not shrink it; if that changes
-- (steel would give a ~22x smaller step), use sim:timestep{dt = 2.6868436e-5}.
local dt = sim:timestep{fraction = 0.2}

-- The timed run. No snapshots, no callback, no progress line: output costs time, and LAMMPS
-- and LIGGGHTS print thermo only three times.
sim:run{steps = P.steps, progress = false}

paddy.result{
  particles = sim:count(),
  contacts  = sim:contact_count(),
  dt        = dt,
  lattice   = {m, m, nz},
}
