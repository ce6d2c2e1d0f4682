# ctest's `install` test (cmake -P): installs the build tree into a fresh prefix, builds the
# consumer project beside this file against it with the same compiler, generator and flags, runs
# it, and runs the installed `pride list --json`. Any failing step fails the test.
#   -DBUILD_DIR= -DWORK_DIR= -DCONSUMER_DIR= -DGENERATOR= -DCXX_COMPILER= [-DCXX_LAUNCHER=]
#   [-DCXX_FLAGS=] [-DCONFIG=] [-DPRIDE_SANITIZE=]
cmake_minimum_required(VERSION 3.22)
foreach(v IN ITEMS BUILD_DIR WORK_DIR CONSUMER_DIR GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${v} OR "${${v}}" STREQUAL "")
    message(FATAL_ERROR "driver.cmake needs -D${v}=...")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()

# Runs a command; on a non-zero exit prints its output and stops the test.
function(step what)
  message(STATUS "install test: ${what}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install test: ${what} failed (${rc}):\n${ARGN}\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer)
file(REMOVE_RECURSE ${WORK_DIR})

step("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG})
foreach(f IN ITEMS include/pride/engine/run.hpp include/pride/framework/problem.hpp
                   include/pride/algorithms/parts/swarm/velocity.hpp include/pride/problems/grid/map.hpp
                   include/pride/problems/continuous/catalog.hpp include/pride/roughset/roughset.hpp
                   include/pride/experiment/campaign/identity.hpp
                   bin/pride)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "install test: ${prefix}/${f} was not installed")
  endif()
endforeach()

set(launcher "")
if(CXX_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
step("configure the consumer"
     ${CMAKE_COMMAND} -S ${CONSUMER_DIR} -B ${consumer_build} -G ${GENERATOR}
     -DCMAKE_CXX_COMPILER=${CXX_COMPILER} ${launcher} "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}"
     -DCMAKE_BUILD_TYPE=${CONFIG} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
     -DCMAKE_EXPORT_COMPILE_COMMANDS=ON)

# The package found must be the one just installed, not a build tree or another installation.
file(STRINGS ${consumer_build}/CMakeCache.txt pride_dir REGEX "^pride_DIR:")
string(REGEX REPLACE "^pride_DIR:[A-Z]+=" "" pride_dir "${pride_dir}")
file(REAL_PATH "${pride_dir}" pride_dir)
file(REAL_PATH "${prefix}" real_prefix)
string(FIND "${pride_dir}/" "${real_prefix}/" at)
if(NOT at EQUAL 0)
  message(FATAL_ERROR "install test: the consumer found pride in ${pride_dir}, not under ${prefix}")
endif()

step("build the consumer" ${CMAKE_COMMAND} --build ${consumer_build} --config ${CONFIG})

# pride's warning flags (and, unless pride was built with them, sanitizers) are pride's own: they
# must not appear in the consumer's compile command unless the consumer asked for them itself.
file(READ ${consumer_build}/compile_commands.json commands)
set(private_flags -Wall -Wextra -Wpedantic)
if(NOT PRIDE_SANITIZE)
  list(APPEND private_flags -fsanitize)
endif()
foreach(flag IN LISTS private_flags)
  string(FIND "${commands}" "${flag}" in_command)
  string(FIND " ${CXX_FLAGS} " "${flag}" in_own_flags)
  if(NOT in_command EQUAL -1 AND in_own_flags EQUAL -1)
    message(FATAL_ERROR "install test: ${flag} leaked into the consumer's compile command:\n${commands}")
  endif()
endforeach()

find_program(consumer_exe consumer PATHS ${consumer_build} ${consumer_build}/${CONFIG} NO_DEFAULT_PATH REQUIRED)
step("run the consumer" ${consumer_exe})
message("${step_output}")

step("run the installed pride list --json" ${prefix}/bin/pride list --json)
string(JSON algorithms ERROR_VARIABLE json_error LENGTH "${step_output}" algorithms)
if(json_error OR algorithms EQUAL 0)
  message(FATAL_ERROR "install test: pride list --json printed no algorithms (${json_error}):\n${step_output}")
endif()
message(STATUS "install test: passed (the installed pride lists ${algorithms} algorithms)")
