-- Coarse-graining study: the slump test (experiments/slump.lua, calibrated mud) at several particle
-- sizes, each with several fill seeds (the seed moves the lattice jitter of the fill), to see
-- whether slump and slump-flow depend on the size beyond their run-to-run scatter.
-- Documentation: docs/validation.md.
--
--   paddy run experiments/validation/coarse_graining.lua --out results/validation/cg \
--       [--set diameters=0.010,0.014,0.020 --set seeds=1,2,3 --set max_parallel=1 --set threads_per_job=1]
--
-- The runs are jobs of a campaign (docs/campaign.md) in <out>/campaign; a rerun skips the finished
-- ones. Per size: mean ± standard deviation (n − 1) over the seeds; one-way ANOVA over the sizes
-- and Welch t tests of each size against the finest. Outputs in --out: cg_runs.csv,
-- cg_summary.csv, cg_tests.csv, cg_profiles.dat, cg_study.json, cg_sizes.png, cg_profiles.png,
-- result.json.
local util = require("lib.util")
local measured = require("lib.reference_measurement").slump()  -- slump and slump-flow of the calibration input
local report = require("report")

local P = paddy.parameters{
  {name = "diameters", default = "0.010,0.014,0.020", unit = "m", description = "particle diameters (comma-separated)"},
  {name = "seeds", default = "1,2,3", description = "fill seeds of each size (comma-separated, at least 2 for a std)"},
  {name = "max_parallel", default = 1, type = "integer", min = 1, max = 256, description = "slump runs at once"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each slump run"},
  {name = "max_attempts", default = 1, type = "integer", min = 1, max = 10, description = "attempts per job (the runs are deterministic)"},
  {name = "slump_set", default = "", description = "extra slump.lua parameters for every run, e.g. 'cone=none,max_time=0.5'"},
  {name = "slump_script", default = "../slump.lua", description = "the slump experiment (relative: beside this script)"},
  {name = "campaign_dir", default = "", description = "campaign directory (empty: <out>/campaign)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys (empty: hash of the paddy executable)"},
  {name = "pictures", default = true, description = "draw cg_sizes.png and cg_profiles.png with gnuplot"},
}

local diameters = report.numbers(P.diameters, "diameters") or error("diameters is empty")
local seeds = report.seed_list(P.seeds)
table.sort(diameters)
local script = P.slump_script
if not script:match("^/") then script = report.script_dir() .. "/" .. script end
local extra = report.assignments(P.slump_set, "slump_set")
if extra.particle_diameter or extra.seed then error("slump_set must not set particle_diameter or seed (use diameters, seeds)") end
local c, campaign_dir = report.campaign(P, P.max_attempts)
local jobs = {}
for _, d in ipairs(diameters) do
  for _, s in ipairs(seeds) do
    local params = report.merge({particle_diameter = d, progress = false}, extra)
    jobs[#jobs + 1] = {d = d, seed = s, key = c:submit{script = script, params = params, seed = s}}
  end
end
io.stderr:write(string.format("coarse_graining: %d sizes x %d seeds = %d runs, campaign %s\n",
                              #diameters, #seeds, #jobs, campaign_dir))
local t0 = os.time()
local results = c:run()

-- Collect: one row per run; per size the lists of each response.
local RESPONSES = {"slump_mm", "slump_flow_mm", "slump_flow_ruler_mm", "slump_flow_area_mm", "edge_ring_h_mm",
                   "fill_solid_fraction"}
local runs, failed, by_size, profiles = {}, {}, {}, {}
for i, run in ipairs(results) do
  local j = jobs[i]
  local e = {d_mm = j.d * 1000, seed = j.seed, key = run.key, status = run.status, error = run.error}
  if run.status == "done" then
    e.paddy = report.slump_row(run)
    by_size[j.d] = by_size[j.d] or {}
    for _, y in ipairs(RESPONSES) do
      by_size[j.d][y] = by_size[j.d][y] or {}
      local v = e.paddy[y]
      if v ~= nil and v == v then table.insert(by_size[j.d][y], v) end
    end
    profiles[j.d] = profiles[j.d] or {}
    table.insert(profiles[j.d], run.result.profile or {})
  else
    failed[#failed + 1] = e
    io.stderr:write(string.format("coarse_graining: d = %g mm, seed %d failed: %s\n", j.d * 1000, j.seed, tostring(run.error)))
  end
  runs[#runs + 1] = e
end

local run_cols = {"d_mm", "alpha", "seed", "slump_mm", "slump_flow_mm", "slump_flow_ruler_mm", "slump_flow_area_mm",
                  "circle_rms_mm", "edge_ring_r_mm", "edge_ring_h_mm", "particles", "pile_particles", "loose_particles",
                  "at_rest", "rest_time_s", "lift_stop_s", "simulated_time_s", "wall_time_s", "threads",
                  "fill_solid_fraction", "core_solid_fraction", "core_neighbours", "core_share_10_neighbours", "status", "key"}
local run_rows = {}
for _, e in ipairs(runs) do
  local p = e.paddy or {}
  local line = {e.d_mm, report.cell(p.alpha), e.seed}
  for k = 4, #run_cols - 2 do line[#line + 1] = report.cell(p[run_cols[k]]) end
  line[#line + 1] = e.status
  line[#line + 1] = e.key
  run_rows[#run_rows + 1] = line
end
util.write_csv("cg_runs.csv", run_cols, run_rows)

-- Per size: mean ± std; the mean wall time.
local summary, sum_rows = {}, {}
for _, d in ipairs(diameters) do
  local g = by_size[d]
  local s = {d_mm = d * 1000, alpha = d / 0.002, runs = g and #g.slump_mm or 0}
  local wall, parts = {}, {}
  for _, e in ipairs(runs) do
    if e.paddy and e.d_mm == d * 1000 then
      wall[#wall + 1] = e.paddy.wall_time_s or 0
      parts[#parts + 1] = e.paddy.particles or 0
    end
  end
  s.wall_time_s = (report.mean_std(wall))
  s.particles = (report.mean_std(parts))
  for _, y in ipairs(RESPONSES) do
    local m, sd = report.mean_std(g and g[y] or {})
    s[y] = {mean = m, std = sd, values = g and g[y] or {}}
  end
  summary[#summary + 1] = s
  sum_rows[#sum_rows + 1] = {s.d_mm, s.alpha, s.runs, report.cell(s.particles),
    report.cell(s.slump_mm.mean), report.cell(s.slump_mm.std), report.cell(s.slump_flow_mm.mean), report.cell(s.slump_flow_mm.std),
    report.cell(s.slump_flow_ruler_mm.mean), report.cell(s.slump_flow_ruler_mm.std),
    report.cell(s.slump_flow_area_mm.mean), report.cell(s.slump_flow_area_mm.std),
    report.cell(s.edge_ring_h_mm.mean), report.cell(s.edge_ring_h_mm.std),
    report.cell(s.fill_solid_fraction.mean), report.cell(s.fill_solid_fraction.std), report.cell(s.wall_time_s)}
end
util.write_csv("cg_summary.csv", {"d_mm", "alpha", "runs", "particles", "slump_mean_mm", "slump_std_mm", "slump_flow_mean_mm",
  "slump_flow_std_mm", "ruler_mean_mm", "ruler_std_mm", "area_mean_mm", "area_std_mm", "edge_ring_h_mean_mm", "edge_ring_h_std_mm",
  "fill_solid_fraction_mean", "fill_solid_fraction_std", "wall_time_mean_s"}, sum_rows)

-- Do the sizes agree within the scatter? One-way ANOVA over the sizes; Welch t of each size vs
-- the finest.
local tests, test_rows = {}, {}
for _, y in ipairs(RESPONSES) do
  local groups = {}
  for _, d in ipairs(diameters) do groups[#groups + 1] = by_size[d] and by_size[d][y] or {} end
  local a = report.one_way_anova(groups)
  tests[y] = {anova = a, versus_finest = {}}
  test_rows[#test_rows + 1] = {y, "anova over sizes", "", report.cell(a.F), report.cell(a.df_between), report.cell(a.df_within), report.cell(a.p)}
  for k = 2, #diameters do
    local w = report.welch(groups[k], groups[1])
    w.d_mm, w.versus_d_mm = diameters[k] * 1000, diameters[1] * 1000
    table.insert(tests[y].versus_finest, w)
    test_rows[#test_rows + 1] = {y, string.format("%g mm - %g mm (Welch)", diameters[k] * 1000, diameters[1] * 1000),
                                 report.cell(w.difference), report.cell(w.t), report.cell(w.df), "", report.cell(w.p)}
  end
end
util.write_csv("cg_tests.csv", {"response", "test", "difference", "F_or_t", "df1", "df2", "p"}, test_rows)

-- Mean profile h(r) per size (seeds share the ring bins of their size).
local prof_lines = {}
local f = assert(io.open(util.out("cg_profiles.dat"), "w"))
f:write("# per size a block: r_mm h_mean_mm h_std_mm coverage_mean (mean over the seeds)\n")
local blocks = 0
for _, d in ipairs(diameters) do
  local list = profiles[d]
  if list and #list > 0 then
    f:write(string.format("# d = %g mm\n", d * 1000))
    local nbins = math.huge
    for _, p in ipairs(list) do nbins = math.min(nbins, #p) end
    for b = 1, nbins do
      local hs, cs = {}, {}
      for _, p in ipairs(list) do hs[#hs + 1], cs[#cs + 1] = p[b].h_mm, p[b].coverage end
      local hm, hsd = report.mean_std(hs)
      local cm = report.mean_std(cs)
      f:write(string.format("%.6g %.6g %.6g %.6g\n", list[1][b].r_mm, hm, hsd, cm))
    end
    f:write("\n\n")
    blocks = blocks + 1
    prof_lines[#prof_lines + 1] = d
  end
end
f:close()

local doc = {
  study = "coarse graining: slump test at several particle sizes, several fill seeds each",
  diameters_mm = (function() local t = {} for k, d in ipairs(diameters) do t[k] = d * 1000 end return t end)(),
  seeds = seeds, slump_set = extra, runs = runs, summary = summary, tests = tests,
  finished = #runs - #failed, failed = #failed, campaign_wall_time_s = os.difftime(os.time(), t0),
}
report.write_json("cg_study.json", doc)

local pictures = {}
if P.pictures and #runs > #failed then
  local pts, means = {}, {}
  for _, e in ipairs(runs) do
    if e.paddy then pts[#pts + 1] = {e.d_mm, e.paddy.slump_mm, e.paddy.slump_flow_mm, e.paddy.slump_flow_ruler_mm, e.seed} end
  end
  for _, s in ipairs(summary) do
    if s.runs > 0 then
      means[#means + 1] = {s.d_mm, s.slump_mm.mean, s.slump_mm.std, s.slump_flow_mm.mean, s.slump_flow_mm.std,
                           s.slump_flow_ruler_mm.mean, s.slump_flow_ruler_mm.std}
    end
  end
  util.write_columns("cg_points.dat", "d_mm slump_mm slump_flow_mm ruler_mm seed", pts)
  util.write_columns("cg_means.dat", "d_mm slump_mean slump_std flow_mean flow_std ruler_mean ruler_std", means)
  local xr = string.format("set xrange [%g:%g]", diameters[1] * 1000 - 2, diameters[#diameters] * 1000 + 2)
  pictures.sizes = util.gnuplot("cg_sizes", string.format([[
set terminal pngcairo size 900,800 noenhanced font 'sans,11'
set output '%s'
set multiplot layout 2,1 title 'Slump test at several particle sizes (calibrated mud; points: seeds, bars: mean +- std)'
%s; set grid; set key outside right
set lmargin at screen 0.1; set rmargin at screen 0.7
set ylabel 'slump [mm]'
plot '%s' using 1:2 with points pt 6 ps 1.2 lc rgb '#888888' title 'runs', \
     '%s' using 1:2:3 with yerrorlines pt 7 lw 2 lc rgb '#cc6644' title 'mean +- std', \
     %g with lines dt 2 lc rgb 'black' title 'measured %g'
set ylabel 'slump-flow [mm]'; set xlabel 'particle diameter d [mm] (reference 2 mm)'
plot '%s' using 1:3 with points pt 6 ps 1.2 lc rgb '#888888' title 'runs (circle fit)', \
     '%s' using 1:4:5 with yerrorlines pt 7 lw 2 lc rgb '#cc6644' title 'circle fit', \
     '%s' using 1:6:7 with yerrorlines pt 5 lw 1 dt 3 lc rgb '#4477aa' title 'ruler (GB/T)', \
     %g with lines dt 2 lc rgb 'black' title 'measured %g'
unset multiplot]], util.out("cg_sizes.png"), xr, util.out("cg_points.dat"), util.out("cg_means.dat"),
    measured.slump_mm, measured.slump_mm, util.out("cg_points.dat"), util.out("cg_means.dat"), util.out("cg_means.dat"),
    measured.slump_flow_mm, measured.slump_flow_mm))
  if blocks > 0 then
    local plots = {}
    for k, d in ipairs(prof_lines) do
      plots[#plots + 1] = string.format("'%s' index %d using 1:2:3 with yerrorlines pt 7 ps 0.6 title 'd = %g mm'",
                                        util.out("cg_profiles.dat"), k - 1, d * 1000)
    end
    pictures.profiles = util.gnuplot("cg_profiles", string.format([[
set terminal pngcairo size 900,500 noenhanced font 'sans,11'
set output '%s'
set title 'Final pile profile h(r) (ring median of the cell maxima, mean +- std over the seeds)'
set xlabel 'r [mm]'; set ylabel 'h [mm]'; set grid; set key top right
plot %s]], util.out("cg_profiles.png"), table.concat(plots, ", \\\n     ")))
  end
end

print(string.format("%6s %5s %4s %16s %16s %16s %9s", "d[mm]", "alpha", "n", "slump [mm]", "flow [mm]", "ruler [mm]", "wall"))
for _, s in ipairs(summary) do
  print(string.format("%6.1f %5.1f %4d %8.1f +- %4.1f %8.1f +- %4.1f %8.1f +- %4.1f %9s", s.d_mm, s.alpha, s.runs,
                      s.slump_mm.mean, s.slump_mm.std, s.slump_flow_mm.mean, s.slump_flow_mm.std,
                      s.slump_flow_ruler_mm.mean, s.slump_flow_ruler_mm.std, report.duration(s.wall_time_s)))
end
for _, y in ipairs{"slump_mm", "slump_flow_mm"} do
  local a = tests[y].anova
  print(string.format("%s: one-way ANOVA over the sizes F = %s, p = %s", y, tostring(a.F), tostring(a.p)))
end

paddy.result{finished = doc.finished, failed = #failed, summary = summary, tests = tests,
             files = {runs_csv = util.out("cg_runs.csv"), summary_csv = util.out("cg_summary.csv"),
                      tests_csv = util.out("cg_tests.csv"), json = util.out("cg_study.json"), pictures = pictures}}
if #failed > 0 then
  error(string.format("coarse_graining: %d of %d runs failed (rerun to retry them; see cg_runs.csv)", #failed, #runs))
end
