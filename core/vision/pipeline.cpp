// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/pipeline.h"

#include <chrono>
#include <exception>
#include <thread>

#include "analysis/power_stats.h"

namespace bs::vision {
namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double, std::milli>(b - a).count(); }

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

PipelineResult run_pipeline(const FrameSource& source, const Preprocessor& preprocess, const Detector& detector,
                            const PipelineConfig& config, const CancelToken& cancel) {
  BoundedQueue<Captured> to_pre(config.queue_capacity, config.policy);
  BoundedQueue<Preprocessed> to_detect(config.queue_capacity, config.policy);
  std::vector<double> pre_ms, detect_ms, e2e_ms;
  // Each counter is written by one thread only: captured/dropped_capture by capture, dropped_pre by preprocessing.
  std::size_t captured = 0, dropped_capture = 0, dropped_pre = 0;
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto fail = [&](std::exception_ptr e) {
    std::lock_guard lock(failure_mutex);
    if (!failure) failure = e;
  };
  PipelineResult result;
  const auto t_start = Clock::now();

  std::thread capture([&] {
    try {
      for (std::size_t i = 0; i < config.max_frames && !cancel.cancelled(); ++i) {
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
        if (cancel.cancelled()) break;
        const auto t0 = Clock::now();
        cv::Mat bgr = preprocess(item->mosaic);
        pre_ms.push_back(ms_between(t0, Clock::now()));
        if (detector) {
          dropped_pre += to_detect.push({item->index, std::move(bgr), item->t_capture});
        } else {
          e2e_ms.push_back(ms_between(item->t_capture, Clock::now()));
          result.last_output = std::move(bgr);
        }
      }
    } catch (...) {
      fail(std::current_exception());
    }
    to_pre.close();  // unblocks a capture thread waiting for room
    to_detect.close();
  });
  try {
    if (detector) {
      while (auto item = to_detect.pop()) {
        if (cancel.cancelled()) break;
        const auto t0 = Clock::now();
        result.last_detections = detector(item->bgr);
        const auto t1 = Clock::now();
        detect_ms.push_back(ms_between(t0, t1));
        e2e_ms.push_back(ms_between(item->t_capture, t1));
        result.last_output = std::move(item->bgr);
      }
    }
  } catch (...) {
    fail(std::current_exception());
  }
  // Stopped early (cancel, or this stage failed): close the queues so blocked producers wake up. Otherwise the
  // upstream stages are finishing on their own and must not lose the frames still queued.
  bool failed = false;
  {
    std::lock_guard lock(failure_mutex);
    failed = failure != nullptr;
  }
  if (cancel.cancelled() || failed) {
    to_detect.close();
    to_pre.close();
  }
  capture.join();
  pre.join();
  if (failure) std::rethrow_exception(failure);

  result.wall_s = std::chrono::duration<double>(Clock::now() - t_start).count();
  result.captured = captured;
  result.dropped = dropped_capture + dropped_pre;
  result.processed = e2e_ms.size();
  result.throughput_fps = result.wall_s > 0 ? static_cast<double>(result.processed) / result.wall_s : 0;
  result.cancelled = cancel.cancelled();
  result.stages.push_back(make_stage_timing("preprocessing", std::move(pre_ms)));
  if (detector) result.stages.push_back(make_stage_timing("detection", std::move(detect_ms)));
  result.stages.push_back(make_stage_timing("end-to-end", std::move(e2e_ms)));
  return result;
}

}  // namespace bs::vision
