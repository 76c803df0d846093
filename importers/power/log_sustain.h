// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The sustained-performance record (#53) of an imported power log: the clocks and temperatures the log carries
// beside its rails, on the power trace's own time axis, so a lab's long tegrastats, jtop or nvidia-smi log shows
// throttling like a `benchscope-cli sustain` run. Shared by those importers so that all three fill it alike.
#include <optional>
#include <string>
#include <vector>

#include "model/power_trace.h"
#include "model/sustain_run.h"
#include "power/sample_series.h"

namespace bs::meter {

// What one log gave besides power, in its own units.
struct LogSensors {
  std::vector<SampleSeries::Series> clocks_mhz;  // one value per trace sample; NaN: off or not read
  std::vector<std::optional<double>> max_mhz;    // per clock, where the log states its maximum
  std::vector<SampleSeries::Series> celsius;     // one value per trace sample; NaN: no reading
  std::vector<std::string> not_exposed;          // what the log lacks, in words ("no GPU clock: ...")
  std::vector<std::string> notes;                // how values were read, for the provenance note
};

// The record for `trace`: same platform, label and provenance (tool, file, date, sensor); t_s = trace.time_s;
// power_w = the trace's total channel; no load, no rate. Series without a single reading (a core off for the whole
// log, a sensor that printed -256 throughout) are left out and named in the note. Empty when no clock and no
// temperature remain: then the log says nothing about throttling that the power trace does not.
std::optional<SustainRun> log_sustain_run(const PowerTrace& trace, LogSensors sensors);

}  // namespace bs::meter
