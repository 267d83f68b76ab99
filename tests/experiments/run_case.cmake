# End-to-end cases of the Lua experiments (CTest experiments.<case>, see CMakeLists.txt):
#   cmake -DPADDY=<exe> -DCASE=<name> -DSOURCE=<source tree> -DHERE=<this dir> -DWORK=<dir> -P run_case.cmake
# Each case runs the built executable in a fresh work directory and checks the exit code and
# result.json (string(JSON), numbers compared with math(EXPR) on integers or with regexes).
cmake_minimum_required(VERSION 3.20)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

include(${CMAKE_CURRENT_LIST_DIR}/../case_helpers.cmake)

# results.<path...> of out/result.json into `var` (fatal if missing); result_length: an array's length.
function(result var)
  result_json(GET out value ${ARGN})
  set(${var} "${value}" PARENT_SCOPE)
endfunction()
function(result_length var)
  result_json(LENGTH out value ${ARGN})
  set(${var} "${value}" PARENT_SCOPE)
endfunction()

# Integer part of a decimal number (truncated toward zero), for math(EXPR) on whole units.
function(integer_part var value)
  string(REGEX MATCH "^-?[0-9]+" i "${value}")
  if(i STREQUAL "")
    message(FATAL_ERROR "'${value}' is not a number")
  endif()
  set(${var} "${i}" PARENT_SCOPE)
endfunction()

# A decimal number of millimetres (no exponent) as whole micrometres (truncated), for math(EXPR).
function(micrometres var value)
  if(NOT value MATCHES "^(-?)([0-9]+)(\\.([0-9]*))?$")
    message(FATAL_ERROR "'${value}' is not a plain decimal number")
  endif()
  set(sign "${CMAKE_MATCH_1}")
  set(whole "${CMAKE_MATCH_2}")
  set(frac "${CMAKE_MATCH_4}000")
  string(SUBSTRING "${frac}" 0 3 frac)
  string(REGEX REPLACE "^0+([0-9])" "\\1" frac "${frac}")
  math(EXPR um "${sign}(${whole} * 1000 + ${frac})")
  set(${var} "${um}" PARENT_SCOPE)
endfunction()

function(expect_file path)
  if(NOT EXISTS ${path})
    message(FATAL_ERROR "missing output file ${path}")
  endif()
endfunction()
# Every named file in ${WORK}/<dir>.
function(expect_outputs dir)
  foreach(f ${ARGN})
    expect_file(${WORK}/${dir}/${f})
  endforeach()
endfunction()
# out/result.json's count of failed runs is 0 (`what` names them in the message).
function(expect_none_failed what)
  result(failed failed)
  expect_number(${failed} EQUAL 0 "${what}")
endfunction()

# The miniature rheometer run of rheometer_mini and rheometer_confirm: ~600 spheres of 12 mm, a
# short start-up, three speeds up and two down, each until steady by a coarse criterion or 0.3 s.
set(rheometer_mini_args
    --set particle_diameter=0.012 --set speeds_rpm=20,40,80 --set max_step_time=0.3
    --set min_step_angle=30 --set window_angle=5 --set steady_windows=4 --set fit_unsteady=true
    --set startup_rpm=10 --set startup_angle=12
    --set settle_max_time=0.6 --set min_rest_time=0.1 --set sample_interval=0.005
    --set snapshot_interval=0 --set vane_diameter=0.05 --set vane_height=0.06
    --set vane_bottom=0.03 --set fill_level=0.12 --set cup_diameter=0.1 --set mud_density=1680)

# The tiny yield-stress study of validation_ys and validation_vfs (one set, 2 seeds, 40 mm spheres in
# the cone, a 4 degree start-up); each case adds its cup's sphere size.
set(ys_tiny --set values=0.06 --set seeds=1,2 --set slump_diameter=0.04
    "--set" "rheometer_set=startup_angle=4,settle_max_time=0.6,min_rest_time=0.1,insert_time=0.01"
    --set slump_set=max_time=0.3 --set code_version=test)

if(CASE STREQUAL "measure_binding")
  run_paddy(code se run ${HERE}/measure_binding.lua --out out --threads 1)
  expect_code(${code} 0)
  result(ok ok)
  expect_file(${WORK}/out/pics/top.png)
  expect_file(${WORK}/out/pics/top.pgm)

elseif(CASE MATCHES "^(rheology_share|fill_structure|pour|conventions|phases|mohr_coulomb_fit|tack_observables|surface_stress)$")
  # Library checks written in Lua (tests/experiments/<case>.lua): each raises an error on a wrong
  # answer and writes ok = true at the end.
  run_paddy(code se run ${HERE}/${CASE}.lua --out out --threads 1)
  expect_code(${code} 0)
  result(ok ok)

elseif(CASE STREQUAL "restitution_step")
  # The restitution example (docs/physics.md §3): both schemes, one restitution, two steps, 4 impacts each.
  run_paddy(code se run ${SOURCE}/experiments/examples/restitution_step.lua --out rs --set restitutions=0.13
            --set fractions=0.1,0.01 --set gaps=4 --set pictures=false)
  expect_code(${code} 0)
  expect_outputs(rs restitution_step.csv result.json)
  run_paddy(code se run ${HERE}/check_restitution_step.lua --set dir=${WORK}/rs --out out)
  expect_code(${code} 0)
  result(ok ok)

elseif(CASE STREQUAL "timestep_damping")
  run_paddy(code se run ${HERE}/timestep_damping.lua --out out --threads 1)
  expect_code(${code} 0)
  result(ok ok)
  # A strongly damped slump (e = 0.01) runs at the shortened step (0.804 x slump.lua's default 0.1)
  # and records it.
  run_paddy(code se run ${SOURCE}/experiments/slump.lua --out slump --threads 1 --set cone=none --set packing=lattice
            --set particle_diameter=0.03 --set max_time=0.05 --set pictures=false --set snapshot_interval=0
            --set progress=false --set mud_mud_restitution=0.01)
  expect_code(${code} 0)
  file(READ ${WORK}/slump/result.json doc)
  string(JSON fraction GET "${doc}" results time_step_fraction)
  string(JSON factor GET "${doc}" results time_step_damping_factor)
  expect_number(${fraction} LESS 0.0805 "time_step_fraction at e = 0.01")
  expect_number(${fraction} GREATER 0.0804 "time_step_fraction at e = 0.01")
  expect_number(${factor} LESS 0.805 "damping factor at e = 0.01")

elseif(CASE STREQUAL "measure_errors")
  # Bad input to a binding is an input error (exit 2) at the script's line.
  file(WRITE ${WORK}/bad.lua [=[
local sim = paddy.simulation{threads = 1}
local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
sim:add_particle{pos = {0, 0, 0.001}, radius = 0.001, material = m}
local ok = pcall(sim.measure_slump, sim, {cone_height = 0.3, quantile = 2})
assert(not ok, "quantile 2 accepted")
sim:measure_slump_flow{pixels = 0.001}
]=])
  run_paddy(code se run bad.lua --out out)
  expect_code(${code} 2)
  if(NOT se MATCHES "bad\\.lua:6:.*unknown option 'pixels'.*pixel")
    message(FATAL_ERROR "the error does not name bad.lua:6 and the option")
  endif()
  file(WRITE ${WORK}/hb.lua "local m = require('paddy.measure')\nm.herschel_bulkley{shear_rate = {1, 2}, stress = {1, 2}}\n")
  run_paddy(code se run hb.lua --out out2)
  expect_code(${code} 2)
  if(NOT se MATCHES "hb\\.lua:2:")
    message(FATAL_ERROR "the HB error does not name hb.lua:2")
  endif()

elseif(CASE STREQUAL "slump_free_rest")
  # The slump test ends once the pile has been at rest and the cone free of mud over
  # free_rest_window (default 0.1 s), before the lift has cleared the pile. The same run with the
  # rule off (0: the lift goes on until the cone is `clearance` above the pile, then min_rest_time
  # more) must be the same run, only longer: the early run's history is the prefix of the long
  # one's to the last bit (one thread, one seed), and nothing changes after the early end: the
  # slump stays within slump_tolerance and the cone is never loaded again. A rule that ended the
  # run while the pile still moved, or that changed the run before its end, fails here.
  # At 22 mm the pile is still moving when the cone is 20 mm above it; with a clearance of 80 mm
  # it comes to rest while the cone still rises, as the main job's does at 10 mm.
  set(free_rest_args ${SOURCE}/experiments/slump.lua --threads 1 --seed 2 --set particle_diameter=0.022
      --set settle_max_time=1.0 --set min_rest_time=0.2 --set max_time=4 --set snapshot_interval=0
      --set pictures=false --set progress=false --set clearance=0.08)
  run_paddy(code se run ${free_rest_args} --out early)
  expect_code(${code} 0)
  run_paddy(code se run ${free_rest_args} --out full --set free_rest_window=0)
  expect_code(${code} 0)
  result_json(GET early criterion rest_criterion)
  result_json(GET full criterion_full rest_criterion)
  if(NOT criterion STREQUAL "at_rest_cone_free" OR criterion_full STREQUAL "at_rest_cone_free")
    message(FATAL_ERROR "rest criteria '${criterion}' (expected at_rest_cone_free) and '${criterion_full}' (rule off)")
  endif()
  result_json(GET early t_early simulated_time_s)
  result_json(GET full t_full simulated_time_s)
  expect_number(${t_early} LESS ${t_full} "simulated time of the early end (the full run's ${t_full} s)")
  result_json(GET early carried mass_on_cone_g)
  expect_number(${carried} EQUAL 0 "mud on the cone at the early end")
  result_json(LENGTH early n_early history)
  result_json(LENGTH full n_full history)
  expect_number(${n_early} LESS ${n_full} "history samples of the early end")
  math(EXPR last_early "${n_early} - 1")
  foreach(k RANGE 0 ${last_early})
    foreach(key t slump_mm slump_flow_mm rms_speed cone_load_N)
      result_json(GET early a history ${k} ${key})
      result_json(GET full b history ${k} ${key})
      if(NOT a STREQUAL b)
        message(FATAL_ERROR "history row ${k}: ${key} ${a} (early end) differs from ${b} (rule off)")
      endif()
    endforeach()
  endforeach()
  result_json(GET early slump_end slump_mm)
  result_json(GET early load_end history ${last_early} cone_load_N)
  expect_number(${load_end} EQUAL 0 "load on the cone at the early end")
  micrometres(end_um ${slump_end})
  math(EXPR last_full "${n_full} - 1")
  foreach(k RANGE ${n_early} ${last_full})
    result_json(GET full load history ${k} cone_load_N)
    expect_number(${load} EQUAL 0 "load on the cone after the early end (row ${k})")
    result_json(GET full later history ${k} slump_mm)
    micrometres(later_um ${later})
    math(EXPR drift "${later_um} - ${end_um}")
    if(drift GREATER 1000 OR drift LESS -1000)
      message(FATAL_ERROR "row ${k}: the slump moved from ${slump_end} mm at the early end to ${later} mm: the pile was not at rest")
    endif()
  endforeach()
  result_json(GET full slump_full slump_mm)
  # The cone force is averaged while the mud loads the cone: the same however long the lift went on.
  foreach(key mean peak samples)
    result_json(GET early a cone_force_N ${key})
    result_json(GET full b cone_force_N ${key})
    if(NOT a STREQUAL b)
      message(FATAL_ERROR "cone_force_N.${key}: ${a} (early end) differs from ${b} (rule off)")
    endif()
  endforeach()
  message(STATUS "ok: early end at ${t_early} s of ${t_full} s, slump ${slump_end} / ${slump_full} mm")

elseif(CASE STREQUAL "slump_mini")
  # ~600 spheres of 22 mm (α = 11). Assertions a broken experiment fails:
  #  - slump > 20 mm: a cone that is not lifted, or a pile measured before it moved, gives ~0;
  #  - slump < 300 mm: some pile is left (the measure found the pile, not the plate);
  #  - slump-flow > 222 mm = the cone's bottom diameter + one particle: the footprint of mud
  #    still inside the cone is at most 200 mm, so more means the pile spread out;
  #  - all particles are still there, the history has samples and the pictures exist.
  # Run in the edem conventions (the default paddy path is run by rheometer_mini and validation_pb):
  # the reference's EDEM set, the explicit rolling torque, 0.2 T_R, and stdout says so.
  run_paddy(code se run ${SOURCE}/experiments/slump.lua --out out --threads 1 --seed 3
            --set particle_diameter=0.022 --set settle_max_time=1.0 --set min_rest_time=0.2
            --set max_time=4 --set history_interval=0.05 --set snapshot_interval=1 --set rest_speed=0.01
            --set contact_conventions=edem)
  expect_code(${code} 0)
  result(slump slump_mm)
  result(flow slump_flow_mm)
  result(ruler slump_flow_ruler_mm)
  result(n particles)
  result_length(nh history)
  # The user sees both responses and where the pictures are on stdout, the same numbers as result.json.
  string(REGEX MATCH "^[0-9]+" slump_int "${slump}")
  string(REGEX MATCH "slump +([0-9]+)\\.[0-9] mm" m "${LAST_STDOUT}")
  if(m)
    math(EXPR diff "${CMAKE_MATCH_1} - ${slump_int}")  # 0, or 1 where %.1f rounds up to the next integer
  endif()
  if(NOT m OR diff LESS 0 OR diff GREATER 1)
    message(FATAL_ERROR "stdout does not report the slump ${slump} mm:\n${LAST_STDOUT}")
  endif()
  foreach(pattern "model +conventions edem; material reference_edem" "step 0\\.2 T_R"
                  "slump-flow +[0-9]+\\.[0-9] mm +circle fit; ruler" "pictures +[^\n]*side_view\\.png" "slump_flow_top\\.png"
                  "ParaView +[^\n]*snapshots/particles\\.xmf")
    if(NOT LAST_STDOUT MATCHES "${pattern}")
      message(FATAL_ERROR "stdout lacks '${pattern}':\n${LAST_STDOUT}")
    endif()
  endforeach()
  expect_number(${slump} GREATER 20 "slump_mm")
  expect_number(${slump} LESS 300 "slump_mm")
  # The poured fill (lib/pour.lua) fills the cone to the rim. Under the edem conventions' explicit
  # rolling torque it may settle into a crystal (docs/validation.md §1.1 item 4: the torque stirs
  # the fill); the run must then say so. That the poured fill is random under Paddy's conventions
  # is asserted by discovery.slump_observables.
  result(packing packing)
  result(cryst fill_structure crystalline)
  result(phi fill_solid_fraction)
  result(hopper hopper_height_m)
  result(spread0 history 1 slump_flow_mm)
  if(NOT packing STREQUAL "poured")
    message(FATAL_ERROR "default fill: packing ${packing} (expected poured)")
  endif()
  if(cryst STREQUAL "ON" AND NOT LAST_STDERR MATCHES "warning: slump: the fill is crystalline")
    message(FATAL_ERROR "a crystalline fill without the warning:\n${LAST_STDERR}")
  endif()
  if(cryst STREQUAL "OFF" AND LAST_STDERR MATCHES "the fill is crystalline")
    message(FATAL_ERROR "the crystalline warning for a fill that is not:\n${LAST_STDERR}")
  endif()
  expect_number(${phi} GREATER 0.4 "fill_solid_fraction")
  expect_number(${phi} LESS 0.64 "fill_solid_fraction")
  expect_number(${hopper} GREATER 0.1 "hopper_height_m")
  expect_number(${spread0} GREATER 100 "history slump_flow_mm")
  # The settling stops by the rule of lib/pour.lua settled or its time limit, never by the old
  # rule's all spheres at rest (settle_rest_of = all). Under the edem conventions' explicit rolling
  # torque this fill creeps and reaches the 1 s limit; the paddy path comes to rest (rheometer_mini).
  result(settle_by settle_stopped_by)
  if(NOT settle_by MATCHES "^(fill_kinetic_energy|top_steady|settle_max_time)$")
    message(FATAL_ERROR "the settling stopped by '${settle_by}' (expected fill_kinetic_energy, top_steady or settle_max_time)")
  endif()
  # A settling time shorter than the pour's fall is refused at the script's line, with the minimum.
  run_paddy(code se run ${SOURCE}/experiments/slump.lua --out short --threads 1 --set particle_diameter=0.022
            --set settle_max_time=0.2)
  expect_code(${code} 2)
  if(NOT se MATCHES "slump\\.lua:[0-9]+: slump: settle_max_time = 0\\.2 s is too short.*allowed: settle_max_time >= [0-9.]+ s")
    message(FATAL_ERROR "the short settling is not refused with file, line and minimum:\n${se}")
  endif()
  expect_number(${flow} GREATER 222 "slump_flow_mm")
  expect_number(${ruler} GREATER 222 "slump_flow_ruler_mm")
  expect_number(${n} GREATER 300 "particles")
  expect_number(${nh} GREATER 5 "history samples")
  # Mass conservation: nothing is created or lost between the strike-off and the end; every
  # particle is either in the pile (its largest connected cluster) or counted as loose.
  result(filled filled)
  result(struck struck_off)
  result(in_pile pile_particles)
  result(loose loose_particles)
  math(EXPR after_strike "${filled} - ${struck}")
  math(EXPR at_end "${in_pile} + ${loose}")
  if(NOT after_strike EQUAL n OR NOT at_end EQUAL n)
    message(FATAL_ERROR "particles not conserved: filled ${filled} - struck ${struck} = ${after_strike}, "
                        "${n} before the lift, pile ${in_pile} + loose ${loose} = ${at_end} at the end")
  endif()
  # Most of the mud stays in one pile (a pile that falls apart, or a cluster search that splits it,
  # would leave a large loose share): loose < 10 %.
  math(EXPR loose_permille "1000 * ${loose} / ${n}")
  expect_number(${loose_permille} LESS 100 "loose particles [per mille]")
  # The slump is the cone height minus the pile height (300 mm - height): the two reported
  # numbers must add up to the cone height (integer parts: 299 or 300).
  result(pile_h pile_height_mm)
  integer_part(slump_i ${slump})
  integer_part(pile_i ${pile_h})
  math(EXPR cone_sum "${slump_i} + ${pile_i}")
  if(cone_sum LESS 299 OR cone_sum GREATER 300)
    message(FATAL_ERROR "slump ${slump} mm + pile height ${pile_h} mm = ${cone_sum}, not the cone height 300 mm")
  endif()
  # The pile only falls: the slump after the lift exceeds the slump of the filled cone before it
  # (which is at most a particle diameter or two: the fill reaches the rim).
  result(slump0 initial_slump_mm)
  expect_number(${slump0} LESS 45 "initial slump (filled cone)")
  expect_number(${slump} GREATER ${slump0} "slump after the lift vs before")
  # The profile describes the same pile: every ring's surface height is at most the pile's
  # highest point plus one particle diameter (a heap is highest near its axis), the rings hold
  # every particle of the pile (profile of the largest cluster), and no ring with mud lies beyond
  # the spread's radius plus two particle diameters (a ring's centre is half a bin from its
  # particles, whose edges may reach a diameter past the fitted circle of the footprint).
  result_length(nrings profile)
  math(EXPR last "${nrings} - 1")
  math(EXPR h_limit "${pile_i} + 22")
  integer_part(flow_i ${flow})
  math(EXPR r_limit "${flow_i} / 2 + 44")
  set(ring_sum 0)
  foreach(k RANGE ${last})
    result(h profile ${k} h_mm)
    result(r profile ${k} r_mm)
    result(np profile ${k} particles)
    expect_number(${h} LESS ${h_limit} "profile ring ${k} height [mm]")
    if(np GREATER 0)
      expect_number(${r} LESS ${r_limit} "radius of profile ring ${k} holding mud [mm]")
    endif()
    math(EXPR ring_sum "${ring_sum} + ${np}")
  endforeach()
  if(NOT ring_sum EQUAL in_pile)
    message(FATAL_ERROR "the profile's rings hold ${ring_sum} particles, the pile ${in_pile}")
  endif()
  result(alpha coarse_graining alpha)
  expect_number(${alpha} GREATER 10.9 "alpha")
  result(gamma coarse_graining scaled_params jkr_surface_energy)
  expect_number(${gamma} GREATER 1.05 "scaled surface energy")  # 11 x the reference's 0.096 J/m^2
  result(conv material conventions)
  result(tsf time_step_fraction)
  if(NOT conv STREQUAL "edem")
    message(FATAL_ERROR "result.json: conventions ${conv} (expected edem)")
  endif()
  expect_number(${tsf} GREATER 0.19999 "time_step_fraction (edem: 0.2)")
  expect_number(${tsf} LESS 0.20001 "time_step_fraction (edem: 0.2)")
  expect_outputs(out slump_flow_top.png slump_flow_top.pgm side_view.png slump_history.png snapshots/particles.xmf)

elseif(CASE STREQUAL "rheometer_mini")
  # ~600 spheres of 12 mm in the cup; three speeds, short steps. Bounds that hold for any correct
  # rheometer, whatever its step criterion (the vane geometry is set explicitly for them):
  #  - the vane feels a resisting torque at every speed (T > 0);
  #  - the torque is converted with the vane relation T = (pi D^3 / 2)(H/D + 1/3) tau (side and
  #    both ends sheared; docs/measurement.md): D = 0.05 m, H = 0.06 m give 3.0107e-4 m^3;
  #  - the stress is of the order of the mud's own scale. A cohesive granular mud at rest has one
  #    stress scale, its weight above the vane's mid-height: sigma = phi rho g h with rho = 1680
  #    kg/m^3, phi ~ 0.55, h = 0.12 - (0.03 + 0.06/2) = 0.06 m, so sigma ~ 540 Pa; the yield shear
  #    stress is mu_eff sigma plus cohesion with mu_eff ~ 0.1-1. tau = T / factor must lie within
  #    [sigma/100, 10 sigma] = [5, 5000] Pa: a torque in the wrong unit (N mm), about the wrong
  #    axis, or including the vane's own weight or inertia falls outside.
  # The run: a short start-up, three speeds up and two down, each until steady by a coarse
  # criterion or 0.3 s. Besides the bounds above: the torque list must follow speeds_rpm, every
  # step called steady must pass its own criterion, and the Herschel-Bulkley fit (told to use
  # unsteady steps too) must count the unsteady ones.
  run_paddy(code se run ${SOURCE}/experiments/rheometer.lua --out out --threads 1 --seed 3
            ${rheometer_mini_args})
  expect_code(${code} 0)
  # The cup's fill came to rest below the fill level once the pour had landed (lib/pour.lua
  # settled), before the time limit.
  result(settle_by settle_stopped_by)
  if(NOT settle_by STREQUAL "fill_kinetic_energy")
    message(FATAL_ERROR "the settling stopped by '${settle_by}' (expected fill_kinetic_energy)")
  endif()
  # The stresses around the vane from the contact forces (lib/vane_stress.lua): as it starts, a
  # compressive overburden of the weight's scale (~540 Pa hydrostatic, less with the wall's share),
  # a lateral ratio between 0 and 1.5 and the vane relation's side share (H/D)/(H/D + 1/3) = 0.7826;
  # at the start-up's peak the side carries a positive part of the torque, not more than all of it.
  result(sv fill_stress sigma_v_Pa)
  expect_number(${sv} GREATER 50 "overburden at mid-height [Pa]")
  expect_number(${sv} LESS 700 "overburden at mid-height [Pa]")
  result(k fill_stress lateral_ratio)
  expect_number(${k} GREATER 0 "lateral ratio")
  expect_number(${k} LESS 1.5 "lateral ratio")
  result(share fill_stress side_share)
  expect_number(${share} GREATER 0.78260 "side share of the vane relation")
  expect_number(${share} LESS 0.78261 "side share of the vane relation")
  result(n startup stress_at_peak samples)
  expect_number(${n} GREATER 0 "stress samples at the start-up's peak")
  result(side startup stress_at_peak side_torque_share)
  expect_number(${side} GREATER 0.05 "the side's share of the peak torque")
  expect_number(${side} LESS 1.2 "the side's share of the peak torque")
  result(factor vane torque_factor_m3)
  expect_number(${factor} GREATER 3.0097e-4 "vane torque factor [m^3]")
  expect_number(${factor} LESS 3.0117e-4 "vane torque factor [m^3]")
  set(unsteady 0)
  foreach(k 0 1 2)
    result(t steps ${k} torque_Nm)
    expect_number(${t} GREATER 0 "steady torque of step ${k}")
    result(tau steps ${k} shear_stress_Pa)
    expect_number(${tau} GREATER 5 "shear stress of step ${k} [Pa]")
    expect_number(${tau} LESS 5000 "shear stress of step ${k} [Pa]")
    result(tl torque_Nm ${k})
    expect_number(${tl} EQUAL ${t} "torque_Nm[${k}] is steps[${k}].torque_Nm")
    result(steady steps ${k} steady)
    result(angle steps ${k} angle_deg)
    result(tstep steps ${k} duration_s)
    if(steady)
      result(p steps ${k} trend_p)
      result(drift steps ${k} drift)
      expect_number(${angle} GREATER 29.999 "steady step ${k}: angle turned")
      expect_number(${p} GREATER 0.05 "steady step ${k}: trend p")
      expect_number(${drift} LESS 0.05 "steady step ${k}: drift")
    else()
      math(EXPR unsteady "${unsteady} + 1")
      expect_number(${tstep} GREATER 0.2999 "unsteady step ${k} ran max_step_time")
    endif()
  endforeach()
  result(fit_unsteady herschel_bulkley unsteady_steps)
  expect_number(${fit_unsteady} EQUAL ${unsteady} "fit counts the unsteady steps")
  result_length(nd down_sweep torque_Nm)
  expect_number(${nd} EQUAL 2 "down-sweep steps (40, 20 rpm)")
  result(ds down_sweep speeds_rpm 0)
  expect_number(${ds} EQUAL 40 "first down-sweep speed")
  result(peak startup peak_torque_Nm)
  result(tau_y yield_stress_Pa)
  expect_number(${peak} GREATER 0 "start-up peak torque")
  expect_number(${tau_y} GREATER 0 "vane yield stress")
  expect_file(${WORK}/out/startup.png)
  expect_file(${WORK}/out/torque.png)
  expect_file(${WORK}/out/vane_loads.csv)
  # stdout: one line per speed with its steady torque (the 80 rpm line carries result.json's value
  # to 4 decimals), the fit, where the pictures are.
  result(t80 steps 2 torque_Nm)
  string(REGEX MATCH "\n +80 +([0-9]+\\.[0-9]+) \\+-" m "${LAST_STDOUT}")
  if(NOT m)
    message(FATAL_ERROR "stdout has no line for 80 rpm:\n${LAST_STDOUT}")
  endif()
  expect_number(${CMAKE_MATCH_1} GREATER 0 "printed torque at 80 rpm")
  # Compare in units of 1e-4 N m: the printed value is result.json's rounded to 4 decimals.
  string(REGEX REPLACE "^([0-9]+)\\.([0-9][0-9][0-9][0-9]).*" "\\1\\2" printed "${CMAKE_MATCH_1}")
  string(REGEX REPLACE "^([0-9]+)\\.([0-9][0-9][0-9][0-9]).*" "\\1\\2" stored "${t80}")
  math(EXPR diff "${printed} - ${stored}")  # 0, or 1 where the rounding went up
  if(diff LESS 0 OR diff GREATER 1)
    message(FATAL_ERROR "printed torque ${CMAKE_MATCH_1} does not match result.json ${t80}")
  endif()
  foreach(pattern "Herschel-Bulkley +tau0 = " "pictures +[^\n]*torque\\.png")
    if(NOT LAST_STDOUT MATCHES "${pattern}")
      message(FATAL_ERROR "stdout lacks '${pattern}':\n${LAST_STDOUT}")
    endif()
  endforeach()

elseif(CASE STREQUAL "validation_pb")
  # The Plackett-Burman validation campaign on 13 tiny slump runs (52 spheres of 40 mm, the column
  # released without a cone, 0.3 s): every run finishes, both fits (EDEM from Table 4 and Paddy)
  # exist, the EDEM fit reproduces the reference's Table 5 (H5 slump-flow coefficient -58.00,
  # p < 0.0001), the files exist, and a second invocation resumes without running a job again.
  set(tiny "cone=none,packing=lattice,max_time=0.3,min_rest_time=0.1,snapshot_interval=0,pictures=false")
  set(args run ${SOURCE}/experiments/validation/plackett_burman.lua --out out --threads 1
      --set particle_diameter=0.04 --set max_parallel=2 --set threads_per_job=1
      --set reference_dir=${SOURCE}/../shared/reference --set slump_set=${tiny})
  run_paddy(code se ${args})
  expect_code(${code} 0)
  result(n finished)
  expect_number(${n} GREATER 12.5 "finished runs")
  result(b effects slump_flow_mm H5 edem coefficient)
  expect_number(${b} LESS -57.99 "EDEM slump-flow H5 coefficient")
  expect_number(${b} GREATER -58.01 "EDEM slump-flow H5 coefficient")
  result(p effects slump_flow_mm H5 edem p)
  expect_number(${p} LESS 0.0001 "EDEM slump-flow H5 p")
  # Paddy's runs and fit against the closed form of the design (check_validation_pb.lua): every
  # main effect is (1/12) sum x_ij y_i over the factorial runs, every slump within the column.
  run_paddy(code se run ${HERE}/check_validation_pb.lua --set dir=${WORK}/out --out check)
  expect_code(${code} 0)
  expect_outputs(out pb_runs.csv pb_effects.csv pb_validation.json pb_runs.png pb_effects.png)
  file(STRINGS ${WORK}/out/pb_runs.csv lines)
  list(LENGTH lines nl)
  expect_number(${nl} GREATER 13.5 "lines of pb_runs.csv")
  run_paddy(code se ${args})
  expect_code(${code} 0)
  if(NOT se MATCHES "13 job\\(s\\) already done")
    message(FATAL_ERROR "the second invocation did not resume from the finished jobs")
  endif()

elseif(CASE STREQUAL "validation_sa")
  # The steepest-ascent validation on Table 6's 4 steps as tiny slump runs (the columns of
  # validation_pb): every run finishes, the files exist, the CSV has a header and 4 rows, its EDEM
  # columns equal Table 6, the agreement and the best steps equal their closed form recomputed
  # from the CSV (check_validation_sa.lua), and a second invocation resumes without running a job.
  set(tiny "cone=none,packing=lattice,max_time=0.3,min_rest_time=0.1,snapshot_interval=0,pictures=false")
  set(args run ${SOURCE}/experiments/validation/steepest_ascent.lua --out out --threads 1
      --set particle_diameter=0.04 --set max_parallel=2 --set threads_per_job=1
      --set reference_dir=${SOURCE}/../shared/reference --set slump_set=${tiny})
  run_paddy(code se ${args})
  expect_code(${code} 0)
  result(n finished)
  expect_number(${n} GREATER 3.5 "finished runs")
  result(nf failed)
  expect_number(${nf} LESS 0.5 "failed runs")
  result(b best_step edem mean step)
  expect_number(${b} GREATER 3.5 "EDEM best step (the reference chose 4)")
  expect_outputs(out sa_runs.csv sa_validation.json sa_runs.png)
  file(STRINGS ${WORK}/out/sa_runs.csv lines)
  list(LENGTH lines nl)
  expect_number(${nl} GREATER 4.5 "lines of sa_runs.csv")
  expect_number(${nl} LESS 5.5 "lines of sa_runs.csv")
  if(NOT LAST_STDOUT MATCHES "best step by δ: EDEM step 4")
    message(FATAL_ERROR "stdout lacks the best step:\n${LAST_STDOUT}")
  endif()
  run_paddy(code se run ${HERE}/check_validation_sa.lua --set dir=${WORK}/out
            --set reference_dir=${SOURCE}/../shared/reference --out check)
  expect_code(${code} 0)
  run_paddy(code se ${args})
  expect_code(${code} 0)
  if(NOT se MATCHES "4 job\\(s\\) already done")
    message(FATAL_ERROR "the second invocation did not resume from the finished jobs")
  endif()

elseif(CASE STREQUAL "validation_ys")
  # The yield-stress study with a vane depth series on tiny runs (one set, 2 seeds, 2 fill levels;
  # 20 mm spheres in the cup, 40 mm in the cone, a 4 degree start-up): every run finishes, the
  # study's files exist (the old ones and the depth series'), each seed's and the pooled fit exist
  # and the pooled fit has the 4 points; ys_runs.csv's vane columns are filled (the reference level).
  # Without a depth series the study runs as before; a depth series with one fill level is refused.
  set(tiny ${ys_tiny} --set rheometer_diameter=0.02)
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress.lua --out out --threads 1 ${tiny}
            --set vane_fill_levels=0.102,0.12)
  expect_code(${code} 0)
  expect_outputs(out ys_runs.csv ys_summary.csv yield_stress_study.json ys_ratio.png ys_depth_runs.csv ys_depth_fit.csv ys_depth.png ys_measured.png)
  expect_none_failed("failed runs")
  result(n depth_series sets 0 pooled n)
  expect_number(${n} EQUAL 4 "points of the pooled fit")
  result(c1 depth_series sets 0 per_seed 0 fit c)
  result(c2 depth_series sets 0 per_seed 1 fit c)
  result(tv runs 0 vane_yield_stress_Pa)
  expect_number(${tv} GREATER 0 "vane yield stress at the reference level")
  file(STRINGS ${WORK}/out/ys_depth_runs.csv lines)
  list(LENGTH lines n_lines)
  expect_number(${n_lines} EQUAL 5 "lines of ys_depth_runs.csv (header + 2 seeds x 2 levels)")
  # The vanes measured their sheared surface's stresses at the peak (rheometer.lua's default): the
  # depth rows carry them and each set has the lines at failure, one per seed.
  list(GET lines 0 header)
  if(NOT header MATCHES "sigma_n_peak_Pa,sigma_rr_peak_Pa,shear_side_peak_Pa,side_torque_share")
    message(FATAL_ERROR "ys_depth_runs.csv lacks the stresses at the peak: ${header}")
  endif()
  result_length(n depth_series sets 0 failure per_seed)
  expect_number(${n} EQUAL 2 "seeds of the line at failure")
  result_length(n depth_series sets 0 side per_seed)
  expect_number(${n} EQUAL 2 "seeds of the side's line at failure")
  result_length(n depth_series sets 0 static per_seed)
  expect_number(${n} EQUAL 2 "seeds of the static line (sigma_n as the vanes started)")
  # Without a depth series the study is as before: one vane per set and seed (its slumps shared
  # through the campaign directory), its files, no depth files.
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress.lua --out plain --threads 1 ${tiny}
            --set campaign_dir=${WORK}/out/campaign)
  expect_code(${code} 0)
  expect_outputs(plain ys_runs.csv ys_summary.csv yield_stress_study.json ys_ratio.png)
  if(EXISTS ${WORK}/plain/ys_depth_fit.csv)
    message(FATAL_ERROR "a depth-series file without vane_fill_levels")
  endif()
  result_json(GET plain ratio summary 0 ratio mean)
  expect_number(${ratio} GREATER 0 "ratio without a depth series")
  # More seeds for a finished study (with_studies): seed 1's study, then seed 2's pooling it, from
  # the same campaign, reports what the study of both seeds reports (check_ys_pooled.lua). A seed
  # already in the pooled study and a study of another design are refused, naming the setting.
  set(depth ${tiny} --set vane_fill_levels=0.102,0.12 --set campaign_dir=${WORK}/out/campaign)
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress.lua --out first --threads 1 ${depth} --set seeds=1)
  expect_code(${code} 0)
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress.lua --out pooled --threads 1 ${depth} --set seeds=2
            --set with_studies=${WORK}/first)
  expect_code(${code} 0)
  run_paddy(code se run ${HERE}/check_ys_pooled.lua --out chk_pooled --set both=${WORK}/out --set pooled=${WORK}/pooled
            --set first=${WORK}/first)
  expect_code(${code} 0)
  # Without seeds of its own, the study runs nothing and reads the finished study again.
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress.lua --out reread --threads 1 ${depth} --set seeds=
            --set with_studies=${WORK}/out --set campaign_dir=${WORK}/reread_campaign)
  expect_code(${code} 0)
  file(GLOB reread_jobs ${WORK}/reread_campaign/jobs/*)
  if(NOT se MATCHES "0 runs" OR reread_jobs)
    message(FATAL_ERROR "a study without seeds ran something: ${se}")
  endif()
  run_paddy(code se run ${HERE}/check_ys_pooled.lua --out chk_reread --set both=${WORK}/out --set pooled=${WORK}/reread
            --set first=${WORK}/out --set first_seeds=2)
  expect_code(${code} 0)
  # Refused before anything runs: a seed already in this study, a directory without a study, a
  # study without a depth series (plain) pooled into one with.
  set(pool_args run ${SOURCE}/experiments/validation/yield_stress.lua --threads 1 ${depth} --set seeds=1,2)
  expect_refusals(pool_args twice with_studies=${WORK}/first "first/yield_stress_study.json: seed 1 is also in this study"
                            missing with_studies=${WORK}/nowhere "nowhere: no yield_stress_study.json there"
                            flat with_studies=${WORK}/plain "vane_fill_levels is none there, 0.102,0.12 here")
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress.lua --out other --threads 1 ${tiny} --set seeds=2
            --set vane_fill_levels=0.102,0.15 --set campaign_dir=${WORK}/out/campaign --set with_studies=${WORK}/first)
  expect_code(${code} 2)
  if(NOT se MATCHES "vane_fill_levels is 0.102,0.12 there, 0.102,0.15 here")
    message(FATAL_ERROR "a study of another design: expected a refusal, got: ${se}")
  endif()
  # A depth series without the reference level (no vane in ys_runs.csv) still compares its fit with
  # the slumps: the pooled intercept over the slumps' mean yield stress.
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress.lua --out noref --threads 1 ${tiny}
            --set vane_fill_levels=0.102,0.12 --set reference_fill_level=0.15 --set campaign_dir=${WORK}/out/campaign)
  expect_code(${code} 0)
  # Its summary has no vane: the agreement is undetermined (said, an empty cell), not a "nan"
  # ratio reported as "NOT within target".
  if(LAST_STDOUT MATCHES "nan" OR NOT LAST_STDOUT MATCHES "no vane at reference_fill_level = 0.15 m")
    message(FATAL_ERROR "a depth series without the reference level: expected the summary to say there is no vane, got:\n${LAST_STDOUT}")
  endif()
  file(STRINGS ${WORK}/noref/ys_summary.csv noref_rows)
  list(GET noref_rows 1 noref_row)
  if(NOT noref_row MATCHES ",$")
    message(FATAL_ERROR "ys_summary.csv without a vane: within_target should be empty, got: ${noref_row}")
  endif()
  result_json(GET noref pr depth_series sets 0 pooled_c_over_slump)
  result_json(GET noref pc depth_series sets 0 pooled c)
  result_json(GET noref ts depth_series sets 0 slump_yield_stress_Pa mean)
  expect_number(${ts} GREATER 0 "slumps' mean yield stress without the reference level")
  file(WRITE ${WORK}/check_noref.lua "local pr, pc, ts = ${pr}, ${pc}, ${ts}\nassert(math.abs(pc / ts - pr) <= 1e-12 * math.abs(pr), 'pooled c over the slump')\npaddy.result{ok = true}\n")
  run_paddy(code se run ${WORK}/check_noref.lua --out chk_noref)
  expect_code(${code} 0)
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress.lua --out one --threads 1 ${tiny}
            --set vane_fill_levels=0.12)
  expect_code(${code} 2)
  if(NOT se MATCHES "at least 2 fill levels")
    message(FATAL_ERROR "one fill level: expected a refusal, got: ${se}")
  endif()

elseif(CASE STREQUAL "validation_ys_resolution")
  # The yield stress of both tests against the sphere size on tiny runs (vane 20 and 16 mm, slump 40
  # and 32 mm lifted fast, 2 seeds): every run finishes, the files exist, each line has its 4 points, the value
  # at the grain is the line's (a + b d) and the ratio there is the vane's over the slump's; a single
  # diameter and a diameter out of range are refused.
  set(tiny --set seeds=1,2 --set rheometer_diameters=0.02,0.016 --set slump_diameters=0.04,0.032
      "--set" "rheometer_set=startup_angle=4,settle_max_time=0.6,min_rest_time=0.1,insert_time=0.01"
      "--set" "slump_set=max_time=0.5,lift_speed=0.3" --set code_version=test)
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress_resolution.lua --out out --threads 1 ${tiny})
  expect_code(${code} 0)
  expect_outputs(out ys_resolution_runs.csv ys_resolution_fit.csv ys_resolution.json ys_resolution.png)
  expect_none_failed("failed runs")
  result(none without_yield_stress)
  expect_number(${none} EQUAL 0 "runs without a yield stress")
  result(nv vane_fit n)
  expect_number(${nv} EQUAL 4 "points of the vane line")
  result(ns slump_fit n)
  expect_number(${ns} EQUAL 4 "points of the slump line")
  result(a vane_fit at_d0_Pa)
  result(b vane_fit slope_Pa_per_m)
  result(vg grain vane value_Pa)
  file(WRITE ${WORK}/check.lua "local a, b, vg = ${a}, ${b}, ${vg}\nassert(math.abs(a + b * 0.002 - vg) <= 1e-9 * math.max(1, math.abs(vg)), 'vane at the grain is not the line')\n")
  result(sg grain slump value_Pa)
  result(r grain ratio)
  file(APPEND ${WORK}/check.lua "local sg, r = ${sg}, ${r}\nassert(math.abs(vg / sg - r) <= 1e-12 * math.abs(r), 'ratio at the grain')\npaddy.result{ok = true}\n")
  run_paddy(code se run ${WORK}/check.lua --out chk)
  expect_code(${code} 0)
  set(args run ${SOURCE}/experiments/validation/yield_stress_resolution.lua --threads 1 ${tiny})
  expect_refusals(args one rheometer_diameters=0.02,0.02 "at least 2 distinct diameters"
                       big rheometer_diameters=0.02,0.03 "rheometer_diameters: 0.03 m is outside the allowed range")

elseif(CASE STREQUAL "validation_vfs")
  # vane_fill_stress.lua on a tiny depth study of yield_stress.lua (12 mm spheres in the cup, one set,
  # 2 seeds, 2 fill levels, a 4 degree start-up): each vane's fill run again alone is the study's
  # (same spheres and solid fraction), its stresses and the pooled line are consistent with its runs
  # (check_vane_fill_stress.lua). A study whose sphere count was altered is a fill that is not the
  # study's: left out and counted, nothing runs again. A missing study, a directory without one and a
  # study without a depth series are refused.
  set(study ${ys_tiny} --set rheometer_diameter=0.012)
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress.lua --out ys --threads 1 ${study}
            --set vane_fill_levels=0.102,0.12)
  expect_code(${code} 0)
  run_paddy(code se run ${SOURCE}/experiments/validation/vane_fill_stress.lua --out out --threads 1
            --set study=${WORK}/ys --set code_version=test)
  expect_code(${code} 0)
  expect_outputs(out vfs_runs.csv vfs_fit.csv vane_fill_stress.json vfs_depth.png)
  result(m mismatched)
  expect_number(${m} EQUAL 0 "fills not the study's")
  expect_none_failed("failed fills")
  run_paddy(code se run ${HERE}/check_vane_fill_stress.lua --out chk --set dir=${WORK}/out)
  expect_code(${code} 0)
  # The study's own static line (its vanes' starting σ_n, recorded as they ran) is the line through
  # the fills run again alone: the same intercept and slope (check_static_line.lua).
  run_paddy(code se run ${HERE}/check_static_line.lua --out chk_static --set study=${WORK}/ys --set fills=${WORK}/out)
  expect_code(${code} 0)
  # The study altered: its first vane had one sphere more.
  file(MAKE_DIRECTORY ${WORK}/altered)
  file(READ ${WORK}/ys/yield_stress_study.json doc)
  string(JSON n GET "${doc}" depth_runs 0 particles)
  math(EXPR n1 "${n} + 1")
  string(JSON doc SET "${doc}" depth_runs 0 particles ${n1})
  file(WRITE ${WORK}/altered/yield_stress_study.json "${doc}")
  run_paddy(code se run ${SOURCE}/experiments/validation/vane_fill_stress.lua --out out2 --threads 1
            --set study=${WORK}/altered --set code_version=test --set campaign_dir=${WORK}/out/campaign)
  expect_code(${code} 0)
  result_json(GET out2 m mismatched)
  expect_number(${m} EQUAL 1 "fills not the study's (altered study)")
  result_json(GET out2 same runs 0 same_fill)
  if(NOT same STREQUAL "OFF" AND NOT same STREQUAL "false")
    message(FATAL_ERROR "the altered vane's fill counted as the study's: ${same}")
  endif()
  if(NOT se MATCHES "not the same fill")
    message(FATAL_ERROR "no message about the altered fill: ${se}")
  endif()
  if(se MATCHES "campaign: [0-9]+/[0-9]+ done, [1-9][0-9]* running")
    message(FATAL_ERROR "fills ran again for the altered study: ${se}")
  endif()
  run_paddy(code se run ${SOURCE}/experiments/validation/yield_stress.lua --out plain --threads 1 ${study}
            --set campaign_dir=${WORK}/ys/campaign)
  expect_code(${code} 0)
  set(args run ${SOURCE}/experiments/validation/vane_fill_stress.lua --threads 1)
  expect_refusals(args none study= "give study = the output directory"
                       empty study=${WORK}/chk "no yield_stress_study.json there"
                       flat study=${WORK}/plain "has no depth series")

elseif(CASE STREQUAL "validation_lift_speed")
  # The slump's yield stress against the cone lift speed on tiny runs (40 mm spheres, two sets, lifts
  # at 0.3, 0.2 and 0.1 m/s, 2 seeds): every run finishes at rest, lifted at its own speed (slump.lua's
  # cone lift over its lift time) within its time limit (cone height / speed + rest_margin), and the
  # study's means, factors, halving changes and lines are those of its runs (check_lift_speed.lua).
  # One speed, a speed out of range, a test speed not among the speeds and a lift speed in slump_set
  # are refused with the parameter and its range.
  set(tiny --set values=0.02,0.1 --set lift_speeds=0.3,0.2,0.1 --set test_speed=0.3 --set seeds=1,2
      --set slump_diameter=0.04 --set rest_margin=1 --set code_version=test)
  run_paddy(code se run ${SOURCE}/experiments/validation/slump_lift_speed.lua --out out --threads 1 ${tiny})
  expect_code(${code} 0)
  expect_outputs(out lift_speed_runs.csv lift_speed_summary.csv lift_speed_sets.csv lift_speed.json lift_speed.png)
  expect_none_failed("failed runs")
  result(left left_out)
  expect_number(${left} EQUAL 0 "runs left out")
  run_paddy(code se run ${HERE}/check_lift_speed.lua --out chk --set dir=${WORK}/out --set speeds=0.3,0.2,0.1
            --set test_speed=0.3 --set values=0.02,0.1 --set seeds=1,2 --set rest_margin=1)
  expect_code(${code} 0)
  set(args run ${SOURCE}/experiments/validation/slump_lift_speed.lua --threads 1 ${tiny})
  expect_refusals(args one lift_speeds=0.3 "needs at least 2 speeds"
                       slow lift_speeds=0.3,0.0005 "0.0005 m/s is outside the allowed range \\[0.001, 2\\] m/s"
                       test lift_speeds=0.2,0.1 "test_speed = 0.3 m/s is not one of lift_speeds"
                       set slump_set=lift_speed=0.1 "slump_set must not set lift_speed")

elseif(CASE STREQUAL "rheometer_confirm")
  # rheometer_mini's run with steady_confirm: a step is steady only when the stretch of
  # steady_windows windows before the compared ones passes the criterion too, so no step can be
  # steady before min_step_angle + steady_windows x window_angle = 30 + 4 x 5 = 50 deg. (Without the
  # option this run's 80 rpm step is steady at 35 deg, so a rheometer that ignored it fails here.)
  run_paddy(code se run ${SOURCE}/experiments/rheometer.lua --out out --threads 1 --seed 3
            ${rheometer_mini_args}
            --set pictures=false --set steady_confirm=true)
  expect_code(${code} 0)
  result(confirm steady_criterion confirm)
  if(NOT confirm)
    message(FATAL_ERROR "result.json steady_criterion.confirm is '${confirm}', expected true")
  endif()
  foreach(k 0 1 2)
    result(steady steps ${k} steady)
    result(angle steps ${k} angle_deg)
    result(tstep steps ${k} duration_s)
    if(steady)
      result(confirmed steps ${k} confirmed)
      if(NOT confirmed)
        message(FATAL_ERROR "step ${k} is steady but not confirmed")
      endif()
      expect_number(${angle} GREATER 49.999 "confirmed steady step ${k}: angle turned")
    else()
      expect_number(${tstep} GREATER 0.2999 "unsteady step ${k} ran max_step_time")
    endif()
  endforeach()
elseif(CASE STREQUAL "validation_rs")
  # The rheometer's steady-torque study on tiny runs (20 mm spheres, 2 speeds, 2 seeds, the steady
  # criterion and fixed 0.3 s steps): every run finishes, the files exist, and the summary agrees
  # with the per-step table (check_validation_rs.lua).
  run_paddy(code se run ${SOURCE}/experiments/validation/rheometer_steady.lua --out out --threads 1
            --set diameters=0.02 --set step_times=0,0.3 --set seeds=1,2 --set max_parallel=2 --set code_version=test
            "--set" "rheometer_set=speeds_rpm=10\;40,max_step_time=1,startup_angle=20,settle_max_time=0.8")
  expect_code(${code} 0)
  expect_outputs(out rs_steps.csv rs_runs.csv rs_summary.csv rheometer_steady.json rs_torques.png)
  run_paddy(code se run ${HERE}/check_validation_rs.lua --set dir=${WORK}/out --out check)
  expect_code(${code} 0)
  # A negative step length is refused with the allowed range.
  run_paddy(code se run ${SOURCE}/experiments/validation/rheometer_steady.lua --out bad --set step_times=-1)
  expect_code(${code} 2)
  if(NOT se MATCHES "step_times: -1 s is outside the allowed range 0-100 s")
    message(FATAL_ERROR "the refusal does not name step_times and its range: ${se}")
  endif()

elseif(CASE STREQUAL "surrogate_trials")
  # experiments/calibration/surrogate_trials.lua on a known linear slump test (check_surrogate_trials.lua
  # writes it): the emulator's data and the seeds' pooled scatter, the trials' table and summary.
  run_paddy(code se run ${HERE}/check_surrogate_trials.lua --set phase=data --out data)
  expect_code(${code} 0)
  run_paddy(code se run ${SOURCE}/experiments/calibration/surrogate_trials.lua --out out --threads 1
            --set input=${SOURCE}/tests/calibration/mini_mud.json --set data=${WORK}/data/simulations.csv
            --set factors=H7,H5 --set trials=3 --set holdout_sizes=12 --set holdout_repeats=3)
  expect_code(${code} 0)
  expect_outputs(out surrogate_trials.csv surrogate_trials_runs.csv surrogate_trials.json surrogate_trials.png)
  run_paddy(code se run ${HERE}/check_surrogate_trials.lua --set dir=${WORK}/out --set trials=3 --out check)
  expect_code(${code} 0)
  # The same command gives the same trials, bit for bit (a sum in the order of a Lua table's keys,
  # which changes from process to process, made the seeds' scatter differ in its last bits).
  foreach(again 1 2)
    run_paddy(code se run ${SOURCE}/experiments/calibration/surrogate_trials.lua --out again${again} --threads 1
              --set input=${SOURCE}/tests/calibration/mini_mud.json --set data=${WORK}/data/simulations.csv
              --set factors=H7,H5 --set trials=3 --set holdout_sizes=12 --set holdout_repeats=3)
    expect_code(${code} 0)
    foreach(f surrogate_trials_runs.csv surrogate_trials.json)
      execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK}/out/${f} ${WORK}/again${again}/${f} RESULT_VARIABLE differ)
      if(differ)
        message(FATAL_ERROR "a second run of the same command wrote another ${f}")
      endif()
    endforeach()
  endforeach()
  # A strategy that does not exist is refused with the allowed ones.
  run_paddy(code se run ${SOURCE}/experiments/calibration/surrogate_trials.lua --out bad
            --set input=${SOURCE}/tests/calibration/mini_mud.json --set data=${WORK}/data/simulations.csv --set strategies=plain,fast)
  expect_code(${code} 2)
  if(NOT se MATCHES "strategies = 'fast' is not one of plain, warped")
    message(FATAL_ERROR "the refusal does not name the strategy and the allowed ones: ${se}")
  endif()
  # More initial points than the budget is refused with the allowed range.
  run_paddy(code se run ${SOURCE}/experiments/calibration/surrogate_trials.lua --out bad2
            --set input=${SOURCE}/tests/calibration/mini_mud.json --set data=${WORK}/data/simulations.csv --set initial_points=9)
  expect_code(${code} 2)
  if(NOT se MATCHES "initial_points = 9 is outside the allowed range \\[2, 8\\] \\(the budget\\)")
    message(FATAL_ERROR "the refusal does not name initial_points and its range: ${se}")
  endif()

elseif(CASE STREQUAL "validation_cg")
  # The coarse-graining campaign on 2 sizes x 2 seeds of tiny released columns: per-size mean and
  # std, the tests and the pictures.
  run_paddy(code se run ${SOURCE}/experiments/validation/coarse_graining.lua --out out --threads 1
            --set diameters=0.03,0.04 --set seeds=1,2 --set max_parallel=2 --set threads_per_job=1
            --set slump_set=cone=none,packing=lattice,max_time=0.3,min_rest_time=0.1,snapshot_interval=0,pictures=false)
  expect_code(${code} 0)
  result(n finished)
  expect_number(${n} GREATER 3.5 "finished runs")
  result(m summary 0 slump_mm mean)
  expect_number(${m} GREATER 20 "mean slump at 30 mm")
  result(sd summary 1 slump_flow_mm std)
  expect_number(${sd} GREATER 0 "std of the slump-flow at 40 mm (two seeds differ)")
  # The ANOVA over the sizes recomputed from the runs, its p-value from the closed form of F(1, 2)
  # (check_validation_cg.lua), and every slump within the column.
  run_paddy(code se run ${HERE}/check_validation_cg.lua --set dir=${WORK}/out --out check)
  expect_code(${code} 0)
  expect_outputs(out cg_runs.csv cg_summary.csv cg_tests.csv cg_study.json cg_sizes.png cg_profiles.png)

elseif(CASE STREQUAL "tack_mini")
  # The plate tack test (experiments/tack.lua) in miniature: ~180 spheres of 8 mm in a 60 mm cup, a
  # 40 mm plate pressed 3 mm and pulled 8 mm, four runs at one seed: no mud-steel attraction (base),
  # wall adhesion (wall), lubrication at 0.01 and 0.04 m/s (slow, fast). check_tack.lua asserts
  # what a broken experiment gets wrong (no pull without attraction, a pull of several spheres'
  # weight with wall adhesion whose end force is the weight of the mud carried, a lubrication pull
  # that grows with the speed, the profile's length and grid); here: exit codes, outputs, stdout,
  # and bad input refused naming the parameter and its allowed range.
  set(tack_mini_args ${SOURCE}/experiments/tack.lua --threads 1 --seed 1
      --set particle_diameter=0.008 --set cup_diameter=0.06 --set cup_depth=0.024 --set plate_diameter=0.04
      --set press_depth=0.003 --set pull_distance=0.008 --set profile_points=8 --set hold_time=0.05
      --set settle_max_time=0.5 --set min_rest_time=0.1 --set snapshot_interval=0 --set progress=false)
  run_paddy(code se run ${tack_mini_args} --out base)
  expect_code(${code} 0)
  foreach(pattern "model +conventions paddy; material paddy_calibrated" "pre-load +[0-9.]+ N"
                  "tack +peak [0-9.]+ N at [0-9.]+ mm, work" "carried +[0-9.]+ g of mud" "pictures +[^\n]*tack_curve\\.png")
    if(NOT LAST_STDOUT MATCHES "${pattern}")
      message(FATAL_ERROR "stdout lacks '${pattern}':\n${LAST_STDOUT}")
    endif()
  endforeach()
  expect_outputs(base tack_curve.csv tack_test.csv tack_curve.png tack_test.png)
  run_paddy(code se run ${tack_mini_args} --out wall --set mud_steel_surface_energy=0.15 --set pictures=false)
  expect_code(${code} 0)
  if(NOT LAST_STDOUT MATCHES "effects: wall_adhesion \\(mud_steel_surface_energy = 0\\.15\\)")
    message(FATAL_ERROR "stdout does not name the wall adhesion:\n${LAST_STDOUT}")
  endif()
  run_paddy(code se run ${tack_mini_args} --out slow --set lubrication_viscosity=0.02 --set pull_speed=0.01 --set pictures=false)
  expect_code(${code} 0)
  run_paddy(code se run ${tack_mini_args} --out fast --set lubrication_viscosity=0.02 --set pull_speed=0.04 --set pictures=false)
  expect_code(${code} 0)
  run_paddy(code se run ${HERE}/check_tack.lua --set dir=${WORK} --set profile_points=8 --out check)
  expect_code(${code} 0)
  result_json(GET check ok ok)
  # Bad input: a pull speed outside its range, a plate wider than the cup allows.
  set(args run ${tack_mini_args})
  expect_refusals(args speed pull_speed=0 "parameter 'pull_speed' = 0 m/s is outside the allowed range"
                       plate plate_diameter=0.05 "plate_diameter = 0.05 m: .*allowed plate_diameter <= cup_diameter - 2 particle_diameter = 0.044 m")

else()
  message(FATAL_ERROR "unknown case ${CASE}")
endif()
