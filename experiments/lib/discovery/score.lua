-- Scoring of blind discovery trials (experiments/validation/discovery_blind.lua): the outcome of
-- one trial against its sealed truth, the confusion matrix, and exact one-sided binomial
-- (Clopper-Pearson) bounds.
--
-- Clopper & Pearson 1934: with k successes in n trials, the one-sided 1 - alpha lower bound of the
-- success probability is the p_L with P(X >= k | n, p_L) = alpha (p_L = 0 for k = 0), the upper
-- bound the p_U with P(X <= k | n, p_U) = alpha (p_U = 1 for k = n). The binomial tail is the finite
-- sum of C(n, j) p^j (1-p)^(n-j); it is monotone in p, so bisection to 1e-12 finds the bound.
-- Known answers (tested): 0 of 20 → upper 13.9 %, 30 of 30 → lower 90.5 %, 49 of 50 → lower 91.0 %.
local M = {}

-- P(X <= k) for X ~ Binomial(n, p).
function M.binomial_cdf(k, n, p)
  if k < 0 then return 0 end
  if k >= n then return 1 end
  local s, term = 0, (1 - p) ^ n       -- j = 0
  if p >= 1 then return 0 end
  for j = 0, k do
    s = s + term
    term = term * (n - j) / (j + 1) * p / (1 - p)
  end
  return math.min(1, s)
end

local function bisect(f, target)      -- f increasing in p on [0, 1]
  local lo, hi = 0, 1
  for _ = 1, 60 do
    local mid = (lo + hi) / 2
    if f(mid) < target then lo = mid else hi = mid end
  end
  return (lo + hi) / 2
end

function M.clopper_pearson_lower(k, n, alpha)
  alpha = alpha or 0.05
  if k <= 0 then return 0 end
  return bisect(function(p) return 1 - M.binomial_cdf(k - 1, n, p) end, alpha)
end

function M.clopper_pearson_upper(k, n, alpha)
  alpha = alpha or 0.05
  if k >= n then return 1 end
  return bisect(function(p) return 1 - M.binomial_cdf(k, n, p) end, 1 - alpha)
end

-- The answer the workflow gave, as one label: a candidate's name, or none/ambiguous/unknown.
function M.answer(result)
  if result.decision == "effect" then return result.named_effect or "effect?" end
  return result.decision
end

-- Correct names of effect trials by how visible the hidden effect is: its expected z, the
-- strength times the z a sensitivity study measured at the candidate's top strength, divided by
-- that strength (z_at_high · strength / high: linear in the strength, as the score test is).
-- trials: scored rows ({truth = {kind, name, strength}, answer =, right =}); sensitivity:
-- {name -> {z_at_high =, high =}}; edges: ascending bin edges of the expected z (e.g. {3, 6, 10}).
-- Returns {rows = per trial {trial, name, strength, z_expected, answer, right} sorted by z,
--          bins = {{from =, to =, trials =, right =, wrong_names =, lower95 =}, ...}}.
function M.by_visibility(trials, sensitivity, edges, candidate_names)
  local rows = {}
  for _, t in ipairs(trials) do
    local tr = t.truth
    if tr.kind == "candidate" then
      local s = sensitivity[tr.name]
      if not s then error("score.by_visibility: the sensitivity study has no candidate " .. tostring(tr.name), 2) end
      local _, wrong = M.judge(tr, t.answer, candidate_names)
      rows[#rows + 1] = {trial = t.trial, name = tr.name, strength = tr.strength, answer = t.answer, right = t.right,
                         wrong_name = wrong, z_expected = s.z_at_high * tr.strength / s.high}
    end
  end
  table.sort(rows, function(a, b) return a.z_expected < b.z_expected end)
  local bins, lo = {}, -math.huge
  for k = 1, #edges + 1 do
    local hi = edges[k] or math.huge
    local b = {from = lo, to = hi, trials = 0, right = 0, wrong_names = 0}
    for _, r in ipairs(rows) do
      if r.z_expected >= lo and r.z_expected < hi then
        b.trials, b.right = b.trials + 1, b.right + (r.right and 1 or 0)
        b.wrong_names = b.wrong_names + (r.wrong_name and 1 or 0)
      end
    end
    b.lower95 = b.trials > 0 and M.clopper_pearson_lower(b.right, b.trials) or nil
    bins[k], lo = b, hi
  end
  return {rows = rows, bins = bins}
end

-- Every kind of trial by the misfit its data showed after the free parameters were calibrated:
-- the p-value of the projected misfit Q0 (result.json q0_p, chi-square on its degrees of freedom),
-- which the workflow computes from the data alone, so a bin is something a user can see. Splits the
-- correct-name rate into the trials whose data show an effect and those the free parameters fit
-- within the noise, and shows how often null trials reach each bin.
-- trials: scored rows ({truth = {kind, name}, answer =, right =, q0_p =}); p_edges: ascending
-- edges in (0, 1) (e.g. {0.001, 0.05}). A trial without q0_p is refused (a summary from before
-- q0_p was recorded cannot be binned).
-- Returns {bins = {{from =, to =, effect = {trials, right, wrong_names, lower95},
--                   null = {trials, alarms, upper95}, outside = {trials, wrong_names}}, ...}}.
function M.by_misfit(trials, p_edges, candidate_names)
  for k, e in ipairs(p_edges) do
    if not (e > 0 and e < 1) or (k > 1 and not (e > p_edges[k - 1])) then
      error(string.format("p_edges = %s: the edges must ascend inside (0, 1)", table.concat(p_edges, ",")), 2)
    end
  end
  local bins, lo = {}, 0
  for k = 1, #p_edges + 1 do
    local hi = p_edges[k] or 1
    bins[k] = {from = lo, to = hi, effect = {trials = 0, right = 0, wrong_names = 0},
               null = {trials = 0, alarms = 0}, outside = {trials = 0, wrong_names = 0}}
    lo = hi
  end
  for _, t in ipairs(trials) do
    local p = t.q0_p
    if type(p) ~= "number" or p ~= p then
      error(string.format("score.by_misfit: trial %s has no q0_p", tostring(t.trial)), 2)
    end
    local b = bins[#bins]
    for k = 1, #p_edges do
      if p < p_edges[k] then b = bins[k]; break end
    end
    local _, wrong = M.judge(t.truth, t.answer, candidate_names)
    if t.truth.kind == "candidate" then
      b.effect.trials, b.effect.right = b.effect.trials + 1, b.effect.right + (t.right and 1 or 0)
      b.effect.wrong_names = b.effect.wrong_names + (wrong and 1 or 0)
    elseif t.truth.kind == "none" then
      b.null.trials, b.null.alarms = b.null.trials + 1, b.null.alarms + (t.answer ~= "none" and 1 or 0)
    else
      b.outside.trials, b.outside.wrong_names = b.outside.trials + 1, b.outside.wrong_names + (wrong and 1 or 0)
    end
  end
  for _, b in ipairs(bins) do
    b.effect.lower95 = b.effect.trials > 0 and M.clopper_pearson_lower(b.effect.right, b.effect.trials) or nil
    b.null.upper95 = b.null.trials > 0 and M.clopper_pearson_upper(b.null.alarms, b.null.trials) or nil
  end
  return {bins = bins}
end

-- Effect trials by what the workflow itself said it could see: the detection limit and the upper
-- limit it gave for the hidden candidate (result.json candidates[].detection_limit, upper_limit;
-- doe detection.hpp), computed from its own signatures and noise, without the truth. A trial is
-- declared detectable when the hidden strength is at least that limit (nil: detectable nowhere).
-- Checks the limits as statements: the declared-detectable trials should be named (at about the
-- stated 90 % power, less where the signature is far from linear), and an answer `none` should come
-- with an upper limit at or above the hidden strength (one-sided 95 %).
-- trials: scored rows with hidden_detection_limit, hidden_upper_limit (nil = infinite).
-- Returns {detectable = {trials, right, wrong_names, lower95}, undetectable = {trials, right,
--          answers = {answer -> count}}, none_answers = {trials, covered, lower95},
--          per_candidate = {name -> {trials, detectable, detectable_right, none, none_covered}}}.
function M.by_detection(trials, candidate_names)
  local det = {trials = 0, right = 0, wrong_names = 0}
  local undet = {trials = 0, right = 0, answers = {}}
  local none = {trials = 0, covered = 0}
  local per = {}
  for _, t in ipairs(trials) do
    if t.truth.kind == "candidate" then
      local _, wrong = M.judge(t.truth, t.answer, candidate_names)
      local c = per[t.truth.name] or {trials = 0, detectable = 0, detectable_right = 0, none = 0, none_covered = 0}
      per[t.truth.name] = c
      c.trials = c.trials + 1
      local limit = t.hidden_detection_limit
      if limit ~= nil and t.truth.strength >= limit then
        det.trials, det.right = det.trials + 1, det.right + (t.right and 1 or 0)
        det.wrong_names = det.wrong_names + (wrong and 1 or 0)
        c.detectable, c.detectable_right = c.detectable + 1, c.detectable_right + (t.right and 1 or 0)
      else
        undet.trials, undet.right = undet.trials + 1, undet.right + (t.right and 1 or 0)
        undet.answers[t.answer] = (undet.answers[t.answer] or 0) + 1
      end
      if t.answer == "none" then
        none.trials, c.none = none.trials + 1, c.none + 1
        local up = t.hidden_upper_limit
        if up == nil or up >= t.truth.strength then none.covered, c.none_covered = none.covered + 1, c.none_covered + 1 end
      end
    end
  end
  det.lower95 = det.trials > 0 and M.clopper_pearson_lower(det.right, det.trials) or nil
  none.lower95 = none.trials > 0 and M.clopper_pearson_lower(none.covered, none.trials) or nil
  return {detectable = det, undetectable = undet, none_answers = none, per_candidate = per}
end

-- Whether an answer is right for a truth {kind = "none"|"candidate"|"outside", name =}:
-- none → "none"; a candidate → its name; an effect outside the list → "unknown" or "none"
-- (never a wrong name). Returns right, wrong_name.
function M.judge(truth, answer, candidate_names)
  local is_name = candidate_names[answer] == true
  if truth.kind == "none" then return answer == "none", is_name end
  if truth.kind == "candidate" then return answer == truth.name, is_name and answer ~= truth.name end
  return answer == "unknown" or answer == "none", is_name
end

-- Summary of scored trials {{truth =, answer =, right =, wrong_name =, strength =, misfit_before =,
-- misfit_after =}, ...}: confusion matrix (rows: truth label, columns: answer), rates with bounds.
function M.summarise(trials, candidate_names_list)
  local columns = {"none"}
  for _, n in ipairs(candidate_names_list) do columns[#columns + 1] = n end
  columns[#columns + 1] = "ambiguous"
  columns[#columns + 1] = "unknown"
  local rows_order = {"none"}
  for _, n in ipairs(candidate_names_list) do rows_order[#rows_order + 1] = n end
  rows_order[#rows_order + 1] = "outside"
  local matrix = {}
  for _, r in ipairs(rows_order) do
    matrix[r] = {}
    for _, c in ipairs(columns) do matrix[r][c] = 0 end
  end
  local eff_n, eff_right, null_n, null_alarm, out_n, out_wrong = 0, 0, 0, 0, 0, 0
  local strength_err, ratio = {}, {}
  -- Named strengths (right names only): the interval's coverage of the truth, the extrapolation to
  -- the finer model (strength_interval.resolution_corrected) and the misfit left.
  local err_rc, covered, covered_rc, n_int, n_rc, misfit_named, whitened_named = {}, 0, 0, 0, 0, {}, {}
  local function covers(iv, x) return iv.low ~= nil and iv.high ~= nil and iv.low <= x and x <= iv.high end
  for _, t in ipairs(trials) do
    local row = t.truth.kind == "candidate" and t.truth.name or (t.truth.kind == "none" and "none" or "outside")
    local col = matrix[row][t.answer] and t.answer or "unknown"
    matrix[row][col] = matrix[row][col] + 1
    if t.truth.kind == "candidate" then
      eff_n = eff_n + 1
      if t.right then
        eff_right = eff_right + 1
        if t.strength and t.truth.strength > 0 then
          strength_err[#strength_err + 1] = (t.strength - t.truth.strength) / t.truth.strength
        end
        local iv = t.strength_interval
        if iv and iv.low and iv.high then
          n_int = n_int + 1
          if covers(iv, t.truth.strength) then covered = covered + 1 end
          local rc = iv.resolution_corrected
          if rc and rc.value then
            n_rc = n_rc + 1
            if covers(rc, t.truth.strength) then covered_rc = covered_rc + 1 end
            if t.truth.strength > 0 then err_rc[#err_rc + 1] = (rc.value - t.truth.strength) / t.truth.strength end
          end
        end
        misfit_named[#misfit_named + 1] = t.misfit_after
        whitened_named[#whitened_named + 1] = t.misfit_whitened_after
      end
    elseif t.truth.kind == "none" then
      null_n = null_n + 1
      if t.answer ~= "none" then null_alarm = null_alarm + 1 end
    else
      out_n = out_n + 1
      if t.wrong_name then out_wrong = out_wrong + 1 end
    end
    if t.misfit_before and t.misfit_before > 0 and t.misfit_after then ratio[#ratio + 1] = t.misfit_after / t.misfit_before end
  end
  local function stats(v)
    if #v == 0 then return nil end
    local s, a = 0, 0
    for _, x in ipairs(v) do s, a = s + x, a + math.abs(x) end
    local sorted = {}
    for i, x in ipairs(v) do sorted[i] = x end
    table.sort(sorted)
    return {n = #v, mean = s / #v, mean_abs = a / #v, median = sorted[(#v + 1) // 2]}
  end
  -- The misfits left after right names against the issue's target of at most 1.2 noise sd.
  local function against_target(v)
    if #v == 0 then return nil end
    local k = 0
    for _, x in ipairs(v) do if x <= 1.2 then k = k + 1 end end
    return {stats = stats(v), at_most_1_2 = k}
  end
  return {
    columns = columns, rows = rows_order, confusion = matrix, trials = #trials,
    effect_trials = eff_n, correct_names = eff_right,
    correct_name_rate = eff_n > 0 and eff_right / eff_n or nil,
    correct_name_lower95 = eff_n > 0 and M.clopper_pearson_lower(eff_right, eff_n) or nil,
    null_trials = null_n, false_alarms = null_alarm,
    false_alarm_rate = null_n > 0 and null_alarm / null_n or nil,
    false_alarm_upper95 = null_n > 0 and M.clopper_pearson_upper(null_alarm, null_n) or nil,
    outside_trials = out_n, outside_wrong_names = out_wrong,
    strength_relative_error = stats(strength_err),
    misfit_after_over_before = stats(ratio),
    strength_interval_coverage = n_int > 0 and {covered = covered, trials = n_int} or nil,
    strength_resolution_corrected = n_rc > 0 and {relative_error = stats(err_rc), covered = covered_rc, trials = n_rc} or nil,
    -- The issue's target: the misfit left after adding a right name at most 1.2 noise sd.
    misfit_after_named = against_target(misfit_named),
    -- The same misfit whitened with the noise covariance's correlations (result.json's
    -- misfit_statistic_after: sqrt(rᵀC⁻¹r / m) instead of the RMS of r_i / sqrt(C_ii)).
    misfit_whitened_after_named = against_target(whitened_named),
  }
end

return M
