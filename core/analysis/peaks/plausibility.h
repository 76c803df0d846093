// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Plausibility flags: a FLOPS or power number that no hardware can produce is shown with a flag that says why,
// never silently. Definitions (docs/cli.md, "Plausibility flags"):
//  - above_spec_peak: a FLOPS figure above kSpecPeakTolerance x the device's vendor FP32 peak (device table);
//  - above_theoretical_peak: above kTheoreticalPeakTolerance x the peak BenchScope computed for the measured device;
//  - negative_value, implausible_magnitude, above_platform_power, magnitude_jump: a power/current/voltage log.
#include <optional>
#include <string>
#include <vector>

#include "analysis/peaks/device_table.h"
#include "model/power_trace.h"

namespace bs {

struct PlausibilityFlag {
  std::string code;    // stable id, e.g. "above_spec_peak"
  std::string reason;  // one or two sentences for a tooltip or a footnote: the numbers, and the likely causes
  bool operator==(const PlausibilityFlag&) const = default;
};

namespace flag_code {
inline constexpr const char* kAboveSpecPeak = "above_spec_peak";
inline constexpr const char* kAboveTheoreticalPeak = "above_theoretical_peak";
inline constexpr const char* kSpecCheckUnavailable = "spec_check_unavailable";
inline constexpr const char* kNegativeValue = "negative_value";
inline constexpr const char* kImplausibleMagnitude = "implausible_magnitude";
inline constexpr const char* kAbovePlatformPower = "above_platform_power";
inline constexpr const char* kMagnitudeJump = "magnitude_jump";
}  // namespace flag_code

// Vendor peaks are at the rated boost clock; GPUs boost opportunistically above it (a GTX 1080 Ti runs ~1.9 GHz
// against a rated 1.58 GHz, 1.2x). 30 % above the vendor peak is more than clocks explain.
inline constexpr double kSpecPeakTolerance = 1.3;
// BenchScope's own peak uses the device's reported clock: 10 % covers turbo above it and timer resolution.
inline constexpr double kTheoreticalPeakTolerance = 1.1;

// Flags of one FLOPS figure: against `spec` (nullptr: unknown device, no spec check) and the theoretical peak.
std::vector<PlausibilityFlag> check_flops(double flops, const DeviceSpec* spec,
                                          std::optional<double> theoretical_flops = std::nullopt);

// Power limits. A robot computer draws watts to hundreds of watts; these catch unit and sign errors, not waste.
inline constexpr double kMaxPlausiblePowerW = 10e3;     // 10 kW
inline constexpr double kMaxPlausibleCurrentA = 1e3;    // 1 kA
inline constexpr double kMaxPlausibleVoltageV = 1e3;    // 1 kV
inline constexpr double kPlatformTdpFactor = 10;        // power above 10x the platform's TDP (device table)
inline constexpr double kNegativeNoiseFraction = 0.01;  // negatives within 1 % of the median |value| are offset,
inline constexpr double kNegativeNoiseFloor = 1e-3;     // ... or within 1 mA / 1 mW / 1 mV
inline constexpr double kJumpRatio = 100;               // two orders of magnitude between neighbouring samples
inline constexpr double kJumpFloorFraction = 0.01;      // ... where the smaller is >= 1 % of the channel's median

// Flags of a power/current log (every channel, NaN samples skipped). `platform_tdp_w` (platform_tdp_w() of the
// device table) adds the check against the platform's TDP.
std::vector<PlausibilityFlag> check_power_trace(const PowerTrace& trace,
                                                std::optional<double> platform_tdp_w = std::nullopt);
// The same with the TDP looked up in the bundled device table by the trace's platform name.
std::vector<PlausibilityFlag> check_power_trace_bundled(const PowerTrace& trace);

// Appends the flags of `more` not already in `flags` (same code and reason).
void merge_flags(std::vector<PlausibilityFlag>& flags, const std::vector<PlausibilityFlag>& more);

// "⚠ reason" lines joined by newlines, for tooltips and footnotes; "" for none.
std::string flags_text(const std::vector<PlausibilityFlag>& flags);

}  // namespace bs
