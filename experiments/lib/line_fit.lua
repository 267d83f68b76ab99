-- Straight line y = a + b·x through points by ordinary least squares, with the standard errors of
-- its coefficients and of its value at any x (a textbook result: e.g. Montgomery & Runger,
-- Applied Statistics and Probability for Engineers, ch. 11):
--     b = Sxy/Sxx,  a = ȳ − b x̄,  s² = SSE/(n − 2),
--     se(b) = s/√Sxx,  se(a + b x0) = s·√(1/n + (x0 − x̄)²/Sxx)   (se(a): x0 = 0).
-- Used by lib/mohr_coulomb.lua (the vane depth series) and validation/yield_stress_resolution.lua
-- (a yield stress against the sphere diameter, extrapolated to the real grain).
local M = {}

-- args: {x = {...}, y = {...}, what = "name used in errors"}; returns {a=, b=, n=, dof=, r2=,
-- residuals=, x_mean=, sxx=, s= (nil for n = 2), se_a=, se_b=}. Refuses fewer than 2 points,
-- unequal lengths, non-finite values and fewer than 2 distinct x.
function M.fit(args)
  local x, y, what = args.x, args.y, args.what or "line_fit.fit"
  if type(x) ~= "table" or type(y) ~= "table" then error(what .. ": needs x = {...} and y = {...}", 2) end
  local n = #x
  if n ~= #y then error(string.format("%s: %d x values but %d y values", what, n, #y), 2) end
  if n < 2 then error(string.format("%s: %d point(s): a line needs at least 2", what, n), 2) end
  local sx, sy = 0, 0
  for k = 1, n do
    for _, v in ipairs({{"x", x[k]}, {"y", y[k]}}) do
      if type(v[2]) ~= "number" or v[2] ~= v[2] or math.abs(v[2]) == math.huge then
        error(string.format("%s: %s[%d] = %s is not a finite number", what, v[1], k, tostring(v[2])), 2)
      end
    end
    sx, sy = sx + x[k], sy + y[k]
  end
  local xm, ym = sx / n, sy / n
  local sxx, sxy, syy = 0, 0, 0
  for k = 1, n do
    sxx = sxx + (x[k] - xm) ^ 2
    sxy = sxy + (x[k] - xm) * (y[k] - ym)
    syy = syy + (y[k] - ym) ^ 2
  end
  if not (sxx > 1e-12 * math.max(xm * xm, 1e-300) * n) then
    error(string.format("%s: all points at one x = %g: a line needs at least 2 distinct x", what, xm), 2)
  end
  local b = sxy / sxx
  local a = ym - b * xm
  local sse, residuals = 0, {}
  for k = 1, n do
    residuals[k] = y[k] - (a + b * x[k])
    sse = sse + residuals[k] ^ 2
  end
  local fit = {a = a, b = b, n = n, dof = n - 2, residuals = residuals, x_mean = xm, sxx = sxx,
               r2 = syy > 0 and 1 - sse / syy or 1}
  if n > 2 then
    fit.s = math.sqrt(sse / (n - 2))
    fit.se_b = fit.s / math.sqrt(sxx)
    fit.se_a = M.se_at(fit, 0)
  end
  return fit
end

-- The fitted line's value at x0 and its standard error (nil when the fit has no residual degree
-- of freedom).
function M.at(fit, x0)
  return fit.a + fit.b * x0, M.se_at(fit, x0)
end

function M.se_at(fit, x0)
  if not fit.s then return nil end
  return fit.s * math.sqrt(1 / fit.n + (x0 - fit.x_mean) ^ 2 / fit.sxx)
end

return M
