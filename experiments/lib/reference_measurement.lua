-- The reference study's measured slump test (shared/reference/README.md: slump 231 mm, slump-flow
-- 480 mm, means of 10 tests), read from the one place the project writes them: the `measured`
-- block of the calibration input experiments/calibration/paddy_mud.json, which the calibration
-- (experiments/calibrate_paddy_mud.lua) reads as its targets too.
--
--   local measured = require("lib.reference_measurement").slump()  --> {slump_mm = 231, slump_flow_mm = 480}
local M = {}

function M.file()
  local here = package.searchpath("lib.reference_measurement", package.path)
  if not here then
    error("lib/reference_measurement.lua: cannot locate itself on package.path to find experiments/calibration/")
  end
  return (here:gsub("lib[/\\]reference_measurement%.lua$", "calibration/paddy_mud.json"))
end

-- {slump_mm =, slump_flow_mm =} of the calibration input; an error naming the file and key if
-- either is missing or not a positive number.
function M.slump()
  local path = M.file()
  local measured = paddy.read_json(path).measured
  if type(measured) ~= "table" then error(path .. ": no 'measured' object", 2) end
  local out = {}
  for _, key in ipairs({"slump_mm", "slump_flow_mm"}) do
    local v = measured[key]
    if type(v) ~= "number" or not (v > 0) then
      error(string.format("%s: measured.%s = %s must be a number > 0 [mm]", path, key, tostring(v)), 2)
    end
    out[key] = v
  end
  return out
end

return M
