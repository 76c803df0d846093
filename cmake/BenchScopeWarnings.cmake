# Warnings are on for our own targets only (never for third-party headers, which come in as SYSTEM).
# BENCHSCOPE_WERROR turns them into errors: `scripts/dev test` (what CI runs) sets it for both the GCC and the clang
# build, so a change that adds a warning fails CI instead of piling up; a plain developer build stays forgiving.
option(BENCHSCOPE_WERROR "Treat compiler warnings in BenchScope's own code as errors" OFF)
add_library(benchscope_warnings INTERFACE)
target_compile_options(benchscope_warnings INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wnon-virtual-dtor>
  $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<CXX_COMPILER_ID:GNU>>:-Wshadow=local>  # clang spells it differently
  $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<BOOL:${BENCHSCOPE_WERROR}>>:-Werror>
  # GCC 11 (JetPack 6's compiler: the aarch64 cross build, `scripts/dev gcc11`) at -O2 reports memchr inside
  # libstdc++'s char_traits::find with a bound of SIZE_MAX as -Wstringop-overread for string_view::find on views
  # cut by substr(0, npos), a false positive of its middle end that GCC 12 no longer gives. Seen in two headroom
  # importers; GCC 12's build and clang's (with AddressSanitizer at run time) keep the warning.
  $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<CXX_COMPILER_ID:GNU>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,12>>:-Wno-stringop-overread>)
