-- HTML building blocks of the calibration report: escaping, number formats, tables, figures,
-- ANOVA tables and regression equations. Output is well-formed XHTML (polyglot HTML5).
-- Text for an element or a double- or single-quoted attribute. Characters XML does not allow
-- (C0 controls other than tab, newline and carriage return; U+FFFE, U+FFFF) become U+FFFD, so any
-- text from an input file leaves the page well-formed.
local function esc(s)
  s = tostring(s):gsub("[\0-\8\11\12\14-\31]", "\239\191\189"):gsub("\239\191[\190\191]", "\239\191\189")
  return (s:gsub("&", "&amp;"):gsub("<", "&lt;"):gsub(">", "&gt;"):gsub('"', "&quot;"):gsub("'", "&#39;"))
end

local function num(v, digits)
  if v == nil then return "–" end
  if type(v) ~= "number" then return esc(v) end
  if v ~= v then return "–" end
  if v == math.floor(v) and math.abs(v) < 1e6 then return string.format("%d", v) end
  return string.format("%." .. (digits or 4) .. "g", v)
end

local function pval(p)
  if p == nil then return "–" end
  if p < 0.0001 then return "&lt; 0.0001" end
  return string.format("%.4f", p)
end

local function pct(v) return v and string.format("%.2f %%", 100 * v) or "–" end

local function rel(path)
  local prefix = paddy.out_dir .. "/"
  if path and path:sub(1, #prefix) == prefix then return path:sub(#prefix + 1) end
  return path
end

local function table_html(header, rows, caption)
  local h = {"<table>"}
  if caption then h[#h + 1] = "<caption>" .. caption .. "</caption>" end
  h[#h + 1] = "<thead><tr>"
  for _, c in ipairs(header) do h[#h + 1] = "<th>" .. c .. "</th>" end
  h[#h + 1] = "</tr></thead><tbody>"
  for _, row in ipairs(rows) do
    h[#h + 1] = "<tr>"
    for _, c in ipairs(row) do h[#h + 1] = "<td>" .. c .. "</td>" end
    h[#h + 1] = "</tr>"
  end
  h[#h + 1] = "</tbody></table>"
  return table.concat(h)
end

local function figure(path, caption)
  if not path then return "" end
  return string.format('<figure><img src="%s" alt="%s"/><figcaption>%s</figcaption></figure>', esc(rel(path)), esc(caption), esc(caption))
end

local function figures_of(list, pattern)
  local out = {}
  for _, p in ipairs(list or {}) do
    if p:match("%.png$") and (not pattern or p:match(pattern)) then out[#out + 1] = p end
  end
  table.sort(out)
  return out
end

local function factor_label(input, sym)
  local f = input.by_symbol[sym]
  return f and string.format("%s %s%s", sym, f.parameter, f.unit ~= "" and " [" .. f.unit .. "]" or "") or sym
end

local function anova_section(input, fit, responses, what)
  local h = {}
  for _, r in ipairs(responses) do
    local a = fit.responses[r]
    local rows = {}
    for _, e in ipairs(a.anova) do
      rows[#rows + 1] = {esc(e.source), num(e.ss, 6), num(e.df), num(e.ms, 6), num(e.F, 4), pval(e.p)}
    end
    h[#h + 1] = table_html({"Source", "Sum of squares", "df", "Mean square", "F", "p"}, rows,
                           string.format("ANOVA of %s (%s)", esc(r), what))
    h[#h + 1] = table_html({"R²", "adjusted R²", "predicted R²", "C.V. %", "Adequate precision", "std. dev.", "mean"},
                           {{num(a.r2), num(a.adj_r2), num(a.pred_r2), num(a.cv_percent, 3), num(a.adeq_precision), num(a.std_dev), num(a.mean)}})
  end
  return table.concat(h, "\n")
end

local function equation(coefficients, terms, response)
  local parts = {}
  for _, t in ipairs(terms) do
    local c = coefficients[t]
    if c then
      if t == "Intercept" then parts[#parts + 1] = string.format("%.6g", c)
      else parts[#parts + 1] = string.format("%s %.6g·%s", c < 0 and "−" or "+", math.abs(c), esc((t:gsub(":", "·")))) end
    end
  end
  return esc(response) .. " = " .. table.concat(parts, " ")
end

return {esc = esc, num = num, pval = pval, pct = pct, rel = rel, table_html = table_html, figure = figure, figures_of = figures_of, factor_label = factor_label, anova_section = anova_section, equation = equation}
