-- Checks of experiments/validation/discovery_sensitivity.lua's output (the discovery.sensitivity
-- case): the confusability matrix is a matrix of cosines, the detectability columns follow from
-- a = g^T P g, the moves table agrees with the signatures, and the effects move what their physics
-- says: wall adhesion pulls on the cone more than on anything else, plastic adhesion (the largest
-- load's pull-off) keeps the pile from slumping.
local P = paddy.parameters{{name = "dir", default = "", description = "output directory of discovery_sensitivity.lua"}}
local function check(cond, fmt, ...)
  if not cond then error(string.format(fmt, ...), 2) end
end
local s = paddy.read_json(P.dir .. "/sensitivity.json")
local high = {}
for _, c in ipairs(s.candidates) do high[c.name] = c.high end
check(#s.groups >= 1, "no group of experiments")
for _, g in ipairs(s.groups) do
  local K = #g.candidates
  check(K == #s.candidates, "%s: %d candidates, expected %d", g.name, K, #s.candidates)
  for k = 1, K do
    check(math.abs(g.confusability[k][k] - 1) < 1e-9, "%s: c[%d][%d] = %.17g", g.name, k, k, g.confusability[k][k])
    for l = 1, K do
      local c = g.confusability[k][l]
      check(math.abs(c - g.confusability[l][k]) < 1e-12 and math.abs(c) <= 1 + 1e-12, "%s: c[%d][%d] = %.17g", g.name, k, l, c)
    end
    local c = g.candidates[k]
    check(c.a > 0, "%s %s: a = %g", g.name, c.name, c.a)
    check(math.abs(c.z_at_high - high[c.name] * math.sqrt(c.a)) < 1e-9 * c.z_at_high, "%s %s: z at high", g.name, c.name)
    check(math.abs(c.strength_at_z3 * math.sqrt(c.a) - 3) < 1e-9, "%s %s: strength at z = 3", g.name, c.name)
    check(c.absorbed_fraction >= 0 and c.absorbed_fraction <= 1, "%s %s: absorbed %g", g.name, c.name, c.absorbed_fraction)
  end
end
-- The moves table: signature x probe / noise sd, per observable.
local rows = {}
for line in io.lines(P.dir .. "/sensitivity_moves.csv") do rows[#rows + 1] = line end
check(#rows == #s.labels + 1, "moves table: %d rows for %d observables", #rows - 1, #s.labels)
local function move(name, i) return s.signatures[name][i] * s.probes[name] / s.noise_sd[i] end
local best = {}
for _, c in ipairs(s.candidates) do
  local bi, bv = nil, 0
  for i = 1, #s.labels do
    if math.abs(move(c.name, i)) > math.abs(bv) then bi, bv = i, move(c.name, i) end
  end
  best[c.name] = {label = s.labels[bi], move = bv}
end
local wa, pa = best.wall_adhesion, best.plastic_adhesion
check(wa.label:match("cone_force_N%.mean$") and wa.move > 3, "wall adhesion moves %s most (%+.2f noise sd): expected the cone force, up", wa.label, wa.move)
local slump_i
for i, l in ipairs(s.labels) do if l:match(" slump_mm$") then slump_i = i end end
check(move("plastic_adhesion", slump_i) < -3, "plastic adhesion moves the slump by %+.2f noise sd: expected a smaller slump", move("plastic_adhesion", slump_i))
print(string.format("ok: %d groups; wall adhesion %s %+.1f; plastic adhesion slump %+.1f noise sd", #s.groups, wa.label, wa.move,
                    move("plastic_adhesion", slump_i)))
paddy.result{ok = true}
