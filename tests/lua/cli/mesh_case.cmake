# Command-line tests of mesh walls from Lua (CTest: cli.mesh.<case>): each case runs one script of
# mesh/ through the built `paddy` (the scripts assert from Lua; a failed check exits 2) and
# checks exit code, messages and output files.
#   cmake -DPADDY=<exe> -DCASE=<name> -DSRC=<dir of mesh/*.lua> -DWORK=<dir> -P mesh_case.cmake
cmake_minimum_required(VERSION 3.20)

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(GLOB scripts ${SRC}/*.lua)
file(COPY ${scripts} DESTINATION ${WORK})

function(run_script script out_code out_stderr)
  execute_process(COMMAND ${PADDY} run ${script} --out out --threads 1 WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE code OUTPUT_VARIABLE so ERROR_VARIABLE se)
  message(STATUS "paddy run ${script} -> ${code}\n--- stdout:\n${so}\n--- stderr:\n${se}")
  set(${out_code} ${code} PARENT_SCOPE)
  set(${out_stderr} "${se}" PARENT_SCOPE)
endfunction()

function(expect_code actual expected)
  if(NOT "${actual}" STREQUAL "${expected}")
    message(FATAL_ERROR "exit code ${actual}, expected ${expected}")
  endif()
endfunction()

function(expect_match text regex)
  if(NOT "${text}" MATCHES "${regex}")
    message(FATAL_ERROR "output does not match '${regex}'")
  endif()
endfunction()

function(expect_file path regex)
  if(NOT EXISTS ${path})
    message(FATAL_ERROR "${path} missing")
  endif()
  file(READ ${path} text)
  expect_match("${text}" "${regex}")
endfunction()

if(CASE STREQUAL "cone_lift")
  run_script(cone_lift.lua code se)
  expect_code(${code} 0)
  expect_file(${WORK}/out/result.json "\"status\": *\"complete\"")
  expect_file(${WORK}/out/result.json "geometry:slump_cone")   # metadata: plugin parts used
  expect_file(${WORK}/out/cone_loads.csv "# wall: cone\nt,Fx,Fy,Fz,Tx,Ty,Tz,T_axis,distance,angle\n0\\.[0-9]")

elseif(CASE STREQUAL "stl_import")
  run_script(stl_import.lua code se)
  expect_code(${code} 0)
  expect_file(${WORK}/out/result.json "mesh_reader:cgal")

elseif(CASE STREQUAL "broken_stl")
  run_script(broken_stl.lua code se)
  expect_code(${code} 2)
  expect_match("${se}" "broken_stl\\.lua:8:")
  expect_match("${se}" "broken\\.stl: triangle 0 is degenerate")

elseif(CASE STREQUAL "unknown_part")
  run_script(unknown_part.lua code se)
  expect_code(${code} 2)
  expect_match("${se}" "unknown_part\\.lua:3:.*slump_kone.*available: cup, plate, slump_cone, vane")

elseif(CASE STREQUAL "unknown_param")
  run_script(unknown_param.lua code se)
  expect_code(${code} 2)
  expect_match("${se}" "unknown_param\\.lua:3:.*no parameter 'heigth' \\(accepted: top_diameter bottom_diameter height")

elseif(CASE STREQUAL "vane")
  run_script(vane.lua code se)
  expect_code(${code} 0)
  expect_file(${WORK}/out/vane_torque.csv "\n[0-9]")

else()
  message(FATAL_ERROR "unknown case ${CASE}")
endif()
