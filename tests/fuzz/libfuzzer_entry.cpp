// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer's entry point for every importer target (fuzz_<id>): the input through the harness.
#include <cstddef>
#include <cstdint>

#include "fuzz_importer.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bs::fuzz::run_one(data, size);
  return 0;
}
