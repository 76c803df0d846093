// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One run of the vision pipeline (paper section 4.2: preprocessing = demosaic + reprojection, then pedestrian
// detection) on one platform: per-stage timing statistics in seconds, what was run, and where the numbers came
// from. Measured runs come from `benchscope-cli pipeline`; the paper's figures are stored as reconstructed runs.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/provenance.h"

namespace bs {

// Canonical stage names (the pipeline JSON keys and the workspace's stage column).
namespace pipeline_stage {
inline constexpr const char* kPreprocess = "preprocess";  // demosaic + reprojection
inline constexpr const char* kDetect = "detect";          // pedestrian detection
inline constexpr const char* kEndToEnd = "end-to-end";    // capture to detection result, per frame
}  // namespace pipeline_stage

// Statistics of one stage over n frames, in seconds. A measured run has all of them; a run rebuilt from a
// publication usually only n, mean and SD (the rest stay empty rather than being invented).
struct StageStats {
  std::string stage;
  std::size_t n = 0;
  double mean_s = 0, sd_s = 0;
  std::optional<double> min_s, max_s, p50_s, p95_s;
};

struct PipelineRun {
  std::string platform;                   // "NUC", "Jetson TX2", or this host's name
  std::string device;                     // what ran it, e.g. "NUC CPU (i7-7567U)", "Jetson GPU (Pascal, 256 cores)"
  std::string backend;                    // "cpu", "opencl", "cuda"
  std::string demosaic;                   // "bilinear", "mhc", "opencv", "fused", ... ; empty when unknown
  std::string detector;                   // "hog", "none", a model file name, "pedestrian detector (paper)"
  int frame_width = 0, frame_height = 0;  // camera frame; 0 when unknown
  std::vector<StageStats> stages;
  std::optional<double> throughput_fps;  // frames through the whole pipeline per second of wall time
  Provenance provenance;

  const StageStats* stage(std::string_view name) const {
    for (const StageStats& s : stages)
      if (s.stage == name) return &s;
    return nullptr;
  }
};

}  // namespace bs
