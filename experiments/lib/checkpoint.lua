-- Periodic checkpoints of an experiment's run phases (sim:run{checkpoint, checkpoint_every};
-- docs/reliability.md). A killed run started again with the same --out, seed and thread count
-- resumes each phase from its last checkpoint and ends in the state of an uninterrupted run.
--
--   local checkpoint = require("lib.checkpoint")
--   local P = paddy.parameters{..., checkpoint_interval = checkpoint.parameter}
--   sim:run(checkpoint.options(P.checkpoint_interval, "lift", {duration = 2, every = 0.01, callback = f}))
local M = {}

M.parameter = {default = 0, unit = "s", min = 0, max = 1000,
               description = "simulated time between checkpoints of each run phase (0 = none)"}

-- The sim:run options `opts` with the checkpoint of phase `name` (file <name>.h5 in the output
-- directory) added when interval > 0; `opts` unchanged otherwise.
function M.options(interval, name, opts)
  if type(name) ~= "string" or not name:match("^[%w_]+$") then
    error("lib.checkpoint.options: the phase name must be letters, digits or _ (got " .. tostring(name) .. ")", 2)
  end
  if interval and interval > 0 then
    opts.checkpoint = name .. ".h5"
    opts.checkpoint_every = interval
  end
  return opts
end

return M
