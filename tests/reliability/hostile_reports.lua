-- Hostile text through the calibration and discovery input files into their HTML reports
-- (hostile_reports.sh runs this and checks the pages with xmllint, the canary and the files
-- outside the output directory; docs/reliability.md, "Hostile input").
--   1. Every name of the input files (calibration: response names, factor symbols and
--      parameters; discovery: experiment names, observable keys, set keys, parameters,
--      candidate names) is refused for each hostile text, with an error naming the file and the
--      key. Free text (descriptions, units, the experiment's file name, string values of set)
--      is accepted unchanged.
--   2. The report layers (lib/calibration/report.lua with its charts, lib/discovery/report.lua
--      with its figures) write report.html from an outcome built around an input file whose
--      name and free text are hostile; the description reads back, after unescaping, as the
--      text given; every unit and file name appears escaped; no tag comes from the text.
local P = paddy.parameters{
  canary = {default = "", type = "string", description = "absolute path of the file no command may create"},
  pictures = {default = true, description = "draw the report figures with gnuplot"},
}
local util = require("lib.util")
local calibration_input = require("lib.calibration.input")
local discovery_input = require("lib.discovery.input")
local calibration_report = require("lib.calibration.report")
local discovery_report = require("lib.discovery.report")
local html = require("lib.calibration.html")

local C = P.canary ~= "" and P.canary or (paddy.out_dir .. "/CANARY")
-- The strings of tests/reliability/test_hostile_input.cpp, and markup that would break a page.
local hostile = {
  "$(touch " .. C .. ")", "`touch " .. C .. "`", "a'; touch " .. C .. "; echo '", 'a"; touch ' .. C .. '; echo "',
  "x\ntouch " .. C, "; touch " .. C, "|| touch " .. C, "../../../etc/passwd", "é ñ 日本 \u{2028} \u{1F600}",
  "'", '"', "\\", "$HOME ${PATH} !x *", "-rf", " leading and trailing ", "",
  "<script>alert(1)</script>", "</td></tr></table><b>bold</b>", "]]><!-- -->&amp;&#39;<![CDATA[",
  "control \1\8\27 and \u{FFFF}", "\" onmouseover=\"alert(1)", "' onclick='alert(1)",
}

local failures = 0
local function check(ok, what)
  if not ok then
    failures = failures + 1
    io.stderr:write("FAIL: ", what, "\n")
  end
end
local function deep_copy(t)
  if type(t) ~= "table" then return t end
  local c = {}
  for k, v in pairs(t) do c[k] = deep_copy(v) end
  return c
end
local function show(s) return string.format("%q", s) end

-- 1. The input files ------------------------------------------------------------------------
local here = debug.getinfo(1, "S").source:match("^@(.*)/[^/]*$") or "."
local cal_base = paddy.read_json(here .. "/../calibration/mini_mud.json")
cal_base.rheometer.measured_torque_csv = nil
local disc_base = paddy.read_json(here .. "/../../experiments/discovery/reference_slump.json")
util.mkdir(util.out("inputs"))

-- reader(path) must fail naming the file and `key`
local function refused(reader, doc, key, h, n)
  local path = paddy.write_json(string.format("inputs/refused_%03d.json", n), doc)
  local ok, err = pcall(reader, path)
  check(not ok, key .. " = " .. show(h) .. " was accepted")
  if not ok then
    err = tostring(err)
    check(err:find(path, 1, true) ~= nil, key .. " = " .. show(h) .. ": the error does not name the file: " .. err)
    check(err:find(key, 1, true) ~= nil, key .. " = " .. show(h) .. ": the error does not name the key: " .. err)
  end
end
local function accepted(reader, doc, n)
  local path = paddy.write_json(string.format("inputs/accepted_%03d.json", n), doc)
  local ok, input = pcall(reader, path)
  check(ok, "a free text was refused: " .. tostring(input))
  return ok and input or nil
end

local n, refusals, acceptances = 0, 0, 0
for _, h in ipairs(hostile) do
  local function next_n() n = n + 1; return n end
  -- calibration: names
  local d = deep_copy(cal_base); d.measured[h] = 100
  refused(calibration_input.read, d, "measured", h, next_n())
  d = deep_copy(cal_base); d.factors[1].symbol = h
  refused(calibration_input.read, d, "factors[1].symbol", h, next_n())
  d = deep_copy(cal_base); d.factors[2].parameter = h
  refused(calibration_input.read, d, "factors[2].parameter", h, next_n())
  -- discovery: names
  d = deep_copy(disc_base); d.experiments[1].name = h
  refused(discovery_input.read, d, "experiments[1].name", h, next_n())
  d = deep_copy(disc_base); d.experiments[1].measured[h] = 1; d.experiments[1].sigma[h] = 1
  refused(discovery_input.read, d, "experiments[1].measured", h, next_n())
  d = deep_copy(disc_base); d.experiments[1].set[h] = 1
  refused(discovery_input.read, d, "experiments[1].set", h, next_n())
  d = deep_copy(disc_base); d.free_parameters[1].parameter = h
  refused(discovery_input.read, d, "free_parameters[1].parameter", h, next_n())
  d = deep_copy(disc_base); d.candidates[2].name = h
  refused(discovery_input.read, d, "candidates[2].name", h, next_n())
  d = deep_copy(disc_base); d.candidates[3].parameter = h
  refused(discovery_input.read, d, "candidates[3].parameter", h, next_n())
  refusals = refusals + 9
  -- free text, kept unchanged
  d = deep_copy(cal_base); d.description = h; d.factors[3].unit = h
  local input = accepted(calibration_input.read, d, next_n())
  if input then
    check(input.description == h and input.factors[3].unit == h, "calibration: free text changed: " .. show(h))
  end
  d = deep_copy(disc_base); d.description = h; d.experiments[1].set.cone = h
  input = accepted(discovery_input.read, d, next_n())
  if input then
    check(input.description == h and input.experiments[1].set.cone == h, "discovery: free text changed: " .. show(h))
  end
  acceptances = acceptances + 2
  -- the experiment's file name: any text without control characters
  d = deep_copy(cal_base); d.experiment = h
  if h == "" or h:find("%c") then
    refused(calibration_input.read, d, "'experiment'", h, next_n())
    refusals = refusals + 1
  else
    input = accepted(calibration_input.read, d, next_n())
    check(input and input.experiment == h, "calibration: experiment changed: " .. show(h))
    acceptances = acceptances + 1
  end
end
-- a result key with dots (a.b reads result.a.b) stays allowed
do
  local d = deep_copy(disc_base)
  d.experiments[1].measured["torque.steady_Nm"] = 1
  d.experiments[1].sigma["torque.steady_Nm"] = 0.1
  check(accepted(discovery_input.read, d, 9999) ~= nil, "discovery: the dotted result key torque.steady_Nm was refused")
end
print(string.format("inputs: %d hostile names refused, %d free texts accepted unchanged", refusals, acceptances))

-- 2. The reports ----------------------------------------------------------------------------
local all = table.concat(hostile, " | ")
local function unescape(s)
  return (s:gsub("&lt;", "<"):gsub("&gt;", ">"):gsub("&quot;", '"'):gsub("&#39;", "'"):gsub("&amp;", "&"))
end
-- What esc makes of characters XML forbids (html.lua): U+FFFD.
local function xml_safe(s)
  return (s:gsub("[\0-\8\11\12\14-\31]", "\u{FFFD}"):gsub("\u{FFFF}", "\u{FFFD}"))
end
local function read(path)
  local f = assert(io.open(path, "rb"))
  local text = f:read("a")
  f:close()
  return text
end
local function check_page(page, name, description, texts)
  local p = page:match("<p>(.-)</p>")
  check(p ~= nil and unescape(p) == xml_safe(description), name .. ": the description does not read back as given")
  for _, t in ipairs(texts) do
    check(page:find(html.esc(t), 1, true) ~= nil, name .. ": " .. show(t) .. " is not in the page, escaped")
  end
  for _, tag in ipairs({"<script", "<b>", "<![CDATA[", "<!--", "onmouseover=\"alert", "onclick='alert"}) do
    check(page:find(tag, 1, true) == nil, name .. ": the page holds " .. tag .. " from the input text")
  end
end

-- The calibration: an input file with a hostile name and hostile free text.
local in_name = "inputs/calib '$(touch " .. C .. ")' `touch " .. C .. "` <b>&amp;\".json"
local d = deep_copy(cal_base)
d.description = all
d.experiment = "../../<script>/slump'\".lua"
for k, f in ipairs(d.factors) do f.unit = hostile[k] end
in_name = paddy.write_json(in_name, d)
local input = calibration_input.read(in_name)
local resp = input.responses
local syms = {}
for _, f in ipairs(input.factors) do syms[#syms + 1] = f.symbol end
local sel = {syms[1], syms[2], syms[3]}
local function per_resp(v)
  local t = {}
  for i, r in ipairs(resp) do t[r] = v * i end
  return t
end
local function fit(terms)
  local responses = {}
  for _, r in ipairs(resp) do
    local coefficients = {}
    for i, t in ipairs(terms) do coefficients[t] = i * 0.5 end
    responses[r] = {anova = {{source = syms[1], ss = 1.5, df = 1, ms = 1.5, F = 3.2, p = 0.04},
                             {source = "Residual", ss = 2, df = 4, ms = 0.5}},
                    r2 = 0.9, adj_r2 = 0.85, pred_r2 = 0.7, cv_percent = 3, adeq_precision = 8, std_dev = 0.2, mean = 100,
                    coefficients = coefficients, coefficients_actual = coefficients}
  end
  return {responses = responses, terms = terms, plots = {}}
end
local real, coded = {}, {}
for _, s in ipairs(syms) do real[s] = 0.1 end
for k = 1, input.screening.dummy_columns do coded["D" .. k] = 1 end
local levels = {}
for _, s in ipairs(sel) do levels[s] = 0.1 end
local o = {
  input = input, responses = resp, measured = input.measured, tolerance = input.tolerance,
  particle_diameter = 0.01, time_step = {fraction = 0.1, factor = 1.2, lowest_restitution = 0.01},
  parameters = {strategy = "both"}, wall_time_s = 12.5,
  simulations = {{index = 1, stage = "screening", label = "run 1", seed = 1, key = string.rep("ab", 32), params = {},
                  responses = per_resp(200), wall_time_s = 3}},
  screening = {selected = sel, design = {runs = {{run = 1, type = "factorial", real = real, coded = coded}}},
               runs = {{responses = per_resp(200), label = "run 1", seed = 1, key = string.rep("ab", 32), index = 1}},
               fit = fit({"Intercept", syms[1]}),
               ranking = {{symbol = syms[1], p_by_response = per_resp(0.01), selected = true, reason = "p < alpha"},
                          {symbol = syms[3], p_by_response = per_resp(0.2), selected = false}}},
  reference = {
    optimum = {factors = levels, predicted = per_resp(230), desirability = 0.9},
    verification = {mean = per_resp(231), sd = per_resp(2), errors = per_resp(0.01), worst = 0.01,
                    runs = {{seed = 1, responses = per_resp(231), dir = util.out("no_such_run")}}},
    steepest_ascent = {{step = 0, values = levels, responses = per_resp(220), errors = per_resp(0.05), worst = 0.05}},
    best_step = {step = 0}, box = {[sel[1]] = {0, 1}, [sel[2]] = {0, 1}, [sel[3]] = {0, 1}},
    runs = {{run = {run = 1, type = "center", real = levels, coded = levels}, mean = per_resp(230), sd = per_resp(1),
             errors = per_resp(0.02), rows = {{responses = per_resp(230)}}}},
    fit = fit({"Intercept", sel[1], sel[1] .. ":" .. sel[2]}),
    optimization = {solutions = {{factors = levels, predicted = per_resp(231), desirability = 0.95}}, plots = {}},
    goals = {{response = resp[1], target = 231, lower = 220, upper = 240}},
    rheometer = {dir = util.out("no_such_run"),
                 result = {steps = {{speed_rpm = 10, torque_Nm = 0.1, shear_rate = 1, shear_stress_Pa = 2}},
                           herschel_bulkley = {tau0 = 1, K = 2, n = 0.5},
                           comparison = {file = "torque '$(touch " .. C .. ")' <b>.csv", mean_relative_error = 0.1,
                                         max_relative_error = 0.2}}},
  },
  surrogate = {factors = {{name = sel[1], low = 0, high = 1}}, budget = 8, success = true, rounds = 1,
               confirmed = {simulations = 3, seeds = 1, worst = 0.01, values = levels, mean = per_resp(231), errors = per_resp(0.01)},
               best = {values = levels, worst = 0.01},
               evaluations = {{n = 1, kind = "ei", seed = 1, values = levels, responses = per_resp(231), errors = per_resp(0.01),
                               predicted = {predicted = {[resp[1]] = {mean = 230, sd = 1}}}, worst = 0.01}}},
}
util.mkdir(util.out("figures"))
local files = calibration_report.write{outcome = o, figures = util.out("figures"), pictures = P.pictures}
local page = read(files.html)
local units = {}
for k = 1, #d.factors do units[k] = hostile[k] end
units[#units + 1] = in_name
units[#units + 1] = d.experiment
units[#units + 1] = o.reference.rheometer.result.comparison.file
check_page(page, "calibration report", all, units)
local figures = 0
for _ in page:gmatch("<img ") do figures = figures + 1 end
if P.pictures then check(figures >= 3, "calibration report: only " .. figures .. " figures") end
assert(os.rename(files.html, util.out("calibration_report.html")))
paddy.read_json(files.json)

-- The discovery: the same for its input file and report.
local dname = "inputs/discovery '$(touch " .. C .. ")' <i>.json"
d = deep_copy(disc_base)
d.description = all
d.experiments[1].set.cone = all
dname = paddy.write_json(dname, d)
local dinput = discovery_input.read(dname)
local cands = {}
for k, c in ipairs(dinput.candidates) do
  cands[k] = {name = c.name, z = 1.5, p = 0.1, p_holm = 0.3, strength = 0.01, strength_se = 0.005, q_after = 2, q_after_p = 0.4,
              bayes_factor = 1.2, identifiable = true}
end
local residuals = {{label = "slump slump_mm", block = "slump", key = "slump_mm", measured = 231, simulated = 228, z = 1},
                   {label = "slump slump_flow_mm", block = "slump", key = "slump_flow_mm", measured = 480, simulated = 470, z = 1.7}}
local signatures = {}
for _, c in ipairs(dinput.candidates) do signatures[c.name] = {0.5, -0.3} end
local dout = {
  input = dinput, parameters = {particle_diameter = 0.01}, wall_time_s = 30,
  simulations = {{index = 1, stage = "calibration", label = "start", seed = 1, key = string.rep("cd", 32), wall_time_s = 2}},
  diagnosis = {decision = "none", reason = "no candidate is significant", misfit = 1.2, q0 = 2, q0_df = 2, q0_p = 0.3,
               candidates = cands, best = dinput.candidates[1].name},
  located = {rms = 1.4, residuals = residuals, noise = {}},
  residual = {1, 1.7}, signatures = signatures, layout = {{vector = false}, {vector = false}},
  calibration = {iterations = {{iteration = 1, theta = {0.096}, rms_sigma = 1.4, accepted = true}}, theta = {0.096}},
  replicates = {1, 2, 3, 4, 5},
}
local dfiles = discovery_report.write{outcome = dout, pictures = P.pictures}
page = read(dfiles.html)
check_page(page, "discovery report", all, {dname})
assert(os.rename(dfiles.html, util.out("discovery_report.html")))

print(string.format("reports: calibration (%d figures) and discovery written; %d failed checks", figures, failures))
if failures > 0 then error(failures .. " checks failed", 0) end
paddy.result{refused = refusals, accepted = acceptances, failures = failures}
