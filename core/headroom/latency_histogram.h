// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The latency distribution of one periodic thread as the real-time community keeps it (cyclictest -h): fixed-width
// bins (1 us by default) up to a limit, a count of the cycles beyond the last bin, and the true maximum kept even
// when it lies beyond the limit. No raw samples are needed: a 20-second 10 kHz run is 200,000 cycles, a night's run
// billions, and the histogram stays the same size.
//
// Bookkeeping invariant: cycles == sum(bins) + overflows. A probe keeps it by construction; an importer checks it
// (cyclictest's JSON gives cycles and the histogram; the overflows are the difference).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace bs::headroom {

// One percentile read from a histogram. `at_least` is set when the rank falls among the overflows (beyond the last
// bin) and is not the maximum: the value is then the limit and the true percentile is somewhere above it.
struct HistogramPercentile {
  std::int64_t ns = 0;
  bool at_least = false;
};

struct LatencyHistogram {
  std::int64_t bin_ns = 1000;          // width of one bin; bins[i] counts latencies in [i*bin_ns, (i+1)*bin_ns)
  std::vector<std::uint64_t> bins;     // bins.size() * bin_ns is the limit
  std::uint64_t overflows = 0;         // cycles whose latency was >= the limit
  std::uint64_t cycles = 0;            // n: every cycle measured, overflows included
  std::optional<std::int64_t> min_ns;  // true extremes when the source kept them (the probe always does)
  std::optional<std::int64_t> max_ns;

  std::int64_t limit_ns() const { return static_cast<std::int64_t>(bins.size()) * bin_ns; }
  std::uint64_t binned() const;  // sum(bins)
  // "" when cycles == sum(bins) + overflows and the extremes are consistent with the bins, else what is wrong
  // ("cycles 1000 != 990 in bins + 5 overflows").
  std::string bookkeeping_error() const;

  // Adds one latency (negative ones count as 0: a wake-up cannot precede its target, only the clock read can).
  void add(std::int64_t latency_ns);
  // Adds every count of `other` (same bin width and limit required; throws std::invalid_argument otherwise).
  void merge(const LatencyHistogram& other);

  // Percentile q in [0, 100] by the nearest-rank rule, read from the bins:
  //   rank k = max(1, ceil(q / 100 * cycles)); the result is the LOWER edge of the bin holding the k-th smallest
  //   latency. With 1 us bins and whole-microsecond latencies (cyclictest's truncation) this is exactly the
  //   nearest-rank percentile of the truncated values; otherwise it is within one bin below the true value.
  //   q = 100 (and any rank equal to cycles) is the true maximum when known. A rank among the overflows gives the
  //   limit with at_least set. An empty histogram gives 0.
  HistogramPercentile percentile(double q) const;
  // Cycles whose latency is certainly above `threshold_ns` (bins wholly above it, the overflows when the threshold
  // is below the limit); `exact` is false when the threshold cuts through a bin (that bin is not counted).
  struct Beyond {
    std::uint64_t count = 0;
    bool exact = true;
  };
  Beyond count_above(std::int64_t threshold_ns) const;
  // Mean from the bins (each at its bin's centre; overflows at the true maximum, or the limit), for sources that
  // kept no exact mean.
  std::optional<double> binned_mean_ns() const;
};

// A histogram with `limit_ns / bin_ns` bins (rounded up), empty.
LatencyHistogram make_histogram(std::int64_t limit_ns, std::int64_t bin_ns = 1000);

}  // namespace bs::headroom
