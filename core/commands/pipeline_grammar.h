// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `benchscope-cli pipeline`'s words, read and written side by side: the CLI reads its command line with
// pipeline_from_words, the Pipeline tab writes what a robot runs (`remote ROBOT pipeline --synthetic ...`) with
// to_words, and the round trip is tested. What only the running computer can check (files exist, the lens reads,
// the backend has a device) stays with the CLI.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "commands/power_words.h"
#include "commands/words.h"
#include "vision/pipeline/pipeline_measure.h"

namespace bs::commands {

struct PipelineSettings {
  bool synthetic = false;                     // --synthetic: the paper camera's synthetic capture, no frame files
  std::vector<std::string> frame_files;       // FRAME... (not with --synthetic)
  std::optional<std::string> lens;            // --lens LENS.json|paper (required with frame files)
  std::optional<std::string> demosaic;        // --demosaic fused|bilinear|mhc|opencv (default by backend)
  std::string backend = "cpu";                // --backend cpu|opencl|cuda
  std::string detector = "hog";               // --detector hog|none|mobilenet-ssd|yolo-n|MODEL[,CONFIG]
  std::optional<std::size_t> frames;          // --frames N (default 20 synthetic, 50 from files)
  std::optional<std::string> policy;          // --policy block|drop-oldest (default block)
  std::optional<std::size_t> queue;           // --queue N (default 2)
  std::optional<std::size_t> detect_workers;  // --detect-workers W (default this machine's threads)
  double detect_scale = 0.5;                  // --detect-scale S, 0 < S <= 1
  std::optional<std::string> pattern;         // --pattern BGGR|RGGB|GRBG|GBRG
  std::optional<std::string> platform;        // --platform NAME (default this host's name)
  std::optional<std::string> out;             // --out DIR: figure 3
  std::optional<std::string> workspace;       // --workspace WS
  bool json = false;                          // --json
  PowerWords power;
  bool operator==(const PipelineSettings&) const = default;
};

// ["pipeline", "--synthetic", "--frames", "20", ...]
std::vector<std::string> to_words(const PipelineSettings& settings);
// The words after "pipeline". Throws UsageError naming the option and what it takes.
PipelineSettings pipeline_from_words(const std::vector<std::string>& words);

// --detect-workers W (1 .. vision::kMaxDetectionWorkers; absent: nullopt) and --detect-scale S (0 < S <= 1, default
// 0.5), shared with `bench pipeline`.
std::optional<std::size_t> read_detect_workers(const Words& words);
double read_detect_scale(const Words& words);

// What the Pipeline tab sends a robot for its synthetic measurement: every setting spelled out, defaults too, so
// the robot runs what the desk shows whatever its own defaults are; `platform` may be empty; `record_power` asks
// for the robot's own sensors (--power auto). Throws std::invalid_argument for a detector that is a model file: it
// lies on this computer, not on the robot.
PipelineSettings robot_pipeline_settings(const vision::SyntheticPipelineOptions& options, const std::string& platform,
                                         bool record_power);

}  // namespace bs::commands
