// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_measurement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bs::headroom {

std::string_view to_string(LatencyKind kind) {
  switch (kind) {
    case LatencyKind::SystemWakeup:
      return "system wake-up latency";
    case LatencyKind::ApplicationLoop:
      return "application loop";
    case LatencyKind::MessageLatency:
      return "message latency";
  }
  return "unknown";
}

std::string_view to_id(LatencyKind kind) {
  switch (kind) {
    case LatencyKind::SystemWakeup:
      return "wakeup";
    case LatencyKind::ApplicationLoop:
      return "loop";
    case LatencyKind::MessageLatency:
      return "message";
  }
  return "unknown";
}

std::optional<LatencyKind> latency_kind_from_id(std::string_view id) {
  for (LatencyKind k : {LatencyKind::SystemWakeup, LatencyKind::ApplicationLoop, LatencyKind::MessageLatency})
    if (to_id(k) == id) return k;
  return std::nullopt;
}

std::string_view to_id(LoadKind kind) {
  switch (kind) {
    case LoadKind::Idle:
      return "idle";
    case LoadKind::Pipeline:
      return "pipeline";
    case LoadKind::Detector:
      return "dnn";
    case LoadKind::Kernels:
      return "flops";
    case LoadKind::Command:
      return "command";
    case LoadKind::Unknown:
      return "unknown";
  }
  return "unknown";
}

std::optional<LoadKind> load_kind_from_id(std::string_view id) {
  for (LoadKind k : {LoadKind::Idle, LoadKind::Pipeline, LoadKind::Detector, LoadKind::Kernels, LoadKind::Command,
                     LoadKind::Unknown})
    if (to_id(k) == id) return k;
  return std::nullopt;
}

const Phase* HeadroomMeasurement::phase(std::string_view name) const {
  for (const Phase& p : phases)
    if (p.name == name) return &p;
  return nullptr;
}

bool HeadroomMeasurement::realtime() const {
  bool any = false;
  for (const Phase& p : phases)
    for (const ThreadLatency& t : p.threads) {
      if (!t.realtime()) return false;
      any = true;
    }
  return any;
}

std::string HeadroomMeasurement::bookkeeping_error() const {
  for (const Phase& p : phases)
    for (const ThreadLatency& t : p.threads)
      if (std::string e = t.histogram.bookkeeping_error(); !e.empty())
        return "phase '" + p.name + "' thread " + std::to_string(t.index) + ": " + e;
  return {};
}

bool load_not_applied(const Phase& p) {
  return p.target_rate && p.achieved_rate && *p.target_rate > 0 &&
         *p.achieved_rate < (1 - kLoadShortfall) * *p.target_rate;
}

std::string rate_text(double rate) {
  char text[32];
  std::snprintf(text, sizeof text, std::abs(rate) >= 100 ? "%.0f" : "%.3g", rate);
  return text;
}

std::string load_not_applied_text(const Phase& p) {
  if (!load_not_applied(p)) return {};
  char share[16];
  std::snprintf(share, sizeof share, "%.0f %%", 100 * *p.achieved_rate / *p.target_rate);
  return "load not applied: " + p.name + " ran at " + rate_text(*p.achieved_rate) + " of " + rate_text(*p.target_rate) +
         " " + p.rate_unit + " (" + share + ")";
}

std::vector<std::string> flags(const HeadroomMeasurement& m) {
  std::vector<std::string> out;
  // First: it decides what the loop result beside that load means.
  for (const Phase& p : m.phases)
    if (load_not_applied(p)) out.push_back(load_not_applied_text(p) + ": the loop result beside it is unknown");
  std::vector<std::string> policies;
  bool unlocked = false, overflow = false, histogram_misses = false, summary_only = false;
  std::int64_t limit_us = 0;
  for (const Phase& p : m.phases)
    for (const ThreadLatency& t : p.threads) {
      if (!t.realtime()) {
        const std::string policy = t.policy.empty() ? "policy unknown" : t.policy;
        if (std::find(policies.begin(), policies.end(), policy) == policies.end()) policies.push_back(policy);
      }
      if (t.memory_locked == false) unlocked = true;
      if (t.histogram.bins.empty()) {
        summary_only = true;
      } else if (t.histogram.overflows > 0) {
        overflow = true;
        limit_us = t.histogram.limit_ns() / 1000;
      }
      if (!t.misses && t.deadline_ns > 0) histogram_misses = true;
    }
  if (!policies.empty()) {
    std::string list;
    for (const std::string& p : policies) list += (list.empty() ? "" : ", ") + p;
    out.push_back("non-real-time (" + list + "): not comparable with real-time results");
  }
  if (m.kernel.preempt_rt == false) out.push_back("kernel not PREEMPT_RT (" + m.kernel.preemption + ")");
  if (unlocked) out.push_back("memory not locked");
  if (!m.kernel.governor.empty() && m.kernel.governor != "performance")
    out.push_back("CPU governor " + m.kernel.governor);
  if (overflow) out.push_back("latencies beyond the " + std::to_string(limit_us) + " us histogram (max kept)");
  if (histogram_misses && !summary_only) out.push_back("misses counted from the histogram: no run lengths");
  if (summary_only) out.push_back("summary only (no histogram): percentiles and misses not in the file");
  return out;
}

std::string comparability_problem(const HeadroomMeasurement& a, const HeadroomMeasurement& b) {
  if (a.kind != b.kind)
    return "different quantities: " + std::string(to_string(a.kind)) + " vs " + std::string(to_string(b.kind));
  if (a.realtime() != b.realtime()) return "one ran real-time (SCHED_FIFO/RR), the other did not";
  return {};
}

}  // namespace bs::headroom
