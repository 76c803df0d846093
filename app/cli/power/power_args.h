// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// --power SENSOR|auto|none, --power-interval-ms M and --sysfs-root DIR, shared by the commands that can record
// the computer's own power while they run (run flops, pipeline, bench kernels|vision|pipeline), and the
// printing of energy per phase.
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands/power_words.h"
#include "common/args.h"
#include "model/power_trace.h"
#include "sensors/recorder.h"

namespace bs::remote {
class EventWriter;
}

namespace bs::cli {

// The options to add to a command's `valued` set.
inline const std::vector<std::string> kPowerOptions = {"--power", "--power-interval-ms", "--sysfs-root"};
// The usage lines for them.
inline constexpr const char* kPowerUsage =
    "  --power SENSOR|auto|none: record this computer's power sensors while it runs (benchscope-cli sensors lists\n"
    "  them; auto: the board or package total), every --power-interval-ms (default 100), from --sysfs-root DIR\n"
    "  (default /). Prints the energy of each phase, stores the trace beside the run.";

// A started recorder, or null for --power none / absent. Throws UsageError with the sensor problem. With
// `events`, every sample is also a "power" event (--events jsonl).
std::unique_ptr<sensors::PowerRecorder> start_power(const ParsedArgs& args, std::ostream& err, bool quiet = false,
                                                    remote::EventWriter* events = nullptr);
// The same from a grammar's power words (core/commands/power_words.h).
std::unique_ptr<sensors::PowerRecorder> start_power(const commands::PowerWords& power, std::ostream& err,
                                                    bool quiet = false, remote::EventWriter* events = nullptr);
// The sensor options as record-power takes them: --sensor, --interval-ms, --sysfs-root.
std::unique_ptr<sensors::PowerRecorder> make_recorder(const std::string& spec, const std::string& root,
                                                      double interval_ms, std::ostream& err, bool quiet,
                                                      remote::EventWriter* events = nullptr);

// Prints "phase: E J over T s, mean P W (n samples)" lines and the measurement kind.
void print_phase_energies(std::ostream& out, const PowerTrace& trace);
// For each (group, items): the energy of every phase whose name starts with `group`, per item ("J per frame").
void print_energy_per_item(std::ostream& out, const PowerTrace& trace,
                           const std::vector<std::pair<std::string, std::size_t>>& groups, const std::string& item);
// "<path without .json>.power.csv": where a command with --out run.json writes the trace.
std::string power_csv_beside(const std::string& out_path);

}  // namespace bs::cli
