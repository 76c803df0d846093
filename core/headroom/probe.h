// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The control-loop probe: a stand-in for a robot's balance loop. Each thread wakes periodically on absolute times of
// CLOCK_MONOTONIC (clock_nanosleep TIMER_ABSTIME, as cyclictest does, so a late wake-up never shifts the schedule),
// records how late it woke, optionally spins for a set "control computation", and counts a deadline miss when
// latency + computation exceeds the deadline. It asks for SCHED_FIFO at a priority and for locked memory; where the
// user may not have them it runs as a normal thread and every result says so (ThreadLatency::policy,
// memory_locked; flags()).
//
// A thread that falls a whole period or more behind (a long preemption, or computation longer than the period)
// skips the activations it lost, as a control loop drops a cycle, and counts each as a cycle that missed with the
// lateness it would have had: the cycle count stays rate x duration and no latency is hidden.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "headroom/thread_latency.h"
#include "util/cancel.h"

namespace bs::headroom {

inline constexpr double kMinRateHz = 50, kMaxRateHz = 10'000;

struct ProbeConfig {
  double rate_hz = 1000;                    // kMinRateHz .. kMaxRateHz
  int threads = 1;                          // 1 .. 64
  std::int64_t computation_ns = 0;          // busy work per cycle; below the period
  std::optional<std::int64_t> deadline_ns;  // default: the period
  std::vector<int> cpus;                    // thread k pinned to cpus[k % size]; empty: not pinned
  bool realtime = true;                     // ask for SCHED_FIFO and mlockall (refusals are recorded, not fatal)
  int priority = 80;                        // SCHED_FIFO priority asked, 1 .. 99
  std::int64_t limit_ns = 10'000'000;       // histogram limit (1 us bins); the true maximum is kept beyond it
  std::int64_t bin_ns = 1000;

  std::int64_t period_ns() const;
  std::int64_t deadline() const { return deadline_ns.value_or(period_ns()); }
};

// "" when the configuration can run, else what is wrong ("rate 20000 Hz is outside 50 .. 10000 Hz").
std::string validate(const ProbeConfig& config);

struct ProbeResult {
  std::vector<ThreadLatency> threads;
  double wall_s = 0;               // how long the threads ran
  double cpu_s_per_s = 0;          // the probe threads' own CPU time per second of wall time (its overhead)
  std::vector<std::string> notes;  // "SCHED_FIFO refused (Operation not permitted): ran as SCHED_OTHER", ...
};

// What the process may have: checked before a run so the user is told up front (the run re-checks per thread).
struct RealtimeRights {
  bool fifo = false;        // sched_setscheduler(SCHED_FIFO) would be allowed (tried on a scratch thread)
  int max_priority = 0;     // RLIMIT_RTPRIO, or 99 with CAP_SYS_NICE
  bool memlock = false;     // mlockall(MCL_CURRENT) allowed
  std::string explanation;  // "SCHED_FIFO not permitted (no CAP_SYS_NICE, RLIMIT_RTPRIO 0)"
};
RealtimeRights probe_realtime_rights();

// Runs the probe for `seconds` (or until cancelled: throws Cancelled after stopping every thread). Progress goes to
// `cancel`'s receiver (CancelToken::report). Throws std::invalid_argument for a configuration validate() refuses,
// std::runtime_error when a thread cannot be started.
ProbeResult run_probe(const ProbeConfig& config, double seconds, const CancelToken* cancel = nullptr,
                      const std::string& step = "probe");

}  // namespace bs::headroom
