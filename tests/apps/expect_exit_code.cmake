# SPDX-License-Identifier: MIT
# cmake -DCLI=<exe> -DARGS=<a|b|c> -DEXPECTED=<code> -P expect_exit_code.cmake
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND ${CLI} ${args} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL EXPECTED)
  message(FATAL_ERROR "exit code ${code}, expected ${EXPECTED}\nstdout: ${out}\nstderr: ${err}")
endif()
if(NOT out STREQUAL "")
  message(FATAL_ERROR "unexpected output on stdout: ${out}")
endif()
message(STATUS "exit code ${code} as expected; stderr: ${err}")
