# SPDX-License-Identifier: MIT
# roiclip_add_library(COMPONENT SOURCES file... [PUBLIC dep...] [PRIVATE dep...])
#
# One library component: target roiclip_COMPONENT, alias roiclip::COMPONENT, warnings, install,
# and its own export file (roiclip-COMPONENT-targets.cmake), so that
# find_package(roiclip COMPONENTS core) loads the core alone and needs only its dependencies
# (cmake/roiclipConfig.cmake.in). Header-only private dependencies go in PRIVATE wrapped in
# $<BUILD_INTERFACE:...>: a static library's private target dependencies are otherwise exported
# as link-only requirements that every consumer would have to find.
#
# Static by default; shared with -DBUILD_SHARED_LIBS=ON, as libroiclip_COMPONENT.so.VERSION with
# SOVERSION MAJOR.MINOR while the major version is 0 (every 0.x minor version may break the ABI:
# 0.2.x share libroiclip_core.so.0.2), MAJOR from 1.0 on. Symbols keep the default visibility.
# Installed shared libraries find each other through RPATH $ORIGIN (all in one folder), so a
# program linked against libroiclip_opencv.so in any prefix loads libroiclip_core.so from it too.
if(roiclip_VERSION_MAJOR EQUAL 0)
  set(ROICLIP_SOVERSION ${roiclip_VERSION_MAJOR}.${roiclip_VERSION_MINOR})
else()
  set(ROICLIP_SOVERSION ${roiclip_VERSION_MAJOR})
endif()
function(roiclip_add_library component)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  set(target roiclip_${component})
  add_library(${target} ${ARG_SOURCES})
  add_library(roiclip::${component} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${component} OUTPUT_NAME roiclip_${component}
                                             POSITION_INDEPENDENT_CODE ON
                                             VERSION ${roiclip_VERSION}
                                             SOVERSION ${ROICLIP_SOVERSION}
                                             INSTALL_RPATH "$ORIGIN")
  target_link_libraries(${target} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  roiclip_set_warnings(${target})
  install(TARGETS ${target} EXPORT roiclip_${component}_targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(EXPORT roiclip_${component}_targets NAMESPACE roiclip::
          FILE roiclip-${component}-targets.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/roiclip)
  set_property(GLOBAL APPEND PROPERTY ROICLIP_COMPONENTS ${component})
endfunction()
