// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/trace_index.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bs {
namespace {

// Linear-interpolated quantiles of `w` (present values, reordered in place): the same rule as percentile() in
// analysis/stats.h, without a full sort. Quantiles ascending, so each nth_element works on what the last left.
Percentiles quantiles_in_place(std::vector<double>& w) {
  Percentiles p;
  if (w.empty()) return p;
  double* out[] = {&p.p5, &p.p50, &p.p95, &p.p99};
  const double qs[] = {5, 50, 95, 99};
  std::size_t start = 0;
  const std::size_t m = w.size();
  for (int i = 0; i < 4; ++i) {
    const double pos = qs[i] / 100.0 * static_cast<double>(m - 1);
    const auto lo = static_cast<std::size_t>(pos);
    const std::size_t hi = std::min(lo + 1, m - 1);
    // Everything before `start` is <= everything from it on (the previous nth_element), so partitioning the tail
    // is enough.
    std::nth_element(w.begin() + static_cast<std::ptrdiff_t>(start), w.begin() + static_cast<std::ptrdiff_t>(lo),
                     w.end());
    start = lo;
    const double vlo = w[lo];
    const double vhi = hi == lo ? vlo : *std::min_element(w.begin() + static_cast<std::ptrdiff_t>(hi), w.end());
    *out[i] = vlo + (vhi - vlo) * (pos - static_cast<double>(lo));
  }
  return p;
}

}  // namespace

Percentiles percentiles(std::span<const double> values) {
  std::vector<double> w;
  w.reserve(values.size());
  for (double v : values)
    if (!std::isnan(v)) w.push_back(v);  // missing samples are skipped, never read as 0
  return quantiles_in_place(w);
}

TraceIndex::TraceIndex(std::span<const double> time_s, std::span<const double> values) {
  if (time_s.size() != values.size())
    throw std::invalid_argument("trace index: " + std::to_string(values.size()) + " values for " +
                                std::to_string(time_s.size()) + " timestamps");
  t_.reserve(time_s.size());
  v_.reserve(values.size());
  long double total = 0;
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!std::isnan(values[k]) && !std::isnan(time_s[k])) {
      t_.push_back(time_s[k]);
      v_.push_back(values[k]);
      total += values[k];
    }
  const std::size_t n = t_.size();
  if (n == 0) return;
  shift_ = static_cast<double>(total / static_cast<long double>(n));
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  block_sum_.assign(blocks + 1, 0);
  block_sumsq_.assign(blocks + 1, 0);
  block_area_.assign(blocks + 1, 0);
  std::vector<double> bmin(blocks), bmax(blocks);
  long double s = 0, s2 = 0;
  double area = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t first = b * kBlock, last = std::min(n, first + kBlock);
    double lo = v_[first], hi = v_[first];
    for (std::size_t k = first; k < last; ++k) {
      const long double d = static_cast<long double>(v_[k]) - shift_;
      s += d;
      s2 += d * d;
      lo = std::min(lo, v_[k]);
      hi = std::max(hi, v_[k]);
      if (k + 1 < n) area += (t_[k + 1] - t_[k]) * (v_[k + 1] + v_[k]) / 2;  // the segment leaving sample k
    }
    block_sum_[b + 1] = s;
    block_sumsq_[b + 1] = s2;
    block_area_[b + 1] = area;  // up to t_[min(last, n - 1)]; last == n only for the final block, never read
    bmin[b] = lo;
    bmax[b] = hi;
  }
  sparse_min_.push_back(std::move(bmin));
  sparse_max_.push_back(std::move(bmax));
  for (std::size_t width = 2; width <= blocks; width *= 2) {
    const std::vector<double>& pmin = sparse_min_.back();
    const std::vector<double>& pmax = sparse_max_.back();
    const std::size_t count = blocks - width + 1, half = width / 2;
    std::vector<double> nmin(count), nmax(count);
    for (std::size_t b = 0; b < count; ++b) {
      nmin[b] = std::min(pmin[b], pmin[b + half]);
      nmax[b] = std::max(pmax[b], pmax[b + half]);
    }
    sparse_min_.push_back(std::move(nmin));
    sparse_max_.push_back(std::move(nmax));
  }
}

long double TraceIndex::prefix_sum(std::size_t k) const {
  const std::size_t b = k / kBlock;
  long double s = block_sum_[b];
  for (std::size_t i = b * kBlock; i < k; ++i) s += static_cast<long double>(v_[i]) - shift_;
  return s;
}

long double TraceIndex::prefix_sumsq(std::size_t k) const {
  const std::size_t b = k / kBlock;
  long double s = block_sumsq_[b];
  for (std::size_t i = b * kBlock; i < k; ++i) {
    const long double d = static_cast<long double>(v_[i]) - shift_;
    s += d * d;
  }
  return s;
}

double TraceIndex::area_to(std::size_t k) const {
  // block_area_[b] ends at t_[b * kBlock]; add the segments from there to k.
  const std::size_t b = k / kBlock;
  double a = block_area_[b];
  for (std::size_t i = b * kBlock; i < k; ++i) a += (t_[i + 1] - t_[i]) * (v_[i + 1] + v_[i]) / 2;
  return a;
}

std::pair<double, double> TraceIndex::min_max(std::size_t first, std::size_t last) const {
  double lo = v_[first], hi = v_[first];
  const auto scan = [&](std::size_t a, std::size_t b) {
    for (std::size_t i = a; i < b; ++i) lo = std::min(lo, v_[i]), hi = std::max(hi, v_[i]);
  };
  const std::size_t b0 = (first + kBlock - 1) / kBlock, b1 = last / kBlock;  // whole blocks [b0, b1)
  if (b0 >= b1) {
    scan(first, last);
    return {lo, hi};
  }
  scan(first, b0 * kBlock);
  scan(b1 * kBlock, last);
  const std::size_t count = b1 - b0;
  std::size_t level = 0;
  while ((std::size_t{2} << level) <= count) ++level;
  const std::size_t width = std::size_t{1} << level;
  lo = std::min({lo, sparse_min_[level][b0], sparse_min_[level][b1 - width]});
  hi = std::max({hi, sparse_max_[level][b0], sparse_max_[level][b1 - width]});
  return {lo, hi};
}

std::pair<std::size_t, std::size_t> TraceIndex::sample_range(double from_s, double to_s) const {
  if (from_s > to_s) std::swap(from_s, to_s);
  const auto first = static_cast<std::size_t>(std::lower_bound(t_.begin(), t_.end(), from_s) - t_.begin());
  const auto last = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), to_s) - t_.begin());
  return {first, std::max(first, last)};
}

double TraceIndex::value_at(double at) const {
  if (t_.empty()) return 0;
  const auto hi = static_cast<std::size_t>(std::lower_bound(t_.begin(), t_.end(), at) - t_.begin());
  if (hi == 0) return v_.front();
  if (hi >= t_.size()) return v_.back();
  const std::size_t lo = hi - 1;
  const double span = t_[hi] - t_[lo];
  if (span <= 0) return v_[hi];
  return v_[lo] + (v_[hi] - v_[lo]) * (at - t_[lo]) / span;
}

double TraceIndex::integral(double from_s, double to_s) const {
  if (from_s > to_s) std::swap(from_s, to_s);
  if (t_.size() < 2) return 0;
  from_s = std::max(from_s, t_.front());
  to_s = std::min(to_s, t_.back());
  if (!(to_s > from_s)) return 0;
  const auto [first, last] = sample_range(from_s, to_s);
  const double va = value_at(from_s), vb = value_at(to_s);
  if (first >= last) return (to_s - from_s) * (va + vb) / 2;  // both ends between the same two samples
  // The whole segments between the first and last sample inside, plus the two partial ones at the ends.
  return (t_[first] - from_s) * (va + v_[first]) / 2 + (area_to(last - 1) - area_to(first)) +
         (to_s - t_[last - 1]) * (v_[last - 1] + vb) / 2;
}

RangeSummary TraceIndex::summary(double from_s, double to_s) const {
  RangeSummary r;
  if (t_.empty()) return r;
  if (from_s > to_s) std::swap(from_s, to_s);
  r.from_s = std::clamp(from_s, t_.front(), t_.back());
  r.to_s = std::clamp(to_s, t_.front(), t_.back());
  r.duration_s = r.to_s - r.from_s;
  r.integral = integral(r.from_s, r.to_s);
  const auto [first, last] = sample_range(r.from_s, r.to_s);
  if (first >= last) return r;
  const std::size_t n = last - first;
  const long double s = prefix_sum(last) - prefix_sum(first);
  const long double s2 = prefix_sumsq(last) - prefix_sumsq(first);
  const long double mean_d = s / static_cast<long double>(n);
  r.samples.n = n;
  r.samples.mean = static_cast<double>(mean_d + shift_);
  if (n > 1) {
    const long double m2 = std::max<long double>(0, s2 - s * mean_d);
    r.samples.sd = static_cast<double>(std::sqrt(m2 / static_cast<long double>(n - 1)));
  }
  const auto [lo, hi] = min_max(first, last);
  r.samples.min = lo;
  r.samples.max = hi;
  return r;
}

Percentiles TraceIndex::percentiles(double from_s, double to_s) const {
  const auto [first, last] = sample_range(from_s, to_s);
  std::vector<double> w(v_.begin() + static_cast<std::ptrdiff_t>(first),
                        v_.begin() + static_cast<std::ptrdiff_t>(last));
  return quantiles_in_place(w);
}

}  // namespace bs
