// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// BenchScope's own vision work as headroom loads: the paper's pipeline paced like a camera (capture -> demosaic +
// reprojection -> detection, dropping the oldest frame when a stage falls behind, as a live camera does), and the
// detector alone (a `bench dnn` architecture or HOG) running frame after frame. Both report what they achieved
// while they ran: frames per second through the whole pipeline, inferences per second.
#include <atomic>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <opencv2/core.hpp>

#include "headroom/load.h"
#include "util/cancel.h"
#include "vision/pipeline/detector.h"
#include "vision/pipeline/pipeline.h"

namespace bs::headroom {

struct PipelineLoadConfig {
  double fps = 30;               // camera rate the capture is paced at
  std::vector<cv::Mat> mosaics;  // the frames, played in turn (8-bit BGGR mosaics of the lens's size)
  std::string frames_note;       // where they came from, for the record
  std::string detector = "hog";  // hog, none, mobilenet-ssd, yolo-n
  double detect_scale = 0.5;
  std::size_t detect_workers = 0;  // 0: vision::default_detection_workers()
};

class PipelineLoad : public Load {
 public:
  explicit PipelineLoad(PipelineLoadConfig config);  // throws std::invalid_argument for a bad detector or rate
  ~PipelineLoad() override;
  std::string name() const override;  // "pipeline@30fps"
  LoadKind kind() const override { return LoadKind::Pipeline; }
  std::string detail() const override;
  std::optional<double> target_rate() const override { return config_.fps; }
  std::string rate_unit() const override { return "fps"; }
  void start() override;
  LoadReport stop() override;
  std::optional<double> work_done() const override { return static_cast<double>(processed_.load()); }

 private:
  PipelineLoadConfig config_;
  vision::Preprocessor preprocess_;
  vision::Detector detector_;
  CancelToken cancel_;
  std::thread thread_;
  vision::PipelineResult result_;
  std::atomic<std::size_t> processed_{0};  // frames through the whole pipeline so far (PipelineConfig's counter)
  std::string error_;
};

struct DetectorLoadConfig {
  std::string network = "mobilenet-ssd";  // mobilenet-ssd, yolo-n (random weights: cost only), or hog
  std::optional<double> rate;             // inferences per second to pace at; empty: back to back
  cv::Mat view;                           // the image fed each time (a reprojected sample frame)
};

class DetectorLoad : public Load {
 public:
  explicit DetectorLoad(DetectorLoadConfig config);
  ~DetectorLoad() override;
  std::string name() const override;  // "dnn:mobilenet-ssd", "dnn:yolo-n@10"
  LoadKind kind() const override { return LoadKind::Detector; }
  std::string detail() const override;
  std::optional<double> target_rate() const override { return config_.rate; }
  std::string rate_unit() const override { return "inferences/s"; }
  void start() override;
  LoadReport stop() override;
  std::optional<double> work_done() const override { return static_cast<double>(inferences_.load()); }

 private:
  DetectorLoadConfig config_;
  vision::Detector detector_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
  std::atomic<std::size_t> inferences_{0};  // atomic: work_done() reads it while the load runs
  double seconds_ = 0;
  std::string error_;
};

// The paper's capture as the sample frames hold it (sample_data/paper-2018/frames is this image).
cv::Mat sample_mosaic();

}  // namespace bs::headroom
