-- Compares a campaign output directory with a reference one (campaign_kill.sh): every JSON file
-- under the directory parses; result.json, stage1.json and summary.json hold the same values as
-- the reference's; every job of the reference is complete here with the same results (the
-- metadata, with times and dates, is left out). Prints "same N jobs" or fails naming the difference.
local P = paddy.parameters{
  dir = {default = "", type = "string", description = "the directory to check"},
  reference = {default = "", type = "string", description = "the uninterrupted run's directory"},
}
local function q(s) return "'" .. s:gsub("'", "'\\''") .. "'" end
local function find(dir, pattern)
  local list = {}
  local p = assert(io.popen("find " .. q(dir) .. " -name " .. q(pattern) .. " -type f | sort"))
  for line in p:lines() do list[#list + 1] = line end
  p:close()
  return list
end
local function same(a, b, where)
  if type(a) ~= type(b) then error(where .. ": " .. tostring(a) .. " here, " .. tostring(b) .. " in the reference", 0) end
  if type(a) ~= "table" then
    if a ~= b then error(where .. ": " .. tostring(a) .. " here, " .. tostring(b) .. " in the reference", 0) end
    return
  end
  for k, v in pairs(a) do same(v, b[k], where .. "." .. tostring(k)) end
  for k, v in pairs(b) do if a[k] == nil then same(nil, v, where .. "." .. tostring(k)) end end
end

local parsed = 0
for _, f in ipairs(find(P.dir, "*.json")) do
  paddy.read_json(f)  -- an error names the file, line and column
  parsed = parsed + 1
end
local top = paddy.read_json(P.dir .. "/result.json")
if top.status ~= "complete" then error("result.json is not complete", 0) end
same(top.results, paddy.read_json(P.reference .. "/result.json").results, "result.json results")
for _, name in ipairs({"stage1.json", "summary.json"}) do
  same(paddy.read_json(P.dir .. "/" .. name), paddy.read_json(P.reference .. "/" .. name), name)
end
local jobs = 0
for _, ref in ipairs(find(P.reference .. "/campaign/jobs", "result.json")) do
  local key = ref:match("/jobs/([0-9a-f]+)/result.json$")
  local mine = P.dir .. "/campaign/jobs/" .. key .. "/result.json"
  local doc = paddy.read_json(mine)
  if doc.status ~= "complete" then error("job " .. key .. " is not complete", 0) end
  same(doc.results, paddy.read_json(ref).results, "job " .. key:sub(1, 12) .. " results")
  same(paddy.read_json(P.dir .. "/campaign/jobs/" .. key .. "/pile.json"),
       paddy.read_json(P.reference .. "/campaign/jobs/" .. key .. "/pile.json"), "job " .. key:sub(1, 12) .. " pile.json")
  jobs = jobs + 1
end
print(string.format("same %d jobs (%d JSON files parsed)", jobs, parsed))
paddy.result{jobs = jobs, parsed = parsed}
