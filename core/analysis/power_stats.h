// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Statistics of a supply current/power trace over the whole log or a time range: n, mean, SD, min, max,
// percentiles, duration and energy for current and power, plus every channel on its own (tegrastats rails).
// Power is the log's main power channel (PowerTrace::total_channel, else the first), else current x voltage
// channel, else current x supply voltage (the paper: 16 V); which one was used is reported, so a derived number
// never passes for a measured one. Missing samples (NaN) are skipped by every statistic: n counts present samples,
// and a signal with none present is reported as unknown, never as 0.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/stats.h"
#include "model/power_trace.h"

namespace bs {

struct Percentiles {
  double p5 = 0, p50 = 0, p95 = 0, p99 = 0;
};
// Linear-interpolated percentiles (the same rule as analysis/power.h's percentile()), one sort for all four, over
// the present (non-NaN) values.
Percentiles percentiles(std::span<const double> values);

struct SignalStats {
  Summary summary;  // n, mean, sample SD, min, max
  Percentiles pct;
};
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
  std::size_t n = 0;               // samples inside the range
  double from_s = 0, to_s = 0;     // the range actually covered (clamped to the trace)
  double duration_s = 0;           // to_s - from_s
  std::optional<SignalStats> current_a;
  std::optional<SignalStats> power_w;
  PowerSource power_source = PowerSource::Unknown;
  std::optional<double> supply_v;  // the voltage used when power_source is CurrentTimesSupply
  std::optional<double> energy_j;  // trapezoidal over [from_s, to_s], interpolated at the range's ends
  std::optional<double> charge_c;  // the same for current (A s = C)
  std::vector<ChannelStats> channels;
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

// Trapezoidal integral over irregular timestamps restricted to [from_s, to_s]; the values at the ends are
// interpolated linearly, so a window cut between two samples gets its exact share. Timestamps non-decreasing.
// Missing samples (NaN) are bridged by the line between the present samples around them; the range is clipped to
// the first..last present sample.
double integrate_range(std::span<const double> time_s, std::span<const double> values, double from_s, double to_s);

}  // namespace bs
