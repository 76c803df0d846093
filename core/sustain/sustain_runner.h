// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One sustained run on this machine (#53): a load runs without a break for S seconds; at the end of every interval
// I the runner takes the load's achieved rate over that interval (the difference of its completed work), reads
// every clock and temperature the sysfs tree exposes, and reports the interval at once (live output, the desk's
// stream). Power, where a recorder is given, is the mean of its total over each interval, computed from the trace
// when the run ends. The result is a SustainRun with this machine's provenance, ready to analyse and store.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "headroom/load.h"
#include "model/power_trace.h"
#include "model/sustain_run.h"
#include "sustain/sysfs_sampler.h"
#include "util/cancel.h"

namespace bs::sensors {
class PowerRecorder;
}

namespace bs::sustain {

inline constexpr double kMinIntervalS = 0.05, kMaxIntervalS = 3600, kMaxRunS = 7 * 86400;

struct RunConfig {
  double seconds = 60;    // how long the load runs
  double interval_s = 1;  // the rate, clocks and temperatures are taken this often (the last may be shorter)
  std::string platform;   // this host's name when empty
  std::string command;    // how the run was asked for, for the record
};

// Called on the runner's thread after each interval with the run so far (interval `index` just added) and the
// warnings that interval's readings gave.
using IntervalFn =
    std::function<void(const SustainRun& so_far, std::size_t index, const std::vector<std::string>& warnings)>;

struct RunOutput {
  SustainRun run;
  std::optional<PowerTrace> power;      // the recorder's trace, when one was given
  std::vector<std::string> load_notes;  // what the load said when stopped ("1234 kernel points")
  std::vector<std::string> warnings;    // every distinct warning of discovery and sampling, with a count
  bool cancelled = false;               // stopped early: `run` holds the intervals completed before
};

// Throws std::invalid_argument for a duration or interval out of range, std::runtime_error when the load cannot
// start or cannot count its work. `power` (may be null) is a started recorder; it is finished at the end.
RunOutput run_sustain(const RunConfig& config, headroom::Load& load, const SysfsSampler& sampler,
                      sensors::PowerRecorder* power, const CancelToken* cancel, const IntervalFn& on_interval = {});

}  // namespace bs::sustain
