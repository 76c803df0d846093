// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/stats.h"

#include <cmath>

namespace bs {

void RunningStats::add(double x) noexcept {
  ++n_;
  if (n_ == 1) {
    min_ = max_ = x;
  } else {
    if (x < min_) min_ = x;
    if (x > max_) max_ = x;
  }
  const double delta = x - mean_;
  mean_ += delta / static_cast<double>(n_);
  m2_ += delta * (x - mean_);
}

double RunningStats::variance() const noexcept { return n_ < 2 ? 0.0 : m2_ / static_cast<double>(n_ - 1); }

double RunningStats::sd() const noexcept { return std::sqrt(variance()); }

Summary summarize(std::span<const double> values) noexcept {
  RunningStats s;
  for (double v : values) s.add(v);
  return {s.count(), s.mean(), s.sd(), s.min(), s.max()};
}

}  // namespace bs
