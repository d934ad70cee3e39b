# SPDX-License-Identifier: MIT
# Regenerate the scenes into a scratch directory and require the ground truth to match the
# committed images/ byte for byte, so images/ always is what the generator makes.
# Usage: cmake -DGENERATOR=<exe> -DIMAGES=<dir> -DOUT=<dir> -P check_scenes.cmake
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${GENERATOR} --out ${OUT} RESULT_VARIABLE rc OUTPUT_QUIET)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${GENERATOR} failed (${rc})")
endif()
file(GLOB generated RELATIVE ${OUT} ${OUT}/*.json ${OUT}/*.png)
file(GLOB committed RELATIVE ${IMAGES} ${IMAGES}/*.json ${IMAGES}/*.png)
if(NOT generated STREQUAL committed)
  message(FATAL_ERROR "file lists differ:\n generated: ${generated}\n committed: ${committed}")
endif()
foreach(name IN LISTS generated)
  if(name MATCHES "\\.json$")
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/${name} ${IMAGES}/${name}
                    RESULT_VARIABLE differ)
    if(differ)
      message(FATAL_ERROR "${name}: regenerated ground truth differs from images/${name}")
    endif()
  endif()
endforeach()
message(STATUS "ground truth of ${generated} matches")
