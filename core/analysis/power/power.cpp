// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/power.h"
#include "analysis/stats/order_stats.h"

#include "analysis/power/power_stats.h"
#include "analysis/power/trace_index.h"

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

double integrate_trapezoid(const std::vector<double>& time_s, const std::vector<double>& values) {
  const std::size_t n = std::min(time_s.size(), values.size());
  const TraceIndex index =
      transient_index(std::span<const double>(time_s).first(n), std::span<const double>(values).first(n));
  return index.integral(index.first_s(), index.last_s());
}

TraceStats trace_stats(const PowerTrace& trace, std::optional<double> supply_v, std::optional<double> from_s,
                       std::optional<double> to_s) {
  const PowerStats p = power_stats(trace, {.supply_v = supply_v, .from_s = from_s, .to_s = to_s});
  TraceStats s;
  s.n = p.n;
  s.duration_s = p.duration_s;
  if (p.current_a) s.current_a = p.current_a->summary;
  if (p.power_w) {
    s.power_w = p.power_w->summary;
    s.power_p5 = p.power_w->pct.p5;
    s.power_p50 = p.power_w->pct.p50;
    s.power_p95 = p.power_w->pct.p95;
    s.power_p99 = p.power_w->pct.p99;
  }
  s.energy_j = p.energy_j.value_or(0);
  return s;
}

double paper_flops_per_watt(double peak_flops, double supply_v, double max_current_a) {
  if (!(supply_v > 0 && max_current_a > 0))
    throw std::invalid_argument("supply voltage and maximum current must be > 0");
  return peak_flops / (supply_v * max_current_a);
}

double constant_power_runtime_h(double nominal_v, double capacity_ah, double mean_power_w, double usable_fraction) {
  if (!(nominal_v > 0 && capacity_ah > 0 && mean_power_w > 0 && usable_fraction > 0 && usable_fraction <= 1))
    throw std::invalid_argument("battery: volts, capacity and power must be > 0 and the usable fraction in (0, 1]");
  return nominal_v * capacity_ah * usable_fraction / mean_power_w;
}

}  // namespace bs
