// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power.h"
#include "analysis/order_stats.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace bs {

// The named total channel when it has quantity `q`, else the first channel of that quantity.
const PowerChannel* main_channel(const PowerTrace& t, PowerQuantity q) {
  if (!t.total_channel.empty())
    for (const PowerChannel& c : t.channels)
      if (c.name == t.total_channel && c.quantity == q && c.values.size() == t.time_s.size()) return &c;
  for (const PowerChannel& c : t.channels)
    if (c.quantity == q && c.values.size() == t.time_s.size()) return &c;
  return nullptr;
}

Summary summarize_samples(std::span<const double> values) noexcept {
  RunningStats s;
  for (double v : values)
    if (!std::isnan(v)) s.add(v);
  return {s.count(), s.mean(), s.sd(), s.min(), s.max()};
}

std::vector<double> current_series(const PowerTrace& trace) {
  const PowerChannel* c = main_channel(trace, PowerQuantity::Current);
  return c ? c->values : std::vector<double>{};
}

std::vector<double> power_series(const PowerTrace& trace, std::optional<double> supply_v) {
  if (const PowerChannel* p = main_channel(trace, PowerQuantity::Power)) return p->values;
  const PowerChannel* i = main_channel(trace, PowerQuantity::Current);
  if (!i) return {};
  std::vector<double> out(i->values.size());
  if (const PowerChannel* v = main_channel(trace, PowerQuantity::Voltage)) {
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = i->values[k] * v->values[k];
    return out;
  }
  const auto volts = supply_v ? supply_v : trace.supply_voltage_v;
  if (!volts) return {};
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = i->values[k] * *volts;
  return out;
}

double percentile(std::vector<double> values, double q) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return std::isnan(v); }), values.end());
  if (values.empty()) return 0;
  const double qs[] = {q};
  return select_percentiles(values, qs)[0];  // selection, not a sort: the same value in linear time
}

double median(std::vector<double> values) { return percentile(std::move(values), 50); }

double integrate_trapezoid(const std::vector<double>& time_s, const std::vector<double>& values) {
  const std::size_t n = std::min(time_s.size(), values.size());
  double sum = 0;
  std::size_t prev = n;  // the last present sample, n while none
  for (std::size_t k = 0; k < n; ++k) {
    if (std::isnan(values[k])) continue;  // bridged: the next present sample joins `prev`
    if (prev < n) sum += (time_s[k] - time_s[prev]) * (values[k] + values[prev]) / 2;
    prev = k;
  }
  return sum;
}

TraceStats trace_stats(const PowerTrace& trace, std::optional<double> supply_v, std::optional<double> from_s,
                       std::optional<double> to_s) {
  std::size_t first = 0, last = trace.time_s.size();
  if (from_s) first = static_cast<std::size_t>(std::lower_bound(trace.time_s.begin(), trace.time_s.end(), *from_s) - trace.time_s.begin());
  if (to_s) last = static_cast<std::size_t>(std::upper_bound(trace.time_s.begin(), trace.time_s.end(), *to_s) - trace.time_s.begin());
  TraceStats s;
  if (first >= last) return s;
  s.n = last - first;
  s.duration_s = trace.time_s[last - 1] - trace.time_s[first];
  const auto slice = [&](const std::vector<double>& v) { return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(first), v.begin() + static_cast<std::ptrdiff_t>(last)); };
  const std::vector<double> current = current_series(trace);
  if (!current.empty()) {
    const Summary c = summarize_samples(slice(current));
    if (c.n > 0) s.current_a = c;  // every sample missing: unknown, not 0 A
  }
  const std::vector<double> power = power_series(trace, supply_v);
  const std::vector<double> p = power.empty() ? std::vector<double>{} : slice(power);
  if (const Summary sp = summarize_samples(p); sp.n > 0) {
    s.power_w = sp;
    s.power_p5 = percentile(p, 5);
    s.power_p50 = percentile(p, 50);
    s.power_p95 = percentile(p, 95);
    s.power_p99 = percentile(p, 99);
    s.energy_j = integrate_trapezoid(slice(trace.time_s), p);
  }
  return s;
}

double paper_flops_per_watt(double peak_flops, double supply_v, double max_current_a) {
  if (!(supply_v > 0 && max_current_a > 0)) throw std::invalid_argument("supply voltage and maximum current must be > 0");
  return peak_flops / (supply_v * max_current_a);
}

double constant_power_runtime_h(double nominal_v, double capacity_ah, double mean_power_w, double usable_fraction) {
  if (!(nominal_v > 0 && capacity_ah > 0 && mean_power_w > 0 && usable_fraction > 0 && usable_fraction <= 1))
    throw std::invalid_argument("battery: volts, capacity and power must be > 0 and the usable fraction in (0, 1]");
  return nominal_v * capacity_ah * usable_fraction / mean_power_w;
}

}  // namespace bs
