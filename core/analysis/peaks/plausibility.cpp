// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/peaks/plausibility.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "analysis/power/power.h"
#include "analysis/power/power_stats.h"
#include "analysis/stats/units.h"
#include "util/enum_words.h"

namespace bs {
namespace {

std::string ratio_text(double r) {
  char buf[32];
  std::snprintf(buf, sizeof buf, r < 10 ? "%.1fx" : "%.0fx", r);
  return buf;
}

std::string seconds_text(double t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f s", t);
  return buf;
}

// Why a FLOPS figure can exceed what the hardware does: both causes the paper's own NUC GPU figure shows.
constexpr const char* kFlopsCauses =
    " No measurement can exceed the hardware's peak: likely not all counted FLOPs were executed (the compiler "
    "removed or merged work whose result was unused, or fewer work-items ran than were counted), or the time is "
    "wrong (an asynchronous kernel launch timed without waiting for it to finish, a wrong clock unit).";

std::string spec_text(const DeviceSpec& spec) {
  // The derivation, not the whole source: the reason goes into footnotes; the source is in the spec itself.
  return spec.name + "'s FP32 peak of " + format_si(spec.fp32_peak_flops, "FLOPS") + " (" + spec.derivation +
         "; device table)";
}

std::string_view quantity_noun(PowerQuantity q) {
  constexpr EnumWord<PowerQuantity> kNouns[] = {
      {PowerQuantity::Current, "current"}, {PowerQuantity::Voltage, "voltage"}, {PowerQuantity::Power, "power"}};
  static_assert(names_every_value(kNouns, PowerQuantity::Power));
  return word_of(kNouns, q, "value");
}

double magnitude_limit(PowerQuantity q) {
  switch (q) {
    case PowerQuantity::Current:
      return kMaxPlausibleCurrentA;
    case PowerQuantity::Voltage:
      return kMaxPlausibleVoltageV;
    case PowerQuantity::Power:
      return kMaxPlausiblePowerW;
  }
  return kMaxPlausiblePowerW;
}

struct Finding {
  std::size_t count = 0;
  std::size_t first = 0;
  double value = 0;  // the first offending value (for a jump: the larger of the pair)
  double other = 0;  // for a jump: the smaller neighbour
};

void note(Finding& f, std::size_t k, double value, double other = 0) {
  if (f.count++ == 0) {
    f.first = k;
    f.value = value;
    f.other = other;
  }
}

std::string where_text(const PowerTrace& trace, const PowerChannel& ch, const Finding& f) {
  std::string s = "channel " + ch.name + ": " + std::to_string(f.count) + (f.count == 1 ? " sample" : " samples");
  if (f.first < trace.time_s.size()) s += ", first at " + seconds_text(trace.time_s[f.first]);
  return s;
}

}  // namespace

std::vector<PlausibilityFlag> check_flops(double flops, const DeviceSpec* spec, std::optional<double> theoretical) {
  std::vector<PlausibilityFlag> flags;
  if (spec && spec->fp32_peak_flops > 0 && flops > kSpecPeakTolerance * spec->fp32_peak_flops)
    flags.push_back({flag_code::kAboveSpecPeak, format_si(flops, "FLOPS") + " is " +
                                                    ratio_text(flops / spec->fp32_peak_flops) + " the " +
                                                    spec_text(*spec) + "." + kFlopsCauses});
  if (theoretical && *theoretical > 0 && flops > kTheoreticalPeakTolerance * *theoretical)
    flags.push_back(
        {flag_code::kAboveTheoreticalPeak, format_si(flops, "FLOPS") + " is " + ratio_text(flops / *theoretical) +
                                               " the theoretical peak BenchScope computed for the measured device (" +
                                               format_si(*theoretical, "FLOPS") + ")." + kFlopsCauses});
  return flags;
}

std::vector<PlausibilityFlag> check_power_trace(const PowerTrace& trace, std::optional<double> platform_tdp) {
  std::vector<PlausibilityFlag> flags;
  const std::string label = trace.label.empty() ? trace.platform : trace.label;
  std::optional<double> max_power;  // over power channels, for the TDP check
  const PowerChannel* max_power_channel = nullptr;
  for (const PowerChannel& ch : trace.channels) {
    const std::string unit(unit_of(ch.quantity));
    std::vector<double> magnitudes;
    magnitudes.reserve(ch.values.size());
    for (double v : ch.values)
      if (std::isfinite(v)) magnitudes.push_back(std::fabs(v));
    if (magnitudes.empty()) continue;
    const double med = median(std::move(magnitudes));  // moved: a 100M-sample channel is not copied twice
    // Sensor offset allowance: 1 % of the median |value| (spikes cannot widen it), at least 1 mA / 1 mW / 1 mV.
    const double allowance = std::max(kNegativeNoiseFraction * med, kNegativeNoiseFloor);
    Finding negative, huge, jump;
    double prev = NAN;
    for (std::size_t k = 0; k < ch.values.size(); ++k) {
      const double v = ch.values[k];
      if (!std::isfinite(v)) continue;  // a missing sample breaks no neighbourhood: compare across it
      if (v < -allowance) note(negative, k, v);
      if (std::fabs(v) > magnitude_limit(ch.quantity)) note(huge, k, v);
      if (std::isfinite(prev)) {
        const double lo = std::min(std::fabs(v), std::fabs(prev)), hi = std::max(std::fabs(v), std::fabs(prev));
        if (lo > 0 && lo >= kJumpFloorFraction * med && hi >= kJumpRatio * lo) note(jump, k, hi, lo);
      }
      prev = v;
      if (ch.quantity == PowerQuantity::Power && (!max_power || v > *max_power)) {
        max_power = v;
        max_power_channel = &ch;
      }
    }
    const std::string noun(quantity_noun(ch.quantity));
    if (negative.count > 0)
      flags.push_back({flag_code::kNegativeValue,
                       label + ": negative " + noun + " (" + format_si(negative.value, unit) + ") in " +
                           where_text(trace, ch, negative) +
                           ". A supply draws, it does not deliver: the shunt or probe is reversed, or the column is "
                           "not what its header says."});
    if (huge.count > 0)
      flags.push_back({flag_code::kImplausibleMagnitude,
                       label + ": " + noun + " of " + format_si(huge.value, unit) + " in " +
                           where_text(trace, ch, huge) + ", above the " +
                           format_si(magnitude_limit(ch.quantity), unit) +
                           " no robot computer draws: likely a unit error (mA or mW read as A or W) or a corrupt "
                           "sample."});
    if (jump.count > 0)
      flags.push_back(
          {flag_code::kMagnitudeJump, label + ": " + noun + " jumps " + ratio_text(jump.value / jump.other) + " (" +
                                          format_si(jump.other, unit) + " to " + format_si(jump.value, unit) +
                                          ") between neighbouring samples in " + where_text(trace, ch, jump) +
                                          ": likely a unit change or a corrupt sample, not a change of load."});
  }
  if (platform_tdp && max_power && max_power_channel && *max_power > kPlatformTdpFactor * *platform_tdp &&
      *max_power <= kMaxPlausiblePowerW)
    flags.push_back({flag_code::kAbovePlatformPower,
                     label + ": power reaches " + format_si(*max_power, "W") + " in channel " +
                         max_power_channel->name + ", " + ratio_text(*max_power / *platform_tdp) + " the " +
                         format_si(*platform_tdp, "W") + " TDP of platform " + trace.platform +
                         " (device table): likely a unit error or a log of another machine."});
  return flags;
}

std::vector<PlausibilityFlag> check_power_trace_bundled(const PowerTrace& trace) {
  return check_power_trace(trace, platform_tdp_w(bundled_device_table().table, trace.platform));
}

void merge_flags(std::vector<PlausibilityFlag>& flags, const std::vector<PlausibilityFlag>& more) {
  for (const PlausibilityFlag& f : more)
    if (std::find(flags.begin(), flags.end(), f) == flags.end()) flags.push_back(f);
}

std::string flags_text(const std::vector<PlausibilityFlag>& flags) {
  std::string s;
  for (const PlausibilityFlag& f : flags) s += (s.empty() ? "" : "\n") + std::string("\xE2\x9A\xA0 ") + f.reason;
  return s;
}

}  // namespace bs
