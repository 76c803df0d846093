# SPDX-License-Identifier: GPL-3.0-or-later
# Less compile work for the same code (issue #42): a cold 2-core machine builds BenchScope twice in `scripts/dev test`
# (GCC, then clang with sanitizers) and the cross test a third time, so every header parsed once instead of in each
# source, and every group of sources compiled as one, counts three times over.
#   BENCHSCOPE_PCH    precompiled headers per library, for the heavy headers its sources include: OpenCV (vision),
#                     Qt Widgets and QCustomPlot (figures, widgets, GUI), nlohmann-json (CLI). Not the standard
#                     library's alone: with GCC 12 a precompiled <string> loses its system-header status, and -O2's
#                     known false -Warray-bounds inside std::string then fails -Werror builds (seen in core/store).
#   BENCHSCOPE_UNITY  unity builds of the libraries (CMake's batches of sources compiled as one translation unit)
#   BENCHSCOPE_MEASURED_FLAGS  compile flags for the code BenchScope times (its kernels, the vision pipeline and
#                     detector, the headroom loads), after the configuration's own. scripts/dev and the cross test
#                     compile everything else at -O1 (a fifth less compile time than -O2, measured on the GCC tree's
#                     sources) and this at -O2: what is measured is compiled as before; parsers, the store, the
#                     analysis and the GUI are not timed, and the headroom probe's clock reads and sleeps are the same
#                     instructions at either level. Empty (a plain CMake configure, the packages): no change.
# docs/guide.md ("Build time") and docs/build-time.md have the measured effect of each.
option(BENCHSCOPE_PCH "Precompile the heavy headers of each library" ON)
option(BENCHSCOPE_UNITY "Compile each library's sources in batches (unity build; off: see below)" OFF)
set(BENCHSCOPE_UNITY_BATCH 8 CACHE STRING "Sources per unity batch")
set(BENCHSCOPE_MEASURED_FLAGS "" CACHE STRING "Flags for the measured code (kernels, vision, headroom loads), e.g. -O2")

# benchscope_measured(<target>): the target is code BenchScope times; BENCHSCOPE_MEASURED_FLAGS apply to it.
function(benchscope_measured target)
  if(NOT BENCHSCOPE_MEASURED_FLAGS STREQUAL "")
    separate_arguments(flags UNIX_COMMAND "${BENCHSCOPE_MEASURED_FLAGS}")
    target_compile_options(${target} PRIVATE "$<$<COMPILE_LANGUAGE:C,CXX>:${flags}>")
  endif()
endfunction()

# GCC 12 forgets, for headers it reads from a precompiled header, that they are system headers, and then reports -O2's
# known false -Warray-bounds and -Wstringop-overflow inside libstdc++'s std::string (char_traits.h: "forming offset
# 32 is out of the bounds [0, 32]", "writing 37 bytes into a region of size 16") in sources that compile clean
# without the PCH; with -Werror that failed 13 of the test and figure sources. Targets with a PCH therefore leave
# these middle-end warnings (and -Wrestrict, -Wstringop-overread, of the same machinery) to clang: the sanitizer build (clang, its own front-end
# -Warray-bounds, -Werror) compiles the same sources, and AddressSanitizer checks every access of the tests at run
# time.
function(benchscope_pch_warnings target)
  target_compile_options(${target} PRIVATE
    "$<$<CXX_COMPILER_ID:GNU>:-Wno-array-bounds;-Wno-stringop-overflow;-Wno-stringop-overread;-Wno-restrict>")
endfunction()

# benchscope_speed_up(<target> [UNITY] [PCH <headers...>])
#   A source with compile options of its own (the SIMD variants' -mavx2, -mavx512f, -march=...) keeps neither: a
#   precompiled header made without those flags cannot serve it (clang refuses it outright), and CMake already
#   leaves such sources out of unity batches.
function(benchscope_speed_up target)
  cmake_parse_arguments(S "UNITY" "" "PCH" ${ARGN})
  if(BENCHSCOPE_UNITY AND S_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${BENCHSCOPE_UNITY_BATCH})
  endif()
  if(BENCHSCOPE_PCH AND S_PCH)
    target_precompile_headers(${target} PRIVATE ${S_PCH})
    benchscope_pch_warnings(${target})
    get_target_property(sources ${target} SOURCES)
    foreach(src IN LISTS sources)
      get_source_file_property(options ${src} COMPILE_OPTIONS)
      get_source_file_property(flags ${src} COMPILE_FLAGS)
      if(options OR flags)
        set_source_files_properties(${src} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
      endif()
    endforeach()
  endif()
endfunction()
