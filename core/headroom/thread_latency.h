// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One periodic thread's result within one phase: who it was (index, CPU, policy and priority actually obtained),
// what it was asked to do (period, per-cycle computation, deadline), and what happened (the histogram, exact mean
// and SD when the source kept them, deadline misses with the longest run of consecutive ones).
#include <cstdint>
#include <optional>
#include <string>

#include "headroom/latency_histogram.h"

namespace bs::headroom {

struct DeadlineMisses {
  std::uint64_t count = 0;        // cycles with latency + computation > deadline
  std::uint64_t longest_run = 0;  // most consecutive missed cycles
};

struct ThreadLatency {
  int index = 0;                      // thread number within the measurement (cyclictest's T:<n>)
  std::optional<int> cpu;             // the CPU it was pinned to; empty when it could float
  std::string policy;                 // obtained, not asked: "SCHED_FIFO", "SCHED_RR", "SCHED_OTHER"; "" when unknown
  std::optional<int> priority;        // real-time priority obtained (1..99), empty for SCHED_OTHER or unknown
  std::optional<bool> memory_locked;  // mlockall succeeded (the probe), unknown for imports
  std::int64_t period_ns = 0;         // the loop's interval; 0 when unknown (message latency)
  std::int64_t computation_ns = 0;    // busy work asked per cycle (0: a pure wake-up test like cyclictest)
  std::int64_t deadline_ns = 0;       // the miss threshold for latency + computation: the period unless set
  LatencyHistogram histogram;
  std::optional<double> mean_ns, sd_ns;         // exact over every cycle, when the source kept them (no raw samples)
  std::optional<DeadlineMisses> misses;         // counted cycle by cycle; empty for sources that only have a histogram
  std::optional<std::int64_t> max_response_ns;  // largest latency + computation

  bool realtime() const { return policy == "SCHED_FIFO" || policy == "SCHED_RR"; }
  double rate_hz() const { return period_ns > 0 ? 1e9 / static_cast<double>(period_ns) : 0.0; }
};

// The numbers every view and table shows for one thread, all from the histogram and the counts above.
struct LatencySummary {
  std::uint64_t cycles = 0;
  HistogramPercentile p50, p99, p999, p9999;
  std::optional<std::int64_t> min_ns, max_ns;
  std::optional<double> mean_ns, sd_ns;  // exact when kept, else the binned estimate (mean only)
  bool mean_from_bins = false;
  // Misses: counted cycle by cycle when the source did, otherwise from the histogram (latency above
  // deadline - computation), which has no run length and may be a lower bound (misses_exact false).
  std::optional<std::uint64_t> misses;
  bool misses_exact = true;
  std::optional<std::uint64_t> longest_miss_run;
  // No histogram at all (an imported summary): percentiles and misses are unknown, not 0; cycles may be 0 (n not
  // given by the source) while min / max / mean are known.
  bool no_distribution = false;
  double miss_percent() const {
    return misses && cycles > 0 ? 100.0 * static_cast<double>(*misses) / static_cast<double>(cycles) : 0.0;
  }
};

LatencySummary summarize(const ThreadLatency& thread);

}  // namespace bs::headroom
