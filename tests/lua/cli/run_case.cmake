# Command-line tests of `paddy` (CTest: cli.<case>). Each case writes its Lua script(s) into a
# fresh work directory, runs the built executable and checks exit code, messages and files.
#   cmake -DPADDY=<exe> -DCASE=<name> -DWORK=<dir> -P run_case.cmake
cmake_minimum_required(VERSION 3.20)

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# A small, fast experiment: 40 spheres settling in a box on a floor.
set(BASE_SCRIPT [=[
local P = paddy.parameters{
  n = {default = 40, type = "integer", min = 1, max = 1000, description = "number of particles"},
  duration = {default = 0.002, unit = "s", min = 0.0001, max = 1, description = "simulated time"},
  mode = {default = "a", choices = {"a", "b"}, description = "a string parameter"},
  verbose = {default = false, description = "a boolean parameter"},
}
local sim = paddy.simulation{threads = paddy.threads}
local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
sim:interaction(m, m, {normal = "hertz", damping = "hertz_mindlin", tangential = "mindlin",
                       restitution = 0.5, friction = 0.3})
sim:add_wall{type = "plane", point = {0, 0, 0}, normal = {0, 0, 1}, material = m}
local placed = sim:fill{region = {type = "box", min = {0, 0, 0}, max = {0.02, 0.02, 0.02}},
                        radius = 0.001, material = m, count = P.n, seed = paddy.seed}
local calls = 0
sim:run{duration = P.duration, every = P.duration / 4, snapshot_every = P.duration / 2,
        callback = function(s) calls = calls + 1 return true end}
paddy.result{placed = placed, calls = calls, ke = sim:kinetic_energy(), mode = P.mode,
             nested = {list = {1, 2, 3}, name = "x"}, hash = sim:state_hash()}
]=])

include(${CMAKE_CURRENT_LIST_DIR}/../../case_helpers.cmake)  # run_paddy, expect_code, expect_match

function(expect_no_result dir)
  if(EXISTS ${dir}/result.json)
    message(FATAL_ERROR "${dir}/result.json exists after a failed run")
  endif()
  if(NOT EXISTS ${dir}/error.json)
    message(FATAL_ERROR "${dir}/error.json missing after a failed run")
  endif()
  file(READ ${dir}/error.json err)
  string(JSON status GET "${err}" status)
  if(NOT status STREQUAL "failed")
    message(FATAL_ERROR "error.json status is '${status}'")
  endif()
endfunction()

if(CASE STREQUAL "version")
  run_paddy(code se --version)
  expect_code(${code} 0)
  expect_match("${LAST_STDOUT}" "paddy [0-9]+\\.[0-9]+")

elseif(CASE STREQUAL "plugins")
  run_paddy(code se plugins)
  expect_code(${code} 0)
  expect_match("${LAST_STDOUT}" "search path")
  expect_match("${LAST_STDOUT}" "hertz")
  expect_match("${LAST_STDOUT}" "restitution")

elseif(CASE STREQUAL "syntax_error")
  file(WRITE ${WORK}/broken.lua "local a = 1\nlocal b = 2\nlocal c = = 3\n")
  run_paddy(code se run broken.lua --out out)
  expect_code(${code} 2)
  expect_match("${se}" "broken\\.lua:3:")
  expect_no_result(${WORK}/out)

elseif(CASE STREQUAL "callback_error")
  string(REPLACE "calls = calls + 1 return true" "calls = calls + 1\nif calls == 2 then error('boom in callback') end\nreturn true"
         script "${BASE_SCRIPT}")
  file(WRITE ${WORK}/cb.lua "${script}")
  run_paddy(code se run cb.lua --out out)
  expect_code(${code} 2)
  expect_match("${se}" "cb\\.lua:17: boom in callback")
  expect_no_result(${WORK}/out)

elseif(CASE STREQUAL "binding_error_line")
  # A C++ exception inside a binding is reported at the calling line of the script.
  file(WRITE ${WORK}/bad_material.lua
       "local sim = paddy.simulation{}\n\nlocal m = sim:material{name = 'x', density = -5, shear_modulus = 1e6, poisson = 0.3}\n")
  run_paddy(code se run bad_material.lua --out out)
  expect_code(${code} 2)
  expect_match("${se}" "bad_material\\.lua:3:")
  expect_no_result(${WORK}/out)

elseif(CASE STREQUAL "integration_scheme")
  # sim:integration selects the scheme and returns its name; a name it does not know is refused
  # at the calling line, with the choices.
  file(WRITE ${WORK}/scheme.lua
       "local sim = paddy.simulation{}\nassert(sim:integration() == 'velocity_verlet')\nassert(sim:integration('euler') == 'euler')\nassert(sim:integration() == 'euler')\nassert(sim:integration('velocity_verlet') == 'velocity_verlet')\n")
  run_paddy(code se run scheme.lua --out out_ok)
  expect_code(${code} 0)
  file(WRITE ${WORK}/bad_scheme.lua "local sim = paddy.simulation{}\n\nsim:integration('leapfrog')\n")
  run_paddy(code se run bad_scheme.lua --out out_bad)
  expect_code(${code} 2)
  expect_match("${se}" "bad_scheme\\.lua:3:")
  expect_match("${se}" "'leapfrog' is not a scheme; choose velocity_verlet or euler")
  expect_no_result(${WORK}/out_bad)

elseif(CASE STREQUAL "unknown_option")
  file(WRITE ${WORK}/typo.lua "local sim = paddy.simulation{gravty = {0, 0, -9.81}}\n")
  run_paddy(code se run typo.lua --out out)
  expect_code(${code} 2)
  expect_match("${se}" "typo\\.lua:1:.*unknown option 'gravty'.*gravity")

elseif(CASE STREQUAL "unknown_set")
  file(WRITE ${WORK}/base.lua "${BASE_SCRIPT}")
  run_paddy(code se run base.lua --out out --set nn=5)
  expect_code(${code} 2)
  expect_match("${se}" "unknown parameter 'nn'")
  expect_match("${se}" "duration, mode, n, verbose")
  expect_no_result(${WORK}/out)

elseif(CASE STREQUAL "set_out_of_range")
  file(WRITE ${WORK}/base.lua "${BASE_SCRIPT}")
  run_paddy(code se run base.lua --out out --set n=5000)
  expect_code(${code} 2)
  expect_match("${se}" "'n' = 5000 is outside the allowed range \\[1, 1000\\]")
  run_paddy(code se run base.lua --out out --set duration=fast)
  expect_code(${code} 2)
  expect_match("${se}" "'duration' needs a number")
  run_paddy(code se run base.lua --out out --set n=2.5)
  expect_code(${code} 2)
  expect_match("${se}" "'n' needs an integer")
  run_paddy(code se run base.lua --out out --set mode=c)
  expect_code(${code} 2)
  expect_match("${se}" "'mode' = 'c' is not one of the allowed values a\\|b")
  run_paddy(code se run base.lua --out out --set verbose=maybe)
  expect_code(${code} 2)
  run_paddy(code se run base.lua --out out --set novalue)
  expect_code(${code} 2)
  expect_match("${se}" "expected name=value")

elseif(CASE STREQUAL "unknown_model")
  string(REPLACE "normal = \"hertz\"" "normal = \"no_such_model\"" script "${BASE_SCRIPT}")
  file(WRITE ${WORK}/model.lua "${script}")
  run_paddy(code se run model.lua --out out)
  expect_code(${code} 2)
  expect_match("${se}" "model\\.lua:9:")
  expect_match("${se}" "no_such_model")
  expect_match("${se}" "jkr")  # the engine lists the available normal models
  expect_no_result(${WORK}/out)

elseif(CASE STREQUAL "help")
  file(WRITE ${WORK}/base.lua "${BASE_SCRIPT}")
  run_paddy(code se run base.lua --help)
  expect_code(${code} 0)
  expect_match("${LAST_STDOUT}" "duration +0\\.002 +s +\\[0\\.0001, 1\\] +simulated time")
  expect_match("${LAST_STDOUT}" "n +40 +\\[1, 1000\\] +number of particles")
  expect_match("${LAST_STDOUT}" "mode +a +a\\|b")
  expect_match("${LAST_STDOUT}" "verbose +false +true\\|false")
  if(EXISTS ${WORK}/out)
    message(FATAL_ERROR "--help created an output directory")
  endif()

elseif(CASE STREQUAL "success")
  file(WRITE ${WORK}/base.lua "${BASE_SCRIPT}")
  run_paddy(code se run base.lua --out out --set n=20 --set mode=b --threads 1 --seed 7)
  expect_code(${code} 0)
  if(EXISTS ${WORK}/out/error.json)
    message(FATAL_ERROR "error.json after a successful run")
  endif()
  file(READ ${WORK}/out/result.json doc)
  string(JSON status GET "${doc}" status)
  string(JSON placed GET "${doc}" results placed)
  string(JSON calls GET "${doc}" results calls)
  string(JSON mode GET "${doc}" results mode)
  string(JSON third GET "${doc}" results nested list 2)
  string(JSON n GET "${doc}" metadata parameters n)
  string(JSON seed GET "${doc}" metadata seed)
  string(JSON threads GET "${doc}" metadata threads)
  string(JSON particles GET "${doc}" metadata particles)
  string(JSON steps GET "${doc}" metadata steps)
  string(JSON t GET "${doc}" metadata simulated_time)
  string(JSON pps GET "${doc}" metadata particle_steps_per_second)
  string(JSON version GET "${doc}" metadata paddy_version)
  string(JSON wall GET "${doc}" metadata wall_time)
  string(JSON plugin GET "${doc}" metadata plugins 0 path)
  string(JSON hash GET "${doc}" metadata final_state_hash)
  string(JSON script_hash GET "${doc}" results hash)
  foreach(check "status STREQUAL complete" "placed EQUAL 20" "calls EQUAL 4" "mode STREQUAL b" "third EQUAL 3"
                "n EQUAL 20" "seed EQUAL 7" "threads EQUAL 1" "particles EQUAL 20" "steps GREATER 0"
                "pps GREATER 0" "hash STREQUAL script_hash")
    separate_arguments(cond UNIX_COMMAND "${check}")
    if(NOT (${cond}))
      message(FATAL_ERROR "result.json check failed: ${check}")
    endif()
  endforeach()
  expect_match("${plugin}" "libpaddy_hertz_mindlin")
  # Two snapshots and the initial state, all listed in the XDMF index.
  file(GLOB snaps ${WORK}/out/snapshots/snap_*.h5)
  list(LENGTH snaps nsnaps)
  if(NOT nsnaps EQUAL 3)
    message(FATAL_ERROR "expected 3 snapshots, found ${nsnaps}")
  endif()
  file(READ ${WORK}/out/snapshots/particles.xmf xmf)
  expect_match("${xmf}" "snap_000002\\.h5:/particles/position")

elseif(CASE STREQUAL "stale_result_removed")
  file(WRITE ${WORK}/base.lua "${BASE_SCRIPT}")
  run_paddy(code se run base.lua --out out --set n=5)
  expect_code(${code} 0)
  if(NOT EXISTS ${WORK}/out/result.json)
    message(FATAL_ERROR "no result.json after a successful run")
  endif()
  run_paddy(code se run base.lua --out out --set n=0)
  expect_code(${code} 2)
  expect_no_result(${WORK}/out)

elseif(CASE STREQUAL "determinism")
  file(WRITE ${WORK}/base.lua "${BASE_SCRIPT}")
  set(hashes "")
  foreach(run a b c)
    set(seed 3)
    if(run STREQUAL "c")
      set(seed 4)
    endif()
    run_paddy(code se run base.lua --out out_${run} --seed ${seed} --threads 2 --set duration=0.004)
    expect_code(${code} 0)
    file(READ ${WORK}/out_${run}/result.json doc)
    string(JSON h_${run} GET "${doc}" metadata final_state_hash)
  endforeach()
  if(NOT h_a STREQUAL h_b)
    message(FATAL_ERROR "same seed and threads gave different final states: ${h_a} vs ${h_b}")
  endif()
  if(h_a STREQUAL h_c)
    message(FATAL_ERROR "a different seed gave the same final state")
  endif()
  # One thread: two runs agree with each other (not necessarily with two threads: the force sums
  # are added in another order).
  foreach(run d e)
    run_paddy(code se run base.lua --out out_${run} --seed 3 --threads 1 --set duration=0.004)
    expect_code(${code} 0)
    file(READ ${WORK}/out_${run}/result.json doc)
    string(JSON h_${run} GET "${doc}" metadata final_state_hash)
  endforeach()
  if(NOT h_d STREQUAL h_e)
    message(FATAL_ERROR "same seed with 1 thread gave different final states: ${h_d} vs ${h_e}")
  endif()

elseif(CASE STREQUAL "require_path")
  file(WRITE ${WORK}/helper.lua "return {answer = 42}\n")
  file(WRITE ${WORK}/main.lua "local h = require('helper')\npaddy.result{answer = h.answer, same = require('paddy') == paddy}\n")
  run_paddy(code se run main.lua --out out)
  expect_code(${code} 0)
  file(READ ${WORK}/out/result.json doc)
  string(JSON answer GET "${doc}" results answer)
  string(JSON same GET "${doc}" results same)
  if(NOT answer EQUAL 42 OR NOT same STREQUAL "ON")
    message(FATAL_ERROR "require from the script directory failed")
  endif()

elseif(CASE STREQUAL "instability")
  # Particles created overlapping by 0.8 radius: the engine refuses to step (exit code 3).
  file(WRITE ${WORK}/overlap.lua [=[
local sim = paddy.simulation{}
local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
sim:interaction(m, m, {normal = "hertz", restitution = 0.5, friction = 0.3})
sim:add_particle{pos = {0, 0, 0}, radius = 0.001, material = m}
sim:add_particle{pos = {0.0012, 0, 0}, radius = 0.001, material = m}
sim:run{steps = 10}
]=])
  run_paddy(code se run overlap.lua --out out)
  expect_code(${code} 3)
  expect_match("${se}" "overlap\.lua:6:.*overlap")
  expect_no_result(${WORK}/out)

elseif(CASE STREQUAL "doe_preload")
  file(WRITE ${WORK}/doe.lua "local doe = require('paddy.doe')\npaddy.result{ok = type(doe.design) == 'function'}\n")
  run_paddy(code se run doe.lua --out out)
  expect_code(${code} 0)
  file(READ ${WORK}/out/result.json doc)
  string(JSON ok GET "${doc}" results ok)
  if(NOT ok STREQUAL "ON")
    message(FATAL_ERROR "require('paddy.doe') did not give the DOE module")
  endif()

elseif(CASE STREQUAL "checkpoint_restart")
  # A restarted simulation continues bit for bit; remove_if and a second snapshot directory.
  file(WRITE ${WORK}/ck.lua [=[
local function setup()
  local sim = paddy.simulation{threads = 1}
  local m = sim:material{name = "mud", density = 1680, shear_modulus = 1e6, poisson = 0.5}
  sim:interaction("mud", "mud", {normal = "jkr", rolling = "constant_torque", restitution = 0.5, friction = 0.3, rolling_friction = 0.1, surface_energy = 0.1})
  sim:add_wall{type = "plane", material = m}
  return sim, m
end
local a, m = setup()
a:fill{region = {type = "cone", radius_bottom = 0.01, radius_top = 0.005, height = 0.02}, radius = {dist = "normal", mean = 0.001, std = 0.0001}, material = m, volume_fraction = 0.3}
a:run{steps = 50, progress = false}
a:checkpoint("ck.h5")
a:run{steps = 50, progress = false}
local b = setup()
b:restart("ck.h5")
b:run{steps = 50, progress = false}
local hb = b:state_hash()
local removed = b:remove_if(function(i, x, y, z, r) return z > 0.01 end)
paddy.result{a = a:state_hash(), b = hb, n = a:count(), removed = removed, left = b:count(), snap = b:snapshot()}
]=])
  run_paddy(code se run ck.lua --out out)
  expect_code(${code} 0)
  file(READ ${WORK}/out/result.json doc)
  string(JSON a GET "${doc}" results a)
  string(JSON b GET "${doc}" results b)
  string(JSON n GET "${doc}" results n)
  string(JSON removed GET "${doc}" results removed)
  string(JSON left GET "${doc}" results left)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "restart from a checkpoint diverged: ${a} vs ${b}")
  endif()
  math(EXPR expected "${n} - ${removed}")
  if(NOT left EQUAL expected OR removed EQUAL 0)
    message(FATAL_ERROR "remove_if: ${n} - ${removed} != ${left}")
  endif()
  if(NOT EXISTS ${WORK}/out/ck.h5 OR NOT EXISTS ${WORK}/out/snapshots_2/particles.xmf)
    message(FATAL_ERROR "checkpoint or second snapshot directory missing")
  endif()

elseif(CASE STREQUAL "missing_script")
  run_paddy(code se run does_not_exist.lua --out out)
  expect_code(${code} 2)
  expect_match("${se}" "does_not_exist\\.lua")

else()
  message(FATAL_ERROR "unknown case ${CASE}")
endif()
