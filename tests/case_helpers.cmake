# Helpers shared by the end-to-end test drivers (tests/experiments/run_case.cmake,
# tests/discovery/run_discovery.cmake, tests/lua/cli/mesh_case.cmake): run the paddy executable
# in ${WORK}, check its exit code and messages, read result.json, compare numbers. Expects PADDY and WORK to be set by the driver's caller.

# run_paddy(<code var> <stderr var> args...): runs ${PADDY} args in ${WORK}; also sets
# LAST_STDOUT and LAST_STDERR in the caller's scope.
function(run_paddy out_code out_stderr)
  string(TIMESTAMP t0 "%s")
  execute_process(COMMAND ${PADDY} ${ARGN} WORKING_DIRECTORY ${WORK}
                  RESULT_VARIABLE code OUTPUT_VARIABLE so ERROR_VARIABLE se)
  string(TIMESTAMP t1 "%s")
  math(EXPR secs "${t1} - ${t0}")
  message(STATUS "paddy ${ARGN} -> ${code} in ${secs} s\n--- stdout:\n${so}\n--- stderr:\n${se}")
  set(${out_code} ${code} PARENT_SCOPE)
  set(${out_stderr} "${se}" PARENT_SCOPE)
  set(LAST_STDOUT "${so}" PARENT_SCOPE)
  set(LAST_STDERR "${se}" PARENT_SCOPE)
endfunction()

function(expect_code actual expected)
  if(NOT "${actual}" STREQUAL "${expected}")
    message(FATAL_ERROR "exit code ${actual}, expected ${expected}")
  endif()
endfunction()

# result_json(GET|LENGTH <dir> <var> path...): results.<path...> of ${WORK}/<dir>/result.json
# (GET: the value, LENGTH: the array's length) into `var`; fatal if missing.
function(result_json op dir var)
  file(READ ${WORK}/${dir}/result.json doc)
  string(JSON value ERROR_VARIABLE err ${op} "${doc}" results ${ARGN})
  if(err)
    message(FATAL_ERROR "${dir}/result.json: results ${ARGN}: ${err}")
  endif()
  set(${var} "${value}" PARENT_SCOPE)
endfunction()

# Fails unless `text` matches the regular expression.
function(expect_match text regex)
  if(NOT "${text}" MATCHES "${regex}")
    message(FATAL_ERROR "output does not match '${regex}'")
  endif()
endfunction()

# Compares a floating-point number with a bound: expect_number(<value> GREATER|LESS|EQUAL <bound> <what>).
function(expect_number value op bound what)
  if(NOT value MATCHES "^-?[0-9.]+([eE][-+]?[0-9]+)?$")
    message(FATAL_ERROR "${what} = '${value}' is not a finite number")
  endif()
  # CMake compares decimal strings as numbers (floating point) in if(... GREATER ...).
  if(NOT (value ${op} bound))
    message(FATAL_ERROR "${what} = ${value}, expected ${op} ${bound}")
  endif()
  message(STATUS "ok: ${what} = ${value} (${op} ${bound})")
endfunction()
