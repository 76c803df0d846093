// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One headroom measurement: periodic threads measured in phases (idle, then each load), with what was measured, the
// kernel's real-time facts and where the numbers came from. BenchScope's probe writes one; the importers turn a
// cyclictest / rttest / performance_test file into one (usually a single phase).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "headroom/kernel_facts.h"
#include "headroom/thread_latency.h"
#include "model/provenance.h"

namespace bs::headroom {

// What a latency means. The three are different quantities and are never mixed in one ranking or plot without
// saying so: cyclictest's wake-up latency is the system's floor, an application loop adds its own work and
// jitter, a message latency is publisher-to-subscriber time through middleware.
enum class LatencyKind { SystemWakeup, ApplicationLoop, MessageLatency };

std::string_view to_string(LatencyKind kind);  // "system wake-up latency", "application loop", "message latency"
std::string_view to_id(LatencyKind kind);      // "wakeup", "loop", "message" (stored, JSON)
std::optional<LatencyKind> latency_kind_from_id(std::string_view id);

// What ran beside the loop during one phase.
enum class LoadKind { Idle, Pipeline, Detector, Kernels, Command, Unknown };
std::string_view to_id(LoadKind kind);  // "idle", "pipeline", "dnn", "flops", "command", "unknown"
std::optional<LoadKind> load_kind_from_id(std::string_view id);

struct Phase {
  std::string name;  // "idle", "pipeline@30fps", "flops W=4", "stress-ng --cpu 4"
  LoadKind load = LoadKind::Idle;
  std::string load_detail;              // what exactly: the command line, the network, the frame set
  std::optional<double> target_rate;    // asked: 30 (fps)
  std::optional<double> achieved_rate;  // what the load really did in this phase, same unit
  std::string rate_unit;                // "fps", "inferences/s", "GFLOPS", "bogo ops/s"
  double duration_s = 0;                // how long the loop was measured in this phase
  std::vector<ThreadLatency> threads;
  std::optional<double> mean_power_w;       // recorded beside the phase where a sensor exists
  std::string power_sensor;                 // "RAPL package-0", ...
  std::optional<double> probe_cpu_s_per_s;  // the probe's own CPU time per second of the phase (its overhead)
  std::vector<std::string> notes;           // "load fell short of 30 fps: 22.4 fps", "stress-ng exited with 1"
};

struct HeadroomMeasurement {
  std::string platform;
  LatencyKind kind = LatencyKind::ApplicationLoop;
  std::string tool;     // "benchscope probe", "cyclictest", "rttest", "performance_test"
  std::string command;  // how it was run, as given
  KernelFacts kernel;
  std::vector<Phase> phases;
  Provenance provenance;

  const Phase* phase(std::string_view name) const;
  // Every thread of every phase ran under SCHED_FIFO/RR. A measurement with any normal thread is "non-real-time":
  // its numbers are not comparable with a real-time one's.
  bool realtime() const;
  // "" when every thread's cycles == histogram sum + overflows, else "phase 'idle' thread 0: cycles ..."
  std::string bookkeeping_error() const;
};

// A load that fell more than this fraction short of its target rate was not applied as asked (issue #50: a phase
// "beside pipeline@30fps" that ran at 9.29 fps measured the loop beside a third of the load): the loop's result
// beside it is "unknown: load not applied", never a pass or a fail.
inline constexpr double kLoadShortfall = 0.05;
// True when the phase asked for a rate and achieved less than (1 - kLoadShortfall) of it.
bool load_not_applied(const Phase& p);
// A load's rate in a few digits: "9.29", "30", "1000" (never "1e+03").
std::string rate_text(double rate);
// "load not applied: pipeline@30fps ran at 9.29 of 30 fps (31 %)", "" when the load was applied.
std::string load_not_applied_text(const Phase& p);

// Flags shown beside the measurement in every view and output: "non-real-time (SCHED_OTHER)", "not PREEMPT_RT",
// "memory not locked", "governor powersave", "overflows beyond 10000 us", "misses from histogram (no runs)".
std::vector<std::string> flags(const HeadroomMeasurement& m);

// Why two measurements cannot be compared directly, "" when they can (same kind, same real-time-ness).
std::string comparability_problem(const HeadroomMeasurement& a, const HeadroomMeasurement& b);

}  // namespace bs::headroom
