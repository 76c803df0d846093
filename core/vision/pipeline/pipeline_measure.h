// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Measuring the pipeline on this machine without a camera: the synthetic capture of the paper's camera (the test
// chart through the 195 degree lens, 1280x1024 BGGR, as `synth-frame` writes it) through the pipeline's default
// stages (fused demosaic + reprojection, HOG people detector), returned as a stored run with this host's
// provenance and the settings that made it. The GUI's Pipeline tab runs it; `bench pipeline` shares the capture.
#include <cstddef>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "model/pipeline_run.h"
#include "util/cancel.h"
#include "vision/pipeline/pipeline.h"

namespace bs::vision {

// The paper camera's synthetic raw mosaic (CV_8UC1, 1280x1024, BGGR).
cv::Mat synthetic_paper_capture();

struct SyntheticPipelineOptions {
  std::size_t frames = 20;
  std::size_t detection_workers = default_detection_workers();
  double detect_scale = 0.5;    // 0 < scale <= 1
  std::string backend = "cpu";  // preprocessing on "cpu" (fused), "opencl" or "cuda"; detection stays on the CPU
  // "hog" (OpenCV's people detector), "mobilenet-ssd" or "yolo-n" (built-in architectures with random weights:
  // the run is labelled architecture timing, no detections), a model file cv::dnn reads (MODEL[,CONFIG]), or
  // "none" (preprocessing only).
  std::string detector = "hog";
  std::string tool;  // the producing tool for the provenance, e.g. "benchscope 0.4.0 (GUI)"
};

// Whether a detector setting names a model file (MODEL[,CONFIG]) rather than hog, none or a built-in architecture.
bool detector_is_model_file(const std::string& detector);

// Runs the pipeline (block policy, queues of 2) and returns the run, or nullopt when cancelled. `progress` (may be
// empty) is called from the capture thread with the fraction of frames captured. `result` (may be null) receives
// the pipeline's own counts (captured, dropped, wall time), which the CLI prints. Throws std::invalid_argument for
// options out of range, std::runtime_error when the backend cannot run here (no OpenCL device, no CUDA GPU).
std::optional<PipelineRun> measure_synthetic_pipeline(const SyntheticPipelineOptions& options,
                                                      const CancelToken& cancel, const ProgressFn& progress = {},
                                                      PipelineResult* result = nullptr);

}  // namespace bs::vision
