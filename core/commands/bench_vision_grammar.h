// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `benchscope-cli bench vision`'s words (the preprocessing kernels against OpenCV on the paper's frame), read and
// written side by side like every command a robot runs for the desk (commands/remote_commands.h).
#include <optional>
#include <string>
#include <vector>

#include "commands/power_words.h"
#include "commands/words.h"

namespace bs::commands {

struct BenchVisionSettings {
  int frames = 200;            // --frames, 1 to 100000: timed repetitions of each kernel
  std::optional<int> threads;  // --threads, 1 to 1024 (default: OpenCV's and OpenMP's own)
  PowerWords power;            // --power, --power-interval-ms, --sysfs-root
  bool operator==(const BenchVisionSettings&) const = default;
};

// ["bench", "vision", "--frames", "200", ...]
std::vector<std::string> to_words(const BenchVisionSettings& settings);
// The words after "bench vision". Throws UsageError naming the option and the accepted range.
BenchVisionSettings bench_vision_from_words(const std::vector<std::string>& words);

}  // namespace bs::commands
