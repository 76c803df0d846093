// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace bs::cli {

// `benchscope-cli bench headroom`: the reference tool (rt-tests' cyclictest) and BenchScope's probe run alternately
// on this machine, idle and beside the same load, their latency distributions side by side with the ratio per
// percentile, and each one's own CPU time per second. Skips (exit 0, saying why) where cyclictest is missing.
int bench_headroom(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

inline constexpr const char* kBenchHeadroomUsage =
    "       benchscope-cli bench headroom [--seconds S] [--rounds R] [--load SPEC] [--rate HZ] [--priority P]\n"
    "         [--cpu N] [--no-rt] [--limit-us L]\n";

inline constexpr const char* kBenchHeadroomHelp =
    "  bench headroom: cyclictest (rt-tests) and BenchScope's probe, one thread each at --rate HZ (default 1000),\n"
    "  SCHED_FIFO --priority P (default 80) with locked memory when permitted (both, or neither), alternately\n"
    "  for S seconds each (default 10) in R rounds (default 2, the order swapped every round), idle and beside\n"
    "  --load SPEC (a headroom load, default pipeline@30fps; 'none' for idle only). Per condition: p50 / p99 / p99.9 "
    "/\n"
    "  p99.99 / max and mean wake-up latency of each (histograms of 1 us bins up to --limit-us, default 10000,\n"
    "  merged over the rounds), probe / cyclictest per percentile, n; then the CPU time per second of each tool\n"
    "  (the probe's threads; cyclictest as a child process). Figures only: nothing passes or fails on time.\n"
    "  Skipped (exit 0) when cyclictest is not installed (Debian: apt-get install rt-tests).\n";

}  // namespace bs::cli
