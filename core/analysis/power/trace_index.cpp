// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/trace_index.h"
#include "analysis/stats/order_stats.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace bs {
namespace {

// The four percentiles of `w` (present values, reordered in place) by selection (analysis/stats/order_stats.h,
// the one implementation of the rule of analysis/stats/stats.h's percentile()).
Percentiles quantiles_in_place(std::vector<double>& w) {
  static constexpr double kQs[] = {5, 50, 95, 99};
  const std::vector<double> q = select_percentiles(w, kQs);
  return {q[0], q[1], q[2], q[3]};
}

struct SampleCopy {
  std::vector<double> t, v;
};

void check_lengths(std::span<const double> time_s, std::span<const double> values) {
  if (time_s.size() != values.size())
    throw std::invalid_argument("trace index: " + std::to_string(values.size()) + " values for " +
                                std::to_string(time_s.size()) + " timestamps");
}

// Copies the present samples (NaN in either dropped), points `t` and `v` at the copy and returns it: the owner that
// keeps them alive.
std::shared_ptr<const void> copy_present(std::span<const double> time_s, std::span<const double> values,
                                         std::span<const double>& t, std::span<const double>& v) {
  auto copy = std::make_shared<SampleCopy>();
  copy->t.reserve(time_s.size());
  copy->v.reserve(values.size());
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!std::isnan(values[k]) && !std::isnan(time_s[k])) {
      copy->t.push_back(time_s[k]);
      copy->v.push_back(values[k]);
    }
  t = copy->t;
  v = copy->v;
  return copy;
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
  check_lengths(time_s, values);
  storage_ = copy_present(time_s, values, t_, v_);
  build_tables();
}

TraceIndex::TraceIndex(std::span<const double> time_s, std::span<const double> values,
                       std::shared_ptr<const void> owner) {
  check_lengths(time_s, values);
  const auto is_nan = [](double x) { return std::isnan(x); };
  if (std::none_of(values.begin(), values.end(), is_nan) && std::none_of(time_s.begin(), time_s.end(), is_nan)) {
    t_ = time_s;
    v_ = values;
    storage_ = std::move(owner);
  } else {
    storage_ = copy_present(time_s, values, t_, v_);
  }
  build_tables();
}

TraceIndex transient_index(std::span<const double> time_s, std::span<const double> values) {
  // An owner that owns nothing (shared_ptr's aliasing constructor on an empty pointer): the caller keeps the samples.
  return TraceIndex(time_s, values, std::shared_ptr<const void>(std::shared_ptr<const void>{}, values.data()));
}

TraceIndex TraceIndex::scaled(double factor) const {
  if (!(factor > 0) || !std::isfinite(factor))
    throw std::invalid_argument("trace index: a scale factor must be finite and > 0");
  TraceIndex r = *this;  // shares the samples and the tables
  r.scale_ = scale_ * factor;
  return r;
}

void TraceIndex::build_tables() {
  const std::size_t n = t_.size();
  if (n == 0) return;
  auto tables = std::make_shared<Tables>();
  long double total = 0;
  for (double v : v_) total += v;
  tables->shift = static_cast<double>(total / static_cast<long double>(n));
  const double shift = tables->shift;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  tables->block_sum.assign(blocks + 1, 0);
  tables->block_sumsq.assign(blocks + 1, 0);
  tables->block_area.assign(blocks + 1, 0);
  std::vector<double> bmin(blocks), bmax(blocks);
  long double s = 0, s2 = 0;
  double area = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t first = b * kBlock, last = std::min(n, first + kBlock);
    double lo = v_[first], hi = v_[first];
    for (std::size_t k = first; k < last; ++k) {
      const long double d = static_cast<long double>(v_[k]) - shift;
      s += d;
      s2 += d * d;
      lo = std::min(lo, v_[k]);
      hi = std::max(hi, v_[k]);
      if (k + 1 < n) area += (t_[k + 1] - t_[k]) * (v_[k + 1] + v_[k]) / 2;  // the segment leaving sample k
    }
    tables->block_sum[b + 1] = s;
    tables->block_sumsq[b + 1] = s2;
    tables->block_area[b + 1] = area;  // up to t_[min(last, n - 1)]; last == n only for the final block, never read
    bmin[b] = lo;
    bmax[b] = hi;
  }
  tables->sparse_min.push_back(std::move(bmin));
  tables->sparse_max.push_back(std::move(bmax));
  for (std::size_t width = 2; width <= blocks; width *= 2) {
    const std::vector<double>& pmin = tables->sparse_min.back();
    const std::vector<double>& pmax = tables->sparse_max.back();
    const std::size_t count = blocks - width + 1, half = width / 2;
    std::vector<double> nmin(count), nmax(count);
    for (std::size_t b = 0; b < count; ++b) {
      nmin[b] = std::min(pmin[b], pmin[b + half]);
      nmax[b] = std::max(pmax[b], pmax[b + half]);
    }
    tables->sparse_min.push_back(std::move(nmin));
    tables->sparse_max.push_back(std::move(nmax));
  }
  tables_ = std::move(tables);
}

long double TraceIndex::prefix_sum(std::size_t k) const {
  const std::size_t b = k / kBlock;
  long double s = tables_->block_sum[b];
  for (std::size_t i = b * kBlock; i < k; ++i) s += static_cast<long double>(v_[i]) - tables_->shift;
  return s;
}

long double TraceIndex::prefix_sumsq(std::size_t k) const {
  const std::size_t b = k / kBlock;
  long double s = tables_->block_sumsq[b];
  for (std::size_t i = b * kBlock; i < k; ++i) {
    const long double d = static_cast<long double>(v_[i]) - tables_->shift;
    s += d * d;
  }
  return s;
}

double TraceIndex::area_to(std::size_t k) const {
  // block_area_[b] ends at t_[b * kBlock]; add the segments from there to k.
  const std::size_t b = k / kBlock;
  double a = tables_->block_area[b];
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
  lo = std::min({lo, tables_->sparse_min[level][b0], tables_->sparse_min[level][b1 - width]});
  hi = std::max({hi, tables_->sparse_max[level][b0], tables_->sparse_max[level][b1 - width]});
  return {lo, hi};
}

std::pair<std::size_t, std::size_t> TraceIndex::sample_range(double from_s, double to_s) const {
  if (from_s > to_s) std::swap(from_s, to_s);
  const auto first = static_cast<std::size_t>(std::lower_bound(t_.begin(), t_.end(), from_s) - t_.begin());
  const auto last = static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), to_s) - t_.begin());
  return {first, std::max(first, last)};
}

double TraceIndex::unscaled_value_at(double at) const {
  if (t_.empty()) return 0;
  const auto hi = static_cast<std::size_t>(std::lower_bound(t_.begin(), t_.end(), at) - t_.begin());
  if (hi == 0) return v_.front();
  if (hi >= t_.size()) return v_.back();
  const std::size_t lo = hi - 1;
  const double span = t_[hi] - t_[lo];
  if (span <= 0) return v_[hi];
  return v_[lo] + (v_[hi] - v_[lo]) * (at - t_[lo]) / span;
}

double TraceIndex::unscaled_integral(double from_s, double to_s) const {
  if (from_s > to_s) std::swap(from_s, to_s);
  if (t_.size() < 2) return 0;
  from_s = std::max(from_s, t_.front());
  to_s = std::min(to_s, t_.back());
  if (!(to_s > from_s)) return 0;
  const auto [first, last] = sample_range(from_s, to_s);
  const double va = unscaled_value_at(from_s), vb = unscaled_value_at(to_s);
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
  r.integral = scale_ * unscaled_integral(r.from_s, r.to_s);
  const auto [first, last] = sample_range(r.from_s, r.to_s);
  if (first >= last) return r;
  const std::size_t n = last - first;
  const long double s = prefix_sum(last) - prefix_sum(first);
  const long double s2 = prefix_sumsq(last) - prefix_sumsq(first);
  const long double mean_d = s / static_cast<long double>(n);
  r.samples.n = n;
  r.samples.mean = scale_ * static_cast<double>(mean_d + tables_->shift);
  if (n > 1) {
    const long double m2 = std::max<long double>(0, s2 - s * mean_d);
    r.samples.sd = scale_ * static_cast<double>(std::sqrt(m2 / static_cast<long double>(n - 1)));
  }
  const auto [lo, hi] = min_max(first, last);
  r.samples.min = scale_ * lo;
  r.samples.max = scale_ * hi;
  return r;
}

Percentiles TraceIndex::percentiles(double from_s, double to_s) const {
  const auto [first, last] = sample_range(from_s, to_s);
  std::vector<double> w(v_.begin() + static_cast<std::ptrdiff_t>(first),
                        v_.begin() + static_cast<std::ptrdiff_t>(last));
  Percentiles p = quantiles_in_place(w);
  for (double* x : {&p.p5, &p.p50, &p.p95, &p.p99}) *x *= scale_;
  return p;
}

double TraceIndex::value_at(double t_s) const { return scale_ * unscaled_value_at(t_s); }

double TraceIndex::integral(double from_s, double to_s) const { return scale_ * unscaled_integral(from_s, to_s); }

}  // namespace bs
