// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/thread_latency.h"

namespace bs::headroom {

LatencySummary summarize(const ThreadLatency& thread) {
  const LatencyHistogram& h = thread.histogram;
  LatencySummary s;
  s.cycles = h.cycles;
  if (h.bins.empty()) {
    // An imported summary without a histogram (performance_test, rttest's statistics, cyclictest's status lines):
    // its extremes and mean are known, its percentiles and misses are not (left at their defaults: no_distribution).
    s.no_distribution = true;
    s.min_ns = h.min_ns;
    s.max_ns = h.max_ns;
    s.mean_ns = thread.mean_ns;
    s.sd_ns = thread.sd_ns;
    return s;
  }
  if (h.cycles == 0) return s;
  s.p50 = h.percentile(50);
  s.p99 = h.percentile(99);
  s.p999 = h.percentile(99.9);
  s.p9999 = h.percentile(99.99);
  s.min_ns = h.min_ns;
  s.max_ns = h.max_ns;
  if (thread.mean_ns) {
    s.mean_ns = thread.mean_ns;
    s.sd_ns = thread.sd_ns;
  } else {
    s.mean_ns = h.binned_mean_ns();
    s.mean_from_bins = true;
  }
  if (thread.misses) {
    s.misses = thread.misses->count;
    s.longest_miss_run = thread.misses->longest_run;
  } else if (thread.deadline_ns > 0) {
    const LatencyHistogram::Beyond beyond = h.count_above(thread.deadline_ns - thread.computation_ns);
    s.misses = beyond.count;
    s.misses_exact = beyond.exact;
  }
  return s;
}

}  // namespace bs::headroom
