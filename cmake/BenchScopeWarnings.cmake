# Warnings are on for our own targets only (never for third-party headers, which come in as SYSTEM).
add_library(benchscope_warnings INTERFACE)
target_compile_options(benchscope_warnings INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wnon-virtual-dtor>
  $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<CXX_COMPILER_ID:GNU>>:-Wshadow=local>)  # clang spells it differently
