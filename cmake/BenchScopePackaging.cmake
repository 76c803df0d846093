# SPDX-License-Identifier: GPL-3.0-or-later
# Debian packages (CPack DEB) of this build:
#   -DBENCHSCOPE_GUI=OFF  benchscope-cli: /usr/bin/benchscope-cli and /usr/share/benchscope/resources, no Qt, no VTK
#                         (what a robot needs)
#   -DBENCHSCOPE_GUI=ON   benchscope: the Qt 6 GUI, the CLI (which then also renders figures, so it links Qt) and
#                         the resources; it provides, and replaces, benchscope-cli
# Build:   cmake --build build --target package      (build/packages/<name>_<version>_<arch>.deb)
# Install: sudo apt install ./build/packages/benchscope-cli_<version>_<arch>.deb
# Dependencies come from dpkg-shlibdeps (the shared libraries the binaries really link), with the package names and
# versions of the distribution the build ran on: build on the robot's own OS (or a sysroot of it) for the robot.
# Cross builds (the arm64 package): with cmake/aarch64-linux-gnu.cmake the package architecture becomes arm64, and
# dpkg-shlibdeps reads the sysroot's own dpkg database that scripts/cross-test writes (below), with
# aarch64-linux-gnu-objdump (binutils-aarch64-linux-gnu, which the cross compiler brings). Build and test it:
#   scripts/dev cross-test arm64   (then: ctest --test-dir build-arm64 -R test_deb_package_arm64)
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME benchscope)
set(CPACK_PACKAGE_VENDOR "BenchScope")
# The Maintainer field: no project address exists yet, so no made-up e-mail either.
set(CPACK_PACKAGE_CONTACT "BenchScope developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Compare robot computing platforms: FLOPS, power and the vision pipeline")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_BINARY_DIR}/packages)
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)

set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL ${BENCHSCOPE_INSTALL_COMPONENT})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # <name>_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_CLI_PACKAGE_NAME benchscope-cli)
set(CPACK_DEBIAN_CLI_DESCRIPTION
  "BenchScope command line (headless, no Qt)\n The paper's rotation kernel on CPU SIMD, OpenCL and CUDA, power sensors (RAPL, INA3221, NVML), the\n vision pipeline and the device table: what a robot runs.")
set(CPACK_DEBIAN_GUI_PACKAGE_NAME benchscope)
set(CPACK_DEBIAN_GUI_DESCRIPTION
  "BenchScope desktop application (Qt 6) and command line\n Workspaces, peaks, rooflines, power traces and the vision pipeline in one window; the CLI with figures.")
# Both install /usr/bin/benchscope-cli: the GUI package takes the CLI package's place.
set(CPACK_DEBIAN_GUI_PACKAGE_PROVIDES benchscope-cli)
set(CPACK_DEBIAN_GUI_PACKAGE_CONFLICTS benchscope-cli)
set(CPACK_DEBIAN_GUI_PACKAGE_REPLACES benchscope-cli)

# The package architecture of the target, not of the machine running cpack (a cross build's arm64 package).
if(CMAKE_CROSSCOMPILING)
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(aarch64|arm64|ARM64)$")
    set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE arm64)
  elseif(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
    set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE amd64)
  endif()
  # A sysroot with its own dpkg database (scripts/cross-test makes one): dpkg-shlibdeps reads the sysroot's libraries
  # and packages through a wrapper, so the arm64 package depends on what the robot's Debian really names them.
  if(BENCHSCOPE_SYSROOT AND EXISTS "${BENCHSCOPE_SYSROOT}/var/lib/dpkg/status")
    configure_file(${CMAKE_CURRENT_LIST_DIR}/dpkg-shlibdeps-cross.sh.in ${PROJECT_BINARY_DIR}/dpkg-shlibdeps-cross.sh
                   @ONLY FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ)
    # A cache entry: CPackDeb's find_program(SHLIBDEPS_EXECUTABLE) searches PATH again past a plain variable.
    file(WRITE ${PROJECT_BINARY_DIR}/CPackCross.cmake
         "set(SHLIBDEPS_EXECUTABLE \"${PROJECT_BINARY_DIR}/dpkg-shlibdeps-cross.sh\" CACHE FILEPATH \"\")\n")
    set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_BINARY_DIR}/CPackCross.cmake)
    set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS
        "${BENCHSCOPE_SYSROOT}/usr/lib/${CMAKE_LIBRARY_ARCHITECTURE};${BENCHSCOPE_SYSROOT}/usr/lib")
  else()
    # Without it dpkg-shlibdeps cannot tell which package holds a library: no Depends rather than wrong ones.
    set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS OFF)
  endif()
endif()

# The CLI loads OpenCV's imgcodecs on first use (core/image_files), so no binary of the package links it and
# dpkg-shlibdeps cannot see it: the package that holds it is named here, as the dpkg database of the system the
# build ran on (or of the cross sysroot) names it. Not found: no made-up name, and the build says so.
if(TARGET opencv_imgcodecs AND CPACK_DEBIAN_PACKAGE_SHLIBDEPS)
  get_target_property(_bs_imgcodecs opencv_imgcodecs LOCATION)
  file(REAL_PATH "${_bs_imgcodecs}" _bs_imgcodecs)
  set(_bs_dpkg_args -S "${_bs_imgcodecs}")
  if(CMAKE_CROSSCOMPILING AND BENCHSCOPE_SYSROOT)
    set(_bs_dpkg_args --admindir=${BENCHSCOPE_SYSROOT}/var/lib/dpkg -S "${_bs_imgcodecs}")
  endif()
  execute_process(COMMAND dpkg-query ${_bs_dpkg_args} OUTPUT_VARIABLE _bs_owner ERROR_QUIET
                  OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE _bs_found)
  # "libopencv-imgcodecs406:amd64: /usr/lib/x86_64-linux-gnu/libopencv_imgcodecs.so.4.6.0"
  if(_bs_found EQUAL 0 AND _bs_owner MATCHES "^([a-z0-9][a-z0-9.+-]*)[:,]")
    set(CPACK_DEBIAN_PACKAGE_DEPENDS "${CMAKE_MATCH_1}")
  else()
    message(WARNING "packaging: no package found holding ${_bs_imgcodecs}; the .deb will not name OpenCV's "
                    "imgcodecs, which the CLI loads when it reads or writes an image file")
  endif()
endif()

include(CPack)
