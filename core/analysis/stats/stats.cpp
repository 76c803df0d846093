// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/stats/stats.h"
#include "analysis/stats/order_stats.h"

#include <algorithm>
#include <cmath>
#include <utility>

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

double percentile(std::vector<double> values, double q) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }), values.end());
  const double qs[] = {q};
  return select_percentiles(values, qs).front();  // the one implementation (order_stats.h): selection, no sort
}

double median(std::vector<double> values) { return percentile(std::move(values), 50); }

}  // namespace bs
