// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_measurement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "util/enum_words.h"
#include "util/text.h"

namespace bs::headroom {

namespace {

// The words the views name each kind by, and the ids files, the workspace and the CLI store (read back by the same
// lines).
constexpr EnumWord<LatencyKind> kLatencyKindNames[] = {{LatencyKind::SystemWakeup, "system wake-up latency"},
                                                       {LatencyKind::ApplicationLoop, "application loop"},
                                                       {LatencyKind::MessageLatency, "message latency"}};
static_assert(names_every_value(kLatencyKindNames, LatencyKind::MessageLatency));
constexpr EnumWord<LatencyKind> kLatencyKindIds[] = {{LatencyKind::SystemWakeup, "wakeup"},
                                                     {LatencyKind::ApplicationLoop, "loop"},
                                                     {LatencyKind::MessageLatency, "message"}};
static_assert(names_every_value(kLatencyKindIds, LatencyKind::MessageLatency));
constexpr EnumWord<LoadKind> kLoadKindIds[] = {{LoadKind::Idle, "idle"},       {LoadKind::Pipeline, "pipeline"},
                                               {LoadKind::Detector, "dnn"},    {LoadKind::Kernels, "flops"},
                                               {LoadKind::Command, "command"}, {LoadKind::Unknown, "unknown"}};
static_assert(names_every_value(kLoadKindIds, LoadKind::Unknown));

}  // namespace

std::string_view to_string(LatencyKind kind) { return word_of(kLatencyKindNames, kind, "unknown"); }

std::string_view to_id(LatencyKind kind) { return word_of(kLatencyKindIds, kind, "unknown"); }

std::optional<LatencyKind> latency_kind_from_id(std::string_view id) { return parse_word(kLatencyKindIds, id); }

std::string_view to_id(LoadKind kind) { return word_of(kLoadKindIds, kind, "unknown"); }

std::optional<LoadKind> load_kind_from_id(std::string_view id) { return parse_word(kLoadKindIds, id); }

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
    out.push_back("non-real-time (" + join(policies, ", ") + "): not comparable with real-time results");
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
