-- How often the surrogate strategy of the calibration reaches its targets, and after how many
-- simulations, on an emulator of the slump test whose answer is known: the strategy's own code
-- (lib/calibration/surrogate.lua, paddy.doe surrogate_suggest) run many times against stand-ins
-- for the simulation. Documentation: docs/calibration.md, "The surrogate's Gaussian processes".
--
--   paddy run experiments/calibration/surrogate_trials.lua --out results/surrogate_trials \
--       [--set trials=100] [--set data=FILE1,FILE2]
--
-- The emulator. A Gaussian process per response fitted to the calibrations' own simulations
-- (`data`: data/simulations.csv of full calibrations; the rows whose non-selected factors sit at
-- their centre: steepest ascent, Box-Behnken, verification, surrogate), its posterior mean the
-- "true" slump test and Gaussian noise of the seeds' scatter added to every emulated run. The
-- scatter is measured from the same files: the pooled standard deviation of the runs that share
-- all parameters (the Box-Behnken replicates, the verification seeds). Two emulators, one with a
-- plain and one with a warped Gaussian process (doe/include/paddy/doe/gaussian_process.hpp), so
-- that neither strategy is judged only on a landscape of its own kind.
--
-- The strategies: the surrogate as the calibration runs it (Latin hypercube, rounds of `batch`,
-- a run within the tolerance confirmed with further seeds, the budget) with plain and with warped
-- Gaussian processes. Trial k uses seed k for the Latin hypercube, the suggestions and the noise,
-- for every strategy and emulator alike.
--
-- Before the trials, a held-out check of the two kinds of Gaussian process on the data themselves:
-- fitted on `holdout_sizes` random simulations (as many as the surrogate has), how well they
-- predict all the others.
--
-- Outputs in --out: surrogate_trials.png (with pictures: the share of trials within the tolerance
-- against the simulations spent), surrogate_trials_runs.csv (every trial), surrogate_trials.csv and
-- surrogate_trials.json (per emulator and strategy: successes with a 95 % Clopper-Pearson
-- interval, simulations used, how often within `fast` simulations, the emulator's true error at
-- the confirmed point; the strategies paired trial by trial with a sign test; the held-out
-- check), result.json.
local util = require("lib.util")
local doe = require("paddy.doe")
local input_file = require("lib.calibration.input")
local jobs = require("lib.calibration.jobs")
local surrogate = require("lib.calibration.surrogate")
local score = require("lib.discovery.score")

local here = paddy.script:match("^(.*)/[^/]*$") or "."
local results = here .. "/results"
local P = paddy.parameters{
  {name = "input", default = here .. "/paddy_mud.json", description = "calibration input file: targets, tolerance, search ranges, surrogate settings"},
  {name = "data", default = results .. "/full_10mm/data/simulations.csv," .. results .. "/full_10mm_2026-12-06/data/simulations.csv",
   description = "comma-separated simulations.csv files of full calibrations (the emulator's data)"},
  {name = "factors", default = "H7,H5,H2,H3", description = "comma-separated symbols the surrogate searches (as the screening selected them)"},
  {name = "trials", default = 100, min = 1, max = 100000, description = "trials per emulator and strategy"},
  {name = "batch", default = 2, min = 1, max = 64, description = "simulations per round (the calibration's runs at once)"},
  {name = "fast", default = 16, min = 1, max = 1000, description = "report how often a strategy stops within this many simulations"},
  {name = "strategies", default = "plain,warped", description = "comma-separated: plain, warped (Gaussian processes of the surrogate)"},
  {name = "emulators", default = "plain,warped", description = "comma-separated: plain, warped (Gaussian processes of the emulator)"},
  {name = "initial_points", default = 0, min = 0, max = 100, description = "Latin-hypercube points of the surrogate (0: the input's surrogate.initial_points)"},
  {name = "holdout_sizes", default = "12,20,30", description = "held-out check: comma-separated numbers of simulations to fit on (empty: no check)"},
  {name = "pictures", default = true, description = "draw surrogate_trials.png (gnuplot): the share of trials within 2 % against the simulations spent"},
  {name = "holdout_repeats", default = 40, min = 0, max = 10000, description = "held-out check: random subsets per size"},
}

local input = input_file.read(P.input)
if P.initial_points > 0 then
  if P.initial_points < 2 or P.initial_points > input.surrogate.budget then
    error(string.format("surrogate_trials: initial_points = %d is outside the allowed range [2, %d] (the budget)", P.initial_points,
                        input.surrogate.budget), 0)
  end
  input.surrogate.initial_points = math.tointeger(P.initial_points) or error("surrogate_trials: initial_points must be a whole number", 0)
end
local measured, responses = input.measured, input.responses

local function list(text, what, allowed)
  local out = {}
  for item in tostring(text):gmatch("[^,]+") do
    item = item:match("^%s*(.-)%s*$")
    if allowed and not allowed[item] then
      error(string.format("surrogate_trials: %s = '%s' is not one of %s", what, item, table.concat((function()
        local k = {} for name in pairs(allowed) do k[#k + 1] = name end table.sort(k) return k end)(), ", ")), 0)
    end
    out[#out + 1] = item
  end
  if #out == 0 then error("surrogate_trials: " .. what .. " is empty", 0) end
  return out
end
local kinds = {plain = true, warped = true}
local strategies, emulators = list(P.strategies, "strategies", kinds), list(P.emulators, "emulators", kinds)

-- Factors of the search: the input's search ranges; the others stay at their centre values.
local symbols = list(P.factors, "factors")
local factors, searched = {}, {}
for _, sym in ipairs(symbols) do
  local f = input.by_symbol[sym]
  if not f then error(string.format("surrogate_trials: factors: '%s' is not a factor of %s", sym, P.input), 0) end
  factors[#factors + 1] = {name = sym, low = f.search[1], high = f.search[2]}
  searched[f.parameter] = sym
end

-- The emulator's data: rows at the centre of every factor not searched, responses present.
local data, groups = {}, {}
for _, file in ipairs(list(P.data, "data")) do
  local rows = util.read_csv(file)
  for _, row in ipairs(rows) do
    local ok = row.stage ~= "screening" and row.stage ~= "rheometer"
    for _, r in ipairs(responses) do ok = ok and type(row[r]) == "number" end
    if ok then
      local x, key = {}, {}
      for _, f in ipairs(input.factors) do
        local v = row[f.parameter]
        if searched[f.parameter] then
          if type(v) ~= "number" then error(string.format("surrogate_trials: %s line %d: no value of %s", file, row._line, f.parameter), 0) end
          x[searched[f.parameter]] = v
        elseif v ~= "" and v ~= nil and not (type(v) == "number" and math.abs(v - f.center) <= 1e-9 * math.abs(f.center)) then
          ok = false  -- a non-selected factor off its centre (not the surrogate's box)
        end
        key[#key + 1] = tostring(v)
      end
      if ok then
        for _, r in ipairs(responses) do x[r] = row[r] end
        data[#data + 1] = x
        local k = file .. "|" .. table.concat(key, "|")
        groups[k] = groups[k] or {}
        table.insert(groups[k], x)
      end
    end
  end
end
if #data < 2 * #factors + 2 then
  error(string.format("surrogate_trials: only %d usable simulations in data = %s", #data, P.data), 0)
end

-- The seeds' scatter: pooled sd of the groups of runs with the same parameters (summed in the
-- groups' sorted order: the same result in every run).
local group_keys = {}
for k in pairs(groups) do group_keys[#group_keys + 1] = k end
table.sort(group_keys)
local noise_sd = {}
for _, r in ipairs(responses) do
  local ss, dof = 0, 0
  for _, gk in ipairs(group_keys) do
    local g = groups[gk]
    if #g > 1 then
      local m = 0
      for _, x in ipairs(g) do m = m + x[r] end
      m = m / #g
      for _, x in ipairs(g) do ss = ss + (x[r] - m) ^ 2 end
      dof = dof + #g - 1
    end
  end
  if dof == 0 then error("surrogate_trials: the data hold no repeated parameters: the seeds' scatter cannot be measured", 0) end
  noise_sd[r] = math.sqrt(ss / dof)
end
print(string.format("surrogate_trials: %d simulations; seeds' scatter %s", #data, table.concat((function()
  local t = {} for _, r in ipairs(responses) do t[#t + 1] = string.format("%s %.2f", r, noise_sd[r]) end return t end)(), ", ")))

-- Held-out check: how well each kind of Gaussian process, fitted on a few of the simulations (as
-- many as the surrogate has), predicts all the others: RMS error per response and mean |ΔJ| of the
-- worst relative error. The same seeded subsets for both kinds.
local holdout = {}
local function lcg(seed)
  local state = seed
  return function()
    state = (state * 6364136223846793005 + 1442695040888963407) & 0x7fffffffffffffff
    return (state >> 11) / 2.0 ^ 52
  end
end
if P.holdout_sizes ~= "" and P.holdout_repeats > 0 then
  for _, text in ipairs(list(P.holdout_sizes, "holdout_sizes")) do
    local n = math.tointeger(tonumber(text))
    if not n or n < 2 or n >= #data then
      error(string.format("surrogate_trials: holdout_sizes: '%s' must be a whole number in [2, %d]", text, #data - 1), 0)
    end
    for _, kind in ipairs({"plain", "warped"}) do
      local rand = lcg(4242 + n)
      local se, dj, count = {}, 0, 0
      for _, r in ipairs(responses) do se[r] = 0 end
      for rep = 1, P.holdout_repeats do
        local idx = {}
        for i = 1, #data do idx[i] = i end
        for i = #idx, 2, -1 do
          local k = 1 + math.floor(rand() * i)
          idx[i], idx[k] = idx[k], idx[i]
        end
        local fit, rest = {}, {}
        for i = 1, #idx do
          if i <= n then fit[#fit + 1] = data[idx[i]] else rest[#rest + 1] = data[idx[i]] end
        end
        local pred = {}
        for k, r in ipairs(responses) do
          local g = doe.gaussian_process{factors = factors, data = fit, response = r, warp_inputs = kind == "warped", seed = rep * 10 + k,
                                         points = rest}
          pred[r] = g.predictions
        end
        for i, x in ipairs(rest) do
          local y = {}
          for _, r in ipairs(responses) do
            y[r] = pred[r][i].mean
            se[r] = se[r] + (y[r] - x[r]) ^ 2
          end
          local _, wp = jobs.errors(y, measured)
          local _, wt = jobs.errors(x, measured)
          dj = dj + math.abs(wp - wt)
          count = count + 1
        end
      end
      local h = {size = n, kind = kind, repeats = P.holdout_repeats, rms = {}, mean_abs_dJ = dj / count}
      for _, r in ipairs(responses) do h.rms[r] = math.sqrt(se[r] / count) end
      holdout[#holdout + 1] = h
      print(string.format("held-out check, %d simulations, %-6s: RMS error %s; mean |dJ| %.4f", n, kind, table.concat((function()
        local t = {} for _, r in ipairs(responses) do t[#t + 1] = string.format("%s %.1f", r, h.rms[r]) end return t end)(), ", "), h.mean_abs_dJ))
    end
  end
end

-- Emulators: hyperparameters fitted once; a prediction conditions on all the data with them.
local emulator = {}
for _, kind in ipairs(emulators) do
  local e = {hyper = {}}
  for k, r in ipairs(responses) do
    local g = doe.gaussian_process{factors = factors, data = data, response = r, warp_inputs = kind == "warped", seed = 100 + k}
    e.hyper[r] = g.hyperparameters
  end
  function e.mean(points)
    local out = {}
    for i = 1, #points do out[i] = {} end
    for _, r in ipairs(responses) do
      local g = doe.gaussian_process{factors = factors, data = data, response = r, hyperparameters = e.hyper[r], points = points}
      for i, p in ipairs(g.predictions) do out[i][r] = p.mean end
    end
    return out
  end
  -- How much of the box is within the tolerance (2,000 seeded uniform points).
  local uniform = lcg(12345)
  local sample = {}
  for i = 1, 2000 do
    local x = {}
    for _, f in ipairs(factors) do x[f.name] = f.low + uniform() * (f.high - f.low) end
    sample[i] = x
  end
  local within, best = 0, math.huge
  for _, y in ipairs(e.mean(sample)) do
    local _, worst = jobs.errors(y, measured)
    if worst <= input.tolerance then within = within + 1 end
    best = math.min(best, worst)
  end
  e.within_fraction, e.best_sampled = within / #sample, best
  print(string.format("emulator %s: %.2f %% of the box within %.0f %% (best sampled point %.2f %%)", kind,
                      100 * e.within_fraction, 100 * input.tolerance, 100 * best))
  emulator[kind] = e
end

-- One trial: the calibration's surrogate loop against an emulator with noise.
local function normal(rand)
  local u1, u2 = rand(), rand()
  return math.sqrt(-2 * math.log(1 - u1)) * math.cos(2 * math.pi * u2)
end
local function trial(k, emu, kind)
  local rand = lcg(k * 7919 + 17)  -- the noise's own stream (the strategy draws from math.random)
  local runner = {}
  function runner:run(_, points)
    local xs = {}
    for i, pt in ipairs(points) do xs[i] = pt.values end
    local rows = {}
    for i, y in ipairs(emu.mean(xs)) do
      local noisy = {}
      for _, r in ipairs(responses) do noisy[r] = y[r] + noise_sd[r] * normal(rand) end
      rows[i] = {responses = noisy, index = i}
    end
    return rows
  end
  local trial_input = {measured = measured, responses = responses, tolerance = input.tolerance,
                       surrogate = {initial_points = input.surrogate.initial_points, budget = input.surrogate.budget,
                                    confirm_seeds = input.surrogate.confirm_seeds, warp_inputs = kind == "warped"},
                       by_symbol = input.by_symbol}
  local rec = surrogate.run{runner = runner, input = trial_input, selected = symbols, seed = 1000 * k, batch = P.batch,
                            params_of = function(v) return v end,
                            row_of = function(v, y)
                              local row = {}
                              for name, x in pairs(v) do row[name] = x end
                              for _, r in ipairs(responses) do row[r] = y[r] end
                              return row
                            end,
                            say = function() end}
  local out = {success = rec.success, simulations = #rec.evaluations, best_run = rec.best.worst}
  if rec.confirmed then
    local _, worst = jobs.errors(emu.mean({rec.confirmed.values})[1], measured)
    out.true_error = worst
  end
  return out
end

-- Two-sided 95 % Clopper-Pearson interval: the one-sided bounds at 2.5 % each (lib/discovery/score.lua).
local function clopper_pearson(x, n)
  return score.clopper_pearson_lower(x, n, 0.025), score.clopper_pearson_upper(x, n, 0.025)
end

local run_rows, summary = {}, {}
for _, ekind in ipairs(emulators) do
  for _, skind in ipairs(strategies) do
    local sims, succ, fast, false_confirm = {}, 0, 0, 0
    for k = 1, P.trials do
      local t = trial(k, emulator[ekind], skind)
      sims[#sims + 1] = t.simulations
      if t.success then succ = succ + 1 end
      if t.simulations <= P.fast then fast = fast + 1 end
      if t.true_error and t.true_error > input.tolerance then false_confirm = false_confirm + 1 end
      run_rows[#run_rows + 1] = {ekind, skind, k, t.success and 1 or 0, t.simulations, t.best_run, t.true_error or ""}
      if k % 10 == 0 or k == P.trials then
        io.write(string.format("\r  emulator %s, strategy %s: %d/%d trials", ekind, skind, k, P.trials))
        io.flush()
      end
    end
    print()
    table.sort(sims)
    local mean = 0
    for _, s in ipairs(sims) do mean = mean + s end
    mean = mean / #sims
    local lo, hi = clopper_pearson(succ, P.trials)
    local s = {emulator = ekind, strategy = skind, trials = P.trials, successes = succ, success_low = lo, success_high = hi,
               simulations_mean = mean, simulations_median = sims[math.floor((#sims + 1) / 2)],
               simulations_q1 = sims[math.max(1, math.floor(#sims / 4 + 0.5))], simulations_q3 = sims[math.max(1, math.floor(3 * #sims / 4 + 0.5))],
               within_fast = fast, fast = P.fast, confirmed_but_outside = false_confirm}
    summary[#summary + 1] = s
    print(string.format("emulator %-6s strategy %-6s: reached %d/%d (95 %% CI %.2f-%.2f), simulations mean %.1f, median %d (quartiles %d-%d), "
                        .. "within %d: %d; confirmed but truly outside the tolerance: %d", ekind, skind, succ, P.trials, lo, hi, mean,
                        s.simulations_median, s.simulations_q1, s.simulations_q3, P.fast, fast, false_confirm))
  end
end

-- Paired comparison of the strategies on each emulator (the same trials): how often one reached
-- the targets where the other did not, and the exact two-sided sign test on those trials.
local paired = {}
if #strategies == 2 then
  for _, ekind in ipairs(emulators) do
    local by = {}
    for _, row in ipairs(run_rows) do
      if row[1] == ekind then
        by[row[3]] = by[row[3]] or {}
        by[row[3]][row[2]] = row
      end
    end
    local only_a, only_b, fewer_a, fewer_b = 0, 0, 0, 0
    for k = 1, P.trials do
      local a, b = by[k][strategies[1]], by[k][strategies[2]]
      if a[4] == 1 and b[4] == 0 then only_a = only_a + 1 elseif b[4] == 1 and a[4] == 0 then only_b = only_b + 1 end
      if a[4] == 1 and b[4] == 1 then
        if a[5] < b[5] then fewer_a = fewer_a + 1 elseif b[5] < a[5] then fewer_b = fewer_b + 1 end
      end
    end
    local function sign_p(x, y)  -- two-sided exact binomial test of x against y successes at p = 1/2
      local m = x + y
      if m == 0 then return 1 end
      local lo = math.min(x, y)
      return math.min(1, 2 * score.binomial_cdf(lo, m, 0.5))
    end
    local pr = {emulator = ekind, a = strategies[1], b = strategies[2], only_a = only_a, only_b = only_b, p_success = sign_p(only_a, only_b),
                fewer_a = fewer_a, fewer_b = fewer_b, p_fewer = sign_p(fewer_a, fewer_b)}
    paired[#paired + 1] = pr
    print(string.format("emulator %s, paired: only %s reached %d, only %s reached %d (sign test p = %.3g); both reached, fewer simulations: %s %d, %s %d (p = %.3g)",
                        ekind, pr.a, only_a, pr.b, only_b, pr.p_success, pr.a, fewer_a, pr.b, fewer_b, pr.p_fewer))
  end
end

util.write_csv("surrogate_trials_runs.csv", {"emulator", "strategy", "trial", "success", "simulations", "best_run_error", "true_error_at_confirmed"}, run_rows)
local rows = {}
for _, s in ipairs(summary) do
  rows[#rows + 1] = {s.emulator, s.strategy, s.trials, s.successes, s.success_low, s.success_high, s.simulations_mean,
                     s.simulations_median, s.simulations_q1, s.simulations_q3, s.within_fast, s.confirmed_but_outside}
end
util.write_csv("surrogate_trials.csv", {"emulator", "strategy", "trials", "successes", "success_low95", "success_high95",
                                        "simulations_mean", "simulations_median", "simulations_q1", "simulations_q3",
                                        "within_fast", "confirmed_but_outside"}, rows)
local emus = {}
for kind, e in pairs(emulator) do emus[kind] = {within_fraction = e.within_fraction, best_sampled_error = e.best_sampled, hyperparameters = e.hyper} end
local doc = {data = P.data, simulations = #data, noise_sd = noise_sd, tolerance = input.tolerance, budget = input.surrogate.budget,
             initial_points = input.surrogate.initial_points, confirm_seeds = input.surrogate.confirm_seeds, batch = P.batch,
             emulators = emus, summary = summary, paired = paired, holdout = holdout}
paddy.write_json("surrogate_trials.json", doc)

-- Picture: for each emulator and strategy, the share of trials that had confirmed a point within
-- the tolerance after n simulations (a trial that never did stays out of the share).
local picture
if P.pictures then
  local lines, plots, nmax = {}, {}, 0
  for _, row in ipairs(run_rows) do nmax = math.max(nmax, row[5]) end
  for b, s in ipairs(summary) do
    lines[#lines + 1] = string.format("# emulator %s, strategy %s: simulations, share of trials within the tolerance", s.emulator, s.strategy)
    for n = 1, nmax do
      local within = 0
      for _, row in ipairs(run_rows) do
        if row[1] == s.emulator and row[2] == s.strategy and row[4] == 1 and row[5] <= n then within = within + 1 end
      end
      lines[#lines + 1] = string.format("%d %.6g", n, within / s.trials)
    end
    lines[#lines + 1] = "\n"
    plots[#plots + 1] = string.format("%s index %d with steps lw 2 dt %d lc rgb '%s' title %s", util.gnuplot_text(util.out("surrogate_trials.dat")),
                                      b - 1, s.strategy == "warped" and 1 or 2, s.emulator == "warped" and "#d95f02" or "#1b9e77",
                                      util.gnuplot_text(string.format("%s surrogate, %s emulator", s.strategy, s.emulator)))
  end
  util.write_file(util.out("surrogate_trials.dat"), table.concat(lines, "\n") .. "\n")
  picture = util.gnuplot("surrogate_trials", string.format([[
set title 'Surrogate trials: share of trials with a confirmed point within %g %%'
set xlabel 'simulations spent (screening not counted)'; set ylabel 'share of trials'; set grid; set key bottom right
set yrange [0:1]; set xrange [0:%d]
plot %s]], 100 * input.tolerance, nmax + 1, table.concat(plots, ", \\\n     ")))
end
paddy.result{summary = summary, paired = paired, holdout = holdout, simulations = #data, noise_sd = noise_sd, picture = picture}
