# Cases of tests/discovery/CMakeLists.txt:
#   cmake -DPADDY=<exe> -DCASE=<name> -DSOURCE=<source tree> -DHERE=<this dir> -DWORK=<dir> -P run_discovery.cmake
cmake_minimum_required(VERSION 3.20)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

include(${CMAKE_CURRENT_LIST_DIR}/../case_helpers.cmake)

# results.<path...> of <dir>/result.json into `var` (fatal if missing); length_of: an array's length.
function(result_of dir var)
  result_json(GET ${dir} value ${ARGN})
  set(${var} "${value}" PARENT_SCOPE)
endfunction()
function(length_of dir var)
  result_json(LENGTH ${dir} value ${ARGN})
  set(${var} "${value}" PARENT_SCOPE)
endfunction()

if(CASE STREQUAL "lib")
  run_paddy(code se run ${HERE}/discovery_lib.lua --out out --threads 1)
  expect_code(${code} 0)
  result_of(out ok ok)

elseif(CASE STREQUAL "visibility")
  # discovery_visibility.lua on the committed small benchmark and sensitivity study: every effect
  # trial lands in one bin, the bins' counts add up to the summary's, and a group the study lacks is
  # refused with the allowed ones.
  run_paddy(code se run ${SOURCE}/experiments/validation/discovery_visibility.lua --out out
            --set blind=${SOURCE}/docs/results/discovery_blind_small60_summary.json
            --set sensitivity=${SOURCE}/docs/results/discovery_sensitivity_25mm_two_cones_vane.json --set group=slump)
  expect_code(${code} 0)
  file(READ ${SOURCE}/docs/results/discovery_blind_small60_summary.json summary)
  string(JSON effect_trials GET "${summary}" summary effect_trials)
  string(JSON correct GET "${summary}" summary correct_names)
  length_of(out n_rows rows)
  length_of(out n_bins bins)
  set(total 0)
  set(named 0)
  math(EXPR last "${n_bins} - 1")
  foreach(k RANGE 0 ${last})
    result_of(out t bins ${k} trials)
    result_of(out r bins ${k} right)
    math(EXPR total "${total} + ${t}")
    math(EXPR named "${named} + ${r}")
  endforeach()
  if(NOT n_rows EQUAL effect_trials OR NOT total EQUAL effect_trials OR NOT named EQUAL correct OR NOT n_bins EQUAL 4)
    message(FATAL_ERROR "rows ${n_rows}, binned ${total}, named ${named}, bins ${n_bins}; the summary: ${effect_trials} effect trials, ${correct} named")
  endif()
  # by the misfit's p-value: three bins (edges 0.001, 0.05) that hold every trial of each kind, the
  # summary's correct names and false alarms; the bins' p ranges join up from 0 to 1
  string(JSON null_trials GET "${summary}" summary null_trials)
  string(JSON alarms GET "${summary}" summary false_alarms)
  string(JSON outside_trials GET "${summary}" summary outside_trials)
  length_of(out n_mbins misfit_bins)
  set(e_sum 0)
  set(r_sum 0)
  set(n_sum 0)
  set(a_sum 0)
  set(o_sum 0)
  set(edge 0)
  math(EXPR last "${n_mbins} - 1")
  foreach(k RANGE 0 ${last})
    result_of(out from misfit_bins ${k} from)
    if(NOT from STREQUAL edge)
      message(FATAL_ERROR "misfit bin ${k} starts at ${from}, the previous one ends at ${edge}")
    endif()
    result_of(out edge misfit_bins ${k} to)
    foreach(pair "effect;trials;e_sum" "effect;right;r_sum" "null;trials;n_sum" "null;alarms;a_sum" "outside;trials;o_sum")
      list(GET pair 0 kind)
      list(GET pair 1 key)
      list(GET pair 2 var)
      result_of(out v misfit_bins ${k} ${kind} ${key})
      math(EXPR ${var} "${${var}} + ${v}")
    endforeach()
  endforeach()
  if(NOT n_mbins EQUAL 3 OR NOT edge EQUAL 1 OR NOT e_sum EQUAL effect_trials OR NOT r_sum EQUAL correct
     OR NOT n_sum EQUAL null_trials OR NOT a_sum EQUAL alarms OR NOT o_sum EQUAL outside_trials)
    message(FATAL_ERROR "misfit bins ${n_mbins} (to ${edge}): effect ${e_sum}, named ${r_sum}, null ${n_sum}, alarms ${a_sum}, outside ${o_sum}; "
                        "the summary: ${effect_trials}, ${correct}, ${null_trials}, ${alarms}, ${outside_trials}")
  endif()
  run_paddy(code se run ${SOURCE}/experiments/validation/discovery_visibility.lua --out bad
            --set blind=${SOURCE}/docs/results/discovery_blind_small60_summary.json
            --set sensitivity=${SOURCE}/docs/results/discovery_sensitivity_25mm_two_cones_vane.json --set group=cone)
  expect_code(${code} 2)
  expect_match("${se}" "group = 'cone' is not in .*allowed: slump, slump_cone150")

elseif(CASE STREQUAL "input_errors")
  # No input file given; an unknown script; a sigma missing: each refused with file, key, allowed values.
  run_paddy(code se run ${SOURCE}/experiments/discover.lua --out out --threads 1)
  if(code EQUAL 0 OR NOT LAST_STDERR MATCHES "give the input file: --set input=FILE.json")
    message(FATAL_ERROR "discover.lua without input: exit ${code}, stderr: ${LAST_STDERR}")
  endif()
  file(WRITE ${WORK}/bad.json [=[{"experiments": [{"name": "slump_slow", "script": "cone.lua", "set": {"lift_speed": 0.05},
   "measured": {"slump_mm": 231}, "sigma": {"slump_mm": 3}}],
 "free_parameters": [{"parameter": "jkr_surface_energy", "low": 0, "high": 0.2}],
 "candidates": [{"name": "wall_adhesion", "parameter": "mud_steel_surface_energy", "low": 0, "high": 0.3}]}]=])
  run_paddy(code se run ${SOURCE}/experiments/discover.lua --out out --threads 1 --set input=${WORK}/bad.json)
  if(code EQUAL 0 OR NOT LAST_STDERR MATCHES "discovery input '[^']*bad.json': experiments\\[1\\]\\.script = cone\\.lua \\(allowed: slump\\.lua, rheometer\\.lua, tack\\.lua\\)")
    message(FATAL_ERROR "bad script: exit ${code}, stderr: ${LAST_STDERR}")
  endif()
  file(WRITE ${WORK}/bad2.json [=[{"experiments": [{"name": "slump_slow", "script": "slump.lua",
   "measured": {"slump_mm": 231, "slump_flow_mm": 480}, "sigma": {"slump_mm": 3}}],
 "free_parameters": [], "candidates": [{"name": "w", "parameter": "mud_steel_rolling_friction", "low": 0, "high": 0.3}]}]=])
  run_paddy(code se run ${SOURCE}/experiments/discover.lua --out out --threads 1 --set input=${WORK}/bad2.json)
  if(code EQUAL 0 OR NOT LAST_STDERR MATCHES "experiments\\[1\\]\\.sigma\\.slump_flow_mm is missing")
    message(FATAL_ERROR "missing sigma: exit ${code}, stderr: ${LAST_STDERR}")
  endif()

  # The blind benchmark's trial selection and lift speeds: a trial the sequence does not have and a
  # speed out of range are refused before any simulation runs.
  run_paddy(code se run ${SOURCE}/experiments/validation/discovery_blind.lua --out blind --threads 1
            --set small=true --set effect_trials=2 --set null_trials=1 --set outside_trials=0 --set only_trials=2,5)
  if(code EQUAL 0 OR NOT LAST_STDERR MATCHES "only_trials names trial 5, which the benchmark's 3 trials do not have")
    message(FATAL_ERROR "only_trials out of the sequence: exit ${code}, stderr: ${LAST_STDERR}")
  endif()
  run_paddy(code se run ${SOURCE}/experiments/validation/discovery_blind.lua --out blind --threads 1
            --set small=true --set lift_speeds=0.1,3)
  if(code EQUAL 0 OR NOT LAST_STDERR MATCHES "lift_speeds = 0.1,3: each speed must be in \\(0, 2\\] m/s")
    message(FATAL_ERROR "lift speed out of range: exit ${code}, stderr: ${LAST_STDERR}")
  endif()
  run_paddy(code se run ${SOURCE}/experiments/validation/discovery_blind.lua --out blind --threads 1
            --set small=true --set cone_scales=1,2.5)
  if(code EQUAL 0 OR NOT LAST_STDERR MATCHES "cone_scales = 1,2.5: each scale must be in \\[0.5, 2\\]")
    message(FATAL_ERROR "cone scale out of range: exit ${code}, stderr: ${LAST_STDERR}")
  endif()
  # A vane scale between 0 (none) and 1 would put the benchmark's coarse spheres in a cup too small.
  run_paddy(code se run ${SOURCE}/experiments/validation/discovery_blind.lua --out blind --threads 1
            --set small=true --set vane_scale=0.5)
  if(code EQUAL 0 OR NOT LAST_STDERR MATCHES "vane_scale = 0.5: must be 0 \\(no vane\\) or in \\[1, 8\\]")
    message(FATAL_ERROR "vane scale out of range: exit ${code}, stderr: ${LAST_STDERR}")
  endif()
  run_paddy(code se run ${SOURCE}/experiments/validation/discovery_sensitivity.lua --out sens --threads 1
            --set cone_scales=0.3)
  if(code EQUAL 0 OR NOT LAST_STDERR MATCHES "cone_scales = 0.3: each scale must be in \\[0.5, 2\\]")
    message(FATAL_ERROR "sensitivity: cone scale out of range: exit ${code}, stderr: ${LAST_STDERR}")
  endif()
  # The rheometer refuses spheres wider than the gap between vane and cup, naming the largest allowed.
  run_paddy(code se run ${SOURCE}/experiments/rheometer.lua --out rheo --threads 1 --set particle_diameter=0.03)
  if(code EQUAL 0 OR NOT LAST_STDERR MATCHES "particle_diameter = 0.03 m: the gap between vane and cup, \\(cup_diameter - vane_diameter\\)/2 = 0.025 m, must be at least one sphere wide: allowed particle_diameter <= 0.025 m")
    message(FATAL_ERROR "rheometer gap: exit ${code}, stderr: ${LAST_STDERR}")
  endif()
  # The smallest relevant strength must stay below the weakest hidden strength (0.15 of the range).
  run_paddy(code se run ${SOURCE}/experiments/validation/discovery_blind.lua --out blind --threads 1
            --set small=true --set relevant_fraction=0.2)
  if(code EQUAL 0 OR NOT LAST_STDERR MATCHES "parameter 'relevant_fraction' = 0.2 is outside the allowed range \\[0, 0.14\\]")
    message(FATAL_ERROR "relevant fraction out of range: exit ${code}, stderr: ${LAST_STDERR}")
  endif()

elseif(CASE STREQUAL "slump_observables")
  # ~400 spheres of 25 mm, a fast lift. A broken sampler fails: wrong lengths (grids must not depend
  # on the run), a profile that does not fall from the axis to the plate, a history that does not
  # rise, no downward pull on the cone while it lifts out of sticky mud.
  run_paddy(code se run ${SOURCE}/experiments/slump.lua --out out --threads 1 --seed 2 --set particle_diameter=0.025
            --set lift_speed=0.3 --set settle_max_time=1.0 --set min_rest_time=0.2 --set max_time=3
            --set pictures=false --set snapshot_interval=0 --set progress=false)
  expect_code(${code} 0)
  length_of(out np profile_mm)
  length_of(out npm profile_mean_mm)
  length_of(out nr profile_radii_mm)
  length_of(out nh history_mm)
  length_of(out nt history_times_s)
  if(NOT np EQUAL 12 OR NOT npm EQUAL 12 OR NOT nr EQUAL 12 OR NOT nh EQUAL nt OR nh LESS 5)
    message(FATAL_ERROR "grid lengths: profile ${np}/${nr}, history ${nh}/${nt}")
  endif()
  result_of(out h0 profile_mm 0)
  result_of(out h11 profile_mm 11)
  result_of(out r0 profile_radii_mm 0)
  result_of(out s_first history_mm 0)
  math(EXPR last "${nh} - 1")
  result_of(out s_last history_mm ${last})
  result_of(out slump slump_mm)
  result_of(out fmean cone_force_N mean)
  result_of(out fpeak cone_force_N peak)
  result_of(out nsamples cone_force_N samples)
  result_of(out mass mass_on_cone_g)
  expect_number(${r0} EQUAL 12.5 "first profile radius [mm]")
  expect_number(${h0} GREATER 20 "profile at the axis [mm]")
  expect_number(${h11} LESS 0.001 "profile at 287.5 mm (bare plate) [mm]")
  # The ring-mean height is at most the ring's highest cell and 0 on the bare plate.
  result_of(out hm0 profile_mean_mm 0)
  result_of(out hm11 profile_mean_mm 11)
  expect_number(${hm0} GREATER 10 "ring-mean profile at the axis [mm]")
  expect_number(${hm11} LESS 0.001 "ring-mean profile at 287.5 mm (bare plate) [mm]")
  expect_number(${s_last} GREATER ${s_first} "slump history rises")
  expect_number(${nsamples} GREATER 10 "load samples during the lift")
  expect_number(${fpeak} GREATER ${fmean} "peak downward force above its mean")
  expect_number(${fpeak} GREATER 0 "peak downward pull of the mud on the cone [N]")
  expect_number(${mass} GREATER -0.000001 "mass on the cone [g]")
  # Paddy's conventions (the default): the poured fill settles as a random packing, not a crystal.
  result_of(out packing packing)
  result_of(out cryst fill_structure crystalline)
  if(NOT packing STREQUAL "poured" OR NOT cryst STREQUAL "OFF")
    message(FATAL_ERROR "default fill: packing ${packing}, crystalline ${cryst} (expected poured, not crystalline)")
  endif()

elseif(CASE STREQUAL "sensitivity")
  # The measured sensitivities at 40 mm (a few hundred spheres), one slump, 2 seeds: 12 runs.
  run_paddy(code se run ${SOURCE}/experiments/validation/discovery_sensitivity.lua --out out --threads 2
            --set particle_diameter=0.04 --set seeds=2)
  expect_code(${code} 0)
  run_paddy(code se run ${HERE}/check_sensitivity.lua --out check --threads 1 --set dir=${WORK}/out)
  expect_code(${code} 0)
  result_of(check ok ok)

elseif(CASE STREQUAL "blind_tiny" OR CASE STREQUAL "blind_full")
  if(CASE STREQUAL "blind_tiny")
    # with the reports' figures: clients.discovery_report opens them in Chromium (tests/clients)
    set(args --set tiny=true --set report_pictures=true)
  endif()
  run_paddy(code se run ${SOURCE}/experiments/validation/discovery_blind.lua --out out --threads 2 --seed 1 ${args})
  expect_code(${code} 0)
  result_of(out failed summary failed)
  expect_number(${failed} EQUAL 0 "failed trials")
  if(CASE STREQUAL "blind_tiny")
    # Trial 1 hides a candidate at the top of its range: the workflow must name it.
    result_of(out answer trials 0 answer)
    result_of(out truth trials 0 truth name)
    if(NOT answer STREQUAL truth)
      message(FATAL_ERROR "strong hidden effect '${truth}' answered '${answer}'")
    endif()
    message(STATUS "ok: strong hidden effect '${truth}' named")
    # Trial 2 hides nothing: any answer but none is a false alarm (an earlier version answered
    # ambiguous; one whose calibration stopped at a scan point answered unknown).
    result_of(out null_answer trials 1 answer)
    result_of(out null_truth trials 1 truth kind)
    if(NOT null_truth STREQUAL "none" OR NOT null_answer STREQUAL "none")
      message(FATAL_ERROR "null trial (truth '${null_truth}') answered '${null_answer}'")
    endif()
    message(STATUS "ok: null trial answered none")
    # The strong effect, at the top of its range, was declared detectable there: its detection limit
    # (what the workflow says it could see, from its own signatures and noise) lies at or below the
    # hidden strength, and the summary counts the trial as declared detectable and named.
    result_of(out limit trials 0 hidden_detection_limit)
    result_of(out hidden trials 0 truth strength)
    if(limit STREQUAL "" OR NOT limit LESS_EQUAL hidden)
      message(FATAL_ERROR "strong hidden effect at ${hidden}: detection limit '${limit}' is not at or below it")
    endif()
    result_of(out det_right summary by_detection detectable right)
    expect_number(${det_right} EQUAL 1 "declared-detectable trials named")
    message(STATUS "ok: detection limit ${limit} <= hidden strength ${hidden}")
  endif()
  if(NOT EXISTS ${WORK}/out/blind_summary.json)
    message(FATAL_ERROR "missing blind_summary.json")
  endif()
else()
  message(FATAL_ERROR "unknown case ${CASE}")
endif()
