-- Blind benchmark of the discovery workflow (experiments/discover.lua; docs/discovery.md, "Blind
-- benchmark"). Each trial draws, from its seed, a hidden truth: nothing missing, one candidate
-- effect at a random strength, or an effect that is not in the candidate list. The "measurements"
-- are Paddy runs of that truth at another particle diameter and with other seeds than the
-- workflow uses, plus Gaussian measurement noise. The trial writes the workflow's input file,
-- seals the truth in truth/<trial>.json (which the workflow never reads), runs the workflow and
-- scores its answer. Summary: confusion matrix, correct-name rate with its Clopper-Pearson bound,
-- false alarms on null trials, strength error, misfit after/before → blind_summary.json.
--
--   paddy run experiments/validation/discovery_blind.lua --out results/blind               # full (long)
--   paddy run experiments/validation/discovery_blind.lua --set tiny=true --out results/tiny # CI, minutes
--
-- Resumable: every truth simulation and every workflow run is a campaign job (docs/campaign.md);
-- running the same command again repeats nothing that finished.
local util = require("lib.util")
local stack = require("lib.discovery.stack")
local score = require("lib.discovery.score")
local bench = require("lib.discovery.benchmark")

local P = paddy.parameters{
  {name = "tiny", default = false, description = "CI variant: 2 trials (a strong hidden candidate, a null), one slump experiment, very coarse spheres"},
  {name = "strong", default = "wall_adhesion", description = "the candidate the tiny version hides at the top of its range ('' = drawn from the trial's seed)"},
  {name = "small", default = false, description = "tiny's spheres, experiment and settings with the trial counts of effect_trials, null_trials, outside_trials (a confusion matrix in an hour or two)"},
  {name = "effect_trials", default = 30, type = "integer", min = 0, max = 1000, description = "trials with a hidden candidate effect"},
  {name = "null_trials", default = 20, type = "integer", min = 0, max = 1000, description = "trials with nothing missing"},
  {name = "outside_trials", default = 10, type = "integer", min = 0, max = 1000, description = "trials with an effect outside the candidate list"},
  {name = "particle_diameter", default = 0.016, unit = "m", min = 0.001, max = 0.04, description = "sphere diameter of the workflow's simulations"},
  {name = "truth_diameter", default = 0.014, unit = "m", min = 0.001, max = 0.04, description = "sphere diameter of the truth (the measurements)"},
  {name = "candidate_set", default = "effects", choices = {"stand_in", "effects"},
   description = "stand_in: existing contact parameters as candidates; effects: the four effect plugins (liquid bridges, lubrication, wall adhesion, plastic adhesion)"},
  {name = "lift_speeds", default = "", description = "lift speeds of the slump experiments, comma-separated m/s ('' = the variant's: full 0.1,0.4; tiny and small 0.3)"},
  {name = "cone_scales", default = "", description = "sizes of the slump cone as factors of the standard one (100/200/300 mm), comma-separated: one slump experiment per size and lift speed ('' = the standard cone only); a larger cone loads the mud more, which load-dependent effects feel and surface forces do not"},
  {name = "vane_scale", default = 0, min = 0, max = 8,
   description = "add the vane rheometer scaled by this factor from the standard 100 mm cup (lib/discovery/benchmark.lua: start-up peak and two steady torques; 0 = none, else 1-8): a flowing strength beside the slump's static one"},
  {name = "vane_speeds", default = "", description = "steady speeds of the vane, comma-separated rpm ('' = 10,40); with vane_scale > 0"},
  {name = "vane_startup_rpm", default = 5, min = 0.1, max = 20, description = "speed of the vane's start-up test (its peak torque), rpm"},
  {name = "vane_shared_sd", default = 0, min = 0, max = 0.5,
   description = "the vane's torques read as one specimen: a relative error of this sd that the sweep's torques and its start-up peak share (the input's shared_error), each torque with its own vane_reading_sd beside it; 0 = every torque its own 5 % error"},
  {name = "vane_reading_sd", default = 0.015, min = 0.001, max = 0.5, description = "each vane torque's own relative reading error when vane_shared_sd > 0"},
  {name = "tack_scale", default = 0, min = 0, max = 10,
   description = "add the plate tack test scaled by this factor from its default 80 mm cup (lib/discovery/benchmark.lua: peak pull, tension profile, mud carried; 0 = none, else 1-10): an observable the cohesion parameter does not move"},
  {name = "tack_speed", default = 0.04, unit = "m/s", min = 0.001, max = 1, description = "pull speed of the tack test; with tack_scale > 0"},
  {name = "tack_press_speed", default = 0.01, unit = "m/s", min = 0.001, max = 1, description = "speed of the tack plate's approach and press; with tack_scale > 0"},
  {name = "tack_speeds", default = "", description = "pull speeds of the tack test, comma-separated m/s: one tack test per speed ('' = tack_speed alone); a viscous pull grows with the speed, a static one does not"},
  {name = "truth_repeats", default = 1, type = "integer", min = 1, max = 20,
   description = "truth runs (seeds) per measurement: the measured value is their mean, as a slump test is reported as the mean of repeated tests (the reference: 10), and the input says measured_repeats = this"},
  {name = "relevant_fraction", default = 0.05, min = 0, max = 0.14,
   description = "each candidate's smallest relevant strength as a fraction of its range (its input key 'relevant'; docs/discovery.md, \"Decision\"): a weaker effect is not named. Hidden strengths are drawn from 0.15 of the range up; 0 = any strength counts"},
  {name = "signature_seeds", default = 0, type = "integer", min = 0, max = 5,
   description = "seeds each candidate's signature is averaged over (settings.signature_seeds; 0 = the variant's: full 2, tiny and small 3)"},
  {name = "confirm_seeds", default = 0, type = "integer", min = 0, max = 10,
   description = "seeds of the confirmation runs at the refit point (settings.confirm_seeds; 0 = the variant's: 2); their scatter also gives the strength's specimen se"},
  {name = "runner_up_refits", default = 0, type = "integer", min = 0, max = 3,
   description = "the workflow's settings.runner_up_refits: when the best candidate's refit leaves a significant misfit, the next candidates with significant scores are refitted in turn (0 = none, as the runs before it)"},
  {name = "probe_fraction", default = 0.5, min = 0.05, max = 1,
   description = "each candidate's probe strength as a fraction of its range (its input key 'probe'): a signature's seed noise does not grow with the probe, its signal does"},
  {name = "refit_zoom", default = 0.15, min = 0, max = 0.5,
   description = "the workflow's settings.refit_zoom: a second response surface around the refit point when the misfit it leaves is significant (0 = none, as the runs measured before it)"},
  {name = "refit_zoom_above", default = 1.2, min = 0, max = 10,
   description = "the workflow's settings.refit_zoom_above: zoom also while the refit's RMS standardised residual is above this many noise sd, significant or not (0 = only when significant, as the runs measured before it)"},
  {name = "only_trials", default = "", description = "comma-separated trial numbers to run of the drawn sequence ('' = all): re-run chosen trials with other settings"},
  {name = "first_trial", default = 1, type = "integer", min = 1, max = 100000, description = "number of the first trial (trial seeds follow from it)"},
  {name = "workflow", default = "", description = "workflow script ('' = experiments/discover.lua)"},
  {name = "report_pictures", default = false, description = "each trial's report.html with its figures (gnuplot; the CI variant checks them in a browser, tests/clients)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys ('' = hash of the binaries)"},
  {name = "progress_of", default = "", description = "output directory of a benchmark started with the same settings (and code_version): summarise its trials finished so far into this run's --out, running nothing"},
}

local here = (debug.getinfo(1, "S").source:match("^@(.*)/[^/]*$")) or "."
local experiments_dir = here .. "/.."
local workflow = P.workflow ~= "" and P.workflow or experiments_dir .. "/discover.lua"
local function say(fmt, ...) io.stderr:write("blind: ", string.format(fmt, ...), "\n") end

local set = bench.CANDIDATE_SETS[P.candidate_set]
local free = bench.FREE

local n_effect, n_null, n_outside = P.effect_trials, P.null_trials, P.outside_trials
local d_work, d_truth = P.particle_diameter, P.truth_diameter
-- measured_repeats (= truth_repeats, below): each measurement is the mean of that many truth runs,
-- so it carries their seed scatter (the specimen scatter of the tests) on top of the measurement
-- noise. resolution_factor: the
-- workflow's own check of its resolution bias, a generic 0.9 x its diameter (it is not told the truth's).
local settings = {iterations = 5, replicates = 5, signature_seeds = 2, confirm_seeds = 2, measured_repeats = 1,
                  resolution_factor = 0.9, resolution_seeds = 2}
if P.tiny and P.small then error("discovery_blind.lua: tiny and small exclude each other", 0) end
if P.tiny or P.small then
  if P.tiny then n_effect, n_null, n_outside = 1, 1, 0 end
  if d_work == 0.016 then d_work = 0.025 end
  if d_truth == 0.014 then d_truth = 0.023 end
  -- three signature seeds: with one, a weak candidate's signature at 25 mm is mostly seed noise
  -- (docs/discovery.md, "Signature noise"): 3 wrong names in 30 effect trials, with three none
  settings = {iterations = 5, replicates = 5, signature_seeds = 3, confirm_seeds = 2, measured_repeats = 1,
              resolution_factor = 0.9, resolution_seeds = 2}
end
if P.signature_seeds > 0 then settings.signature_seeds = P.signature_seeds end
if P.confirm_seeds > 0 then settings.confirm_seeds = P.confirm_seeds end
if P.runner_up_refits > 0 then settings.runner_up_refits = P.runner_up_refits end
settings.refit_zoom = P.refit_zoom
settings.refit_zoom_above = P.refit_zoom_above
-- Experiments (lib/discovery/benchmark.lua): the variant's slumps, or one per lift speed, each in
-- every cone size, and the vane when vane_scale > 0.
local experiments = bench.experiments{variant = (P.tiny or P.small) and "small" or "full", lift_speeds = P.lift_speeds,
                                      cone_scales = P.cone_scales, vane_scale = P.vane_scale, vane_speeds = P.vane_speeds, vane_startup_rpm = P.vane_startup_rpm,
                                      vane_shared_sd = P.vane_shared_sd, vane_reading_sd = P.vane_reading_sd,
                                      tack_scale = P.tack_scale, tack_speed = P.tack_speed, tack_speeds = P.tack_speeds,
                                      tack_press_speed = P.tack_press_speed}

-- Trials in a fixed order, their truths drawn from their seeds.
local trials = {}
local function add_trial(kind)
  local no = P.first_trial + #trials
  trials[#trials + 1] = {no = no, kind = kind, seed = 7919 * no + 17}
end
-- The kinds take turns (effect, null, outside, effect, ...), so that a benchmark stopped early has
-- trials of every kind.
if P.tiny then add_trial("strong") end
local n_cand = P.tiny and 0 or n_effect
for i = 1, math.max(n_cand, n_null, n_outside) do
  if i <= n_cand then add_trial("candidate") end
  if i <= n_null then add_trial("none") end
  if i <= n_outside then add_trial("outside") end
end

-- only_trials: keep the chosen trials of the sequence (their numbers and truths unchanged).
if P.only_trials ~= "" then
  local keep, kept = {}, {}
  for _, n in ipairs(util.numbers(P.only_trials, "only_trials")) do keep[math.tointeger(n) or n] = true end
  for _, t in ipairs(trials) do if keep[t.no] then kept[#kept + 1] = t; keep[t.no] = nil end end
  local missing = next(keep)
  if missing then error(string.format("discovery_blind.lua: only_trials names trial %s, which the benchmark's %d trials do not have", tostring(missing), #trials), 0) end
  trials = kept
end

local function draw_truth(t)
  math.randomseed(t.seed)
  local truth = {trial = t.no, seed = t.seed, params = {}, kind = t.kind == "strong" and "candidate" or t.kind}
  for _, f in ipairs(free) do
    local v = f.low + (0.2 + 0.6 * math.random()) * (f.high - f.low)
    truth.params[f.parameter] = v
  end
  for _, c in ipairs(set.candidates) do truth.params[c.parameter] = 0 end
  if truth.kind == "candidate" then
    local c = set.candidates[math.random(#set.candidates)]
    if t.kind == "strong" and P.strong ~= "" then
      c = nil
      for _, x in ipairs(set.candidates) do if x.name == P.strong then c = x end end
      if not c then error(string.format("discovery_blind.lua: strong = '%s' is not a candidate of candidate_set '%s'", P.strong, P.candidate_set), 0) end
    end
    -- strengths from barely to clearly detectable: 15 % ... 100 % of the range (strong: the top)
    local s = t.kind == "strong" and c.high or c.high * (0.15 + 0.85 * math.random())
    truth.name, truth.strength, truth.params[c.parameter] = c.name, s, s
  elseif truth.kind == "outside" then
    local o = set.outside[math.random(#set.outside)]
    local f = o.factor[1] + (o.factor[2] - o.factor[1]) * math.random()
    truth.name, truth.strength, truth.params[o.parameter] = o.parameter, o.default * f, o.default * f
  end
  return truth
end

-- progress_of: the same job keys in another benchmark's directory, read and not run (its inputs
-- and truths are not written again: the digest of an input's text gives its path there).
local partial = P.progress_of ~= ""
local base = partial and util.absolute(P.progress_of) or nil
local function bench_path(name) return partial and (base .. "/" .. name) or util.out(name) end
local campaign_dir = util.absolute(bench_path("campaign"))
local sims = paddy.campaign{dir = campaign_dir, executor = "local", code_version = P.code_version ~= "" and P.code_version or nil}
local flows = paddy.campaign{dir = bench_path("trials"), executor = "local", max_parallel = 1,
                             code_version = P.code_version ~= "" and P.code_version or nil}
util.mkdir(util.out("truth"))
util.mkdir(util.out("inputs"))
-- The jobs' entries as campaign:run gives them; with progress_of only those finished, others pending.
local function entries_of(c, ks)
  if not partial then return c:run(ks) end
  local out = {}
  for i, key in ipairs(ks) do
    local st = c:status(key)
    out[i] = {status = st == "done" and "done" or "pending", result = st == "done" and c:result(key) or nil}
  end
  return out
end

-- FNV-1a, 32 bits (Fowler, Noll, Vo): a short digest of a text.
local function fnv1a(text)
  local h = 2166136261
  for i = 1, #text do h = ((h ~ text:byte(i)) * 16777619) & 0xffffffff end
  return h
end

-- 1. The measurements: every trial's truth at truth_diameter, seeds far from the workflow's
-- (repeat r of truth_repeats at 500000 + trial seed + 10^6 (r - 1)).
local keys, truths = {}, {}
local R = P.truth_repeats
settings.measured_repeats = R
for i, t in ipairs(trials) do
  truths[i] = draw_truth(t)
  for _, e in ipairs(experiments) do
    local params = {particle_diameter = d_truth, pictures = false, snapshot_interval = 0, progress = false}
    for k, v in pairs(e.set) do params[k] = v end
    for k, v in pairs(truths[i].params) do params[k] = v end
    for r = 1, R do
      keys[#keys + 1] = sims:submit{script = experiments_dir .. "/" .. e.script, params = params, seed = 500000 + t.seed + 1000000 * (r - 1)}
    end
  end
end
say("%d trials (%d effect, %d null, %d outside), workflow at %.0f mm, truth at %.0f mm: %d truth simulations",
    #trials, P.tiny and 1 or n_effect, n_null, n_outside, d_work * 1000, d_truth * 1000, #keys)
local entries = entries_of(sims, keys)

-- 2. Input files with noisy measurements; truths sealed apart.
local k = 0
local flow_keys = {}
for i, t in ipairs(trials) do
  math.randomseed(t.seed + 1)
  local function gauss() return math.sqrt(-2 * math.log(1 - math.random())) * math.cos(2 * math.pi * math.random()) end
  local exps, pending = {}, false
  for j, e in ipairs(experiments) do
    local runs = {}
    for r = 1, R do
      k = k + 1
      local entry = entries[k]
      pending = pending or entry.status == "pending"
      if not pending and entry.status ~= "done" then
        error(string.format("blind: truth simulation of trial %d (%s, repeat %d) failed: %s", t.no, e.name, r, tostring(entry.error)), 0)
      end
      runs[r] = entry.result
    end
    if pending then goto next_experiment end
    local measured, sigma = {}, {}
    -- A shared error: one factor for the listed keys of this experiment (drawn only then, so the
    -- noise of experiments without one is what it was).
    local shared_factor, shared_keys = 1, {}
    if e.shared_error then
      shared_factor = 1 + e.shared_error.rel_sd * gauss()
      for _, key in ipairs(e.shared_error.keys) do shared_keys[key] = true end
    end
    for _, o in ipairs(e.observables) do
      local v = assert(stack.extract(runs[1], o.key))
      for r = 2, R do
        local w = assert(stack.extract(runs[r], o.key))
        for n = 1, #v do v[n] = v[n] + w[n] end
      end
      for n = 1, #v do v[n] = v[n] / R end
      local mv, sv = {}, {}
      for n, x in ipairs(v) do
        sv[n] = bench.noise_sd(o, x)
        mv[n] = (shared_keys[o.key] and shared_factor or 1) * x + sv[n] * gauss()
      end
      if #v == 1 then mv, sv = mv[1], sv[1] end
      measured[o.key], sigma[o.key] = mv, sv
    end
    exps[j] = {name = e.name, script = e.script, set = e.set, measured = measured, sigma = sigma, shared_error = e.shared_error}
    ::next_experiment::
  end
  if pending then goto next_trial end
  do
  local cands = {}
  for n, c in ipairs(set.candidates) do
    cands[n] = {name = c.name, parameter = c.parameter, low = c.low, high = c.high, probe = P.probe_fraction * c.high}
    if P.relevant_fraction > 0 then cands[n].relevant = P.relevant_fraction * c.high end
  end
  local input = {description = string.format("blind trial %d", t.no), experiments = exps, free_parameters = free,
                 candidates = cands, settings = settings}
  -- The file name carries a digest of the content: the workflow's job key holds the input's path,
  -- so a changed input (other noise, observables, settings) is a new job, never a stale result.
  local tmp = paddy.write_json(string.format("inputs/trial_%04d.tmp.json", t.no), input)
  local f = assert(io.open(tmp, "rb"))
  local text = f:read("a")
  f:close()
  os.remove(tmp)
  local name = string.format("inputs/trial_%04d_%08x.json", t.no, fnv1a(text))
  local path = partial and bench_path(name) or paddy.write_json(name, input)
  if not partial then paddy.write_json(string.format("truth/trial_%04d.json", t.no), truths[i]) end
  flow_keys[i] = flows:submit{script = workflow,
                              params = {input = util.absolute(path), particle_diameter = d_work, campaign_dir = campaign_dir, max_parallel = 2,
                                        pictures = P.report_pictures, code_version = P.code_version},
                              seed = 1000 + t.no}
  end
  ::next_trial::
end

-- 3. The workflow on every trial (one at a time; each runs its simulations two at a time).
say("running the workflow on %d trials", #trials)
local results, run_keys, pending_n = {}, {}, 0
for i = 1, #trials do if flow_keys[i] then run_keys[#run_keys + 1] = flow_keys[i] end end
local ran = entries_of(flows, run_keys)
do
  local n = 0
  for i = 1, #trials do
    if flow_keys[i] then n = n + 1; results[i] = ran[n] else results[i] = {status = "pending"} end
    if results[i].status == "pending" then pending_n = pending_n + 1 end
  end
end
local names, name_list = {}, {}
for _, c in ipairs(set.candidates) do names[c.name] = true; name_list[#name_list + 1] = c.name end
local scored = {}
for i, t in ipairs(trials) do
  local r = results[i]
  local row = {trial = t.no, truth = truths[i], status = r.status}
  if r.status == "done" then
    row.answer = score.answer(r.result)
    row.right, row.wrong_name = score.judge(truths[i], row.answer, names)
    row.strength = r.result.strength and r.result.strength.value or nil
    row.strength_interval = r.result.strength
    row.misfit_before, row.misfit_after = r.result.misfit_before, r.result.misfit_after
    row.misfit_whitened_after = r.result.misfit_statistic_after
    row.simulations, row.wall_time_s = r.result.simulations, r.result.wall_time_s
    row.q0_p = r.result.q0_p
    -- What the workflow said it could see of the hidden candidate (nil: nowhere / unbounded).
    for _, c in ipairs(r.result.candidates or {}) do
      if truths[i].kind == "candidate" and c.name == truths[i].name then
        row.hidden_detection_limit, row.hidden_upper_limit = c.detection_limit, c.upper_limit
      end
    end
    say("trial %d: truth %s%s -> %s (%s)", t.no, truths[i].kind, truths[i].name and (" " .. truths[i].name) or "",
        row.answer, row.right and "right" or "wrong")
    scored[#scored + 1] = row
  elseif r.status ~= "pending" then
    say("trial %d: the workflow failed: %s", t.no, tostring(r.error))
  end
end
local summary = score.summarise(scored, name_list)
summary.particle_diameter, summary.truth_diameter, summary.candidate_set = d_work, d_truth, P.candidate_set
summary.by_detection = score.by_detection(scored, names)
summary.failed = #trials - #scored - pending_n
summary.pending = pending_n   -- progress_of: trials not finished yet (0 for a benchmark run to its end)
local wall, sims_n = 0, 0
for _, row in ipairs(scored) do wall, sims_n = wall + (row.wall_time_s or 0), sims_n + (row.simulations or 0) end
summary.mean_wall_time_s = #scored > 0 and wall / #scored or nil
summary.mean_simulations = #scored > 0 and sims_n / #scored or nil
summary.truth_simulations_per_trial = #experiments * R
summary.truth_repeats = R
paddy.write_json("blind_summary.json", {summary = summary, trials = scored})
say("correct names %d/%d, false alarms %d/%d", summary.correct_names, summary.effect_trials, summary.false_alarms, summary.null_trials)
if summary.strength_interval_coverage then
  local rc = summary.strength_resolution_corrected
  local wn = summary.misfit_whitened_after_named
  say("named strengths: intervals cover the truth %d/%d%s; misfit after at most 1.2 noise sd %d/%d%s",
      summary.strength_interval_coverage.covered, summary.strength_interval_coverage.trials,
      rc and string.format(" (extrapolated to the finer model %d/%d)", rc.covered, rc.trials) or "",
      summary.misfit_after_named and summary.misfit_after_named.at_most_1_2 or 0, summary.misfit_after_named and summary.misfit_after_named.stats.n or 0,
      wn and string.format(" (whitened with the noise correlations %d/%d)", wn.at_most_1_2, wn.stats.n) or "")
end
do
  local bd = summary.by_detection
  say("declared detectable: %d/%d named; below the stated limit: %d/%d named; answers none with the upper limit above the truth: %d/%d",
      bd.detectable.right, bd.detectable.trials, bd.undetectable.right, bd.undetectable.trials, bd.none_answers.covered, bd.none_answers.trials)
end
paddy.result{summary = summary, trials = scored}
