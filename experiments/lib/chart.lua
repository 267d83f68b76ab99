-- Charts: one gnuplot picture (PNG, util.gnuplot) from a description, so that experiments say
-- what they plot, not how gnuplot is driven.
--
--   local chart = require("lib.chart")
--   pictures.slump_history = chart.plot("slump_history", {
--     title = "Slump against time", xlabel = "t [s]", ylabel = "[mm]",
--     settings = {"set key outside right"},           -- further gnuplot commands, as they are
--     series = {
--       {file = dat, using = "1:2", with = "linespoints pt 7", title = "slump"},    -- a data file
--       {expr = "231", with = "lines dt 3", title = "measured slump 231 mm"},       -- a function of x
--       {rows = {{-100, 0}, {-50, 300}}, using = "1:2", with = "lines"},            -- inline points
--     },
--   })
--
-- title, xlabel and ylabel are text (quoted here); a series without `title` has no key entry.
-- `grid` (default true) draws the grid. Returns the PNG's path, or nil and a message when gnuplot
-- failed (util.gnuplot: pictures are optional).
local util = require("lib.util")

local M = {}

-- A gnuplot single-quoted string: quotes inside are doubled.
function M.quote(text)
  return "'" .. tostring(text):gsub("'", "''") .. "'"
end

local function series_line(s)
  local source
  if s.file then
    source = M.quote(s.file)
  elseif s.expr then
    source = s.expr
  elseif s.rows then
    source = "'-'"
  else
    error("chart.plot: a series needs file, expr or rows", 3)
  end
  local parts = {source}
  if s.using then parts[#parts + 1] = "using " .. s.using end
  if s.with then parts[#parts + 1] = "with " .. s.with end
  parts[#parts + 1] = s.title and ("title " .. M.quote(s.title)) or "notitle"
  return table.concat(parts, " ")
end

-- The gnuplot script of a chart (without terminal and output: util.gnuplot adds them).
function M.script(c)
  local lines = {}
  if c.title then lines[#lines + 1] = "set title " .. M.quote(c.title) end
  if c.xlabel then lines[#lines + 1] = "set xlabel " .. M.quote(c.xlabel) end
  if c.ylabel then lines[#lines + 1] = "set ylabel " .. M.quote(c.ylabel) end
  if c.grid ~= false then lines[#lines + 1] = "set grid" end
  for _, s in ipairs(c.settings or {}) do lines[#lines + 1] = s end
  if not c.series or #c.series == 0 then error("chart.plot: no series to plot", 2) end
  local plots = {}
  for k, s in ipairs(c.series) do plots[k] = series_line(s) end
  lines[#lines + 1] = "plot " .. table.concat(plots, ", \\\n     ")
  for _, s in ipairs(c.series) do
    if s.rows then
      for _, row in ipairs(s.rows) do
        local cells = {}
        for j, v in ipairs(row) do cells[j] = string.format("%.9g", v) end
        lines[#lines + 1] = table.concat(cells, " ")
      end
      lines[#lines + 1] = "e"
    end
  end
  return table.concat(lines, "\n")
end

-- Draws the chart into <stem>.png in the output directory (the script beside it as <stem>.gp).
function M.plot(stem, c)
  return util.gnuplot(stem, M.script(c))
end

return M
