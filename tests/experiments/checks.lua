-- Assertions of the check_*.lua scripts that read a study's written files (required from the
-- script's directory): check(cond, fmt, ...) raises the formatted message at the caller's line;
-- near(a, b, rel, what) checks two numbers agree to rel × max(1, |b|), also at the caller's line.
local M = {}

function M.check(cond, fmt, ...)
  if not cond then error(string.format(fmt, ...), 2) end
end

function M.near(a, b, rel, what)
  if not (type(a) == "number" and type(b) == "number" and math.abs(a - b) <= rel * math.max(1, math.abs(b))) then
    error(string.format("%s: %s against %s", what, tostring(a), tostring(b)), 2)
  end
end

return M
