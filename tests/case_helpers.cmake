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

# expect_refusals(<args var> <dir> <setting> <regex> [<dir> <setting> <regex> ...]): for each triple,
# runs ${PADDY} with the arguments in the list variable <args var> plus --out <dir> --set <setting>
# and expects a refusal (exit code 2) whose message matches <regex>.
function(expect_refusals args_var)
  set(cases ${ARGN})
  list(LENGTH cases n)
  math(EXPR rest "${n} % 3")
  if(n EQUAL 0 OR NOT rest EQUAL 0)
    message(FATAL_ERROR "expect_refusals: needs triples of dir, setting and pattern, got ${n} values")
  endif()
  math(EXPR last "${n} - 3")
  foreach(k RANGE 0 ${last} 3)
    math(EXPR k1 "${k} + 1")
    math(EXPR k2 "${k} + 2")
    list(GET cases ${k} dir)
    list(GET cases ${k1} setting)
    list(GET cases ${k2} pattern)
    run_paddy(code se ${${args_var}} --out ${dir} --set ${setting})
    expect_code(${code} 2)
    if(NOT se MATCHES "${pattern}")
      message(FATAL_ERROR "${setting}: expected a refusal with '${pattern}', got: ${se}")
    endif()
  endforeach()
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
