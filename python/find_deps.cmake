# SPDX-License-Identifier: MIT
# Decides the default of ROICLIP_BUILD_PYTHON (included by the top-level CMakeLists.txt before the
# option): ON when roiclip is the top-level project and Debian's Python 3 (/usr/bin/python3 with
# python3-dev) and pybind11 (pybind11-dev, its CMake config) are found; OFF otherwise, with a
# STATUS line saying why. Nothing is downloaded.
set(ROICLIP_PYTHON_DEFAULT OFF)
set(_roiclip_python_off "")
if(NOT PROJECT_IS_TOP_LEVEL)
  set(_roiclip_python_off "roiclip is not the top-level project")
elseif(ROICLIP_SANITIZE OR ROICLIP_BUILD_FUZZ)
  # An instrumented module only loads into python3 with the sanitizer runtime preloaded.
  set(_roiclip_python_off "sanitizer/fuzzer build")
elseif(NOT ROICLIP_BUILD_OPENCV OR NOT ROICLIP_BUILD_APRILTAG)
  set(_roiclip_python_off "the module needs roiclip::opencv and roiclip::apriltag")
else()
  # Debian's interpreter, not whatever python3 comes first on PATH (pyenv, venvs): the module is
  # built for it, and python3-numpy, -opencv, -shapely, -pytest belong to it.
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter of the roiclip module")
  endif()
  find_package(Python3 COMPONENTS Interpreter Development QUIET)
  if(NOT Python3_FOUND)
    set(_roiclip_python_off "Python 3 with its headers not found (Debian: python3-dev)")
  else()
    find_package(pybind11 2.6 CONFIG QUIET)
    if(NOT pybind11_FOUND)
      set(_roiclip_python_off "pybind11 not found (Debian: pybind11-dev)")
    else()
      set(ROICLIP_PYTHON_DEFAULT ON)
    endif()
  endif()
endif()
if(NOT ROICLIP_PYTHON_DEFAULT)
  message(STATUS "roiclip: ROICLIP_BUILD_PYTHON defaults to OFF: ${_roiclip_python_off}")
endif()
