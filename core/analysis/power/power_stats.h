// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Statistics of a supply current/power trace over the whole log or a time range: n, mean, SD, min, max,
// percentiles, duration and energy for current and power, plus every channel on its own (tegrastats rails).
// Power is the log's main power channel (PowerTrace::total_channel, else the first), else current x voltage
// channel, else current x supply voltage (the paper: 16 V); which one was used is reported, so a derived number
// never passes for a measured one. Missing samples (NaN) are skipped by every statistic: n counts present samples,
// and a signal with none present is reported as unknown, never as 0.
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/power/trace_index.h"
#include "analysis/stats/stats.h"
#include "model/power_trace.h"
#include "model/reading_samples.h"

namespace bs {

// Percentiles and percentiles(span) live in analysis/trace_index.h (linear interpolation, the rule of
// analysis/stats.h's percentile()).
struct SignalStats {
  Summary summary;  // n, mean, sample SD, min, max
  Percentiles pct;
  bool has_percentiles = true;  // false: left out on request (PowerIndex::stats with_percentiles = false)
};
// How many samples hold one reading (kSamplesPerReadingSetting in the trace's provenance; 1 when not said).
std::size_t samples_per_reading(const PowerTrace& trace);

// Of a plain span of values (no time): n, mean, SD, min, max and percentiles of the present values.
SignalStats signal_stats(std::span<const double> values);

enum class PowerSource { Channel, CurrentTimesVoltage, CurrentTimesSupply, Unknown };
std::string_view to_string(PowerSource source);  // "power channel", "current x voltage channel", ...

std::string_view unit_of(PowerQuantity quantity);  // "A", "V", "W"

struct ChannelStats {
  std::string name;
  PowerQuantity quantity = PowerQuantity::Current;
  SignalStats stats;
};

struct PowerStatsOptions {
  // Default member initializers let callers name only what they set ({.supply_v = v}) without GCC 12's
  // -Wmissing-field-initializers.
  std::optional<double> supply_v{};  // overrides the trace's own supply voltage
  std::optional<double> from_s{};    // seconds from the start of the trace; unset = the start
  std::optional<double> to_s{};      // unset = the end
};

struct PowerStats {
  // Readings of the main signal (power, else current) present inside the range: what the mean is over (issue
  // #32.5: an nvidia-smi "[N/A]" cell or a perf stat row of another event is no reading). `rows` counts every
  // timestamp inside the range, present or missing.
  std::size_t n = 0;
  std::size_t rows = 0;
  double from_s = 0, to_s = 0;  // the range actually covered (clamped to the main signal's present samples)
  double duration_s = 0;        // to_s - from_s (interpolated ends: not the span of the samples inside)
  std::optional<SignalStats> current_a;
  std::optional<SignalStats> power_w;
  PowerSource power_source = PowerSource::Unknown;
  std::optional<double> supply_v;      // the voltage used when power_source is CurrentTimesSupply
  std::optional<double> energy_j;      // trapezoidal over [from_s, to_s], interpolated at the range's ends
  std::optional<double> charge_c;      // the same for current (A s = C)
  std::optional<double> mean_power_w;  // energy_j / duration_s: time-weighted, unlike power_w's sample mean
  std::vector<ChannelStats> channels;
};

// The one implementation of a trace's range statistics (analysis/trace_index.h gives the definition): built once
// per trace (an index per channel and for derived power), then each range is answered in O(log n) plus exact
// percentiles. power_stats() below builds one and asks once; the Power tab keeps one per trace and asks on every
// mouse move, so the GUI and `benchscope-cli power` give the same numbers by construction.
class PowerIndex {
 public:
  PowerIndex() = default;
  // Copies the samples it needs. Throws std::invalid_argument for a supply voltage <= 0.
  explicit PowerIndex(const PowerTrace& trace, std::optional<double> supply_v = std::nullopt);
  // Reads the trace's samples in place and keeps `trace` alive (copies only channels with missing samples):
  // what a view holding a 100-million-sample log uses, so the log is not duplicated. Power as current x a
  // constant supply voltage shares the current's index in either form.
  explicit PowerIndex(std::shared_ptr<const PowerTrace> trace, std::optional<double> supply_v = std::nullopt);
  // Throws std::invalid_argument when to_s < from_s. `with_percentiles` false skips the one O(m) part (the
  // percentiles of current, power and channels), for live updates over long ranges.
  PowerStats stats(std::optional<double> from_s = std::nullopt, std::optional<double> to_s = std::nullopt,
                   bool with_percentiles = true) const;
  const TraceIndex* current() const {
    return current_ < 0 ? nullptr : &channels_[static_cast<std::size_t>(current_)].index;
  }
  const TraceIndex* power() const;  // nullptr when power is unknown
  // The main signal: power when known, else current; nullptr for a trace with neither.
  const TraceIndex* main() const;
  PowerSource power_source() const { return source_; }

 private:
  void build(const PowerTrace& trace, std::optional<double> supply_v, std::shared_ptr<const void> owner);
  void note_missing_rows(const PowerTrace& trace);
  struct Channel {
    std::string name;
    PowerQuantity quantity = PowerQuantity::Current;
    TraceIndex index;
  };
  std::vector<Channel> channels_;  // the channels whose length matches the time axis
  int current_ = -1, power_ = -1;  // main current / power channel in channels_, -1: none
  TraceIndex derived_power_;       // current x voltage or x supply when there is no power channel
  std::vector<double> missing_t_;  // timestamps of the rows where the main signal is missing, for PowerStats::rows
  std::size_t samples_per_reading_ = 1;
  PowerSource source_ = PowerSource::Unknown;
  std::optional<double> supply_v_;
};

// Throws std::invalid_argument for a range with to < from or a supply voltage <= 0.
PowerStats power_stats(const PowerTrace& trace, const PowerStatsOptions& options = {});

// Power per sample and where it came from (see the header comment). Empty values when unknown.
struct PowerSeries {
  std::vector<double> values;
  PowerSource source = PowerSource::Unknown;
  std::optional<double> supply_v;
};
PowerSeries derive_power(const PowerTrace& trace, std::optional<double> supply_v = std::nullopt);

// Trapezoidal integral over irregular timestamps restricted to [from_s, to_s] (TraceIndex::integral, built for one
// query; keep a TraceIndex for many); the values at the ends are interpolated linearly, so a window cut between two
// samples gets its exact share. Timestamps non-decreasing. Missing samples (NaN) are bridged by the line between the
// present samples around them; the range is clipped to the first..last present sample.
double integrate_range(std::span<const double> time_s, std::span<const double> values, double from_s, double to_s);

}  // namespace bs
