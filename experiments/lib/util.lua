-- Small helpers shared by the Lua experiments: rest criterion, output files, CSV input, number
-- lists in parameters, and gnuplot pictures (PNG via pngcairo, run with os.execute).
local M = {}

-- RMS translational speed of the particles, mass-weighted: v = sqrt(2 KE_trans / M). The
-- rotational part is left out: the rest criterion asks whether the mud still flows, and a
-- sphere spinning in place (held by its neighbours) does not move the pile. Every sphere has the
-- mud's density, so its mass is proportional to r^3 and the weights need no density.
-- With `top`, only the spheres wholly below z = top (z + r <= top: what a strike-off at that
-- level keeps).
function M.rms_speed(sim, top)
  local v = sim:velocities()
  local radii = sim:radii()
  local zs
  if top then zs = select(3, sim:xyz()) end
  local sum, mass = 0, 0
  for i = 1, #v do
    if not zs or zs[i] + radii[i] <= top then
      local m = radii[i] ^ 3
      local w = v[i]
      sum = sum + m * (w[1] * w[1] + w[2] * w[2] + w[3] * w[3])
      mass = mass + m
    end
  end
  if mass <= 0 then return 0 end
  return math.sqrt(sum / mass)
end

-- Total mass of the particles: Σ ρ 4/3 π r³ (one density).
function M.total_mass(sim, density)
  local m = 0
  for _, r in ipairs(sim:radii()) do m = m + density * 4 / 3 * math.pi * r ^ 3 end
  return m
end

-- Whether a sphere of vertical speed vz goes up with a wall rising at `speed`: faster than half of
-- it (stuck to the wall, not just pushed or left behind).
function M.moving_with(vz, speed)
  return vz > 0.5 * speed
end

-- Mud carried by a rising wall: the spheres for which inside(x, y, z, r) holds that move with it
-- (M.moving_with). → {mass_g = Σ ρ 4/3 π r³ in grams (the simulated spheres: coarse graining keeps
-- the density), count =}
function M.carried(sim, inside, speed, density)
  local xs, ys, zs = sim:xyz()
  local radii = sim:radii()
  local v = sim:velocities()
  local count, mass = 0, 0
  for i = 1, #xs do
    local r = radii[i]
    if inside(xs[i], ys[i], zs[i], r) and M.moving_with(v[i][3], speed) then
      count = count + 1
      mass = mass + 4 / 3 * math.pi * r ^ 3 * density
    end
  end
  return {mass_g = mass * 1000, count = count}
end

-- Path inside the output directory.
function M.out(name)
  return paddy.out_dir .. "/" .. name
end

-- `path` as an absolute path (relative paths are taken from the working directory), for values
-- handed to campaign jobs, which run in their own directories.
function M.absolute(path)
  if path:sub(1, 1) == "/" then return path end
  local pipe = assert(io.popen("pwd", "r"))
  local cwd = pipe:read("l")
  pipe:close()
  return cwd .. "/" .. path
end

-- Creates a directory (and its parents) if it does not exist; returns it.
function M.mkdir(dir)
  os.execute("mkdir -p " .. M.shell_quote(dir))
  return dir
end

-- Writes `text` to `path` atomically: a temporary file beside it, then a rename, so a full disk,
-- `ulimit -f` or a kill never leaves a half-written file under the real name (an earlier file
-- stays). Every failure is an error naming the file and the cause. Returns path.
function M.write_file(path, text)
  local tmp = path .. ".tmp"
  local f, err = io.open(tmp, "wb")
  if not f then error("cannot write '" .. path .. "': " .. tostring(err), 2) end
  local ok, werr = f:write(text)
  local closed, cerr = f:close()  -- the buffered rest is written here: it can fail too
  if not ok or not closed then
    os.remove(tmp)
    error("cannot write '" .. path .. "' (temporary '" .. tmp .. "'): " .. tostring(werr or cerr), 2)
  end
  local renamed, rerr = os.rename(tmp, path)
  if not renamed then
    os.remove(tmp)
    error("cannot write '" .. path .. "': " .. tostring(rerr), 2)
  end
  return path
end

-- Writes rows (arrays of numbers) as whitespace-separated columns, with a header comment.
function M.write_columns(name, header, rows)
  local lines = {"# " .. header}
  for _, row in ipairs(rows) do
    local cells = {}
    for k, v in ipairs(row) do cells[k] = string.format("%.9g", v) end
    lines[#lines + 1] = table.concat(cells, " ")
  end
  return M.write_file(M.out(name), table.concat(lines, "\n") .. "\n")
end

-- A CSV cell: numbers as %.9g; text in double quotes (quotes doubled, RFC 4180) when it holds a
-- comma, a quote or a line break, so a text can never add a column or a row.
local function csv_cell(v)
  if type(v) == "number" then return string.format("%.9g", v) end
  local text = tostring(v)
  if text:find('[,"\r\n]') then return '"' .. text:gsub('"', '""') .. '"' end
  return text
end

-- Writes a CSV file with a header line.
function M.write_csv(name, columns, rows)
  local header = {}
  for k, c in ipairs(columns) do header[k] = csv_cell(c) end
  local lines = {table.concat(header, ",")}
  for _, row in ipairs(rows) do
    local cells = {}
    for k, v in ipairs(row) do cells[k] = csv_cell(v) end
    lines[#lines + 1] = table.concat(cells, ",")
  end
  return M.write_file(M.out(name), table.concat(lines, "\n") .. "\n")
end

-- Reads a CSV file with a header line into an array of {column = number or string}. Lines are
-- split by the design-of-experiments library's CSV reader (paddy.doe csv_fields): a field in
-- double quotes may hold commas and doubled quotes, as write_csv writes them; blanks around an
-- unquoted field are dropped; an unterminated quote is an error naming the file and line.
function M.read_csv(path)
  local doe = require("paddy.doe")
  local f, err = io.open(path, "r")
  if not f then error("cannot read CSV file '" .. path .. "': " .. tostring(err), 2) end
  local header, rows = nil, {}
  local line_no = 0
  for line in f:lines() do
    line_no = line_no + 1
    line = line:gsub("\r$", "")
    if line:match("%S") and not line:match("^%s*#") then
      local ok, cells = pcall(doe.csv_fields, {line = line, where = path .. " line " .. line_no})
      if not ok then
        f:close()
        error(cells, 2)
      end
      if not header then
        header = cells
      else
        local row = {}
        for k, name in ipairs(header) do row[name] = tonumber(cells[k]) or cells[k] end
        row._line = line_no
        rows[#rows + 1] = row
      end
    end
  end
  f:close()
  if not header then error("CSV file '" .. path .. "' is empty", 2) end
  return rows, header
end

-- "cone=none, max_time=0.5, speeds_rpm=5;10" → {cone = "none", max_time = 0.5, speeds_rpm = "5,10"}:
-- name=value items separated by commas; numbers and true/false converted; a ";" inside a value
-- stands for a comma (list parameters). "" → {}. An item that is not name=value is an error
-- naming the parameter.
function M.assignments(text, what)
  local out = {}
  for item in tostring(text or ""):gmatch("[^,]+") do
    if item:match("%S") then
      local name, value = item:match("^%s*([%w_]+)%s*=%s*(.-)%s*$")
      if not name or value == "" then error(what .. ": '" .. item .. "' is not name=value", 2) end
      if tonumber(value) then
        out[name] = math.tointeger(tonumber(value)) or tonumber(value)
      elseif value == "true" or value == "false" then
        out[name] = value == "true"
      else
        out[name] = (value:gsub(";", ","))
      end
    end
  end
  return out
end

-- "5, 10,20" → {5, 10, 20}; error naming the parameter on anything else.
function M.numbers(text, what)
  local list = {}
  for item in tostring(text):gmatch("[^,;%s]+") do
    local v = tonumber(item)
    if not v then error(what .. ": '" .. item .. "' is not a number", 2) end
    list[#list + 1] = v
  end
  if #list == 0 then error(what .. " is empty", 2) end
  return list
end

-- Runs a gnuplot script (text) written to <stem>.gp inside the output directory; the picture
-- is <stem>.png. Returns the PNG path, or nil and a message when gnuplot fails (pictures are
-- optional: the measurements do not depend on them).
-- Text as one shell word (single quotes; for os.execute and io.popen).
function M.shell_quote(text)
  return "'" .. tostring(text):gsub("'", "'\\''") .. "'"
end

-- Text as a gnuplot string constant: single quotes (gnuplot runs `commands` in double-quoted
-- strings, never in single-quoted ones), a quote doubled, a line break (which would end the
-- gnuplot command and start another) a blank.
function M.gnuplot_text(text)
  return "'" .. tostring(text):gsub("'", "''"):gsub("[\r\n]", " ") .. "'"
end

function M.gnuplot(stem, script)
  local gp = M.out(stem .. ".gp")
  local png = M.out(stem .. ".png")
  M.write_file(gp, "set terminal pngcairo size 900,700 noenhanced font 'sans,11'\n" ..
                   "set output " .. M.gnuplot_text(png) .. "\n" .. script .. "\n")
  local ok = os.execute(string.format("gnuplot %s > %s 2>&1", M.shell_quote(gp), M.shell_quote(M.out(stem .. ".log"))))
  if not ok then
    local msg = "gnuplot failed on " .. gp .. " (see " .. M.out(stem .. ".log") .. ")"
    io.stderr:write("warning: ", msg, "\n")
    return nil, msg
  end
  os.remove(M.out(stem .. ".log"))
  return png
end

-- Volume of a sim:fill region of type cone or cylinder (axis +z).
function M.region_volume(region)
  if region.type == "cylinder" then return math.pi * region.radius ^ 2 * region.height end
  if region.type == "cone" then
    local a, b = region.radius_bottom, region.radius_top
    return math.pi * region.height / 3 * (a * a + a * b + b * b)
  end
  error("region type '" .. tostring(region.type) .. "' is not one of cone, cylinder", 2)
end

-- Radius of a cone or cylinder region at height `h` above its base.
function M.region_radius_at(region, h)
  if region.type == "cylinder" then return region.radius end
  return region.radius_bottom + (region.radius_top - region.radius_bottom) * h / region.height
end

-- The part of a cone or cylinder region at least `margin` from its walls, floor and top, measured
-- horizontally for a cone's slanted wall: the same type, `margin` less in radius at every height.
function M.inner_region(region, margin)
  local b = region.base
  local inner = {type = region.type, base = {b[1], b[2], b[3] + margin}, height = region.height - 2 * margin}
  if region.type == "cylinder" then
    inner.radius = region.radius - margin
  else
    inner.radius_bottom = M.region_radius_at(region, margin) - margin
    inner.radius_top = M.region_radius_at(region, region.height - margin) - margin
  end
  return inner
end

-- The closing lines of an experiment on stdout: where result.json is, then the pictures that were
-- drawn (names in `order`, looked up in `pictures`; missing ones skipped), one per line.
function M.print_outputs(pictures, order)
  print("results     " .. M.out("result.json"))
  local shown = {}
  for _, name in ipairs(order) do
    if pictures[name] then shown[#shown + 1] = pictures[name] end
  end
  if #shown > 0 then print("pictures    " .. table.concat(shown, "\n            ")) end
end

-- Mean of values[i] for i in [first, last].
function M.mean(values, first, last)
  local s, n = 0, 0
  for i = first or 1, last or #values do
    s = s + values[i]
    n = n + 1
  end
  return n > 0 and s / n or 0 / 0
end

-- Sample standard deviation of the same range.
function M.std(values, first, last)
  local m = M.mean(values, first, last)
  local s, n = 0, 0
  for i = first or 1, last or #values do
    s = s + (values[i] - m) ^ 2
    n = n + 1
  end
  return n > 1 and math.sqrt(s / (n - 1)) or 0
end

return M
