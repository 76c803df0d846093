// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The CSV `record-power` writes (and `run flops --power --out` beside its run JSON): comment lines first, then
// one column of watts per channel.
//
//   # benchscope power recording v1
//   # sensor: rapl package-0 (rapl:package-0)
//   # kind: rapl
//   # host: robot-nuc
//   # start_time: 2026-11-22T10:00:01.250Z
//   # measurement: on-board sensor
//   # total_channel: package-0
//   # setting: sample interval = 100 ms
//   # phase: W=64, D=4 = 1.250000 .. 2.500000
//   time_s,package-0 power (W),package-0 core power (W)
//   0.000000,12.5,8.25
//
// Every power-CSV reader reads the columns (time + "... power (W)"); importers/power_recording reads the comments
// back into the trace's provenance, total channel and phases.
#include <ostream>
#include <string>

#include "model/power_trace.h"

namespace bs::sensors {

inline constexpr const char* kRecordingMagic = "# benchscope power recording v1";
// The column header of a channel: "<name> power (W)" (what the importer strips to get the name back).
std::string recording_column(const std::string& channel);
void write_recording_csv(std::ostream& out, const PowerTrace& trace);
// Writes to `path` through a temporary file renamed into place, so a crash never leaves half a file.
void save_recording_csv(const std::string& path, const PowerTrace& trace);

}  // namespace bs::sensors
