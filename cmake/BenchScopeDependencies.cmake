# Every dependency is found through CMake's own find_package / imported targets. A missing one fails at
# configure time naming the Debian package that provides it (scripts/dev installs them all).
include(CheckLanguage)

macro(benchscope_require pkg debian)
  if(NOT ${pkg}_FOUND)
    message(FATAL_ERROR "BenchScope needs ${pkg}: install the Debian package(s) '${debian}' "
                        "(or run scripts/dev setup).")
  endif()
endmacro()

# --- Needed by core / importers / CLI (no Qt) ---------------------------------------------------------------
find_package(nlohmann_json 3.10 QUIET)
benchscope_require(nlohmann_json "nlohmann-json3-dev")
find_package(SQLite3 QUIET)
benchscope_require(SQLite3 "libsqlite3-dev")
find_package(OpenMP QUIET COMPONENTS CXX)
benchscope_require(OpenMP "libomp-dev (g++ ships libgomp)")
find_package(OpenCL QUIET)
benchscope_require(OpenCL "ocl-icd-opencl-dev opencl-headers pocl-opencl-icd")
# Components are always listed: without them OpenCV's highgui would pull Qt 5 into the process. Found without a
# version so that a too old or too new one is named with the minimum (BenchScopeOpenCVVersion.cmake) instead of
# a bare "not found".
find_package(OpenCV QUIET COMPONENTS core imgproc imgcodecs dnn objdetect calib3d)
benchscope_require(OpenCV "libopencv-dev")
include(BenchScopeOpenCVVersion)
benchscope_check_opencv_version("${OpenCV_VERSION}" "${OpenCV_DIR}")
message(STATUS "BenchScope: OpenCV ${OpenCV_VERSION} (minimum ${BENCHSCOPE_OPENCV_MINIMUM}) from ${OpenCV_DIR}")
# Highway: portable SIMD with run-time dispatch for the demosaic (core/vision/demosaic/bayer_simd.cpp). Optional:
# without it the demosaic runs its scalar definition in row stripes (bayer_portable.cpp), the same result, slower.
# 1.0.0 is the oldest release the code compiles with for both x86 and aarch64 (checked against Highway's tags:
# 0.16 lacks StoreInterleaved3 for all lane types, 0.17 does not compile the NEON static target with GCC 11).
# Debian 12 ships 1.0.3, Ubuntu 24.04 1.0.7; Ubuntu 22.04 (JetPack 6) ships 0.15, too old.
option(BENCHSCOPE_HIGHWAY "Vectorise the demosaic with Highway when Highway >= 1.0 is found" ON)
set(BENCHSCOPE_HIGHWAY_MINIMUM 1.0.0)
set(BENCHSCOPE_HAVE_HIGHWAY OFF)
if(BENCHSCOPE_HIGHWAY)
  find_package(hwy QUIET)
  if(NOT hwy_FOUND)
    message(WARNING "Highway not found: the demosaic uses its portable scalar path (same result, slower). Install "
                    "libhwy-dev ${BENCHSCOPE_HIGHWAY_MINIMUM} or newer (or pass -DBENCHSCOPE_HIGHWAY=OFF to silence this).")
  elseif(NOT hwy_VERSION OR hwy_VERSION VERSION_LESS BENCHSCOPE_HIGHWAY_MINIMUM)
    message(WARNING "Highway ${hwy_VERSION} (${hwy_DIR}) is older than ${BENCHSCOPE_HIGHWAY_MINIMUM}: the demosaic "
                    "uses its portable scalar path (same result, slower). Install Highway ${BENCHSCOPE_HIGHWAY_MINIMUM} "
                    "or newer and point CMake at it (-Dhwy_DIR=<prefix>/lib/cmake/hwy), or pass "
                    "-DBENCHSCOPE_HIGHWAY=OFF to silence this.")
  else()
    set(BENCHSCOPE_HAVE_HIGHWAY ON)
    message(STATUS "Highway ${hwy_VERSION}: the demosaic is vectorised (run-time choice of instruction set)")
  endif()
else()
  message(STATUS "Highway off (-DBENCHSCOPE_HIGHWAY=OFF): the demosaic uses its portable scalar path")
endif()
find_package(Threads REQUIRED)

# CUDA is optional: compiled when a CUDA compiler is found, run only when a GPU is present. -DBENCHSCOPE_CUDA=OFF
# skips it (the sanitizer build does: nvcc-compiled code is not instrumented, and it would only cost build time).
option(BENCHSCOPE_CUDA "Build the CUDA kernels when a CUDA compiler (nvcc) is found" ON)
if(BENCHSCOPE_CUDA)
  check_language(CUDA)
endif()
if(BENCHSCOPE_CUDA AND CMAKE_CUDA_COMPILER)
  set(BENCHSCOPE_HAVE_CUDA_COMPILER ON)
else()
  set(BENCHSCOPE_HAVE_CUDA_COMPILER OFF)
endif()

# --- Needed by the GUI and the tests -------------------------------------------------------------------------
# Without the GUI, the tests (Qt Test suites of the core, the importers and the CLI) need Qt Core and Test only: a
# robot's build (or the aarch64 cross build) then needs no Qt GUI modules.
if(BENCHSCOPE_GUI)
  set(_qt_components Core Gui Widgets OpenGL OpenGLWidgets Sql Svg PrintSupport Concurrent Test)
else()
  set(_qt_components Core Test)
endif()
if(BENCHSCOPE_GUI OR BUILD_TESTING)
  find_package(Qt6 6.4 QUIET COMPONENTS ${_qt_components})
  benchscope_require(Qt6 "qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-svg-dev libqt6sql6-sqlite")
  foreach(c ${_qt_components})
    if(NOT Qt6${c}_FOUND)
      message(FATAL_ERROR "BenchScope needs Qt6::${c}: install 'qt6-base-dev libqt6opengl6-dev qt6-svg-dev'.")
    endif()
  endforeach()
endif()
if(BENCHSCOPE_GUI)
  # Must come after Qt6: its imported target links Qt6::PrintSupport.
  find_package(QCustomPlotQt6 QUIET)
  benchscope_require(QCustomPlotQt6 "libqcustomplot-dev libqcustomplot2.1-qt6")
  # VTK's parallel modules need MPI's C target to exist before VTK is found.
  find_package(MPI QUIET COMPONENTS C)
  # Only Qt-free VTK modules: Debian's VTK Qt modules are built for Qt 5 and must never be linked.
  find_package(VTK 9.1 QUIET COMPONENTS RenderingOpenGL2 RenderingCore InteractionStyle FiltersSources
                                        RenderingFreeType RenderingAnnotation IOImage CommonCore)
  benchscope_require(VTK "libvtk9-dev")
endif()
