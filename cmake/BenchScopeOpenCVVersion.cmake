# SPDX-License-Identifier: GPL-3.0-or-later
# The OpenCV versions BenchScope builds against: 4.5.4 (Ubuntu 22.04, the base of JetPack 6; JetPack 5 has 4.5 too)
# up to the last 4.x. The code uses nothing newer than 4.5.4: every OpenCV-using source was compiled against
# Ubuntu 22.04's 4.5.4 headers (docs/robot.md). Included by BenchScopeDependencies.cmake; also run in script mode by
# the test tests/cmake (cmake -DOPENCV_VERSION=x -P ...).
set(BENCHSCOPE_OPENCV_MINIMUM 4.5.4)

function(benchscope_check_opencv_version version where)
  if(version VERSION_LESS BENCHSCOPE_OPENCV_MINIMUM OR NOT version VERSION_LESS 5)
    message(FATAL_ERROR "BenchScope needs OpenCV ${BENCHSCOPE_OPENCV_MINIMUM} or a later 4.x; found ${version} "
                        "(${where}). Ubuntu 22.04 / JetPack 6: apt install libopencv-dev (4.5.4; JetPack's own is 4.8); "
                        "Debian 12: libopencv-dev (4.6). Point CMake at another with -DOpenCV_DIR=<dir with OpenCVConfig.cmake>.")
  endif()
endfunction()

if(CMAKE_SCRIPT_MODE_FILE AND DEFINED OPENCV_VERSION)
  benchscope_check_opencv_version("${OPENCV_VERSION}" "given on the command line")
  message(STATUS "OpenCV ${OPENCV_VERSION}: accepted")
endif()
