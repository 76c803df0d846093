// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Per-cycle bookkeeping of one periodic thread, without keeping the samples: the histogram, the exact mean and SD
// of the latency (Welford), and the deadline misses with the longest run of consecutive ones, which no histogram can
// recover afterwards. The probe feeds it from its loop (no allocation per cycle); tests feed it synthetic series.
#include <cstdint>

#include "headroom/latency_histogram.h"
#include "headroom/thread_latency.h"

namespace bs::headroom {

class LatencyRecorder {
 public:
  // deadline_ns: a cycle misses when latency + computation > deadline_ns (the period, or a user deadline).
  LatencyRecorder(std::int64_t limit_ns, std::int64_t bin_ns, std::int64_t deadline_ns);

  // One cycle: its wake-up latency (actual wake-up minus the intended one) and the time its computation took.
  void add(std::int64_t latency_ns, std::int64_t computation_ns = 0) noexcept;
  // An activation the loop lost because it was a whole period or more behind: counted as a cycle with the
  // lateness it had when skipped, and always as a miss (it never ran), whatever the deadline.
  void add_skipped(std::int64_t latency_ns) noexcept;
  std::uint64_t skipped() const noexcept { return skipped_; }

  const LatencyHistogram& histogram() const noexcept { return histogram_; }
  // Everything recorded, as the stored per-thread record (identity and configuration left to the caller).
  ThreadLatency result() const;

 private:
  LatencyHistogram histogram_;
  std::int64_t deadline_ns_;
  double mean_ = 0, m2_ = 0;  // Welford over the latency in ns
  std::uint64_t misses_ = 0, run_ = 0, longest_run_ = 0, skipped_ = 0;
  void record(std::int64_t latency_ns, bool missed) noexcept;
  std::int64_t max_response_ns_ = 0;
};

}  // namespace bs::headroom
