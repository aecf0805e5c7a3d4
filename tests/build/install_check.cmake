# cmake -DBUILD_DIR=… -P install_check.cmake: install the build into a fresh prefix, then run the
# installed magnus on the installed demo case from an unrelated directory, with no environment help.
if(NOT BUILD_DIR)
  message(FATAL_ERROR "BUILD_DIR not set")
endif()
set(prefix "${BUILD_DIR}/install-check/prefix")
set(work "${BUILD_DIR}/install-check/elsewhere")
file(REMOVE_RECURSE "${BUILD_DIR}/install-check")
file(MAKE_DIRECTORY "${work}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}"
  RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(ENV{MAGNUS_DATA_DIR} "")
execute_process(COMMAND "${prefix}/bin/magnus" run "${prefix}/share/magnus/cases/spin_ratio_1.toml"
  -o "${work}/demo.h5" WORKING_DIRECTORY "${work}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "installed magnus run failed (${rc}): ${err}")
endif()
if(NOT out MATCHES "Kutta")
  message(FATAL_ERROR "installed magnus run printed no lift summary: ${out}")
endif()
if(NOT EXISTS "${work}/demo.h5")
  message(FATAL_ERROR "installed magnus run wrote no result")
endif()
# The data directory is found relative to the installed binary: the sweep overlays the reference data.
execute_process(COMMAND "${prefix}/bin/magnus" sweep "${prefix}/share/magnus/cases/spin_ratio_1.toml"
  --spin-ratio 0:2:1 -o "${work}/sweep.h5" --plot "${work}/sweep.png"
  WORKING_DIRECTORY "${work}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "installed magnus sweep failed (${rc}): ${err}")
endif()
# The installed binary reads the installed reference data (not the source tree's): the sweep lists it.
if(NOT out MATCHES "Stojkovi" OR err MATCHES "reference data not shown")
  message(FATAL_ERROR "installed magnus sweep did not find its reference data: ${err}")
endif()
file(RENAME "${prefix}/share/magnus/data" "${prefix}/share/magnus/data-moved")
execute_process(COMMAND "${prefix}/bin/magnus" sweep "${prefix}/share/magnus/cases/spin_ratio_1.toml"
  --spin-ratio 0:2:1 WORKING_DIRECTORY "${work}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT err MATCHES "reference data not shown")
  message(FATAL_ERROR "with its data moved away, the installed magnus still found reference data: ${out}")
endif()
message(STATUS "installed magnus ran from ${work}")
