// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Synthetic headroom measurements whose percentiles, maxima and miss runs are known by construction, shared by the
// tests of the loop requirement, the Platforms tab and the headroom figure.
#include <string>
#include <utility>
#include <vector>

#include "headroom/headroom_measurement.h"
#include "headroom/latency_recorder.h"

namespace bs::test {

// A 1 kHz SCHED_FIFO thread (deadline = period, 1 us bins up to 10 ms): `n` cycles at `base_us`, then one cycle at
// each of `late_us` in order (consecutive ones above 1000 us make a run of misses).
inline headroom::ThreadLatency loop_thread(int n, int base_us, const std::vector<int>& late_us = {}) {
  headroom::LatencyRecorder r(10'000'000, 1000, 1'000'000);
  for (int i = 0; i < n; ++i) r.add(base_us * 1000LL);
  for (int us : late_us) r.add(us * 1000LL);
  headroom::ThreadLatency t = r.result();
  t.policy = "SCHED_FIFO";
  t.priority = 80;
  t.period_ns = 1'000'000;
  t.deadline_ns = 1'000'000;
  return t;
}

// An application-loop measurement of the probe on `platform`, one thread per phase.
inline headroom::HeadroomMeasurement loop_measurement(
    const std::string& platform, const std::vector<std::pair<std::string, headroom::ThreadLatency>>& phases,
    const std::string& date = "2026-11-28T10:00:00Z") {
  headroom::HeadroomMeasurement m;
  m.platform = platform;
  m.kind = headroom::LatencyKind::ApplicationLoop;
  m.tool = "benchscope probe";
  m.provenance.date = date;
  m.provenance.origin = DataOrigin::Measured;
  for (const auto& [name, thread] : phases) {
    headroom::Phase p;
    p.name = name;
    p.threads.push_back(thread);
    m.phases.push_back(p);
  }
  return m;
}

}  // namespace bs::test
