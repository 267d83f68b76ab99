-- Two virtual tests, one material: the yield stress from the vane start-up test
-- (experiments/rheometer.lua, peak torque and the vane relation of Nguyen & Boger 1983) against the
-- yield stress the slump implies (experiments/slump.lua, Schowalter & Christensen 1998 cone
-- model), for the same mud at several parameter sets (default: the JKR surface energy at the low,
-- centre and high levels of the reference's Table 3), each with several seeds.
-- Documentation: docs/validation.md §6 and §6.1 (the depth series).
--
--   paddy run experiments/validation/yield_stress.lua --out results/validation/yield_stress \
--       [--set surface_energies=0.02,0.06,0.1 --set seeds=1,2 --set slump_diameter=0.012 ...]
--
-- The runs are jobs of a campaign (docs/campaign.md) in <out>/campaign; a rerun skips the finished
-- ones. Per set: each seed's ratio τ_vane / τ_slump (the two tests of one seed share nothing but
-- the seed number), then mean ± std (n − 1) over the seeds of τ_vane, τ_slump and the ratio, and
-- whether the mean ratio is within `target` (25 %) of 1. Outputs in --out: ys_runs.csv,
-- ys_summary.csv, yield_stress_study.json, ys_ratio.png, result.json.
--
-- Vane depth series (vane_fill_levels, e.g. 0.102,0.12,0.15): the start-up test at each fill level
-- (the same blades, so a different overburden above them; the cup at least as high as the fill).
-- Per set the Mohr–Coulomb line τ_peak = c + σ_v tanφ by least squares (lib/mohr_coulomb.lua) against
-- the mean vertical stress at the blades' mid-height σ_v = ρ_p φ g z (φ the run's measured fill
-- solid fraction, z the depth of the mid-height below the fill level): per seed, then mean ± std of
-- c, tanφ and c / τ_slump over the seeds, and pooled over the seeds with the standard errors of c
-- and tanφ; c counts as determined (and can be within target) when the pooled c > 2 se(c). Also
-- the shallowest level's τ_vane / τ_slump. The columns of ys_runs.csv then hold the vane at
-- reference_fill_level. With janssen_lateral_ratio = K > 0 also the fit against Janssen's
-- σ_v (the cup wall carrying part of the weight; lib/mohr_coulomb.lua). When the vanes measured
-- the stresses on their sheared surface during the start-up (rheometer.lua startup_stress_every,
-- lib/vane_stress.lua) also the lines at failure, from the contact forces at the peak: τ_peak against
-- the torque-weighted normal stress σ_n there ("failure"), and the side's own shear stress against
-- its normal stress σ_rr ("side"), and the static reading, τ_peak against σ_n as the vane started
-- ("static"). Extra outputs: ys_depth_runs.csv, ys_depth_fit.csv, ys_depth.png.
--
-- More seeds for a finished study: with_studies = its output directory (several: comma-separated)
-- and seeds = the new seeds only. The finished study's rows are read back from its
-- yield_stress_study.json (yield_stress_rows.lua; the design must be the same and no seed may
-- repeat, checked before anything runs), and every statistic is over all the seeds, as if one study
-- had run them (to the 10 digits its JSON keeps); the JSON lists the pooled studies.
local util = require("lib.util")
local mohr_coulomb = require("lib.mohr_coulomb")
local report = require("report")
local ys_jobs = require("yield_stress_jobs")
local ys_rows = require("yield_stress_rows")

local P = paddy.parameters{
  {name = "parameter", default = "jkr_surface_energy", description = "the mud parameter that differs between the sets"},
  {name = "values", default = "", description = "its values (comma-separated); empty: low, centre, high of table_parameter in table3_pb_levels.csv"},
  {name = "table_parameter", default = "jkr_surface_energy_mud", description = "the parameter's name in table3_pb_levels.csv (H7)"},
  {name = "seeds", default = "1,2", description = "seeds of each set (comma-separated, at least 2 for a std); empty with with_studies: run nothing, read those studies again"},
  {name = "slump_diameter", default = 0.014, unit = "m", min = 0.001, max = 0.04, description = "sphere diameter of the slump runs"},
  {name = "rheometer_diameter", default = 0.012, unit = "m", min = 0.001, max = 0.02, description = "sphere diameter of the rheometer runs"},
  {name = "slump_set", default = "", description = "extra slump.lua parameters for every run, e.g. 'max_time=4'"},
  {name = "rheometer_set", default = "", description = "extra rheometer.lua parameters for every run, e.g. 'startup_rpm=1'"},
  {name = "vane_fill_levels", default = "", description = "vane depth series: fill levels [m] of the rheometer runs (comma-separated, at least 2; empty: one run at rheometer.lua's fill level)"},
  {name = "reference_fill_level", default = 0.12, unit = "m", min = 0.01, max = 1, description = "with vane_fill_levels: the level whose vane fills ys_runs.csv's vane columns (rheometer.lua's default fill)"},
  {name = "janssen_lateral_ratio", default = 0, min = 0, max = 10, description = "with vane_fill_levels: also fit against Janssen's vertical stress with this lateral stress ratio K (0: no such fit)"},
  {name = "janssen_wall_friction", default = 0.6, min = 0, max = 10, description = "with janssen_lateral_ratio: the wall friction coefficient of the cup (lib/mud.lua's mud-steel sliding friction)"},
  {name = "with_studies", default = "", description = "finished studies of the same design (their output directories, comma-separated) whose seeds pool with this study's: more seeds without running the old ones again"},
  {name = "target", default = 0.25, min = 0, max = 10, description = "agreement target: |mean ratio − 1| within this"},
  {name = "max_parallel", default = 1, type = "integer", min = 1, max = 256, description = "runs at once"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each run"},
  {name = "max_attempts", default = 1, type = "integer", min = 1, max = 10, description = "attempts per job (the runs are deterministic)"},
  {name = "reference_dir", default = "", description = "shared/reference directory (empty: beside the source tree)"},
  {name = "campaign_dir", default = "", description = "campaign directory (empty: <out>/campaign)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys (empty: hash of the paddy executable)"},
  {name = "pictures", default = true, description = "draw ys_ratio.png with gnuplot"},
}

-- The parameter sets.
local values = report.numbers(P.values, "values")
local levels = {}
if values then
  for k, v in ipairs(values) do levels[k] = {label = string.format("%s = %g", P.parameter, v), value = v} end
else
  local path = report.reference_dir(P.reference_dir) .. "/table3_pb_levels.csv"
  for _, row in ipairs(util.read_csv(path)) do
    if row.parameter == P.table_parameter then
      for _, l in ipairs({"low", "center", "high"}) do
        levels[#levels + 1] = {label = l, value = row[l]}
      end
    end
  end
  if #levels == 0 then error(path .. ": no row for parameter '" .. P.table_parameter .. "' (give values= or table_parameter=)") end
end
-- No seeds of its own (seeds empty) with with_studies: the study runs nothing and reads the pooled
-- studies again (e.g. a finished study with this version's fits).
local seeds = (P.seeds:match("^%s*$") and P.with_studies ~= "") and {} or report.seed_list(P.seeds)
local dir = report.script_dir()
local slump_extra, rheo_extra = ys_jobs.extras(P.parameter, P.slump_set, P.rheometer_set)
-- The depth series: fill levels of the vane runs (false: one run at rheometer.lua's fill level, the
-- job parameters and keys as before the series existed).
local fill_levels = report.numbers(P.vane_fill_levels, "vane_fill_levels") or false
-- rheometer.lua's default cup_height, read from its parameter table (no copy that could go stale).
local function rheometer_default(name)
  local path = dir .. "/../rheometer.lua"
  local f = assert(io.open(path, "r"), "cannot read " .. path)
  local text = f:read("a")
  f:close()
  local v = text:match('name = "' .. name .. '", default = ([%d%.eE+-]+)')
  if not tonumber(v) then error(string.format("%s: no numeric default of parameter '%s' found", path, name), 0) end
  return tonumber(v)
end
local RHEOMETER_CUP_HEIGHT = rheometer_default("cup_height")
if fill_levels then
  if #fill_levels < 2 then error("vane_fill_levels: a depth series needs at least 2 fill levels, got " .. P.vane_fill_levels) end
  if rheo_extra.fill_level then error("rheometer_set must not set fill_level when vane_fill_levels is given") end
  for k = 2, #fill_levels do
    if not (fill_levels[k] > fill_levels[k - 1]) then error("vane_fill_levels = " .. P.vane_fill_levels .. ": must increase strictly") end
  end
end

-- Finished studies to pool with this one (with_studies), checked before anything runs.
local pooled_in = ys_rows.load_studies(P, {levels = levels, seeds = seeds, fill_levels = fill_levels})

local c = report.campaign(P, P.max_attempts)
local jobs = {}
for li, l in ipairs(levels) do
  for _, s in ipairs(seeds) do
    local sp = ys_jobs.params(P.slump_diameter, P.parameter, l.value, slump_extra)
    local rp = ys_jobs.params(P.rheometer_diameter, P.parameter, l.value, rheo_extra)
    if fill_levels then
      for fi, f in ipairs(fill_levels) do
        local cup = math.max(tonumber(rheo_extra.cup_height) or RHEOMETER_CUP_HEIGHT, f)
        local rpf = report.merge(rp, {fill_level = f, cup_height = cup})
        jobs[#jobs + 1] = {level = li, seed = s, test = "vane", fill = fi,
                           key = c:submit{script = dir .. "/../rheometer.lua", params = rpf, seed = s}}
      end
    else
      jobs[#jobs + 1] = {level = li, seed = s, test = "vane", key = c:submit{script = dir .. "/../rheometer.lua", params = rp, seed = s}}
    end
    jobs[#jobs + 1] = {level = li, seed = s, test = "slump", key = c:submit{script = dir .. "/../slump.lua", params = sp, seed = s}}
  end
end
io.stderr:write(string.format("yield_stress: %d sets x %d seeds x (1 slump + %d vane) = %d runs\n", #levels, #seeds,
                              fill_levels and #fill_levels or 1, #jobs))
local results = #jobs > 0 and c:run() or {}

-- Every run becomes a row: one per set and seed (ys_runs.csv) and, with a depth series, one per
-- set, seed and fill level (ys_depth_runs.csv). The statistics below read only these rows, so the
-- seeds of finished studies (with_studies) pool with this study's own.
local reference_fill
if fill_levels then
  for fi, f in ipairs(fill_levels) do if math.abs(f - P.reference_fill_level) < 1e-9 then reference_fill = fi end end
end
local by = {}  -- by[level][seed] = {slump = entry, vane = entry, depth = {[fill index] = entry}}
local failed = 0
for i, run in ipairs(results) do
  local j = jobs[i]
  by[j.level] = by[j.level] or {}
  by[j.level][j.seed] = by[j.level][j.seed] or {depth = {}}
  if run.status == "done" then
    local e = {result = run.result, wall = run.metadata and run.metadata.wall_time}
    if j.fill then
      by[j.level][j.seed].depth[j.fill] = e
      if j.fill == reference_fill then by[j.level][j.seed].vane = e end
    else
      by[j.level][j.seed][j.test] = e
    end
  else
    failed = failed + 1
    io.stderr:write(string.format("yield_stress: %s, seed %d, %s%s failed: %s\n", levels[j.level].label, j.seed, j.test,
                                  j.fill and string.format(" at fill level %g m", fill_levels[j.fill]) or "", tostring(run.error)))
  end
end

local run_of, depth_of = {}, {}  -- run_of[level][seed] = row; depth_of[level][seed][fill index] = row
for li, l in ipairs(levels) do
  run_of[li], depth_of[li] = {}, {}
  for _, s in ipairs(seeds) do
    local e = by[li] and by[li][s] or {depth = {}}
    run_of[li][s] = ys_rows.run_row(l, s, e.slump, e.vane)
    if fill_levels then
      depth_of[li][s] = {}
      for fi, f in ipairs(fill_levels) do depth_of[li][s][fi] = ys_rows.depth_row(l, s, f, fi, e.depth[fi], e.slump, P) end
    end
  end
end

-- Finished studies of the same design pooled in (their rows as they wrote them).
local all_seeds, pooled_studies = ys_rows.pool(pooled_in, {levels = levels, seeds = seeds, fill_levels = fill_levels, run_of = run_of,
                                                            depth_of = depth_of})

local run_rows, runs, summary, sum_rows = {}, {}, {}, {}
for li, l in ipairs(levels) do
  local tv, ts, ratios = {}, {}, {}
  for _, s in ipairs(all_seeds) do
    local row = run_of[li][s]
    -- Each test's mean over the seeds that ran it: a depth series without the reference level has
    -- no vane here, and its fits still compare with the slumps.
    if row.slump_yield_stress_Pa then ts[#ts + 1] = row.slump_yield_stress_Pa end
    if row.vane_yield_stress_Pa then tv[#tv + 1] = row.vane_yield_stress_Pa end
    if row.ratio then ratios[#ratios + 1] = row.ratio end
    runs[#runs + 1] = row
  end
  local s = {set = l.label, value = l.value, seeds = #ratios}
  s.vane_yield_stress_Pa = {report.mean_std(tv)}
  s.slump_yield_stress_Pa = {report.mean_std(ts)}
  s.ratio = {report.mean_std(ratios)}
  s.vane_yield_stress_Pa = {mean = s.vane_yield_stress_Pa[1], std = s.vane_yield_stress_Pa[2], values = tv}
  s.slump_yield_stress_Pa = {mean = s.slump_yield_stress_Pa[1], std = s.slump_yield_stress_Pa[2], values = ts}
  s.ratio = {mean = s.ratio[1], std = s.ratio[2], values = ratios}
  -- Without a vane at the reference level (a depth series without it) there is no ratio: the
  -- agreement is undetermined (nil: an empty cell), not "false".
  if #ratios > 0 then s.within_target = math.abs(s.ratio.mean - 1) <= P.target end
  summary[#summary + 1] = s
  sum_rows[#sum_rows + 1] = {l.label, l.value, #ratios, report.cell(s.vane_yield_stress_Pa.mean), report.cell(s.vane_yield_stress_Pa.std),
                             report.cell(s.slump_yield_stress_Pa.mean), report.cell(s.slump_yield_stress_Pa.std),
                             report.cell(s.ratio.mean), report.cell(s.ratio.std),
                             s.within_target == nil and "" or tostring(s.within_target)}
end
local run_cols = {"set", "value", "seed", "slump_mm", "slump_flow_mm", "fill_solid_fraction", "slump_yield_stress_Pa",
                  "slump_at_rest", "vane_peak_torque_Nm", "vane_peak_angle_deg", "vane_peak_reached", "vane_yield_stress_Pa", "ratio",
                  "slump_wall_s", "vane_wall_s"}
report.cells(runs, run_cols, run_rows)
util.write_csv("ys_runs.csv", run_cols, run_rows)
util.write_csv("ys_summary.csv", {"set", "value", "seeds", "vane_Pa", "vane_std_Pa", "slump_Pa", "slump_std_Pa", "ratio", "ratio_std",
                                  "within_target"}, sum_rows)

-- The depth series: per set the Mohr–Coulomb line of the vane's peak stress against the overburden
-- at the blades' mid-height, per seed and pooled; c / τ_slump; the shallowest level against the slump.
-- The lines from the stresses measured on the sheared surface (lib/mohr_coulomb.lua envelope): at
-- failure, from those at the peak; and the static reading, the peak against the normal stress the
-- vane started in (what validation/vane_fill_stress.lua reads from the fills run again).
local AT_PEAK = {{name = "failure", sigma = "sigma_n_peak_Pa", tau = "vane_yield_stress_Pa", what = "against sigma_n measured at the peak"},
                 {name = "side", sigma = "sigma_rr_peak_Pa", tau = "shear_side_peak_Pa", what = "the side's shear against its sigma_rr at the peak"},
                 {name = "static", sigma = "sigma_n_start_Pa", tau = "vane_yield_stress_Pa", what = "against sigma_n measured as the vane starts"}}
local depth_runs, depth = {}, nil
local measured_at_peak = false  -- some vane measured its stresses at the peak
if fill_levels then
  depth = {fill_levels = fill_levels, reference_fill_level = reference_fill and P.reference_fill_level or nil, sets = {}}
  local drows, frows = {}, {}
  local function ms(v)
    local m, sd = report.mean_std(v)
    return {mean = m, std = sd, values = v}
  end
  local measured_of, slump_of_set = {}, {}  -- per set: the AT_PEAK lines' points, τ_slump per seed
  for li, l in ipairs(levels) do
    -- Per set the lines against the hydrostatic and (janssen_lateral_ratio > 0) Janssen's
    -- overburden, per seed and pooled over the seeds (lib/mohr_coulomb.lua envelope).
    local points, janssen_points, shallow, slump_of = {}, {}, {}, {}
    local measured = {}
    for _, e in ipairs(AT_PEAK) do measured[e.name] = {} end
    for _, s in ipairs(all_seeds) do
      slump_of[s] = run_of[li][s].slump_yield_stress_Pa
      for fi in ipairs(fill_levels) do
        local row = depth_of[li][s][fi]
        if row.vane_yield_stress_Pa then
          if row.sigma_n_peak_Pa then measured_at_peak = true end
          points[#points + 1] = {seed = s, sigma = row.sigma_v_Pa, tau = row.vane_yield_stress_Pa}
          if row.sigma_janssen_Pa then janssen_points[#janssen_points + 1] = {seed = s, sigma = row.sigma_janssen_Pa, tau = row.vane_yield_stress_Pa} end
          if row.ratio_to_slump then shallow[#shallow + 1] = row.ratio_to_slump end
        end
        for _, e in ipairs(AT_PEAK) do
          if row[e.sigma] and row[e.tau] then
            local m = measured[e.name]
            m[#m + 1] = {seed = s, sigma = row[e.sigma], tau = row[e.tau]}
          end
        end
        depth_runs[#depth_runs + 1] = row
      end
    end
    measured_of[li], slump_of_set[li] = measured, slump_of
    local slump = summary[li].slump_yield_stress_Pa
    local function line(pts)
      return mohr_coulomb.envelope{points = pts, seeds = all_seeds, slump_of = slump_of, slump_mean = slump.mean, target = P.target}
    end
    local ds = line(points)
    ds.set, ds.value, ds.slump_yield_stress_Pa = l.label, l.value, slump
    ds.shallow_over_slump = ms(shallow)
    ds.shallow_within_target = #shallow > 0 and math.abs(ds.shallow_over_slump.mean - 1) <= P.target
    if #janssen_points > 0 then
      local j = line(janssen_points)
      for k, ps in ipairs(ds.per_seed) do ps.janssen_fit, ps.janssen_fit_error = j.per_seed[k].fit, j.per_seed[k].fit_error end
      ds.janssen = {lateral_ratio = P.janssen_lateral_ratio, wall_friction = P.janssen_wall_friction, c_Pa = j.c_Pa,
                    c_over_slump = j.c_over_slump, pooled = j.pooled, pooled_error = j.pooled_error}
    end
    local pooled = ds.pooled
    depth.sets[li] = ds
    frows[#frows + 1] = {l.label, l.value, #ds.c_Pa.values, report.cell(pooled and pooled.c), report.cell(pooled and pooled.se_c),
                         report.cell(pooled and pooled.tan_phi), report.cell(pooled and pooled.se_tan_phi),
                         report.cell(pooled and pooled.r2), report.cell(ds.c_Pa.mean), report.cell(ds.c_Pa.std),
                         report.cell(ds.tan_phi.mean), report.cell(ds.tan_phi.std), report.cell(ds.slump_yield_stress_Pa.mean),
                         report.cell(ds.c_over_slump.mean), report.cell(ds.c_over_slump.std), report.cell(ds.pooled_c_over_slump),
                         tostring(ds.c_determined), tostring(ds.c_within_target), report.cell(ds.shallow_over_slump.mean), report.cell(ds.shallow_over_slump.std),
                         tostring(ds.shallow_within_target),
                         report.cell(ds.janssen and ds.janssen.pooled and ds.janssen.pooled.c),
                         report.cell(ds.janssen and ds.janssen.pooled and ds.janssen.pooled.se_c),
                         report.cell(ds.janssen and ds.janssen.pooled and ds.janssen.pooled.tan_phi),
                         report.cell(ds.janssen and ds.janssen.c_over_slump.mean),
                         report.cell(ds.janssen and ds.janssen.c_over_slump.std)}
  end
  if measured_at_peak then
    for li, ds in ipairs(depth.sets) do
      for _, e in ipairs(AT_PEAK) do
        ds[e.name] = mohr_coulomb.envelope{points = measured_of[li][e.name], slump_of = slump_of_set[li],
                                           slump_mean = ds.slump_yield_stress_Pa.mean, target = P.target}
        local env = ds[e.name]
        for _, cell in ipairs({report.cell(env.pooled and env.pooled.c), report.cell(env.pooled and env.pooled.se_c),
                               report.cell(env.pooled and env.pooled.tan_phi), report.cell(env.c_over_slump.mean),
                               report.cell(env.c_over_slump.std), report.cell(env.pooled_c_over_slump), tostring(env.c_within_target)}) do
          frows[li][#frows[li] + 1] = cell
        end
      end
    end
  end
  local dcols = {"set", "value", "seed", "fill_level", "cup_height", "depth_mid_m", "fill_solid_fraction", "bulk_density", "sigma_v_Pa",
                 "sigma_janssen_Pa",
                 "particles", "peak_torque_Nm", "peak_angle_deg", "peak_reached", "vane_yield_stress_Pa", "ratio_to_slump", "wall_s"}
  local fcols = {"set", "value", "seeds", "c_pooled_Pa", "c_pooled_se_Pa", "tan_phi_pooled", "tan_phi_pooled_se",
                 "r2_pooled", "c_seed_mean_Pa", "c_seed_std_Pa", "tan_phi_seed_mean", "tan_phi_seed_std",
                 "slump_Pa", "c_over_slump", "c_over_slump_std", "c_pooled_over_slump", "c_determined", "c_within_target",
                 "shallow_over_slump", "shallow_over_slump_std", "shallow_within_target", "c_janssen_pooled_Pa",
                 "c_janssen_pooled_se_Pa", "tan_phi_janssen_pooled", "c_janssen_over_slump",
                 "c_janssen_over_slump_std"}
  if measured_at_peak then
    for _, col in ipairs({"sigma_v_measured_Pa", "sigma_n_start_Pa", "sigma_n_peak_Pa", "sigma_rr_peak_Pa", "shear_side_peak_Pa",
                          "side_torque_share"}) do dcols[#dcols + 1] = col end
    for _, e in ipairs(AT_PEAK) do
      for _, col in ipairs({"c_pooled_Pa", "c_pooled_se_Pa", "tan_phi_pooled", "c_over_slump", "c_over_slump_std", "c_pooled_over_slump",
                            "c_within_target"}) do fcols[#fcols + 1] = e.name .. "_" .. col end
    end
  end
  report.cells(depth_runs, dcols, drows)
  util.write_csv("ys_depth_runs.csv", dcols, drows)
  util.write_csv("ys_depth_fit.csv", fcols, frows)
end

local doc = {parameter = P.parameter, seeds = all_seeds, pooled_studies = pooled_studies, slump_diameter = P.slump_diameter, rheometer_diameter = P.rheometer_diameter,
             slump_set = P.slump_set, rheometer_set = P.rheometer_set, target = P.target, runs = runs, summary = summary,
             depth_series = depth, depth_runs = fill_levels and depth_runs or nil,
             failed = failed, finished = os.date("!%Y-%m-%dT%H:%M:%SZ")}
report.write_json("yield_stress_study.json", doc)

local pictures = {}
if P.pictures then
  local rows = {}
  for k, s in ipairs(summary) do rows[k] = {k, s.ratio.mean, s.ratio.std, s.vane_yield_stress_Pa.mean, s.slump_yield_stress_Pa.mean} end
  util.write_columns("ys_ratio.dat", "set ratio ratio_std vane_Pa slump_Pa", rows)
  local xt = {}
  for k, s in ipairs(summary) do xt[k] = string.format("'%s' %d", s.set, k) end
  pictures.ratio = util.gnuplot("ys_ratio", string.format([[
set title 'Yield stress: vane start-up / slump (Schowalter-Christensen), mean +- std over seeds'
set xlabel '%s'; set ylabel 'tau_vane / tau_slump'; set grid; set key top left
set xrange [0.5:%d.5]; set yrange [0:*]; set xtics (%s)
plot '%s' using 1:2:3 with yerrorbars pt 7 ps 1.5 title 'ratio', 1 lc rgb 'black' title 'agreement', \
     %g lc rgb 'gray' dt 2 title '+-%g %%', %g lc rgb 'gray' dt 2 notitle]],
    P.parameter, #summary, table.concat(xt, ", "), util.out("ys_ratio.dat"), 1 + P.target, 100 * P.target, 1 - P.target))
  if depth then
    local plots = {}
    local colors = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e"}
    for li, ds in ipairs(depth.sets) do
      local pts = {}
      for _, r in ipairs(depth_runs) do
        if r.set == ds.set and r.sigma_v_Pa then pts[#pts + 1] = {r.sigma_v_Pa, r.vane_yield_stress_Pa, r.seed} end
      end
      local f = util.write_columns("ys_depth_" .. li .. ".dat", "sigma_v_Pa vane_yield_stress_Pa seed", pts)
      local col = colors[(li - 1) % #colors + 1]
      for _, clause in ipairs(report.depth_plot_clauses(f, "1:2", col, ds.set, "vane peak", ds.pooled, ds.slump_yield_stress_Pa.mean)) do
        plots[#plots + 1] = clause
      end
    end
    pictures.depth = report.depth_picture("ys_depth", "Vane peak stress against the overburden at blade mid-height (Mohr-Coulomb fit, pooled seeds)",
                                          "sigma_v = rho_bulk g z [Pa]", "shear stress [Pa]", plots)
    -- With the stresses measured on the sheared surface: the peak against σ_n as the vane started
    -- (the static line, filled) and at the peak (the line at failure, open), ys_measured.png.
    if measured_at_peak then
      local mplots = {}
      for li, ds in ipairs(depth.sets) do
        local pts = {}
        for _, r in ipairs(depth_runs) do
          if r.set == ds.set and r.sigma_n_start_Pa and r.sigma_n_peak_Pa then
            pts[#pts + 1] = {r.sigma_n_start_Pa, r.sigma_n_peak_Pa, r.vane_yield_stress_Pa, r.seed}
          end
        end
        local f = util.write_columns("ys_measured_" .. li .. ".dat", "sigma_n_start_Pa sigma_n_peak_Pa vane_yield_stress_Pa seed", pts)
        local col = colors[(li - 1) % #colors + 1]
        for _, clause in ipairs(report.depth_plot_clauses(f, "1:3", col, ds.set, "as it starts", ds.static and ds.static.pooled,
                                                          ds.slump_yield_stress_Pa.mean)) do
          mplots[#mplots + 1] = clause
        end
        for _, clause in ipairs(report.depth_plot_clauses(f, "2:3", col, ds.set, "at the peak", ds.failure and ds.failure.pooled, nil, 6)) do
          mplots[#mplots + 1] = clause
        end
      end
      pictures.measured = report.depth_picture("ys_measured", "Vane peak stress against the normal stress measured on the sheared surface (pooled seeds)",
                                               "sigma_n [Pa]", "shear stress [Pa]", mplots)
    end
  end
end

-- "v +- e" for the console, the spread shown as n/a where it is undefined (report.plus_minus).
local function pm(v, e, digits) return report.plus_minus(v, e, digits, " +- n/a") end
-- A {mean, std, values} over seeds: its std is undefined for one seed.
local function pm_seeds(stat, digits)
  if not stat then return "-" end
  return pm(stat.mean, stat.values and #stat.values > 1 and stat.std or nil, digits)
end
local function num(v, digits) return (v == nil or v ~= v) and "-" or string.format("%." .. digits .. "f", v) end

print(string.format("%-10s %8s  %18s  %18s  %16s", "set", "value", "vane [Pa]", "slump [Pa]", "ratio"))
for _, s in ipairs(summary) do
  if s.within_target == nil then
    print(string.format("%-10s %8g  %18s  %18s  no vane at reference_fill_level = %g m: see the depth series",
                        s.set, s.value, "-", pm_seeds(s.slump_yield_stress_Pa, 1), P.reference_fill_level))
  else
    print(string.format("%-10s %8g  %18s  %18s  %16s %s", s.set, s.value, pm_seeds(s.vane_yield_stress_Pa, 1),
                        pm_seeds(s.slump_yield_stress_Pa, 1), pm_seeds(s.ratio, 3),
                        s.within_target and "within target" or "NOT within target"))
  end
end
if depth then
  print(string.format("vane depth series at fill levels %s m: tau_peak = c + sigma_v tan(phi) (pooled over seeds; per seed mean +- std)",
                      P.vane_fill_levels))
  print(string.format("%-10s %8s  %16s  %14s  %10s  %16s  %16s", "set", "value", "c [Pa]", "tan phi", "c/slump", "c/slump seeds",
                      "shallow/slump"))
  for _, ds in ipairs(depth.sets) do
    local p = ds.pooled or {}
    print(string.format("%-10s %8g  %16s  %14s  %10s  %16s  %16s", ds.set, ds.value, pm(p.c, p.se_c, 1),
                        pm(p.tan_phi, p.se_tan_phi, 3), num(ds.pooled_c_over_slump, 3), pm_seeds(ds.c_over_slump, 3),
                        pm_seeds(ds.shallow_over_slump, 3)))
    local j = ds.janssen
    if j and j.pooled then
      print(string.format("%-10s %8s  %16s  %14s  %10s  %16s  (Janssen K = %g, mu_w = %g)", "", "", pm(j.pooled.c, j.pooled.se_c, 1),
                          pm(j.pooled.tan_phi, j.pooled.se_tan_phi, 3), "", pm_seeds(j.c_over_slump, 3), j.lateral_ratio,
                          j.wall_friction))
    end
    for _, m in ipairs(AT_PEAK) do
      local e = ds[m.name]
      if e and e.pooled then
        print(string.format("%-10s %8s  %16s  %14s  %10s  %16s  (%s)", "", "", pm(e.pooled.c, e.pooled.se_c, 1),
                            pm(e.pooled.tan_phi, e.pooled.se_tan_phi, 3), num(e.pooled_c_over_slump, 3),
                            pm_seeds(e.c_over_slump, 3), m.what))
      end
    end
  end
end
paddy.result{summary = summary, runs = runs, depth_series = depth, failed = failed, pictures = pictures}
