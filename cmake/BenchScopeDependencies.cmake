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
# Highway: portable SIMD with run-time dispatch (core/vision/demosaic/bayer_simd.cpp).
find_package(hwy QUIET)
benchscope_require(hwy "libhwy-dev")
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
set(_qt_components Core Gui Widgets OpenGL OpenGLWidgets Sql Svg PrintSupport Concurrent Test)
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
