// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "model/provenance.h"

namespace bs {

// What a logged channel measures. Values are always stored in SI base units (A, V, W).
enum class PowerQuantity { Current, Voltage, Power };

struct PowerChannel {
  std::string name;  // as in the file: "current", "VDD_IN", "VDD_SYS_GPU", "I_main"
  PowerQuantity quantity = PowerQuantity::Current;
  // One per timestamp, SI units. NaN marks a missing sample ("[N/A]", an empty cell, "<not counted>"): it is
  // never read as zero, and statistics skip it.
  std::vector<double> values;
};

// A named time range of a trace: marked by the user or found from level changes ("idle", "load", "benchmark").
struct TracePhase {
  std::string name;
  double start_s = 0;
  double end_s = 0;
};

// A supply current/power log of one platform. Timestamps are seconds from the first sample, non-decreasing;
// irregular spacing is allowed (energy integrates trapezoidally).
struct PowerTrace {
  std::string platform;    // "NUC", "Jetson TX2"
  std::string label;       // e.g. file stem or "pedestrian detection run"
  std::string start_time;  // ISO 8601 of the first sample when the log had absolute times, else empty
  std::vector<double> time_s;
  std::vector<PowerChannel> channels;
  // Supply voltage used to turn current into power when the log has no voltage channel (paper: 16 V).
  std::optional<double> supply_voltage_v;
  std::vector<TracePhase> phases;
  Provenance provenance;
  // The channel that is the whole board's or package's power or current (tegrastats VDD_IN, jtop "Power TOT", a
  // meter's single channel). Empty: the first power channel, else the first current channel (the rule before
  // this field existed). Never the sum of the rails together with their total.
  std::string total_channel;
};

}  // namespace bs
