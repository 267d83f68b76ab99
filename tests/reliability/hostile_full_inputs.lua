-- Input files for hostile_full_run.sh (docs/reliability.md, section 4): a miniature calibration
-- input (tests/calibration/mini_mud.json: 40 mm spheres, small designs, no rheometer) and a
-- miniature discovery input (one slump at a fast lift, no free parameter, one candidate: the
-- fewest simulations the workflow allows) whose free text (the descriptions, every factor unit) holds hostile strings:
-- quotes, $(...) and backticks that would create the canary file, ;, a line break followed by
-- a command, ../, markup and non-ASCII. Also one input of each with a hostile name (a response
-- and an experiment name), which the full run must refuse before any simulation. Written into
-- this run's output directory; the hostile description is also written to description.txt so
-- the shell can look for it in the reports.
local P = paddy.parameters{
  canary = {default = "", type = "string", description = "absolute path of the file no command may create"},
}
local here = debug.getinfo(1, "S").source:match("^@(.*)/[^/]*$") or "."
local C = P.canary ~= "" and P.canary or (paddy.out_dir .. "/CANARY")
local hostile = {
  "$(touch " .. C .. ")", "`touch " .. C .. "`", "a'; touch " .. C .. "; echo '", 'a"; touch ' .. C .. '; echo "',
  "x\ntouch " .. C, "|| touch " .. C, "../../../etc/passwd", "é ñ 日本 \u{1F600}", "<script>alert(1)</script>",
  "\" onmouseover=\"alert(1)", "' onclick='alert(1)", "]]><!-- -->&amp;",
}
local description = "hostile: " .. table.concat(hostile, " | ")

local cal = paddy.read_json(here .. "/../calibration/mini_mud.json")
cal.description = description
cal.rheometer = {run = false}
for k, f in ipairs(cal.factors) do f.unit = hostile[(k - 1) % #hostile + 1] end
paddy.write_json("calibration.json", cal)
local bad = paddy.read_json(here .. "/../calibration/mini_mud.json")
bad.measured = {["slump_mm; touch " .. C] = 231}
paddy.write_json("calibration_bad_name.json", bad)

local disc = {
  description = description,
  experiments = {{name = "slump", script = "slump.lua", set = {lift_speed = 0.3},
                  measured = {slump_mm = 231, slump_flow_mm = 480}, sigma = {slump_mm = 5, slump_flow_mm = 10}}},
  free_parameters = {},  -- allowed by the reader; the run used to fail on it in paddy.doe.diagnose
  candidates = {{name = "wall_adhesion", parameter = "mud_steel_surface_energy", low = 0, high = 0.3}},
  settings = {iterations = 0, replicates = 5, signature_seeds = 1, confirm_seeds = 1, start_scan = 0,
              thresholds = "tables"},
}
paddy.write_json("discovery.json", disc)
disc.experiments[1].name = "slump$(touch " .. C .. ")"
paddy.write_json("discovery_bad_name.json", disc)

local f = assert(io.open(paddy.out_dir .. "/description.txt", "wb"))
f:write(description)
f:close()
paddy.result{written = 4}
