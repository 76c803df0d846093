// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's vision pipeline as a concurrent pipeline: capture -> preprocessing (demosaic + reprojection) ->
// detection, capture and preprocessing on one thread each, detection on `detection_workers` threads that take
// frames in turn (detection is ~99% of the work, so it is the stage worth spreading over the cores), bounded
// queues between the stages (block, or drop the oldest frame), and per-stage and end-to-end timings with n, mean,
// SD, percentiles and throughput.
#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "analysis/stats/stats.h"
#include "util/cancel.h"
#include "vision/pipeline/bounded_queue.h"
#include "vision/pipeline/detector.h"

namespace bs::vision {

// Frame `index` of the source (a mosaic, CV_8UC1), or nullopt when the source has no more frames.
using FrameSource = std::function<std::optional<cv::Mat>(std::size_t index)>;
// Mosaic -> reprojected BGR view.
using Preprocessor = std::function<cv::Mat(const cv::Mat& mosaic)>;

inline constexpr std::size_t kMaxDetectionWorkers = 256;
// This machine's hardware threads (at least 1): the default number of detection workers.
std::size_t default_detection_workers();

struct PipelineConfig {
  std::size_t max_frames = 100;    // stop after this many captured frames
  std::size_t queue_capacity = 2;  // per queue
  QueuePolicy policy = QueuePolicy::Block;
  double capture_fps = 0;  // pace the capture like a camera; 0: as fast as the pipeline takes frames
  // Threads running the detector, each on its own frame (1..kMaxDetectionWorkers). With more than one the
  // detector is called concurrently: HOG's detectMultiScale is const and safe; the cv::dnn detector serialises
  // forward() with its own mutex.
  std::size_t detection_workers = default_detection_workers();
  // Counted up as each frame leaves the pipeline, for a caller following the rate while it runs (a sustained run,
  // #53, takes its differences per interval); null: not counted. Must outlive the run.
  std::atomic<std::size_t>* processed_counter = nullptr;
};

struct StageTiming {
  std::string stage;       // "preprocessing", "detection", "end-to-end"
  std::vector<double> ms;  // one per processed frame
  Summary summary;         // of ms
  double p50 = 0, p95 = 0, p99 = 0;
};

struct PipelineResult {
  std::vector<StageTiming> stages;  // preprocessing, detection (when a detector ran), end-to-end
  std::size_t captured = 0, processed = 0, dropped = 0;
  double wall_s = 0;
  double throughput_fps = 0;  // processed / wall
  bool cancelled = false;
  std::vector<Detection> last_detections;
  cv::Mat last_output;                // the reprojected frame with the highest index (for drawing the detections)
  std::size_t last_index = 0;         // its index; last_detections are its detections
  std::size_t detection_workers = 0;  // how many detection threads ran (0 without a detector)
  const StageTiming* stage(const std::string& name) const;
};

// Runs until the source is exhausted, max_frames were captured, or `cancel` (checked before every frame by every
// stage and worker: after a cancel no frame starts, the ones in flight finish). `detector` may be empty
// (preprocessing only). Throws std::invalid_argument when detection_workers is outside 1..kMaxDetectionWorkers.
PipelineResult run_pipeline(const FrameSource& source, const Preprocessor& preprocess, const Detector& detector,
                            const PipelineConfig& config, const CancelToken& cancel);

// Timings of a list of per-frame milliseconds: summary and percentiles.
StageTiming make_stage_timing(std::string stage, std::vector<double> ms);

}  // namespace bs::vision
