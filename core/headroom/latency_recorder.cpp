// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/latency_recorder.h"

#include <algorithm>
#include <cmath>

namespace bs::headroom {

LatencyRecorder::LatencyRecorder(std::int64_t limit_ns, std::int64_t bin_ns, std::int64_t deadline_ns)
    : histogram_(make_histogram(limit_ns, bin_ns)), deadline_ns_(deadline_ns) {}

void LatencyRecorder::add(std::int64_t latency_ns, std::int64_t computation_ns) noexcept {
  latency_ns = std::max<std::int64_t>(latency_ns, 0);
  computation_ns = std::max<std::int64_t>(computation_ns, 0);
  const std::int64_t response = latency_ns + computation_ns;
  max_response_ns_ = std::max(max_response_ns_, response);
  record(latency_ns, response > deadline_ns_);
}

void LatencyRecorder::add_skipped(std::int64_t latency_ns) noexcept {
  ++skipped_;
  record(std::max<std::int64_t>(latency_ns, 0), true);
}

void LatencyRecorder::record(std::int64_t latency_ns, bool missed) noexcept {
  // Bins are preallocated, so recording never allocates: safe inside a real-time loop after mlockall.
  histogram_.add(latency_ns);
  const double x = static_cast<double>(latency_ns);
  const double delta = x - mean_;
  mean_ += delta / static_cast<double>(histogram_.cycles);
  m2_ += delta * (x - mean_);
  if (missed) {
    ++misses_;
    longest_run_ = std::max(longest_run_, ++run_);
  } else {
    run_ = 0;
  }
}

ThreadLatency LatencyRecorder::result() const {
  ThreadLatency t;
  t.histogram = histogram_;
  t.deadline_ns = deadline_ns_;
  if (histogram_.cycles > 0) {
    t.mean_ns = mean_;
    t.sd_ns = histogram_.cycles > 1 ? std::sqrt(m2_ / static_cast<double>(histogram_.cycles - 1)) : 0.0;
    t.misses = DeadlineMisses{misses_, longest_run_};
    t.max_response_ns = max_response_ns_;
  }
  return t;
}

}  // namespace bs::headroom
