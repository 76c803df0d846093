// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's vision pipeline as a concurrent pipeline: capture -> preprocessing (demosaic + reprojection) ->
// detection, each stage on its own thread, bounded queues between them (block, or drop the oldest frame), and
// per-stage and end-to-end timings with n, mean, SD, percentiles and throughput.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "analysis/stats.h"
#include "util/cancel.h"
#include "vision/bounded_queue.h"
#include "vision/detector.h"

namespace bs::vision {

// Frame `index` of the source (a mosaic, CV_8UC1), or nullopt when the source has no more frames.
using FrameSource = std::function<std::optional<cv::Mat>(std::size_t index)>;
// Mosaic -> reprojected BGR view.
using Preprocessor = std::function<cv::Mat(const cv::Mat& mosaic)>;

struct PipelineConfig {
  std::size_t max_frames = 100;     // stop after this many captured frames
  std::size_t queue_capacity = 2;   // per queue
  QueuePolicy policy = QueuePolicy::Block;
  double capture_fps = 0;           // pace the capture like a camera; 0: as fast as the pipeline takes frames
};

struct StageTiming {
  std::string stage;          // "preprocessing", "detection", "end-to-end"
  std::vector<double> ms;     // one per processed frame
  Summary summary;            // of ms
  double p50 = 0, p95 = 0, p99 = 0;
};

struct PipelineResult {
  std::vector<StageTiming> stages;  // preprocessing, detection (when a detector ran), end-to-end
  std::size_t captured = 0, processed = 0, dropped = 0;
  double wall_s = 0;
  double throughput_fps = 0;        // processed / wall
  bool cancelled = false;
  std::vector<Detection> last_detections;
  cv::Mat last_output;              // the last reprojected frame (for drawing the detections)
  const StageTiming* stage(const std::string& name) const;
};

// Runs until the source is exhausted, max_frames were captured, or `cancel` (checked between frames by every
// stage: a cancel ends the run within one frame's work). `detector` may be empty (preprocessing only).
PipelineResult run_pipeline(const FrameSource& source, const Preprocessor& preprocess, const Detector& detector,
                            const PipelineConfig& config, const CancelToken& cancel);

// Timings of a list of per-frame milliseconds: summary and percentiles.
StageTiming make_stage_timing(std::string stage, std::vector<double> ms);

}  // namespace bs::vision
