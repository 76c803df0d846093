// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `benchscope-cli bench dnn`'s words (detection networks' forward passes on each cv::dnn target), read and written
// side by side like every command a robot runs for the desk (commands/remote_commands.h). Whether the model files
// exist, the input suits the architecture and a target is available are the running computer's to say (the CLI);
// `remote` carries a desk's model files to the robot through these settings.
#include <optional>
#include <string>
#include <vector>

#include "commands/power_words.h"
#include "commands/words.h"

namespace bs::commands {

struct BenchDnnSettings {
  std::optional<std::string> model;      // --model MODEL[,CONFIG] (not with --arch)
  std::optional<std::string> arch;       // --arch mobilenet-ssd|yolo-n (neither: both architectures)
  int input_width = 0;                   // --input WxH, sides 32 to 4096 px; 0 x 0: the network's own
  int input_height = 0;                  // (two ints, not an optional size: see bench_dnn.cpp on GCC 11)
  int batch = 1;                         // --batch, 1 to 256
  int runs = 20;                         // --runs, 1 to 100000: timed forward passes
  std::string backend = "all";           // --backend cpu|opencl|cuda|all
  std::optional<std::string> platform;   // --platform NAME (default: this host's name)
  std::optional<std::string> workspace;  // --workspace WS
  bool json = false;                     // --json
  PowerWords power;                      // --power, --power-interval-ms, --sysfs-root
  bool operator==(const BenchDnnSettings&) const = default;
};

// ["bench", "dnn", "--runs", "20", "--batch", "1", "--backend", "all", ...]: the timing spelled out (the robot's
// defaults may differ).
std::vector<std::string> to_words(const BenchDnnSettings& settings);
// The words after "bench dnn". Throws UsageError naming the option and the accepted range.
BenchDnnSettings bench_dnn_from_words(const std::vector<std::string>& words);

}  // namespace bs::commands
