// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power_stats.h"

#include "analysis/power.h"
#include "analysis/order_stats.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>


namespace bs {
namespace {

// Linear interpolation at `at` between the samples around it; `t` and `v` hold present samples only.
double interpolate(std::span<const double> t, std::span<const double> v, double at) {
  const auto hi = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), at) - t.begin());
  if (hi == 0) return v.front();
  if (hi >= t.size()) return v.back();
  const std::size_t lo = hi - 1;
  const double span = t[hi] - t[lo];
  if (span <= 0) return v[hi];
  return v[lo] + (v[hi] - v[lo]) * (at - t[lo]) / span;
}

// The trace's main channel of quantity q (its named total, else the first: analysis/power.h).
const PowerChannel* first_channel(const PowerTrace& t, PowerQuantity q) { return main_channel(t, q); }

double integrate_present(std::span<const double> t, std::span<const double> v, double from_s, double to_s);

}  // namespace

Percentiles percentiles(std::span<const double> values) {
  Percentiles p;
  std::vector<double> sorted;
  sorted.reserve(values.size());
  for (double v : values)
    if (!std::isnan(v)) sorted.push_back(v);  // missing samples are skipped, never read as 0
  if (sorted.empty()) return p;
  // Selection, not a sort (analysis/order_stats.h): the same values, in linear time for a 100M-sample log.
  const double qs[] = {5, 50, 95, 99};
  const std::vector<double> at = select_percentiles(sorted, qs);
  p.p5 = at[0];
  p.p50 = at[1];
  p.p95 = at[2];
  p.p99 = at[3];
  return p;
}

SignalStats signal_stats(std::span<const double> values) { return {summarize_samples(values), percentiles(values)}; }

std::string_view to_string(PowerSource source) {
  switch (source) {
    case PowerSource::Channel: return "power channel";
    case PowerSource::CurrentTimesVoltage: return "current x voltage channel";
    case PowerSource::CurrentTimesSupply: return "current x supply voltage";
    case PowerSource::Unknown: break;
  }
  return "unknown (current only, no supply voltage)";
}

std::string_view unit_of(PowerQuantity quantity) {
  switch (quantity) {
    case PowerQuantity::Current: return "A";
    case PowerQuantity::Voltage: return "V";
    case PowerQuantity::Power: return "W";
  }
  return "";
}

PowerSeries derive_power(const PowerTrace& trace, std::optional<double> supply_v) {
  PowerSeries out;
  if (supply_v && !(*supply_v > 0)) throw std::invalid_argument("the supply voltage must be > 0 V");
  if (const PowerChannel* p = first_channel(trace, PowerQuantity::Power)) {
    out.values = p->values;
    out.source = PowerSource::Channel;
    return out;
  }
  const PowerChannel* i = first_channel(trace, PowerQuantity::Current);
  if (!i) return out;
  out.values.resize(i->values.size());
  if (const PowerChannel* v = first_channel(trace, PowerQuantity::Voltage)) {
    for (std::size_t k = 0; k < out.values.size(); ++k) out.values[k] = i->values[k] * v->values[k];
    out.source = PowerSource::CurrentTimesVoltage;
    return out;
  }
  const auto volts = supply_v ? supply_v : trace.supply_voltage_v;
  if (!volts) {
    out.values.clear();
    return out;
  }
  for (std::size_t k = 0; k < out.values.size(); ++k) out.values[k] = i->values[k] * *volts;
  out.source = PowerSource::CurrentTimesSupply;
  out.supply_v = volts;
  return out;
}

double integrate_range(std::span<const double> t, std::span<const double> v, double from_s, double to_s) {
  const std::size_t n = std::min(t.size(), v.size());
  t = t.first(n);
  v = v.first(n);
  if (std::none_of(v.begin(), v.end(), [](double x) { return std::isnan(x); })) return integrate_present(t, v, from_s, to_s);
  // Missing samples: integrate the present ones, so a gap is bridged by the straight line between its neighbours
  // and the range shrinks to the first..last present sample (analysis/power.h says the same for
  // integrate_trapezoid).
  std::vector<double> tp, vp;
  for (std::size_t k = 0; k < n; ++k)
    if (!std::isnan(v[k])) {
      tp.push_back(t[k]);
      vp.push_back(v[k]);
    }
  return integrate_present(tp, vp, from_s, to_s);
}

namespace {

double integrate_present(std::span<const double> t, std::span<const double> v, double from_s, double to_s) {
  const std::size_t n = t.size();
  if (n < 2 || !(to_s > from_s)) return 0;
  from_s = std::max(from_s, t.front());
  to_s = std::min(to_s, t.back());
  if (!(to_s > from_s)) return 0;
  // Samples strictly inside (from, to), with the interpolated end values as the outer trapezoids' corners.
  auto k = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), from_s) - t.begin());
  double prev_t = from_s, prev_v = interpolate(t, v, from_s), sum = 0;
  for (; k < n && t[k] < to_s; ++k) {
    sum += (t[k] - prev_t) * (v[k] + prev_v) / 2;
    prev_t = t[k];
    prev_v = v[k];
  }
  sum += (to_s - prev_t) * (interpolate(t, v, to_s) + prev_v) / 2;
  return sum;
}

}  // namespace

PowerStats power_stats(const PowerTrace& trace, const PowerStatsOptions& options) {
  if (options.from_s && options.to_s && *options.to_s < *options.from_s)
    throw std::invalid_argument("the range ends before it starts");
  PowerStats s;
  const std::vector<double>& t = trace.time_s;
  if (t.empty()) return s;
  s.from_s = std::max(options.from_s.value_or(t.front()), t.front());
  s.to_s = std::min(options.to_s.value_or(t.back()), t.back());
  const auto first = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), s.from_s) - t.begin());
  const auto last = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), s.to_s) - t.begin());
  if (first >= last || s.to_s < s.from_s) {
    s.to_s = std::max(s.to_s, s.from_s);
    return s;
  }
  s.n = last - first;
  s.duration_s = s.to_s - s.from_s;
  const auto slice = [&](const std::vector<double>& v) { return std::span<const double>(v).subspan(first, last - first); };
  for (const PowerChannel& c : trace.channels)
    if (c.values.size() == t.size()) s.channels.push_back({c.name, c.quantity, signal_stats(slice(c.values))});
  if (const PowerChannel* i = first_channel(trace, PowerQuantity::Current)) {
    const SignalStats c = signal_stats(slice(i->values));
    if (c.summary.n > 0) {  // every sample missing: unknown, not 0 A
      s.current_a = c;
      s.charge_c = integrate_range(t, i->values, s.from_s, s.to_s);
    }
  }
  const PowerSeries power = derive_power(trace, options.supply_v);
  s.power_source = power.source;
  s.supply_v = power.supply_v;
  if (!power.values.empty()) {
    const SignalStats p = signal_stats(slice(power.values));
    if (p.summary.n > 0) {
      s.power_w = p;
      s.energy_j = integrate_range(t, power.values, s.from_s, s.to_s);
    }
  }
  return s;
}

}  // namespace bs
