// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/power_stats.h"

#include "analysis/power/power.h"
#include "analysis/stats/order_stats.h"
#include "util/enum_words.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bs {
namespace {

// The trace's main channel of quantity q (its named total, else the first: analysis/power.h).
const PowerChannel* first_channel(const PowerTrace& t, PowerQuantity q) { return main_channel(t, q); }

SignalStats signal_of(const TraceIndex& index, const RangeSummary& r, double from_s, double to_s,
                      bool with_percentiles) {
  SignalStats s;
  s.summary = r.samples;
  s.has_percentiles = with_percentiles;
  if (with_percentiles) s.pct = index.percentiles(from_s, to_s);
  return s;
}

}  // namespace

SignalStats signal_stats(std::span<const double> values) {
  return {summarize_samples(values), percentiles(values), true};
}

std::string_view to_string(PowerSource source) {
  constexpr EnumWord<PowerSource> kWords[] = {{PowerSource::Channel, "power channel"},
                                              {PowerSource::CurrentTimesVoltage, "current x voltage channel"},
                                              {PowerSource::CurrentTimesSupply, "current x supply voltage"},
                                              {PowerSource::Unknown, "unknown (current only, no supply voltage)"}};
  static_assert(names_every_value(kWords, PowerSource::Unknown));
  return word_of(kWords, source, "unknown (current only, no supply voltage)");
}

std::string_view unit_of(PowerQuantity quantity) {
  constexpr EnumWord<PowerQuantity> kUnits[] = {
      {PowerQuantity::Current, "A"}, {PowerQuantity::Voltage, "V"}, {PowerQuantity::Power, "W"}};
  static_assert(names_every_value(kUnits, PowerQuantity::Power));
  return word_of(kUnits, quantity, "");
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
  if (!(to_s > from_s)) return 0;
  return transient_index(t.first(n), v.first(n)).integral(from_s, to_s);
}

PowerIndex::PowerIndex(const PowerTrace& trace, std::optional<double> supply_v) { build(trace, supply_v, nullptr); }

PowerIndex::PowerIndex(std::shared_ptr<const PowerTrace> trace, std::optional<double> supply_v) {
  if (!trace) throw std::invalid_argument("power index: no trace");
  const PowerTrace& t = *trace;
  build(t, supply_v, std::move(trace));
}

void PowerIndex::build(const PowerTrace& trace, std::optional<double> supply_v, std::shared_ptr<const void> owner) {
  // With an owner the samples are read in place (TraceIndex's borrowing constructor), else copied.
  const auto index_of = [&](std::span<const double> values) {
    return owner ? TraceIndex(trace.time_s, values, owner) : TraceIndex(trace.time_s, values);
  };
  if (supply_v && !(*supply_v > 0)) throw std::invalid_argument("the supply voltage must be > 0 V");
  const PowerChannel* main_current = first_channel(trace, PowerQuantity::Current);
  const PowerChannel* main_power = first_channel(trace, PowerQuantity::Power);
  for (const PowerChannel& c : trace.channels) {
    if (c.values.size() != trace.time_s.size()) continue;
    if (&c == main_current) current_ = static_cast<int>(channels_.size());
    if (&c == main_power) power_ = static_cast<int>(channels_.size());
    channels_.push_back({c.name, c.quantity, index_of(c.values)});
  }
  const std::optional<double> volts = supply_v ? supply_v : trace.supply_voltage_v;
  if (main_power) {
    source_ = PowerSource::Channel;
  } else if (main_current && !first_channel(trace, PowerQuantity::Voltage) && volts && *volts > 0 &&
             std::isfinite(*volts)) {
    // Current x a constant supply voltage: the current's own index, scaled (no second copy of a long log).
    source_ = PowerSource::CurrentTimesSupply;
    supply_v_ = volts;
    derived_power_ = channels_[static_cast<std::size_t>(current_)].index.scaled(*volts);
  } else {
    PowerSeries p = derive_power(trace, supply_v);  // current x voltage channel: its own index
    source_ = p.source;
    supply_v_ = p.supply_v;
    if (!p.values.empty()) derived_power_ = TraceIndex(trace.time_s, p.values);
  }
  note_missing_rows(trace);
}

std::size_t samples_per_reading(const PowerTrace& trace) {
  for (const auto& [key, value] : trace.provenance.settings)
    if (key == kSamplesPerReadingSetting && (value == "2" || value == "3" || value == "4"))
      return static_cast<std::size_t>(value[0] - '0');
  return 1;
}

void PowerIndex::note_missing_rows(const PowerTrace& trace) {
  samples_per_reading_ = samples_per_reading(trace);
  // The rows where the main signal has no value still count as rows of the range (PowerStats::rows).
  const PowerChannel* main_power = first_channel(trace, PowerQuantity::Power);
  const PowerChannel* main_current = first_channel(trace, PowerQuantity::Current);
  const PowerChannel* voltage = first_channel(trace, PowerQuantity::Voltage);
  for (std::size_t k = 0; k < trace.time_s.size(); ++k) {
    bool missing = true;
    if (main_power)
      missing = std::isnan(main_power->values[k]);
    else if (main_current && source_ != PowerSource::Unknown)
      missing = std::isnan(main_current->values[k]) ||
                (source_ == PowerSource::CurrentTimesVoltage && std::isnan(voltage->values[k]));
    else if (main_current)
      missing = std::isnan(main_current->values[k]);
    if (missing) missing_t_.push_back(trace.time_s[k]);
  }
}

const TraceIndex* PowerIndex::power() const {
  if (power_ >= 0) return &channels_[static_cast<std::size_t>(power_)].index;
  return source_ == PowerSource::Unknown ? nullptr : &derived_power_;
}

const TraceIndex* PowerIndex::main() const {
  if (const TraceIndex* p = power(); p && !p->empty()) return p;
  if (const TraceIndex* c = current(); c && !c->empty()) return c;
  return nullptr;
}

PowerStats PowerIndex::stats(std::optional<double> from, std::optional<double> to, bool with_percentiles) const {
  if (from && to && *to < *from) throw std::invalid_argument("the range ends before it starts");
  PowerStats s;
  s.power_source = source_;
  s.supply_v = supply_v_;
  const TraceIndex* main_signal = main();
  if (!main_signal) {
    // Neither power nor current: the channels alone (e.g. a voltage-only log).
    for (const Channel& c : channels_) {
      const RangeSummary r = c.index.summary(from.value_or(c.index.first_s()), to.value_or(c.index.last_s()));
      s.channels.push_back({c.name, c.quantity, signal_of(c.index, r, r.from_s, r.to_s, with_percentiles)});
    }
    return s;
  }
  // The range is the main signal's, clamped to its samples; every other signal is asked over the same range.
  const RangeSummary m =
      main_signal->summary(from.value_or(main_signal->first_s()), to.value_or(main_signal->last_s()));
  if (from && *from > main_signal->last_s()) return s;  // entirely after the log: nothing inside
  if (to && *to < main_signal->first_s()) return s;
  s.from_s = m.from_s;
  s.to_s = m.to_s;
  s.duration_s = m.duration_s;
  // A reading held over several samples (perf stat's interval start and end) counts once; a range that cuts one
  // counts the part inside as a reading.
  s.n = (m.samples.n + samples_per_reading_ - 1) / samples_per_reading_;
  s.rows = m.samples.n + static_cast<std::size_t>(std::upper_bound(missing_t_.begin(), missing_t_.end(), s.to_s) -
                                                  std::lower_bound(missing_t_.begin(), missing_t_.end(), s.from_s));
  for (const Channel& c : channels_) {
    const RangeSummary r = c.index.summary(s.from_s, s.to_s);
    s.channels.push_back({c.name, c.quantity, signal_of(c.index, r, s.from_s, s.to_s, with_percentiles)});
  }
  if (const TraceIndex* i = current()) {
    const RangeSummary r = i->summary(s.from_s, s.to_s);
    if (r.samples.n > 0) {  // every sample missing: unknown, not 0 A
      s.current_a = signal_of(*i, r, s.from_s, s.to_s, with_percentiles);
      s.charge_c = r.integral;
    }
  }
  if (const TraceIndex* p = power()) {
    const RangeSummary r = p->summary(s.from_s, s.to_s);
    if (r.samples.n > 0) {
      s.power_w = signal_of(*p, r, s.from_s, s.to_s, with_percentiles);
      s.energy_j = r.integral;
      if (s.duration_s > 0) s.mean_power_w = r.integral / s.duration_s;
    }
  }
  return s;
}

PowerStats power_stats(const PowerTrace& trace, const PowerStatsOptions& options) {
  if (options.from_s && options.to_s && *options.to_s < *options.from_s)
    throw std::invalid_argument("the range ends before it starts");
  // Asked once and dropped: the index reads the trace in place (an owner that owns nothing; `trace` outlives it).
  const std::shared_ptr<const PowerTrace> in_place(std::shared_ptr<const PowerTrace>{}, &trace);
  return PowerIndex(in_place, options.supply_v).stats(options.from_s, options.to_s);
}

}  // namespace bs
