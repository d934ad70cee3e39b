# Warnings are set per target, never in CMAKE_CXX_FLAGS.
function(roiclip_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wno-pedantic)
endfunction()
