// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One headroom measurement on this machine: the probe measured in phases, idle first, then beside each load in
// turn, with the power recorded through all of them where a sensor exists. Each load gets a settling time before
// the loop is measured (a pipeline fills its queues, a detector loads its network), and reports what it achieved
// while the loop was measured. The result is a HeadroomMeasurement with this machine's kernel facts and
// provenance, ready to store; the power trace (phases named after the phases) comes with it.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "headroom/headroom_measurement.h"
#include "headroom/load.h"
#include "headroom/probe.h"
#include "model/power_trace.h"
#include "util/cancel.h"

namespace bs::sensors {
class PowerRecorder;
}

namespace bs::headroom {

struct RunConfig {
  ProbeConfig probe;
  double phase_s = 20;            // the loop is measured this long in each phase
  double settle_s = 1;            // a load runs this long before its phase is measured
  bool idle_phase = true;         // measure the loop alone first
  std::string platform;           // this host's name when empty
  std::string command;            // how the run was asked for, for the record
  std::string kernel_root = "/";  // where kernel facts are read (a fixture tree in tests)
};

struct RunOutput {
  HeadroomMeasurement measurement;
  std::optional<PowerTrace> power;  // with one phase per measured phase, when a recorder was given
};

// Runs every phase in order. `power` (may be null) is a started recorder: each phase is marked on it and it is
// finished at the end (the trace comes back in RunOutput::power).
// Progress and cancel go through `cancel` (may be null): a cancel stops the running load and the probe and throws
// Cancelled, with nothing returned. A load that cannot start throws std::runtime_error naming it, after stopping
// everything started so far.
RunOutput run_headroom(const RunConfig& config, const std::vector<Load*>& loads, sensors::PowerRecorder* power,
                       const CancelToken* cancel);

}  // namespace bs::headroom
