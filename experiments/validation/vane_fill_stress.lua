-- The vane depth series read against the stress the vane really starts in: for a finished depth
-- study of validation/yield_stress.lua (its output directory: yield_stress_study.json), each
-- vane's fill is run again alone (rheometer.lua fill_only, the same parameters and seed, so the
-- same fill: checked by its sphere count and solid fraction), and the stresses around the vane
-- are measured from the contact forces (lib/vane_stress.lua: the overburden σ_v across the cup at
-- the blades' mid-height, σ_rr on the cylinder the blade tips sweep, σ_zz across its end discs,
-- their torque-weighted mean σ_n on the sheared surface). Per set, the Mohr–Coulomb line
-- τ_peak = c + σ_n tanφ (lib/mohr_coulomb.lua) per seed and pooled, beside the study's
-- hydrostatic fit: no lateral stress ratio or wall friction has to be assumed.
-- Documentation: docs/validation.md §6.6.
--
--   paddy run experiments/validation/vane_fill_stress.lua --out results/vfs --set study=<yield_stress output dir>
--
-- The fills are jobs of a campaign in <out>/campaign (campaign_dir); a rerun skips the finished
-- ones. Outputs in --out: vfs_runs.csv, vfs_fit.csv, vane_fill_stress.json, vfs_depth.png.
local util = require("lib.util")
local mohr_coulomb = require("lib.mohr_coulomb")
local report = require("report")
local ys_jobs = require("yield_stress_jobs")

local P = paddy.parameters{
  {name = "study", default = "", description = "output directory of a finished yield_stress.lua depth study (holds yield_stress_study.json)"},
  {name = "target", default = 0.25, min = 0, max = 10, description = "agreement target: |c / tau_slump - 1| within this"},
  {name = "max_parallel", default = 1, type = "integer", min = 1, max = 256, description = "runs at once"},
  {name = "threads_per_job", default = 1, type = "integer", min = 1, max = 256, description = "threads of each run"},
  {name = "campaign_dir", default = "", description = "campaign directory (empty: <out>/campaign)"},
  {name = "code_version", default = "", description = "fixed code version for the job keys (empty: hash of the paddy executable)"},
  {name = "pictures", default = true, description = "draw vfs_depth.png with gnuplot"},
}
if P.study == "" then error("vane_fill_stress: give study = the output directory of a yield_stress.lua depth study", 0) end
local study_file = P.study .. "/yield_stress_study.json"
local f = io.open(study_file, "r")
if not f then error("vane_fill_stress: study = " .. P.study .. ": no yield_stress_study.json there", 0) end
f:close()
local study = paddy.read_json(study_file)
if not study.depth_runs or not study.depth_series then
  error("vane_fill_stress: " .. study_file .. " has no depth series (run yield_stress.lua with vane_fill_levels)", 0)
end

-- One fill per vane of the study: the vane job's parameters (yield_stress_jobs.lua) and fill_only.
local dir = report.script_dir()
local _, rheo_extra = ys_jobs.extras(study.parameter, study.slump_set or "", study.rheometer_set or "")
local c = report.campaign(P, 1)
local rows = {}
for _, r in ipairs(study.depth_runs) do
  if r.vane_yield_stress_Pa then
    local params = report.merge(ys_jobs.params(study.rheometer_diameter, study.parameter, r.value, rheo_extra),
                                {fill_level = r.fill_level, cup_height = r.cup_height, fill_only = true})
    rows[#rows + 1] = {study = r, key = c:submit{script = dir .. "/../rheometer.lua", params = params, seed = r.seed}}
  end
end
io.stderr:write(string.format("vane_fill_stress: %d fills of %s\n", #rows, study_file))
local results = c:run()

-- Read each fill; a fill that is not the vane's (another code) is reported and left out.
local mismatched, failed = 0, 0
for k, row in ipairs(rows) do
  local run, r = results[k], row.study
  if run.status ~= "done" then
    failed = failed + 1
    io.stderr:write(string.format("vane_fill_stress: %s, seed %d, fill level %g m failed: %s\n", r.set, r.seed, r.fill_level, tostring(run.error)))
  else
    local fr = run.result
    row.fill_particles, row.fill_solid_fraction = fr.particles, fr.fill_solid_fraction
    row.same_fill = fr.particles == r.particles and math.abs(fr.fill_solid_fraction - r.fill_solid_fraction) <= 1e-9 * r.fill_solid_fraction
    row.fill_wall_s = run.metadata and run.metadata.wall_time
    if row.same_fill then
      row.stress = fr.fill_stress
    else
      mismatched = mismatched + 1
      io.stderr:write(string.format("vane_fill_stress: %s, seed %d, fill level %g m: the fill has %d spheres (solid fraction %.9g), the "
                                    .. "study's vane %d (%.9g): not the same fill (another code?); left out\n", r.set, r.seed,
                                    r.fill_level, fr.particles, fr.fill_solid_fraction, r.particles, r.fill_solid_fraction))
    end
  end
end

-- Per set: the line per seed and pooled against σ_n (lib/mohr_coulomb.lua), beside the study's
-- hydrostatic fit.
local sets, fit_rows = {}, {}
for _, ds in ipairs(study.depth_series.sets) do
  local slump_of = {}
  for _, ps in ipairs(ds.per_seed or {}) do slump_of[ps.seed] = ps.slump_yield_stress_Pa end
  local points = {}
  for _, row in ipairs(rows) do
    local r = row.study
    if r.set == ds.set and row.stress then
      points[#points + 1] = {seed = r.seed, sigma = row.stress.sheared_normal_Pa, tau = r.vane_yield_stress_Pa}
    end
  end
  local slump = ds.slump_yield_stress_Pa and ds.slump_yield_stress_Pa.mean
  local out = mohr_coulomb.envelope{points = points, slump_of = slump_of, slump_mean = slump, target = P.target}
  out.set, out.value, out.slump_yield_stress_Pa, out.hydrostatic = ds.set, ds.value, slump, ds.pooled
  sets[#sets + 1] = out
  local pooled = out.pooled
  fit_rows[#fit_rows + 1] = {ds.set, ds.value, #out.c_Pa.values, report.cell(pooled and pooled.c), report.cell(pooled and pooled.se_c),
                             report.cell(pooled and pooled.tan_phi), report.cell(pooled and pooled.se_tan_phi),
                             report.cell(pooled and pooled.r2), report.cell(out.c_Pa.mean), report.cell(out.c_Pa.std),
                             report.cell(slump), report.cell(out.c_over_slump.mean), report.cell(out.c_over_slump.std),
                             report.cell(out.pooled_c_over_slump), tostring(out.c_determined), tostring(out.c_within_target),
                             report.cell(ds.pooled and ds.pooled.c), report.cell(ds.pooled and ds.pooled.tan_phi)}
end

local run_records = {}
for _, row in ipairs(rows) do
  local r, st = row.study, row.stress or {}
  run_records[#run_records + 1] = {
    set = r.set, value = r.value, seed = r.seed, fill_level = r.fill_level, depth_mid_m = r.depth_mid_m, particles = r.particles,
    same_fill = row.same_fill, vane_yield_stress_Pa = r.vane_yield_stress_Pa, sigma_v_hydrostatic_Pa = r.sigma_v_Pa,
    sigma_v_janssen_Pa = r.sigma_janssen_Pa, sigma_v_Pa = st.sigma_v_Pa, sigma_rr_Pa = st.sigma_rr_Pa,
    sigma_zz_top_Pa = st.sigma_zz_top_Pa, sigma_zz_bottom_Pa = st.sigma_zz_bottom_Pa, lateral_ratio = st.lateral_ratio,
    sigma_n_Pa = st.sheared_normal_Pa, measured_over_hydrostatic = st.sigma_v_Pa and r.sigma_v_Pa and st.sigma_v_Pa / r.sigma_v_Pa,
    fill_wall_s = row.fill_wall_s}
end
local run_cols = {"set", "value", "seed", "fill_level", "depth_mid_m", "particles", "same_fill", "vane_yield_stress_Pa",
                  "sigma_v_hydrostatic_Pa", "sigma_v_janssen_Pa", "sigma_v_Pa", "measured_over_hydrostatic", "sigma_rr_Pa",
                  "lateral_ratio", "sigma_zz_top_Pa", "sigma_zz_bottom_Pa", "sigma_n_Pa", "fill_wall_s"}
local csv_rows = {}
report.cells(run_records, run_cols, csv_rows)
util.write_csv("vfs_runs.csv", run_cols, csv_rows)
util.write_csv("vfs_fit.csv", {"set", "value", "seeds", "c_pooled_Pa", "c_pooled_se_Pa", "tan_phi_pooled", "tan_phi_pooled_se", "r2_pooled",
                               "c_seed_mean_Pa", "c_seed_std_Pa", "slump_Pa", "c_over_slump", "c_over_slump_std",
                               "c_pooled_over_slump", "c_determined", "c_within_target", "c_hydrostatic_pooled_Pa",
                               "tan_phi_hydrostatic_pooled"}, fit_rows)
report.write_json("vane_fill_stress.json", {study = study_file, rheometer_diameter = study.rheometer_diameter, target = P.target,
                                            runs = run_records, sets = sets, mismatched = mismatched, failed = failed,
                                            finished = os.date("!%Y-%m-%dT%H:%M:%SZ")})

local pictures = {}
if P.pictures then
  local plots = {}
  local colors = {"#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e"}
  for k, s in ipairs(sets) do
    local pts = {}
    for _, r in ipairs(run_records) do
      if r.set == s.set and r.sigma_n_Pa then pts[#pts + 1] = {r.sigma_n_Pa, r.vane_yield_stress_Pa, r.sigma_v_hydrostatic_Pa} end
    end
    local file = util.write_columns("vfs_depth_" .. k .. ".dat", "sigma_n_Pa vane_yield_stress_Pa sigma_v_hydrostatic_Pa", pts)
    local col = colors[(k - 1) % #colors + 1]
    for _, clause in ipairs(report.depth_plot_clauses(file, "1:2", col, s.set, "against measured sigma_n", s.pooled, s.slump_yield_stress_Pa)) do
      plots[#plots + 1] = clause
    end
    plots[#plots + 1] = string.format("'%s' using 3:2 with points pt 6 ps 1.3 lc rgb '%s' title '%s: against rho_b g z'", file, col, s.set)
  end
  pictures.depth = report.depth_picture("vfs_depth", "Vane peak stress against the normal stress on the sheared surface, measured before the start-up",
                                        "normal stress [Pa]", "vane peak shear stress [Pa]", plots)
end

print(string.format("%-28s %18s %14s %16s %16s %20s", "set", "c [Pa]", "tan phi", "c/slump (pooled)", "c/slump seeds", "hydrostatic c [Pa]"))
for _, s in ipairs(sets) do
  local p, h = s.pooled or {}, s.hydrostatic or {}
  print(string.format("%-28s %7.1f +- %-7.1f %5.3f +- %-5.3f %16.3f %7.3f +- %-6.3f %20.1f", s.set, p.c or 0 / 0, p.se_c or 0 / 0,
                      p.tan_phi or 0 / 0, p.se_tan_phi or 0 / 0, s.pooled_c_over_slump or 0 / 0, s.c_over_slump.mean or 0 / 0,
                      s.c_over_slump.std or 0 / 0, h.c or 0 / 0))
end
if mismatched > 0 then print(string.format("%d fill(s) not the study's: left out (see stderr)", mismatched)) end
paddy.result{sets = sets, runs = run_records, mismatched = mismatched, failed = failed, pictures = pictures}
