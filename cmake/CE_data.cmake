# SPDX-License-Identifier: GPL-3.0-or-later
# Test/example meshes from CGAL's data archive (Debian package libcgal-demo).
#
# ce_extract_data([ARCHIVE <path>] [DESTINATION <dir>])
#
# Extracts data/meshes/bunny00.off (required) and, when the archive holds them,
# data/meshes/elephant.off, data/meshes/armadillo.off and
# data/meshes/ChineseDragon-10kv.off into <dir>/data/
# (default <dir> = PROJECT_BINARY_DIR, i.e. CMAKE_BINARY_DIR for a top-level
# build) at configure time. Files already extracted are not extracted again.
#
# Sets, in the caller's scope and in the cache:
#   CE_DATA_DIR        <dir>/data   (meshes are in ${CE_DATA_DIR}/meshes/)
#   CE_DATA_AVAILABLE  ON when bunny00.off is available, OFF otherwise
#
# ce_target_data_definitions(<target>) adds the compile definitions
#   CE_DATA_DIR="<dir>/data"  and  CE_DATA_AVAILABLE=0|1
# to <target> (PRIVATE).

set(CE_CGAL_DATA_ARCHIVE "/usr/share/doc/libcgal-dev/data.tar.gz"
    CACHE FILEPATH "CGAL data archive (Debian package libcgal-demo) holding data/meshes/*.off")

function(ce_extract_data)
  cmake_parse_arguments(ARG "" "ARCHIVE;DESTINATION" "" ${ARGN})
  if(NOT ARG_ARCHIVE)
    set(ARG_ARCHIVE "${CE_CGAL_DATA_ARCHIVE}")
  endif()
  if(NOT ARG_DESTINATION)
    set(ARG_DESTINATION "${PROJECT_BINARY_DIR}")
  endif()

  set(data_dir "${ARG_DESTINATION}/data")
  set(required  data/meshes/bunny00.off)
  # ChineseDragon-10kv.off: a fourth real mesh for the speed benchmarks.
  set(optional  data/meshes/elephant.off data/meshes/armadillo.off data/meshes/ChineseDragon-10kv.off)

  # Which of the wanted files are still missing?
  set(missing "")
  foreach(f IN LISTS required optional)
    if(NOT EXISTS "${ARG_DESTINATION}/${f}")
      list(APPEND missing "${f}")
    endif()
  endforeach()

  if(missing AND NOT EXISTS "${ARG_ARCHIVE}")
    message(WARNING
      "CGAL data archive '${ARG_ARCHIVE}' not found: meshes (${missing}) are not extracted; "
      "examples and tests that read them will fail or skip. Install the Debian package "
      "libcgal-demo (scripts/install_dependencies.sh) or set CE_CGAL_DATA_ARCHIVE.")
  elseif(missing)
    # List the archive (tar tzf) to know which optional meshes it holds.
    execute_process(
      COMMAND "${CMAKE_COMMAND}" -E tar tzf "${ARG_ARCHIVE}"
      OUTPUT_VARIABLE listing
      RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(WARNING "Cannot list '${ARG_ARCHIVE}' (exit ${rc}); no mesh extracted.")
    else()
      string(REPLACE "\n" ";" listing "${listing}")
      set(to_extract "")
      foreach(f IN LISTS missing)
        if("${f}" IN_LIST listing)
          list(APPEND to_extract "${f}")
        elseif("${f}" IN_LIST required)
          message(WARNING "'${ARG_ARCHIVE}' does not contain ${f}.")
        else()
          message(STATUS "'${ARG_ARCHIVE}' does not contain ${f} (optional), skipped.")
        endif()
      endforeach()
      if(to_extract)
        file(MAKE_DIRECTORY "${ARG_DESTINATION}")
        message(STATUS "Extracting from ${ARG_ARCHIVE}: ${to_extract}")
        execute_process(
          COMMAND "${CMAKE_COMMAND}" -E tar xzf "${ARG_ARCHIVE}" -- ${to_extract}
          WORKING_DIRECTORY "${ARG_DESTINATION}"
          RESULT_VARIABLE rc
          ERROR_VARIABLE err)
        if(NOT rc EQUAL 0)
          message(WARNING "Extracting meshes from '${ARG_ARCHIVE}' failed (exit ${rc}): ${err}")
        endif()
      endif()
    endif()
  endif()

  if(EXISTS "${ARG_DESTINATION}/data/meshes/bunny00.off")
    set(available ON)
    message(STATUS "CE_DATA_DIR = ${data_dir}")
  else()
    set(available OFF)
    message(STATUS "CE_DATA_DIR = ${data_dir} (bunny00.off NOT available)")
  endif()

  set(CE_DATA_DIR "${data_dir}" CACHE PATH
      "Directory holding the extracted meshes (meshes/*.off); set by ce_extract_data()" FORCE)
  set(CE_DATA_AVAILABLE ${available} CACHE BOOL
      "Whether the meshes were extracted; set by ce_extract_data()" FORCE)
  mark_as_advanced(CE_DATA_DIR CE_DATA_AVAILABLE)
  set(CE_DATA_DIR "${data_dir}" PARENT_SCOPE)
  set(CE_DATA_AVAILABLE ${available} PARENT_SCOPE)
endfunction()

function(ce_target_data_definitions target)
  if(CE_DATA_AVAILABLE)
    set(avail 1)
  else()
    set(avail 0)
  endif()
  target_compile_definitions(${target} PRIVATE
    "CE_DATA_DIR=\"${CE_DATA_DIR}\""
    "CE_DATA_AVAILABLE=${avail}")
endfunction()
