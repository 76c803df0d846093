// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// bench kernels' ceiling section: the CPU SIMD throughput variant alternating with the empirical-ceiling
// micro-kernels (rotation mix, FMA, triad) round by round, their figures, the ratios and the 97 % target.
#include <cstdint>
#include <ostream>

#include "kernels/backends/backend.h"
#include "kernels/ceilings/ceilings.h"

namespace bs::cli {

// Measures `rounds` rounds, prints the section and returns the ceilings measured (also stored in the cache by the
// caller).
kernels::CeilingSet bench_ceilings(const kernels::CpuInfo& cpu, const kernels::Backend& simd, int rounds,
                                   std::int64_t workers, std::ostream& out);

// "rotation mix 123.4 ± 1.2 GFLOPS (n = 5) = 97.1 % of the computed peak" lines of a set, with flags spelled out
// (`devices`, `bench kernels`).
void print_ceilings(const kernels::CeilingSet& set, std::ostream& out, const char* indent = "  ");

}  // namespace bs::cli
