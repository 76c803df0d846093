// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `benchscope-cli bench kernels`'s words (the FLOPS kernels' figures and the empirical ceilings, measured in one
// process), read and written side by side like every command a robot runs for the desk
// (commands/remote_commands.h). Which instruction sets and power sensors exist is the running computer's to say.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "commands/power_words.h"
#include "commands/words.h"

namespace bs::commands {

struct BenchKernelsSettings {
  int runs = 7;                         // --runs, 1 to 1000: timed runs of each backend and variant
  std::optional<std::int64_t> workers;  // --workers, 1 to 1e6 (default 16384 throughput, 2048 paper)
  std::optional<std::string> isa;       // --isa avx512|avx2|sse4|generic
  bool no_ceilings = false;             // --no-ceilings: skip the empirical ceilings
  bool ceilings_only = false;           // --ceilings-only: only them (not with --no-ceilings)
  PowerWords power;                     // --power: also the sampler's cost and the energy per run
  bool operator==(const BenchKernelsSettings&) const = default;
};

// ["bench", "kernels", "--runs", "7", ...]: the runs spelled out (the robot's default may differ).
std::vector<std::string> to_words(const BenchKernelsSettings& settings);
// The words after "bench kernels". Throws UsageError naming the option and the accepted range.
BenchKernelsSettings bench_kernels_from_words(const std::vector<std::string>& words);

}  // namespace bs::commands
