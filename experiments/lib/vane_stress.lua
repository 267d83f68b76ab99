-- The stress state around a vane in its cup, measured from the contact forces (sim:measure_stress:
-- the force the packing carries across a surface, method of planes; docs/measurement.md). What the
-- Mohr–Coulomb reading of a vane depth series needs instead of an assumed overburden:
--
--   sigma_v_Pa        σ_zz across the cup's section at the blades' mid-height (axis to cup wall):
--                     the overburden that the hydrostatic (ρ_b g z) and Janssen formulas estimate
--   sigma_rr_Pa       σ_rr on the cylinder the blade tips sweep (r = D/2, over the blade height):
--                     the normal stress on the side of the sheared surface
--   sigma_zz_top_Pa,  σ_zz across the discs at the blades' top and bottom edges (r ≤ D/2, outside
--   sigma_zz_bottom_Pa  the shaft): the normal stress on the sheared ends
--   lateral_ratio     K = sigma_rr / sigma_v
--   sheared_normal_Pa the normal stress on the sheared surface weighted as the vane relation
--                     weights the shear stress in the torque: the side's share
--                     s = (H/D) / (H/D + m/6) (m = 2 ends; Nguyen & Boger 1983),
--                     σ_n = s σ_rr + (1 − s) (σ_top + σ_bottom) / 2
--   shear_rtheta_Pa   τ_rθ on the swept cylinder (at rest ≈ 0; while the vane turns, the side's shear)
--
-- The vane's own contacts count (sim:measure_stress walls = the vane): the spheres its blade tips
-- and edges push carry their load across these surfaces through the vane. The cup's contacts do
-- not: what the cup wall holds up (Janssen) is not carried by the packing across the mid-height.
local M = {}

-- vane: {diameter, height, bottom (z of the lower edge), shaft_radius, cup_diameter, sheared_ends,
-- wall (the vane's wall: index or name)}
function M.measure(sim, vane)
  local R, H, zb = vane.diameter / 2, vane.height, vane.bottom
  local zt = zb + H
  local rs = vane.shaft_radius or 0
  local m = vane.sheared_ends or 2
  local side, top, bottom, mid = table.unpack(sim:measure_stress{walls = vane.wall, surfaces = {
    {surface = "cylinder", radius = R, z_min = zb, z_max = zt},
    {surface = "disc", z = zt, r_min = rs, r_max = R},
    {surface = "disc", z = zb, r_min = rs, r_max = R},
    {surface = "disc", z = zb + H / 2, r_min = rs, r_max = vane.cup_diameter / 2},
  }})
  local s = (H / (2 * R)) / (H / (2 * R) + m / 6)
  local ends = m > 0 and (top.normal + bottom.normal) / 2 or 0
  return {
    sigma_v_Pa = mid.normal, sigma_rr_Pa = side.normal, sigma_zz_top_Pa = top.normal, sigma_zz_bottom_Pa = bottom.normal,
    lateral_ratio = mid.normal ~= 0 and side.normal / mid.normal or nil,
    side_share = s, sheared_normal_Pa = s * side.normal + (1 - s) * ends,
    shear_rtheta_Pa = side.shear,
    crossings = {side = side.crossings, top = top.crossings, bottom = bottom.crossings, mid = mid.crossings},
  }
end

-- The start-up's stresses at its peak: the mean of the samples within window_deg of the peak angle
-- (the nearest sample if none is), from rows {angle_deg, sigma_rr, shear_side, sigma_zz_top,
-- sigma_zz_bottom, sigma_n} (rheometer.lua's startup_stress.dat). With the side's resisting shear
-- τ_side: the side's torque τ_side · 2πR·H·R and its share of the peak torque (the vane relation
-- assumes it is `side_share`, M.measure; blade-tip contacts with the outer spheres are wall contacts
-- and not in τ_side).
function M.at_peak(rows, peak_deg, window_deg, vane, peak_torque)
  local picked = {}
  for _, r in ipairs(rows) do
    if math.abs(r[1] - peak_deg) <= window_deg then picked[#picked + 1] = r end
  end
  if #picked == 0 then
    local best
    for _, r in ipairs(rows) do
      if not best or math.abs(r[1] - peak_deg) < math.abs(best[1] - peak_deg) then best = r end
    end
    picked = {best}
  end
  local sum = {0, 0, 0, 0, 0, 0}
  for _, r in ipairs(picked) do
    for k = 1, 6 do sum[k] = sum[k] + r[k] end
  end
  local n = #picked
  local R, H = vane.diameter / 2, vane.height
  local out = {angle_deg = sum[1] / n, sigma_rr_Pa = sum[2] / n, shear_side_Pa = sum[3] / n, sigma_zz_top_Pa = sum[4] / n,
               sigma_zz_bottom_Pa = sum[5] / n, sigma_n_Pa = sum[6] / n, samples = n, window_deg = window_deg}
  out.side_torque_Nm = out.shear_side_Pa * 2 * math.pi * R * H * R
  if peak_torque and peak_torque ~= 0 then out.side_torque_share = out.side_torque_Nm / peak_torque end
  return out
end

return M
