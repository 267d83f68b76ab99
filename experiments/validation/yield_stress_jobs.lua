-- The runs of the yield-stress studies (validation/yield_stress.lua, validation/yield_stress_resolution.lua):
-- the slump and the vane start-up of one parameter set at one sphere size. One definition, so that
-- both studies submit the same job parameters and a shared campaign directory reuses their runs
-- (docs/campaign.md: a job's key hashes its parameters).
local report = require("report")

local M = {}

-- The extra parameters of every slump and every rheometer run, from the studies' slump_set and
-- rheometer_set; the rheometer runs only the start-up test (no speed steps) unless rheometer_set
-- says otherwise. Refuses extras that would set the study's own parameter, the seed or the size.
function M.extras(parameter, slump_set, rheometer_set)
  local slump_extra = report.assignments(slump_set, "slump_set")
  local rheo_extra = report.merge({speeds_rpm = "", down_sweep = false}, report.assignments(rheometer_set, "rheometer_set"))
  for _, extra in ipairs({slump_extra, rheo_extra}) do
    if extra[parameter] or extra.seed or extra.particle_diameter then
      error("slump_set / rheometer_set must not set " .. parameter .. ", seed or particle_diameter", 0)
    end
  end
  return slump_extra, rheo_extra
end

-- Parameters of one run at sphere diameter d with `parameter` = value (no pictures, snapshots or
-- progress), the extras on top.
function M.params(d, parameter, value, extra)
  return report.merge({particle_diameter = d, progress = false, pictures = false, snapshot_interval = 0,
                       [parameter] = value}, extra)
end

return M
