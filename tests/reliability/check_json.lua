-- Parses every JSON file given (paddy.read_json; an error names the file, line and column) and
-- prints "ok N". Used by the reliability scripts to prove that no JSON file was left half-written.
--   paddy run check_json.lua --set "files=a.json;b.json" [--set contains=TEXT --set in=a.json]
local P = paddy.parameters{
  files = {default = "", type = "string", description = "JSON files separated by ';'"},
}
local n = 0
for path in P.files:gmatch("[^;]+") do
  local doc = paddy.read_json(path)
  if type(doc) ~= "table" then error("JSON file '" .. path .. "' does not hold an object or array") end
  n = n + 1
end
print("ok " .. n)
paddy.result{parsed = n}
