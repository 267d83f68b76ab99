-- Helpers shared by the validation campaigns (experiments/validation/*.lua): lists and
-- "name=value" overrides in parameters, statistics, a JSON writer, the paths of the reference
-- tables, and the collection of one slump run into a flat row. Pictures and CSV files go through
-- lib.util (util.gnuplot, util.write_csv).
local util = require("lib.util")
local M = {}

-- The campaign directory of a study: its parameter campaign_dir, '' = <out>/campaign.
function M.campaign_dir(P)
  return P.campaign_dir ~= "" and P.campaign_dir or paddy.out_dir .. "/campaign"
end

-- The campaign of a study from its parameters campaign_dir, max_parallel, threads_per_job and
-- code_version ('' = the binaries' hash), with `attempts` per job (nil: the campaign's default).
-- → campaign, its directory
function M.campaign(P, attempts)
  local dir = M.campaign_dir(P)
  return paddy.campaign{dir = dir, max_parallel = P.max_parallel, threads_per_job = P.threads_per_job,
                        max_attempts = attempts,
                        code_version = P.code_version ~= "" and P.code_version or nil}, dir
end

-- "1, 2,3" → {1, 2, 3} (util.numbers); "" → nil.
function M.numbers(text, what)
  if text == nil or tostring(text):match("^%s*$") then return nil end
  return util.numbers(text, what)
end

-- "cone=none, max_time=0.5" → {cone = "none", max_time = 0.5} (util.assignments).
M.assignments = util.assignments

-- Copy of a table with `extra` merged over it.
function M.merge(base, extra)
  local out = {}
  for k, v in pairs(base) do out[k] = v end
  for k, v in pairs(extra or {}) do out[k] = v end
  return out
end

-- gnuplot plot clauses of one set in a Mohr–Coulomb depth picture: its points (columns `using` of
-- `file`, titled points_title), its line τ = c + σ tanφ (`line`: a lib/mohr_coulomb.lua fit, or nil)
-- and its slump yield stress as a dashed level (nil: none), all in `color`; point_type: gnuplot's
-- pt (default 7, filled circles), the line dashed (dt 3) when it is not 7.
function M.depth_plot_clauses(file, using, color, label, points_title, line, tau_slump, point_type)
  local pt = point_type or 7
  local out = {string.format("'%s' using %s with points pt %d ps 1.3 lc rgb '%s' title '%s: %s'", file, using, pt, color, label, points_title)}
  if line then
    out[#out + 1] = string.format("%g + %g * x lc rgb '%s'%s title sprintf('%s: c = %%.0f +- %%.0f Pa, tan phi = %%.2f', %g, %g, %g)",
                                  line.c, line.tan_phi, color, pt == 7 and "" or " dt 3", label, line.c, line.se_c or 0, line.tan_phi)
  end
  if tau_slump then out[#out + 1] = string.format("%g lc rgb '%s' dt 2 title '%s: tau_slump'", tau_slump, color, label) end
  return out
end

-- A Mohr–Coulomb depth picture <stem>.png: shear stress against a normal stress, both axes from
-- zero, with the plot clauses (M.depth_plot_clauses) of every set. → the picture's path (util.gnuplot)
function M.depth_picture(stem, title, xlabel, ylabel, plots)
  return util.gnuplot(stem, string.format([[
set title '%s'
set xlabel '%s'; set ylabel '%s'; set grid; set key top left font ',9'
set xrange [0:*]; set yrange [0:*]
plot %s]], title, xlabel, ylabel, table.concat(plots, ", \\\n     ")))
end

-- "v +- e" with `digits` decimals, for a console table: "-" for a missing value (nil or NaN); where
-- the spread is undefined (nil or NaN: one seed, a fit through as many points as it has
-- parameters) the value alone, followed by `no_spread` if given (e.g. " +- n/a").
function M.plus_minus(v, e, digits, no_spread)
  local f = "%." .. digits .. "f"
  if v == nil or v ~= v then return "-" end
  if e == nil or e ~= e then return string.format(f, v) .. (no_spread or "") end
  return string.format(f .. " +- " .. f, v, e)
end

-- Mean and sample standard deviation (n − 1) of a list; the std is 0 for one value.
function M.mean_std(values)
  local n = #values
  if n == 0 then return 0 / 0, 0 / 0, 0 end
  local s = 0
  for _, v in ipairs(values) do s = s + v end
  local m = s / n
  local q = 0
  for _, v in ipairs(values) do q = q + (v - m) ^ 2 end
  return m, n > 1 and math.sqrt(q / (n - 1)) or 0, n
end

-- Directory of this script's file (paddy.script may be relative to the working directory).
function M.script_dir()
  return (paddy.script:match("^(.*)/[^/]*$") or ".")
end

-- shared/reference/ beside the source tree: <repo>/../shared/reference, found from the script's
-- place (experiments/validation/) unless given.
function M.reference_dir(given)
  if given and given ~= "" then return given end
  return M.script_dir() .. "/../../../shared/reference"
end

-- JSON text of a Lua value (tables with keys 1..n are arrays; NaN and ±inf are null).
local function encode(v, indent, depth)
  local t = type(v)
  if t == "nil" then return "null" end
  if t == "boolean" then return tostring(v) end
  if t == "number" then
    if v ~= v or v == math.huge or v == -math.huge then return "null" end
    if math.type(v) == "integer" then return tostring(v) end
    return string.format("%.10g", v)
  end
  if t == "string" then
    return '"' .. v:gsub('[%c"\\]', function(c)
      local map = {['"'] = '\\"', ['\\'] = '\\\\', ['\n'] = '\\n', ['\t'] = '\\t', ['\r'] = '\\r'}
      return map[c] or string.format("\\u%04x", c:byte())
    end) .. '"'
  end
  if t ~= "table" then return "null" end
  local pad, pad_in = string.rep(indent, depth), string.rep(indent, depth + 1)
  local n = #v
  local is_array = n > 0 or next(v) == nil
  if is_array then
    for k in pairs(v) do
      if math.type(k) ~= "integer" or k < 1 or k > n then is_array = false break end
    end
  end
  local parts = {}
  if is_array then
    if n == 0 then return "[]" end
    for i = 1, n do parts[i] = pad_in .. encode(v[i], indent, depth + 1) end
    return "[\n" .. table.concat(parts, ",\n") .. "\n" .. pad .. "]"
  end
  local keys = {}
  for k in pairs(v) do keys[#keys + 1] = tostring(k) end
  table.sort(keys)
  for _, k in ipairs(keys) do
    local val = v[k]
    if val == nil then val = v[tonumber(k)] end
    parts[#parts + 1] = pad_in .. encode(k) .. ": " .. encode(val, indent, depth + 1)
  end
  return "{\n" .. table.concat(parts, ",\n") .. "\n" .. pad .. "}"
end

-- Writes value as JSON to <out_dir>/<name> (through a temporary file and a rename).
function M.write_json(name, value)
  local path = paddy.out_dir .. "/" .. name
  local tmp = path .. ".tmp"
  local f = assert(io.open(tmp, "w"))
  f:write(encode(value, "  ", 0), "\n")
  f:close()
  assert(os.rename(tmp, path))
  return path
end

-- The flat row of one finished slump run (mm, s). `run` is an entry of c:run().
function M.slump_row(run)
  local r, meta = run.result or {}, run.metadata or {}
  -- Edge of the spread from the profile: the outermost ring that is at least half covered.
  local edge_r, edge_h = 0 / 0, 0 / 0
  for _, b in ipairs(r.profile or {}) do
    if (b.coverage or 0) >= 0.5 then edge_r, edge_h = b.r_mm, b.h_mm end
  end
  return {
    slump_mm = r.slump_mm, slump_flow_mm = r.slump_flow_mm,
    slump_flow_ruler_mm = r.slump_flow_ruler_mm, slump_flow_area_mm = r.slump_flow_area_mm,
    circle_rms_mm = r.slump_flow_circle and r.slump_flow_circle.rms_mm,
    particles = r.particles, pile_particles = r.pile_particles, loose_particles = r.loose_particles,
    at_rest = r.at_rest, rest_time_s = r.rest_time_s, lift_stop_s = r.lift_stop_s,
    simulated_time_s = r.simulated_time_s, wall_time_s = meta.wall_time, threads = meta.threads,
    alpha = r.coarse_graining and r.coarse_graining.alpha,
    edge_ring_r_mm = edge_r, edge_ring_h_mm = edge_h,
    fill_solid_fraction = r.fill_solid_fraction,
    core_solid_fraction = r.fill_structure and r.fill_structure.solid_fraction,
    core_neighbours = r.fill_structure and r.fill_structure.neighbours,
    core_share_10_neighbours = r.fill_structure and r.fill_structure.neighbours_10_or_more,
  }
end

-- "1m23s" for a duration in seconds.
function M.duration(s)
  if not s or s ~= s then return "n/a" end
  s = math.floor(s + 0.5)
  if s >= 3600 then return string.format("%dh%02dm%02ds", s // 3600, s % 3600 // 60, s % 60) end
  if s >= 60 then return string.format("%dm%02ds", s // 60, s % 60) end
  return string.format("%ds", s)
end

-- A comma-separated list of seeds as positive integers; errors name the setting's value (at the
-- caller's line).
function M.seed_list(text)
  local seeds = M.numbers(text, "seeds") or error("seeds is empty", 2)
  for k, s in ipairs(seeds) do
    seeds[k] = math.tointeger(s) or error("seeds: " .. s .. " is not an integer", 2)
    if seeds[k] < 1 then error("seeds: " .. s .. " must be positive", 2) end
  end
  return seeds
end

-- A value for a CSV cell (nil → empty).
function M.cell(v)
  if v == nil then return "" end
  if type(v) == "number" and v ~= v then return "" end
  return v
end

-- CSV rows of records: one row per record, its fields in the order of cols (nil → empty, booleans
-- as true/false), appended to rows (a new list when nil); returns rows.
function M.cells(records, cols, rows)
  rows = rows or {}
  for _, r in ipairs(records) do
    local line = {}
    for k, col in ipairs(cols) do
      local v = r[col]
      if type(v) == "boolean" then v = tostring(v) end
      line[k] = M.cell(v)
    end
    rows[#rows + 1] = line
  end
  return rows
end

-- ln Γ(x), x > 0 (Lanczos, g = 7, 9 terms; relative error ~1e-15).
local LANCZOS = {0.99999999999980993, 676.5203681218851, -1259.1392167224028, 771.32342877765313,
                 -176.61502916214059, 12.507343278686905, -0.13857109526572012, 9.9843695780195716e-6,
                 1.5056327351493116e-7}
local function log_gamma(x)
  if x < 0.5 then return math.log(math.pi / math.abs(math.sin(math.pi * x))) - log_gamma(1 - x) end
  x = x - 1
  local a = LANCZOS[1]
  local t = x + 7.5
  for i = 2, 9 do a = a + LANCZOS[i] / (x + i - 1) end
  return 0.5 * math.log(2 * math.pi) + (x + 0.5) * math.log(t) - t + math.log(a)
end

-- Continued fraction of the incomplete beta function (modified Lentz; Numerical Recipes §6.4).
local function beta_cf(a, b, x)
  local tiny, eps = 1e-300, 1e-15
  local qab, qap, qam = a + b, a + 1, a - 1
  local c, d = 1, 1 - qab * x / qap
  if math.abs(d) < tiny then d = tiny end
  d = 1 / d
  local h = d
  for m = 1, 500 do
    local m2 = 2 * m
    local aa = m * (b - m) * x / ((qam + m2) * (a + m2))
    d = 1 + aa * d; if math.abs(d) < tiny then d = tiny end
    c = 1 + aa / c; if math.abs(c) < tiny then c = tiny end
    d = 1 / d
    h = h * d * c
    aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2))
    d = 1 + aa * d; if math.abs(d) < tiny then d = tiny end
    c = 1 + aa / c; if math.abs(c) < tiny then c = tiny end
    d = 1 / d
    local del = d * c
    h = h * del
    if math.abs(del - 1) < eps then break end
  end
  return h
end

-- Regularised incomplete beta function I_x(a, b).
function M.incomplete_beta(x, a, b)
  if x <= 0 then return 0 end
  if x >= 1 then return 1 end
  local bt = math.exp(log_gamma(a + b) - log_gamma(a) - log_gamma(b) + a * math.log(x) + b * math.log(1 - x))
  if x < (a + 1) / (a + b + 2) then return bt * beta_cf(a, b, x) / a end
  return 1 - bt * beta_cf(b, a, 1 - x) / b
end

-- Upper tail P(F > f) of Fisher's F with (d1, d2) degrees of freedom.
function M.f_pvalue(f, d1, d2)
  if not (f == f) or d1 <= 0 or d2 <= 0 then return 0 / 0 end
  if f <= 0 then return 1 end
  return M.incomplete_beta(d2 / (d2 + d1 * f), d2 / 2, d1 / 2)
end

-- Two-sided P(|T| > |t|) of Student's t with nu degrees of freedom.
function M.t_pvalue(t, nu)
  if not (t == t) or nu <= 0 then return 0 / 0 end
  return M.incomplete_beta(nu / (nu + t * t), nu / 2, 0.5)
end

-- One-way ANOVA of groups (lists of numbers): F = MS_between / MS_within, p = P(F_{k-1, N-k} > F).
function M.one_way_anova(groups)
  local k, n, total = 0, 0, 0
  for _, g in ipairs(groups) do
    if #g > 0 then k, n = k + 1, n + #g end
    for _, v in ipairs(g) do total = total + v end
  end
  if k < 2 or n <= k then return {groups = k, runs = n} end
  local grand = total / n
  local ssb, ssw = 0, 0
  for _, g in ipairs(groups) do
    if #g > 0 then
      local m = M.mean_std(g)
      ssb = ssb + #g * (m - grand) ^ 2
      for _, v in ipairs(g) do ssw = ssw + (v - m) ^ 2 end
    end
  end
  local df_b, df_w = k - 1, n - k
  local F = ssw > 0 and (ssb / df_b) / (ssw / df_w) or math.huge
  return {groups = k, runs = n, ss_between = ssb, ss_within = ssw, df_between = df_b, df_within = df_w,
          F = F, p = ssw > 0 and M.f_pvalue(F, df_b, df_w) or 0}
end

-- Welch's t test of two groups: {t, df, p, difference = mean(a) − mean(b), se}.
function M.welch(a, b)
  local ma, sa, na = M.mean_std(a)
  local mb, sb, nb = M.mean_std(b)
  if na < 2 or nb < 2 then return {difference = ma - mb} end
  local va, vb = sa * sa / na, sb * sb / nb
  local se = math.sqrt(va + vb)
  if se == 0 then return {difference = ma - mb, se = 0} end
  local t = (ma - mb) / se
  local df = (va + vb) ^ 2 / (va * va / (na - 1) + vb * vb / (nb - 1))
  return {difference = ma - mb, se = se, t = t, df = df, p = M.t_pvalue(t, df)}
end

return M
