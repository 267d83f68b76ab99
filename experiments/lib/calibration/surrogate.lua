-- Sequential surrogate-based calibration (docs/calibration.md): a Gaussian process per response
-- and expected improvement of the worst relative error (paddy.doe surrogate_suggest; formulas in
-- doe/include/paddy/doe/surrogate_calibration.hpp), over the factors the screening selected,
-- inside their "search" ranges; the other factors stay at their centre values.
--   1. A seeded Latin hypercube of `initial_points` simulations.
--   2. Rounds of `batch` suggestions (run in parallel) until the budget is spent or
--   3. a simulation within the tolerance is confirmed: `confirm_seeds` further seeds at the same
--      parameters (run even when the search budget is spent), and the mean of all of them is
--      within the tolerance too.
-- With warp_inputs (the input's default) each Gaussian process also fits a warping of every input
-- (Kumaraswamy CDF; gaussian_process.hpp), for responses that change fast in one part of a range
-- (docs/calibration.md, "The surrogate's Gaussian processes").
local jobs = require("lib.calibration.jobs")
local doe = require("paddy.doe")
local M = {}

local function latin_hypercube(n, d, seed)
  math.randomseed(seed)
  local u = {}
  for i = 1, n do u[i] = {} end
  for j = 1, d do
    local perm = {}
    for i = 1, n do perm[i] = i - 1 end
    for i = n, 2, -1 do
      local k = math.random(i)
      perm[i], perm[k] = perm[k], perm[i]
    end
    for i = 1, n do u[i][j] = (perm[i] + math.random()) / n end
  end
  return u
end

-- o: runner, input, selected, params_of, row_of, seed, batch, say. Returns the record of the run.
function M.run(o)
  local input, S = o.input, o.input.surrogate
  local measured, resp, tol = input.measured, input.responses, input.tolerance
  local factors = {}
  for _, sym in ipairs(o.selected) do
    local f = input.by_symbol[sym]
    factors[#factors + 1] = {name = sym, low = f.search[1], high = f.search[2]}
  end
  local evaluations, data, best = {}, {}, nil
  local function evaluate(kind, list)
    local points = {}
    for i, x in ipairs(list) do
      local seed = o.seed + #evaluations + i
      points[i] = {params = o.params_of(x.values), values = x.values, seed = seed,
                   label = string.format("%s %d", kind, #evaluations + i)}
    end
    local rows = o.runner:run("surrogate", points)
    local added = {}
    for i, row in ipairs(rows) do
      local e, worst = jobs.errors(row.responses, measured)
      local ev = {n = #evaluations + 1, kind = kind, values = points[i].values, seed = points[i].seed, responses = row.responses,
                  errors = e, worst = worst, index = row.index, predicted = list[i].predicted, of = list[i].of}
      evaluations[#evaluations + 1] = ev
      if not best or ev.worst < best.worst then best = ev end
      data[#data + 1] = o.row_of(ev.values, ev.responses)
      added[#added + 1] = ev
    end
    return added
  end

  local u = latin_hypercube(S.initial_points, #factors, o.seed)
  local initial = {}
  for i = 1, S.initial_points do
    local values = {}
    for j, f in ipairs(factors) do values[f.name] = f.low + u[i][j] * (f.high - f.low) end
    initial[i] = {values = values}
  end
  o.say("   %d initial points (Latin hypercube)", #initial)
  local pending = evaluate("initial", initial)
  local confirmed, round, rounds = nil, 0, {}
  while true do
    -- Confirm the best new point within the tolerance.
    table.sort(pending, function(a, b) return a.worst < b.worst end)
    local cand = pending[1]
    if cand and cand.worst <= tol then
      local group = {cand}
      if S.confirm_seeds > 0 then   -- confirmation belongs to the result, like a verification: not cut by the budget
        local list = {}
        for s = 1, S.confirm_seeds do list[s] = {values = cand.values, of = cand.n} end
        for _, ev in ipairs(evaluate("confirm", list)) do group[#group + 1] = ev end
      end
      local rows = {}
      for i, ev in ipairs(group) do rows[i] = {responses = ev.responses} end
      local mean, sd = jobs.mean_responses(rows, resp)
      local e, worst = jobs.errors(mean, measured)
      o.say("   point %d within %.1f %% in one run; over %d seeds %.2f %%", cand.n, 100 * tol, #group, 100 * worst)
      if #group == 1 + S.confirm_seeds and worst <= tol then
        confirmed = {values = cand.values, mean = mean, sd = sd, errors = e, worst = worst, seeds = #group,
                     simulations = #evaluations, last_index = group[#group].index, point = cand.n}
        break
      end
    end
    if #evaluations >= S.budget then break end
    round = round + 1
    local s = doe.surrogate_suggest{factors = factors, data = data, responses = resp, targets = measured,
                                    batch = math.min(o.batch, S.budget - #evaluations), seed = o.seed + round,
                                    warp_inputs = S.warp_inputs}
    local list = {}
    for i, sg in ipairs(s.suggestions) do list[i] = {values = sg.factors, predicted = sg} end
    rounds[#rounds + 1] = {round = round, incumbent_error = s.incumbent_error, hyperparameters = s.hyperparameters,
                           suggestions = s.suggestions}
    pending = evaluate("ei", list)
    o.say("   round %d: %d simulations, best single-run error %.2f %%", round, #evaluations,
          100 * best.worst)
  end
  return {factors = factors, evaluations = evaluations, rounds = rounds, confirmed = confirmed, best = best,
          budget = S.budget, success = confirmed ~= nil}
end

return M
