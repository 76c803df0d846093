// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Range queries on one channel of a power/current trace, built once so that a cursor or selection dragged over a
// ten-million-sample log is answered without rescanning it.
//
// The one definition of a range's statistics (the Power tab, `benchscope-cli power` and every other caller go
// through this): for a range [from, to] clamped to the channel's first..last present sample,
//   n, mean, SD, min, max, percentiles  over the present samples with from <= t <= to;
//   duration = to - from (not the span of the samples inside it);
//   integral = trapezoid over [from, to] with the values at the two ends interpolated linearly between the
//              samples around them, so a range cut between samples gets its exact share (A s for current, J for
//              power). Missing samples (NaN) are bridged by the straight line between their present neighbours.
//
// Layout: the present samples (NaN removed) are copied, or read in place when the caller hands over an owner that
// keeps them alive and none is missing (a 100-million-sample log is not duplicated per view); per block of kBlock
// samples the index keeps prefix sums of value, value² (shifted by the channel mean, in long double, so the SD over a
// range does not cancel) and of the trapezoid areas, and a sparse table of block minima/maxima. A query scans at most
// two partial blocks and looks up the rest: O(kBlock + log n). Percentiles are exact (nth_element on a copy of the
// range), O(m) for m samples in the range: cheap for short ranges, a few tens of ms for ten million (the Power tab
// computes them when a drag ends for ranges that long).
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "analysis/stats/stats.h"

namespace bs {

struct Percentiles {
  double p5 = 0, p50 = 0, p95 = 0, p99 = 0;
};

struct RangeSummary {
  double from_s = 0, to_s = 0;  // the range actually covered (clamped to the present samples)
  double duration_s = 0;        // to_s - from_s
  Summary samples;              // n, mean, sample SD, min, max of the present samples inside; n = 0: none
  double integral = 0;          // trapezoid over [from_s, to_s] with interpolated ends (see the header comment)
};

class TraceIndex {
 public:
  static constexpr std::size_t kBlock = 256;

  TraceIndex() = default;
  // Copies the present samples. Throws std::invalid_argument when the lengths differ. Timestamps must be
  // non-decreasing.
  TraceIndex(std::span<const double> time_s, std::span<const double> values);
  // Reads `time_s` and `values` in place, keeping `owner` (what holds them) alive, when no sample is missing;
  // copies the present samples otherwise. Copies of the index share the samples and the tables.
  TraceIndex(std::span<const double> time_s, std::span<const double> values, std::shared_ptr<const void> owner);
  // The same samples times `factor` (> 0; throws std::invalid_argument otherwise), sharing this index's samples and
  // tables: power as current x a constant supply voltage costs no memory of its own.
  TraceIndex scaled(double factor) const;
  double scale() const noexcept { return scale_; }

  std::size_t size() const noexcept { return t_.size(); }  // present samples
  bool empty() const noexcept { return t_.empty(); }
  double first_s() const noexcept { return t_.empty() ? 0 : t_.front(); }
  double last_s() const noexcept { return t_.empty() ? 0 : t_.back(); }

  // Everything but percentiles over [from_s, to_s]; from_s > to_s is swapped. Empty channel: all zero.
  RangeSummary summary(double from_s, double to_s) const;
  // Trapezoidal integral over [from_s, to_s] with interpolated ends (clamped to the channel).
  double integral(double from_s, double to_s) const;
  // The value at `t_s`, interpolated between the present samples around it (clamped at the ends).
  double value_at(double t_s) const;
  // Exact linear-interpolated percentiles of the present samples with from_s <= t <= to_s.
  Percentiles percentiles(double from_s, double to_s) const;
  // Present samples with from_s <= t <= to_s as [first, last) indices into time()/values().
  std::pair<std::size_t, std::size_t> sample_range(double from_s, double to_s) const;
  std::span<const double> time() const noexcept { return t_; }
  // The present samples as stored: multiply by scale() for the values this index reports.
  std::span<const double> unscaled_values() const noexcept { return v_; }

 private:
  struct Tables {
    double shift = 0;
    std::vector<long double> block_sum, block_sumsq;  // over samples [0, b * kBlock)
    std::vector<double> block_area;                   // integral from t_[0] to t_[b * kBlock]
    // sparse_min[j][b] / sparse_max[j][b]: extremes of blocks [b, b + 2^j)
    std::vector<std::vector<double>> sparse_min, sparse_max;
  };
  void build_tables();
  long double prefix_sum(std::size_t k) const;    // sum of (v - shift) over samples [0, k)
  long double prefix_sumsq(std::size_t k) const;  // sum of (v - shift)² over samples [0, k)
  double area_to(std::size_t k) const;            // unscaled integral from t_[0] to t_[k]
  double unscaled_integral(double from_s, double to_s) const;
  double unscaled_value_at(double t_s) const;
  std::pair<double, double> min_max(std::size_t first, std::size_t last) const;  // over [first, last), non-empty

  std::shared_ptr<const void> storage_;  // keeps t_ and v_ alive: a copy of the present samples, or the owner
  std::span<const double> t_, v_;
  std::shared_ptr<const Tables> tables_;  // null while empty
  double scale_ = 1;
};

// An index that reads `time_s` and `values` in place without keeping them alive (when none is missing): for a query
// or two on samples the caller holds for as long as the index lives. A 100-million-sample log is not copied to be
// integrated once (trace summaries at import, integrate_range()).
TraceIndex transient_index(std::span<const double> time_s, std::span<const double> values);

// Exact linear-interpolated percentiles of the present (non-NaN) values: one copy, nth_element per quantile.
Percentiles percentiles(std::span<const double> values);

}  // namespace bs
