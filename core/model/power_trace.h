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
  std::vector<double> values;  // one per timestamp, SI units
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
  std::string platform;      // "NUC", "Jetson TX2"
  std::string label;         // e.g. file stem or "pedestrian detection run"
  std::string start_time;    // ISO 8601 of the first sample when the log had absolute times, else empty
  std::vector<double> time_s;
  std::vector<PowerChannel> channels;
  // Supply voltage used to turn current into power when the log has no voltage channel (paper: 16 V).
  std::optional<double> supply_voltage_v;
  std::vector<TracePhase> phases;
  Provenance provenance;
};

}  // namespace bs
