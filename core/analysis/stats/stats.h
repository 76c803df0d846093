// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstddef>
#include <span>
#include <vector>

namespace bs {

// Welford's online mean/variance: numerically stable in one pass, so traces of millions of samples need no copy.
class RunningStats {
 public:
  void add(double x) noexcept;
  std::size_t count() const noexcept { return n_; }
  double mean() const noexcept { return mean_; }
  double variance() const noexcept;  // sample variance (n - 1); 0 when n < 2
  double sd() const noexcept;        // sample standard deviation
  double min() const noexcept { return min_; }
  double max() const noexcept { return max_; }

 private:
  std::size_t n_ = 0;
  double mean_ = 0, m2_ = 0, min_ = 0, max_ = 0;
};

struct Summary {
  std::size_t n = 0;
  double mean = 0, sd = 0, min = 0, max = 0;
};

Summary summarize(std::span<const double> values) noexcept;

// Linear-interpolated percentile q in [0, 100] of the present (non-NaN) values: position q/100 x (n - 1) in the
// sorted values, interpolated between its two neighbours; 0 when none.
double percentile(std::vector<double> values, double q);
// percentile(values, 50): the middle value, or the mean of the middle two for an even count.
double median(std::vector<double> values);

}  // namespace bs
