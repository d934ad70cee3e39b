# SPDX-License-Identifier: MIT
# Warnings are set per target, never in CMAKE_CXX_FLAGS. Not -Wpedantic: the exact predicates use
# __int128, a GNU extension (CMAKE_CXX_EXTENSIONS is on for it).
function(roiclip_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow -Wconversion -Wno-sign-conversion)
endfunction()
