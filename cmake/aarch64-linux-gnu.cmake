# CMake toolchain file: cross-compile BenchScope for ARM64 (aarch64 Linux: Jetson, Raspberry Pi) on an x86 Debian 12
# host, and run what it builds (tests, the CLI) under qemu-user. scripts/dev cross-test arm64 uses it:
#   cmake -S . -B build-arm64 -G Ninja --toolchain cmake/aarch64-linux-gnu.cmake \
#         -DBENCHSCOPE_SYSROOT=$PWD/build-arm64/sysroot -DBENCHSCOPE_GUI=OFF
# The sysroot is Debian 12 arm64 packages unpacked into a folder (scripts/dev makes it). Multiarch arm64 -dev packages
# installed beside the amd64 ones cannot do: libopencv-imgcodecs406:arm64 needs libgdal32:arm64, which is not
# co-installable with the amd64 libgdal32 (and apt would remove the amd64 OpenCV the main build needs).
# SPDX-License-Identifier: GPL-3.0-or-later
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

# GCC 11 by default: JetPack 6's Ubuntu 22.04 compiles with GCC 11, so this one build also proves the code builds
# with it (issue #38). -DBENCHSCOPE_CROSS_GCC_SUFFIX= (empty) takes Debian's default cross GCC (12).
set(BENCHSCOPE_CROSS_GCC_SUFFIX "-11" CACHE STRING "Suffix of aarch64-linux-gnu-g++<suffix>")
set(BENCHSCOPE_SYSROOT "" CACHE PATH "Folder with the Debian arm64 packages unpacked (scripts/dev makes it)")
if(NOT BENCHSCOPE_SYSROOT OR NOT EXISTS "${BENCHSCOPE_SYSROOT}/usr/lib/aarch64-linux-gnu")
  message(FATAL_ERROR "aarch64 cross build: -DBENCHSCOPE_SYSROOT=<folder> must name an arm64 sysroot "
                      "(scripts/dev cross-test arm64 makes one in build-arm64/sysroot); got '${BENCHSCOPE_SYSROOT}'")
endif()
# try_compile projects see only what is forwarded here.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES BENCHSCOPE_SYSROOT BENCHSCOPE_CROSS_GCC_SUFFIX)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc${BENCHSCOPE_CROSS_GCC_SUFFIX})
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++${BENCHSCOPE_CROSS_GCC_SUFFIX})
set(CMAKE_SYSROOT "${BENCHSCOPE_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH "${BENCHSCOPE_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)  # build tools (moc, ccache) are the host's
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# Qt's build tools (moc for the Qt Test suites) run on the host: Qt 6 finds them through QT_HOST_PATH, here the amd64
# qt6-base-dev-tools the main build uses already (same Qt version as the arm64 libraries: both Debian 12's).
set(QT_HOST_PATH "/usr" CACHE PATH "Where the host's Qt 6 build tools live")
set(QT_HOST_PATH_CMAKE_DIR "/usr/lib/x86_64-linux-gnu/cmake" CACHE PATH "The host Qt 6's CMake packages")

# ctest and add_custom_command run the aarch64 programs through qemu-user, with the sysroot as their root ("/").
# QEMU_LD_PREFIX rather than -L: the environment also reaches programs a test starts where the kernel hands aarch64
# programs to qemu (binfmt_misc). QEMU_CPU, where a test sets it, picks the emulated core
# (tests/core/vision/CMakeLists.txt: one demosaic run per Highway target set).
find_program(BENCHSCOPE_QEMU_AARCH64 qemu-aarch64)
if(BENCHSCOPE_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR "env;QEMU_LD_PREFIX=${BENCHSCOPE_SYSROOT};${BENCHSCOPE_QEMU_AARCH64}")
endif()
