-- Correct names of a blind benchmark's effect trials by how visible each hidden effect was:
-- its expected z = z_at_high · strength / high, with z_at_high from a sensitivity study of the
-- same experiments and resolution (experiments/validation/discovery_sensitivity.lua, group
-- `group`). Then every trial by the misfit its data showed after the free parameters were
-- calibrated (the p-value of Q0, from the data alone): effect trials named, null trials alarmed,
-- outside trials wrongly named, per bin; and, for a summary that has them, the effect trials by the
-- workflow's own detection limits (score.by_detection). Reads two committed result files, runs no simulation
-- (docs/discovery.md, "Which hidden effects can be named").
--
--   paddy run experiments/validation/discovery_visibility.lua \
--     --set blind=docs/results/discovery_blind_small60_summary.json \
--     --set sensitivity=docs/results/discovery_sensitivity_25mm_two_cones_vane.json --set group=slump --out DIR
local score = require("lib.discovery.score")
local util = require("lib.util")

local P = paddy.parameters{
  {name = "blind", default = "", description = "a blind benchmark's summary (blind_summary.json or its committed copy)"},
  {name = "sensitivity", default = "", description = "a sensitivity study's result (discovery_sensitivity.lua's sensitivity.json)"},
  {name = "group", default = "slump", description = "the group of experiments of the sensitivity study that the benchmark ran"},
  {name = "edges", default = "3,6,10", description = "bin edges of the expected z, ascending"},
  {name = "p_edges", default = "0.001,0.05", description = "bin edges of the misfit's p-value (q0_p), ascending in (0, 1)"},
}
if P.blind == "" or P.sensitivity == "" then
  error("discovery_visibility.lua: give --set blind=FILE and --set sensitivity=FILE", 0)
end
local blind = paddy.read_json(P.blind)
local sens = paddy.read_json(P.sensitivity)
local trials = blind.trials or (blind.results and blind.results.trials)
if type(trials) ~= "table" then error(string.format("discovery_visibility.lua: %s has no 'trials'", P.blind), 0) end

local group
for _, g in ipairs(sens.groups or {}) do if g.name == P.group then group = g end end
if not group then
  local names = {}
  for _, g in ipairs(sens.groups or {}) do names[#names + 1] = g.name end
  error(string.format("discovery_visibility.lua: group = '%s' is not in %s (allowed: %s)", P.group, P.sensitivity,
                      table.concat(names, ", ")), 0)
end
local high = {}
for _, c in ipairs(sens.candidates) do high[c.name] = c.high end
local visibility, names = {}, {}
for _, c in ipairs(group.candidates) do
  visibility[c.name] = {z_at_high = c.z_at_high, high = high[c.name]}
  names[c.name] = true
end
local edges = util.numbers(P.edges, "edges")
for k = 2, #edges do
  if not (edges[k] > edges[k - 1]) then error("discovery_visibility.lua: edges must ascend", 0) end
end

local v = score.by_visibility(trials, visibility, edges, names)
print(string.format("%-5s %-17s %9s %7s  %s", "trial", "hidden effect", "strength", "z exp", "answer"))
for _, r in ipairs(v.rows) do
  print(string.format("%-5d %-17s %9.4g %7.1f  %s%s", r.trial, r.name, r.strength, r.z_expected, r.answer,
                      r.right and "" or (r.wrong_name and "  (wrong name)" or "  (missed)")))
end
print()
print("expected z      trials  named  wrong names  lower 95 % bound")
for _, b in ipairs(v.bins) do
  print(string.format("[%4s, %4s)  %7d  %5d  %11d  %s", b.from == -math.huge and "-inf" or string.format("%g", b.from),
                      b.to == math.huge and "inf" or string.format("%g", b.to), b.trials, b.right, b.wrong_names,
                      b.lower95 and string.format("%.1f %%", 100 * b.lower95) or "-"))
end
local p_edges = util.numbers(P.p_edges, "p_edges")
local m = score.by_misfit(trials, p_edges, names)   -- refuses edges that do not ascend inside (0, 1)
print()
print("misfit p (Q0)    effect trials  named  wrong names  lower 95 %   null trials  alarms   outside  wrong names")
for _, b in ipairs(m.bins) do
  print(string.format("[%-6g, %-6g)  %13d  %5d  %11d  %10s   %11d  %6d   %7d  %11d", b.from, b.to, b.effect.trials, b.effect.right,
                      b.effect.wrong_names, b.effect.lower95 and string.format("%.1f %%", 100 * b.effect.lower95) or "-",
                      b.null.trials, b.null.alarms, b.outside.trials, b.outside.wrong_names))
end
-- By the workflow's own detection limits (a summary written since they exist carries by_detection;
-- an older one has no limits to score).
local detection
if blind.summary and blind.summary.by_detection then
  detection = score.by_detection(trials, names)
  print()
  print("hidden candidate    effect trials  declared detectable  named of those  answered none  upper limit covers")
  local cnames = {}
  for n in pairs(detection.per_candidate) do cnames[#cnames + 1] = n end
  table.sort(cnames)
  for _, n in ipairs(cnames) do
    local c = detection.per_candidate[n]
    print(string.format("%-18s  %13d  %19d  %14d  %13d  %18d", n, c.trials, c.detectable, c.detectable_right, c.none, c.none_covered))
  end
  print(string.format("all: declared detectable %d, named %d (lower 95 %% %s); below the limit %d, named %d; none answers covered %d of %d",
                      detection.detectable.trials, detection.detectable.right,
                      detection.detectable.lower95 and string.format("%.1f %%", 100 * detection.detectable.lower95) or "-",
                      detection.undetectable.trials, detection.undetectable.right, detection.none_answers.covered,
                      detection.none_answers.trials))
end
paddy.result{blind = P.blind, sensitivity = P.sensitivity, group = P.group, rows = v.rows, bins = v.bins,
             p_edges = p_edges, misfit_bins = m.bins, detection = detection}
