-- experiments.validation_vfs: checks what experiments/validation/vane_fill_stress.lua wrote (its CSV
-- files, printed to 9 digits) against its own runs: every fill is the study's (same spheres), the
-- measured overburden is a compression below the hydrostatic one (the cup wall carries part of the
-- weight), σ_n is the torque-weighted mean of the side and the ends, and the pooled line is the
-- least-squares line through (σ_n, τ_peak), recomputed here.
local util = require("lib.util")
local P = paddy.parameters{
  {name = "dir", default = "", description = "output directory of vane_fill_stress.lua"},
  {name = "runs", default = 4, type = "integer", description = "fills expected"},
  {name = "side_share", default = 0.78260869565, description = "(H/D)/(H/D + 1/3) of the study's vane"},
}
local checks = require("checks")
local check, near = checks.check, checks.near
local REL = 1e-7

local runs = util.read_csv(P.dir .. "/vfs_runs.csv")
check(#runs == P.runs, "%d fills, expected %d", #runs, P.runs)
local sx, sy, sxx, sxy, n = 0, 0, 0, 0, 0
for _, r in ipairs(runs) do
  check(r.same_fill == "true", "fill %s seed %s level %s is not the study's", r.set, tostring(r.seed), tostring(r.fill_level))
  check(r.sigma_v_Pa > 0 and r.sigma_v_Pa < 1.05 * r.sigma_v_hydrostatic_Pa,
        "measured overburden %g Pa against hydrostatic %g Pa", r.sigma_v_Pa, r.sigma_v_hydrostatic_Pa)
  near(r.measured_over_hydrostatic, r.sigma_v_Pa / r.sigma_v_hydrostatic_Pa, REL, "measured / hydrostatic")
  near(r.lateral_ratio, r.sigma_rr_Pa / r.sigma_v_Pa, REL, "lateral ratio")
  local s = P.side_share
  near(r.sigma_n_Pa, s * r.sigma_rr_Pa + (1 - s) * (r.sigma_zz_top_Pa + r.sigma_zz_bottom_Pa) / 2, REL, "sigma_n")
  local x, y = r.sigma_n_Pa, r.vane_yield_stress_Pa
  sx, sy, sxx, sxy, n = sx + x, sy + y, sxx + x * x, sxy + x * y, n + 1
end
local slope = (n * sxy - sx * sy) / (n * sxx - sx * sx)
local c = (sy - slope * sx) / n
local fit = util.read_csv(P.dir .. "/vfs_fit.csv")
check(#fit == 1, "%d sets in vfs_fit.csv, expected 1", #fit)
near(fit[1].tan_phi_pooled, slope, 1e-6, "pooled tan phi")
near(fit[1].c_pooled_Pa, c, 1e-6, "pooled c")
near(fit[1].c_pooled_over_slump, fit[1].c_pooled_Pa / fit[1].slump_Pa, 1e-6, "pooled c / slump")
paddy.result{ok = true}
