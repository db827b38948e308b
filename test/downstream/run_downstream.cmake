# SPDX-License-Identifier: GPL-3.0-or-later
# Build and run the downstream consumer project test/downstream/.
#
#   cmake -DCE_MODE=find_package|add_subdirectory
#         -DCE_SOURCE_DIR=<repo root> -DCE_BINARY_DIR=<build dir of the repo>
#         -DCE_WORK_DIR=<scratch dir> [-DCE_GENERATOR=<generator>]
#         [-DCE_CXX_COMPILER=<c++>] [-DCE_CONFIG=Release] [-DCE_CGAL_DIR=<CGAL's CMake dir>]
#         -P test/downstream/run_downstream.cmake
#
# find_package:     cmake --install CE_BINARY_DIR --prefix CE_WORK_DIR/prefix,
#                   then configure with -DCMAKE_PREFIX_PATH=CE_WORK_DIR/prefix.
# add_subdirectory: configure with -DCE_USE_ADD_SUBDIRECTORY=ON -DCE_SOURCE_DIR=...
# Then build and run the program; any failure is a FATAL_ERROR (non-zero exit).
cmake_minimum_required(VERSION 3.16)

foreach(var CE_MODE CE_SOURCE_DIR CE_WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "run_downstream.cmake: -D${var}=... is required")
  endif()
endforeach()
if(NOT CE_CONFIG)
  set(CE_CONFIG Release)
endif()

set(project_dir "${CE_SOURCE_DIR}/test/downstream")
set(build_dir   "${CE_WORK_DIR}/build")
set(prefix      "${CE_WORK_DIR}/prefix")

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "downstream (${CE_MODE}): ${step} failed (${rc}):\n  ${ARGN}")
  endif()
endfunction()

file(REMOVE_RECURSE "${build_dir}")
# The consumer is compiled without optimization flags (an empty build type; a multi-config
# generator builds CE_CONFIG): it checks what the package's target propagates, which no flag
# changes, and an optimized build of the umbrella header took a minute of CI per mode.
set(configure_args -S "${project_dir}" -B "${build_dir}" "-DCMAKE_BUILD_TYPE=")
if(CE_GENERATOR)
  list(APPEND configure_args -G "${CE_GENERATOR}")
endif()
if(CE_CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CE_CXX_COMPILER}")
endif()
if(CE_CGAL_DIR)
  # The CGAL the package was configured with, also for find_dependency(CGAL) of the installed config.
  list(APPEND configure_args "-DCGAL_DIR=${CE_CGAL_DIR}")
endif()

if(CE_MODE STREQUAL "find_package")
  if(NOT DEFINED CE_BINARY_DIR)
    message(FATAL_ERROR "run_downstream.cmake: -DCE_BINARY_DIR=... is required for find_package")
  endif()
  file(REMOVE_RECURSE "${prefix}")
  run("install" "${CMAKE_COMMAND}" --install "${CE_BINARY_DIR}" --prefix "${prefix}" --config "${CE_CONFIG}")
  list(APPEND configure_args "-DCMAKE_PREFIX_PATH=${prefix}" "-DCE_EXPECTED_PREFIX=${prefix}")
elseif(CE_MODE STREQUAL "add_subdirectory")
  list(APPEND configure_args -DCE_USE_ADD_SUBDIRECTORY=ON "-DCE_SOURCE_DIR=${CE_SOURCE_DIR}")
else()
  message(FATAL_ERROR "run_downstream.cmake: unknown CE_MODE '${CE_MODE}'")
endif()

run("configure" "${CMAKE_COMMAND}" ${configure_args})
run("build" "${CMAKE_COMMAND}" --build "${build_dir}" --config "${CE_CONFIG}")

set(exe "${build_dir}/ce_downstream")
if(NOT EXISTS "${exe}" AND EXISTS "${build_dir}/${CE_CONFIG}/ce_downstream${CMAKE_EXECUTABLE_SUFFIX}")
  set(exe "${build_dir}/${CE_CONFIG}/ce_downstream${CMAKE_EXECUTABLE_SUFFIX}")
elseif(NOT EXISTS "${exe}" AND EXISTS "${build_dir}/ce_downstream.exe")
  set(exe "${build_dir}/ce_downstream.exe")
endif()
run("run" "${exe}")
message(STATUS "downstream (${CE_MODE}): OK")
