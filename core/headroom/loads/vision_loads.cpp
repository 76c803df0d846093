// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/loads/vision_loads.h"

#include <time.h>

#include <chrono>
#include <cstdio>
#include <stdexcept>

#include "headroom/loads/worker_thread.h"
#include "vision/lens/lens.h"
#include "vision/pipeline/dnn_architectures.h"
#include "vision/pipeline/pipeline_measure.h"
#include "vision/reproject/preprocess.h"

namespace bs::headroom {
namespace {

using namespace bs::vision;

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

Detector make_detector(const std::string& name, double scale) {
  if (name == "none") return {};
  if (name == "hog") return hog_people_detector(scale);
  if (const auto arch = architecture_from_string(name))
    return scaled_detector(architecture_timing_detector(*arch), scale);
  throw std::invalid_argument("detector '" + name + "' is not hog, none, mobilenet-ssd or yolo-n");
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

cv::Mat sample_mosaic() { return synthetic_paper_capture(); }

PipelineLoad::PipelineLoad(PipelineLoadConfig config) : config_(std::move(config)) {
  if (!(config_.fps > 0 && config_.fps <= 1000)) throw std::invalid_argument("pipeline rate must be 0 .. 1000 fps");
  if (config_.mosaics.empty()) {
    config_.mosaics.push_back(sample_mosaic());
    config_.frames_note = "the sample frame (synthetic paper capture, 1280x1024 BGGR)";
  }
  const Lens lens = Lens::paper();
  for (const cv::Mat& m : config_.mosaics)
    if (m.cols != lens.width || m.rows != lens.height || m.type() != CV_8UC1)
      throw std::invalid_argument("pipeline load frames must be 8-bit " + std::to_string(lens.width) + "x" +
                                  std::to_string(lens.height) + " mosaics (the paper's camera)");
  preprocess_ = make_preprocessor(lens, View{}, BayerPattern::BGGR, DemosaicMethod::Bilinear, PreprocessPath::Fused);
  detector_ = make_detector(config_.detector, config_.detect_scale);
  if (config_.detect_workers == 0) config_.detect_workers = default_detection_workers();
}

PipelineLoad::~PipelineLoad() {
  cancel_.cancel();
  if (thread_.joinable()) thread_.join();
}

std::string PipelineLoad::name() const { return "pipeline@" + number(config_.fps) + "fps"; }

std::string PipelineLoad::detail() const {
  return "vision pipeline at " + number(config_.fps) +
         " fps (drop-oldest): fused demosaic + reprojection (paper lens, " + "1280x1024 150 deg view), detector " +
         config_.detector + " at scale " + number(config_.detect_scale) + " on " +
         std::to_string(config_.detect_workers) + " worker(s); frames: " + config_.frames_note;
}

void PipelineLoad::start() {
  PipelineConfig pc;
  pc.max_frames = std::size_t{1} << 40;  // until stopped
  pc.capture_fps = config_.fps;
  pc.policy = QueuePolicy::DropOldest;  // a live camera: a late stage sees the newest frame
  pc.detection_workers = config_.detect_workers;
  processed_ = 0;
  pc.processed_counter = &processed_;
  thread_ = std::thread([this, pc] {
    try {
      const FrameSource source = [this](std::size_t i) -> std::optional<cv::Mat> {
        return config_.mosaics[i % config_.mosaics.size()];
      };
      result_ = run_pipeline(source, preprocess_, detector_, pc, cancel_);
    } catch (const std::exception& e) {
      error_ = e.what();
    }
  });
}

LoadReport PipelineLoad::stop() {
  cancel_.cancel();
  if (auto failed = join_worker(thread_, error_, "pipeline")) return *failed;
  LoadReport r;
  // Frames through the whole pipeline per second over the run (settling included: the queues are full by then).
  r.achieved_rate = result_.throughput_fps;
  char text[200];
  std::snprintf(text, sizeof text, "pipeline: %zu frames captured, %zu processed, %zu dropped in %.1f s",
                result_.captured, result_.processed, result_.dropped, result_.wall_s);
  r.notes.push_back(text);
  return r;
}

DetectorLoad::DetectorLoad(DetectorLoadConfig config) : config_(std::move(config)) {
  if (config_.rate && !(*config_.rate > 0 && *config_.rate <= 10000))
    throw std::invalid_argument("detector rate must be 0 .. 10000 inferences/s");
  if (config_.network == "hog")
    detector_ = hog_people_detector(1.0);
  else if (const auto arch = architecture_from_string(config_.network))
    detector_ = architecture_timing_detector(*arch);
  else
    throw std::invalid_argument("detector network '" + config_.network + "' is not mobilenet-ssd, yolo-n or hog");
  if (config_.view.empty()) {
    const Preprocessor pre =
        make_preprocessor(Lens::paper(), View{}, BayerPattern::BGGR, DemosaicMethod::Bilinear, PreprocessPath::Fused);
    config_.view = pre(sample_mosaic());
  }
}

DetectorLoad::~DetectorLoad() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

std::string DetectorLoad::name() const {
  return "dnn:" + config_.network + (config_.rate ? "@" + number(*config_.rate) : std::string());
}

std::string DetectorLoad::detail() const {
  const bool arch = architecture_from_string(config_.network).has_value();
  return "detector " +
         (arch ? architecture_detector_name(*architecture_from_string(config_.network)) : config_.network) +
         " on the reprojected sample frame, " +
         (config_.rate ? "paced at " + number(*config_.rate) + " inferences/s" : std::string("back to back"));
}

void DetectorLoad::start() {
  stop_ = false;
  inferences_ = 0;
  thread_ = std::thread([this] {
    try {
      const auto t0 = std::chrono::steady_clock::now();
      while (!stop_) {
        (void)detector_(config_.view);
        ++inferences_;
        if (config_.rate) {  // next inference at its slot on an absolute schedule
          const auto slot = t0 + std::chrono::duration<double>(static_cast<double>(inferences_.load()) / *config_.rate);
          while (!stop_ && std::chrono::steady_clock::now() < slot) {
            const timespec ts{0, 2'000'000};
            nanosleep(&ts, nullptr);
          }
        }
      }
      seconds_ = seconds_since(t0);
    } catch (const std::exception& e) {
      error_ = e.what();
    }
  });
}

LoadReport DetectorLoad::stop() {
  stop_ = true;
  if (auto failed = join_worker(thread_, error_, "detector")) return *failed;
  LoadReport r;
  if (seconds_ > 0) r.achieved_rate = static_cast<double>(inferences_.load()) / seconds_;
  r.notes.push_back(std::to_string(inferences_.load()) + " inferences");
  return r;
}

}  // namespace bs::headroom
