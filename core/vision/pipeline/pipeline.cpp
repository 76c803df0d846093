// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline/pipeline.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "analysis/power/power_stats.h"

namespace bs::vision {
namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

struct Captured {
  std::size_t index;
  cv::Mat mosaic;
  Clock::time_point t_capture;
};

struct Preprocessed {
  std::size_t index;
  cv::Mat bgr;
  Clock::time_point t_capture;
};

}  // namespace

const StageTiming* PipelineResult::stage(const std::string& name) const {
  for (const auto& s : stages)
    if (s.stage == name) return &s;
  return nullptr;
}

StageTiming make_stage_timing(std::string stage, std::vector<double> ms) {
  StageTiming t;
  t.stage = std::move(stage);
  t.summary = summarize(ms);
  if (!ms.empty()) {
    const Percentiles p = percentiles(ms);
    t.p50 = p.p50;
    t.p95 = p.p95;
    t.p99 = p.p99;
  }
  t.ms = std::move(ms);
  return t;
}

std::size_t default_detection_workers() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : std::min<std::size_t>(n, kMaxDetectionWorkers);
}

PipelineResult run_pipeline(const FrameSource& source, const Preprocessor& preprocess, const Detector& detector,
                            const PipelineConfig& config, const CancelToken& cancel) {
  if (config.detection_workers < 1 || config.detection_workers > kMaxDetectionWorkers)
    throw std::invalid_argument("detection workers must be between 1 and " + std::to_string(kMaxDetectionWorkers) +
                                " (got " + std::to_string(config.detection_workers) + ")");
  BoundedQueue<Captured> to_pre(config.queue_capacity, config.policy);
  BoundedQueue<Preprocessed> to_detect(config.queue_capacity, config.policy);
  std::vector<double> pre_ms, detect_ms, e2e_ms;
  // Each counter is written by one thread only: captured/dropped_capture by capture, dropped_pre by preprocessing.
  std::size_t captured = 0, dropped_capture = 0, dropped_pre = 0;
  std::exception_ptr failure;
  std::mutex failure_mutex;
  std::atomic<bool> failed{false};  // a stage threw: every stage stops before its next frame
  const auto stop = [&] { return cancel.cancelled() || failed.load(std::memory_order_relaxed); };
  const auto fail = [&](std::exception_ptr e) {
    {
      std::lock_guard lock(failure_mutex);
      if (!failure) failure = e;
    }
    failed = true;
    to_pre.close();
    to_detect.close();
  };
  PipelineResult result;
  bool have_output = false;
  std::mutex result_mutex;  // detection workers share detect_ms, e2e_ms and the latest frame
  // Keeps the frame with the highest index: with several workers frames finish out of order, and the latest
  // captured frame is the one a live display should show.
  const auto keep_latest = [&](std::size_t index, cv::Mat& bgr, std::vector<Detection>* detections) {
    if (have_output && index < result.last_index) return;
    have_output = true;
    result.last_index = index;
    result.last_output = std::move(bgr);
    if (detections) result.last_detections = std::move(*detections);
  };
  const auto t_start = Clock::now();

  std::thread capture([&] {
    try {
      for (std::size_t i = 0; i < config.max_frames && !stop(); ++i) {
        if (config.capture_fps > 0)
          std::this_thread::sleep_until(t_start + std::chrono::duration_cast<Clock::duration>(
                                                      std::chrono::duration<double>(i / config.capture_fps)));
        std::optional<cv::Mat> frame = source(i);
        if (!frame) break;
        ++captured;
        dropped_capture += to_pre.push({i, std::move(*frame), Clock::now()});
      }
    } catch (...) {
      fail(std::current_exception());
    }
    to_pre.close();
  });
  std::thread pre([&] {
    try {
      while (auto item = to_pre.pop()) {
        if (stop()) break;
        const auto t0 = Clock::now();
        cv::Mat bgr = preprocess(item->mosaic);
        pre_ms.push_back(ms_between(t0, Clock::now()));
        if (detector) {
          dropped_pre += to_detect.push({item->index, std::move(bgr), item->t_capture});
        } else {
          e2e_ms.push_back(ms_between(item->t_capture, Clock::now()));
          if (config.processed_counter) ++*config.processed_counter;
          keep_latest(item->index, bgr, nullptr);
        }
      }
    } catch (...) {
      fail(std::current_exception());
    }
    to_pre.close();  // unblocks a capture thread waiting for room
    to_detect.close();
  });
  // Detection workers: each takes the next preprocessed frame from the shared queue, so every frame is detected
  // exactly once (Block) and the stage's throughput scales with the workers while the cores last.
  const std::size_t workers = detector ? config.detection_workers : 0;
  std::vector<std::thread> detection;
  detection.reserve(workers);
  for (std::size_t w = 0; w < workers; ++w)
    detection.emplace_back([&] {
      try {
        while (auto item = to_detect.pop()) {
          if (stop()) break;
          const auto t0 = Clock::now();
          std::vector<Detection> found = detector(item->bgr);
          const auto t1 = Clock::now();
          std::lock_guard lock(result_mutex);
          detect_ms.push_back(ms_between(t0, t1));
          e2e_ms.push_back(ms_between(item->t_capture, t1));
          if (config.processed_counter) ++*config.processed_counter;
          keep_latest(item->index, item->bgr, &found);
        }
      } catch (...) {
        fail(std::current_exception());
      }
      // A stopped worker (cancel or failure) wakes blocked producers; a worker that saw the queue closed and
      // drained leaves the others alone, since the upstream stages finished on their own and lost no frame.
      if (stop()) {
        to_detect.close();
        to_pre.close();
      }
    });
  if (workers == 0) {
    // Preprocessing ends the pipeline: nothing to run here but the cancel, which must wake a blocked capture.
    pre.join();
    capture.join();
  } else {
    for (auto& t : detection) t.join();
    capture.join();
    pre.join();
  }
  if (failure) std::rethrow_exception(failure);

  result.wall_s = std::chrono::duration<double>(Clock::now() - t_start).count();
  result.captured = captured;
  result.dropped = dropped_capture + dropped_pre;
  result.processed = e2e_ms.size();
  result.throughput_fps = result.wall_s > 0 ? static_cast<double>(result.processed) / result.wall_s : 0;
  result.cancelled = cancel.cancelled();
  result.detection_workers = workers;
  result.stages.push_back(make_stage_timing("preprocessing", std::move(pre_ms)));
  if (detector) result.stages.push_back(make_stage_timing("detection", std::move(detect_ms)));
  result.stages.push_back(make_stage_timing("end-to-end", std::move(e2e_ms)));
  return result;
}

}  // namespace bs::vision
