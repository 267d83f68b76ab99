-- Measured sensitivities of the discovery benchmark's experiments (docs/discovery.md,
-- "Sensitivities measured"): which observable each candidate effect moves, how strongly, and which
-- experiments tell the candidates apart once the free parameter is recalibrated.
--
--   paddy run experiments/validation/discovery_sensitivity.lua --set cone_scales=1,1.5 --set vane_scale=4 --out DIR
--
-- At one model point (the free parameter at `theta`, every candidate off) it runs `seeds` seeds of
-- every experiment (lib/discovery/benchmark.lua), the free parameter moved by fd_step of its range,
-- and each candidate at its probe strength (half its range), all at the same seeds (common random
-- numbers). Per seed the finite differences give the free parameter's Jacobian column and each
-- candidate's signature; their means are used. The noise is the workflow's: the measurement sd of
-- the benchmark and the seed scatter of the base runs with one truth run as the measurement
-- (measured_repeats = 1) and `replicates` replicates (paddy.doe.noise_covariance).
-- For every group of experiments (each alone, all, all but each) paddy.doe.diagnose on a zero
-- residual gives, per candidate, a = g^T P g (whitened, projected off the free parameter), hence
--   * z at the top of its range, high sqrt(a): the size of the score test's signal there,
--   * the smallest strength the score test sees at z = 3, 3 / sqrt(a),
--   * the share of its signature recalibration absorbs (absorbed_fraction),
-- and the confusability c_kl = cos(P g_k, P g_l) of every pair. Output: sensitivity.json,
-- sensitivity_moves.csv (every observable's move per candidate in noise sd), a table on stdout.
-- Every run is a campaign job: running the command again repeats nothing that finished.
local doe = require("paddy.doe")
local util = require("lib.util")
local stack = require("lib.discovery.stack")
local bench = require("lib.discovery.benchmark")
local jobs = require("lib.calibration.jobs")

local P = paddy.parameters{
  {name = "particle_diameter", default = 0.025, unit = "m", min = 0.001, max = 0.04, description = "sphere diameter of every run"},
  {name = "theta", default = 0.15, unit = "J/m^2", min = 0, max = 10, description = "the free parameter (jkr_surface_energy, 2 mm value) at the model point, inside [free_low, free_high]"},
  {name = "free_low", default = 0.05, unit = "J/m^2", min = 0, max = 10, description = "lower end of the free parameter's range (the benchmark's: 0.05)"},
  {name = "free_high", default = 0.3, unit = "J/m^2", min = 0, max = 10, description = "upper end of the free parameter's range (the benchmark's: 0.3)"},
  {name = "material", default = "", description = "named contact-parameter set of every run ('' = the experiments' default; experiments/materials/paddy_mud.json)"},
  {name = "seeds", default = 3, type = "integer", min = 2, max = 50, description = "seeds of every run (the base runs' scatter is the seed noise)"},
  {name = "replicates", default = 5, type = "integer", min = 2, max = 1000, description = "replicates the workflow would average at the model point (its noise: Sigma_seed (1/replicates + 1))"},
  {name = "fd_step", default = 0.1, min = 0.01, max = 0.5, description = "the free parameter's finite-difference step as a fraction of its range"},
  {name = "variant", default = "small", choices = {"small", "full"}, description = "the benchmark's slump experiments: small (one lift at 0.3 m/s) or full (0.1 and 0.4 m/s)"},
  {name = "lift_speeds", default = "", description = "lift speeds of the slump experiments, comma-separated m/s ('' = the variant's)"},
  {name = "cone_scales", default = "", description = "cone sizes of the slump experiments as factors of the standard cone ('' = the standard cone)"},
  {name = "vane_scale", default = 0, min = 0, max = 8, description = "the vane rheometer scaled by this factor (0 = none)"},
  {name = "candidate_set", default = "effects", choices = {"stand_in", "effects"}, description = "candidate effects (lib/discovery/benchmark.lua)"},
  {name = "timestep_fraction", default = 0.1, min = 0.01, max = 0.5, description = "time step / Rayleigh time (as discover.lua)"},
  {name = "max_parallel", default = 0, type = "integer", min = 0, max = 1024, description = "simulations at once (0: one per core)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys ('' = hash of the binaries)"},
}

local here = (debug.getinfo(1, "S").source:match("^@(.*)/[^/]*$")) or "."
local experiments_dir = here .. "/.."
local function say(fmt, ...) io.stderr:write("sensitivity: ", string.format(fmt, ...), "\n") end

local cands = bench.CANDIDATE_SETS[P.candidate_set].candidates
local free = {parameter = bench.FREE[1].parameter, low = P.free_low, high = P.free_high}
if not (free.low < free.high and P.theta >= free.low and P.theta <= free.high) then
  error(string.format("discovery_sensitivity.lua: theta = %g must lie in [free_low, free_high] = [%g, %g] with free_low < free_high",
                      P.theta, free.low, free.high), 0)
end
local exps = bench.experiments{variant = P.variant, lift_speeds = P.lift_speeds, cone_scales = P.cone_scales, vane_scale = P.vane_scale}
-- The same fixed parameters as discover.lua's runs: one step for all, no pictures.
local mud = require("lib.mud")
local fixed = {particle_diameter = P.particle_diameter, pictures = false, snapshot_interval = 0, progress = false,
               timestep_fraction = P.timestep_fraction * mud.timestep_factor(0.055), timestep_damping = false}
local campaign = paddy.campaign{dir = util.out("campaign"), executor = "local", max_parallel = P.max_parallel > 0 and P.max_parallel or nil,
                                threads_per_job = 1, code_version = P.code_version ~= "" and P.code_version or nil}
if P.material ~= "" then fixed.material = P.material end
local runner = jobs.new{campaign = campaign, script = "slump.lua", fixed = fixed, responses = {}}

-- Model points: base, the free parameter stepped, each candidate at its probe; every one at every seed.
local h = P.fd_step * (free.high - free.low)
if P.theta + h > free.high then h = -h end
local variants = {{label = "base", theta = P.theta}, {label = "theta+h", theta = P.theta + h}}
for _, c in ipairs(cands) do variants[#variants + 1] = {label = c.name, theta = P.theta, candidate = c, probe = 0.5 * c.high} end
local points = {}
for _, v in ipairs(variants) do
  for s = 1, P.seeds do
    for _, e in ipairs(exps) do
      local params = {}
      for k, x in pairs(e.set) do params[k] = x end
      params[free.parameter] = v.theta
      for _, c in ipairs(cands) do params[c.parameter] = (v.candidate == c) and v.probe or 0 end
      points[#points + 1] = {script = experiments_dir .. "/" .. e.script, params = params, seed = 700 + s,
                             label = string.format("%s seed %d %s", v.label, s, e.name), variant = v, s = s, e = e}
    end
  end
end
say("%d experiment(s) x %d variants x %d seeds = %d simulations at %.0f mm", #exps, #variants, P.seeds, #points, P.particle_diameter * 1000)
local rows = runner:run("sensitivity", points)

-- The stacked layout from the base runs' means: the measurement sd follows the benchmark's rule at
-- the base value (as a truth run's measurement would have it).
local results = {}   -- results[variant label][seed][experiment name]
for i, pt in ipairs(points) do
  local byseed = results[pt.variant.label] or {}
  results[pt.variant.label] = byseed
  byseed[pt.s] = byseed[pt.s] or {}
  byseed[pt.s][pt.e.name] = rows[i].result
end
local pseudo = {experiments = {}}
for _, e in ipairs(exps) do
  local obs = {}
  for _, o in ipairs(e.observables) do
    local sum
    for s = 1, P.seeds do
      local v = assert(stack.extract(results.base[s][e.name], o.key))
      sum = sum or {}
      for n, x in ipairs(v) do sum[n] = (sum[n] or 0) + x / P.seeds end
    end
    local sd = {}
    for n, x in ipairs(sum) do sd[n] = bench.noise_sd(o, x) end
    obs[#obs + 1] = {key = o.key, measured = sum, sigma = sd, vector = #sum > 1}
  end
  pseudo.experiments[#pseudo.experiments + 1] = {name = e.name, observables = obs}
end
local L = stack.layout(pseudo)
stack.label(L, results.base[1])
local m = #L
local function vec(label, s) return stack.simulated(L, results[label][s], label) end
local base = {}
for s = 1, P.seeds do base[s] = vec("base", s) end
local J, G = {}, {}
for i = 1, m do J[i] = 0 end
for s = 1, P.seeds do
  local f = vec("theta+h", s)
  for i = 1, m do J[i] = J[i] + (f[i] - base[s][i]) / h / P.seeds end
end
for k, c in ipairs(cands) do
  G[k] = {}
  for i = 1, m do G[k][i] = 0 end
  for s = 1, P.seeds do
    local f = vec(c.name, s)
    for i = 1, m do G[k][i] = G[k][i] + (f[i] - base[s][i]) / variants[k + 2].probe / P.seeds end
  end
end
local ones = {}
for i = 1, m do ones[i] = 1 end
local n_eff = 1 / (1 / P.replicates + 1)
local noise = doe.noise_covariance{replicates = base, sigma = ones, n_avg = n_eff}
local seed_sd, noise_sd = {}, {}
for i = 1, m do seed_sd[i], noise_sd[i] = math.sqrt(noise.seed_covariance[i][i]), math.sqrt(noise.covariance[i][i]) end

-- Every observable's move per candidate at its probe (and the free parameter's per step), in noise
-- sd (the workflow's standardised units: measurement sd and seed scatter together).
local move_rows = {}
for i, l in ipairs(L) do
  local row = {l.label, l.measured, l.sigma * seed_sd[i], l.sigma, l.sigma * noise_sd[i], J[i] * h / noise_sd[i]}
  for k, c in ipairs(cands) do row[#row + 1] = G[k][i] * variants[k + 2].probe / noise_sd[i] end
  move_rows[i] = row
end
local cols = {"observable", "base_mean", "seed_sd", "measurement_sd", "noise_sd", free.parameter .. "_step"}
for _, c in ipairs(cands) do cols[#cols + 1] = c.name .. "_probe" end
util.write_csv("sensitivity_moves.csv", cols, move_rows)

-- Groups of experiments: each alone, all of them, all but each.
local groups = {}
for _, e in ipairs(exps) do groups[#groups + 1] = {name = e.name, members = {[e.name] = true}} end
if #exps > 1 then
  local all = {}
  for _, e in ipairs(exps) do all[e.name] = true end
  groups[#groups + 1] = {name = "all", members = all}
  if #exps > 2 then
    for _, x in ipairs(exps) do
      local g = {}
      for _, e in ipairs(exps) do if e ~= x then g[e.name] = true end end
      groups[#groups + 1] = {name = "all but " .. x.name, members = g}
    end
  end
end
local out_groups = {}
for _, g in ipairs(groups) do
  local idx = {}
  for i, l in ipairs(L) do if g.members[l.block] then idx[#idx + 1] = i end end
  local sub = function(v) local o = {}; for n, i in ipairs(idx) do o[n] = v[i] end; return o end
  local cov, jac, dc = {}, {}, {}
  for a, i in ipairs(idx) do
    cov[a] = {}
    for b, j in ipairs(idx) do cov[a][b] = noise.covariance[i][j] end
    jac[a] = {J[i]}
  end
  for k, c in ipairs(cands) do dc[k] = {name = c.name, signature = sub(G[k]), low = c.low, high = c.high} end
  local zero = {}
  for a = 1, #idx do zero[a] = 0 end
  local d = doe.diagnose{residual = zero, covariance = cov, jacobian = jac, candidates = dc}
  local per, high = {}, {}
  for _, c in ipairs(cands) do high[c.name] = c.high end
  for k, c in ipairs(d.candidates) do
    local ra = math.sqrt(math.max(c.a, 0))
    per[k] = {name = c.name, a = c.a, z_at_high = high[c.name] * ra, strength_at_z3 = ra > 0 and 3 / ra or nil,
              absorbed_fraction = c.absorbed_fraction, identifiable = c.identifiable}
  end
  out_groups[#out_groups + 1] = {name = g.name, observables = #idx, candidates = per, confusability = d.confusability}
end

-- The table.
print(string.format("%d observables, %d seeds, %s at %.4g (step %.4g), %.0f mm", m, P.seeds, free.parameter, P.theta, h, P.particle_diameter * 1000))
for _, g in ipairs(out_groups) do
  print(string.format("\n%s (%d observables)", g.name, g.observables))
  local head = string.format("  %-18s %10s %12s %9s ", "candidate", "z at high", "z=3 at", "absorbed")
  for _, c in ipairs(cands) do head = head .. string.format(" %8s", c.name:sub(1, 8)) end
  print(head)
  for k, c in ipairs(g.candidates) do
    local line = string.format("  %-18s %10.2f %12.4g %9.3f ", c.name, c.z_at_high, c.strength_at_z3 or 0 / 0, c.absorbed_fraction or 0 / 0)
    for l = 1, #cands do line = line .. string.format(" %8.3f", g.confusability[k][l]) end
    print(line)
  end
end
-- The five observables each probe (and the free parameter's step) moves most.
local function largest(col, what)
  local order = {}
  for i = 1, m do order[i] = i end
  table.sort(order, function(a, b) return math.abs(move_rows[a][col]) > math.abs(move_rows[b][col]) end)
  local t = {}
  for n = 1, math.min(5, m) do t[n] = string.format("%s %+.1f", L[order[n]].label, move_rows[order[n]][col]) end
  print(string.format("  %-24s %s", what, table.concat(t, ", ")))
end
print("\nlargest moves [noise sd]")
largest(6, free.parameter .. " +" .. string.format("%.3g", h))
for k, c in ipairs(cands) do largest(6 + k, c.name .. " " .. string.format("%.3g", variants[k + 2].probe)) end
local out = {particle_diameter = P.particle_diameter, theta = P.theta, theta_step = h, seeds = P.seeds, replicates = P.replicates,
             experiments = exps, candidates = cands, probes = {}, groups = out_groups, labels = {}, jacobian = J, signatures = {},
             seed_sd = seed_sd, noise_sd = noise_sd, seed_shrinkage = noise.shrinkage, simulations = #points}
for k, c in ipairs(cands) do out.probes[c.name], out.signatures[c.name] = variants[k + 2].probe, G[k] end
for i, l in ipairs(L) do out.labels[i] = l.label end
paddy.write_json("sensitivity.json", out)
paddy.result{groups = out_groups, simulations = #points}
