# SPDX-License-Identifier: MIT
# cmake -DDIR=<prefix>/lib/cmake/roiclip -P check_no_absolute_paths.cmake
# Fails when an installed roiclip CMake file names an absolute include folder or library file of
# the build machine: consumers must get those from their own find_package() of the dependency.
file(GLOB files "${DIR}/*.cmake")
if(NOT files)
  message(FATAL_ERROR "no CMake files in ${DIR}")
endif()
set(bad "")
foreach(f IN LISTS files)
  file(STRINGS "${f}" lines)
  foreach(line IN LISTS lines)
    # A path that starts a token ("${_IMPORT_PREFIX}/lib/..." is relative to the prefix).
    if(line MATCHES "(^|[ \";:<])/[^ \";]*(/include|\\.so|\\.a)([\";/. >]|$)")
      list(APPEND bad "${f}: ${line}")
    endif()
  endforeach()
endforeach()
if(bad)
  list(JOIN bad "\n" text)
  message(FATAL_ERROR "absolute paths in the installed package:\n${text}")
endif()
list(LENGTH files n)
message(STATUS "${n} files checked, no absolute include or library paths")
