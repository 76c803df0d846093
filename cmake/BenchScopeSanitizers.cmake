# SPDX-License-Identifier: GPL-3.0-or-later
# Instrumented builds, applied to every target of the project (core, importers, CLI, tests).
#
#   -DBENCHSCOPE_SANITIZE=address,undefined   AddressSanitizer + UndefinedBehaviorSanitizer (scripts/dev sanitize)
#   -DBENCHSCOPE_FUZZ=ON                       libFuzzer targets under tests/fuzz (clang only; scripts/fuzz)
#   -DBENCHSCOPE_COVERAGE=ON                   clang source-based coverage, replay_<id> only (scripts/fuzz --coverage)
#
# Undefined behaviour is made fatal (-fno-sanitize-recover) so a test that triggers it fails instead of printing
# a line nobody reads. Third-party libraries (Qt, OpenCV, PoCL) are not instrumented; that is fine for ASan.
set(BENCHSCOPE_SANITIZE "" CACHE STRING "Sanitizers for all targets, e.g. address,undefined (empty: none)")
option(BENCHSCOPE_FUZZ "Build the libFuzzer importer targets (needs clang)" OFF)
option(BENCHSCOPE_COVERAGE "Build the fuzz replays with clang source-based coverage (needs clang)" OFF)

if(BENCHSCOPE_COVERAGE)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "BENCHSCOPE_COVERAGE needs clang: use scripts/fuzz --coverage")
  endif()
  # Source-based (not gcov) coverage: exact line and branch counts that llvm-cov maps back to the sources.
  add_compile_options("$<$<COMPILE_LANGUAGE:C,CXX>:-fprofile-instr-generate;-fcoverage-mapping>")
  add_link_options(-fprofile-instr-generate)
endif()

set(_bs_sanitize "${BENCHSCOPE_SANITIZE}")
if(BENCHSCOPE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "BENCHSCOPE_FUZZ needs clang: configure with CC=clang CXX=clang++ "
                        "(Debian: apt install clang libclang-rt-14-dev), or use scripts/fuzz")
  endif()
  # Coverage instrumentation everywhere; only the fuzz executables link libFuzzer's main (-fsanitize=fuzzer).
  if(_bs_sanitize STREQUAL "")
    set(_bs_sanitize "address,undefined")
  endif()
  set(_bs_sanitize "fuzzer-no-link,${_bs_sanitize}")
endif()

if(NOT _bs_sanitize STREQUAL "")
  message(STATUS "BenchScope: building with -fsanitize=${_bs_sanitize}")
  # C and C++ only: nvcc does not take these flags (CUDA code is not instrumented).
  add_compile_options("$<$<COMPILE_LANGUAGE:C,CXX>:-fsanitize=${_bs_sanitize};-fno-omit-frame-pointer>"
                      "$<$<COMPILE_LANGUAGE:C,CXX>:-fno-sanitize-recover=undefined>")
  add_link_options(-fsanitize=${_bs_sanitize})
endif()
