// SPDX-License-Identifier: GPL-3.0-or-later
#include "headroom/headroom_table.h"

#include <cstdio>

#include "util/text.h"

namespace bs::headroom {
std::string latency_text(std::int64_t ns) {
  const double us = static_cast<double>(ns) / 1000.0;
  if (ns % 1000 == 0 || us >= 100) return format_number("%.0f us", us);
  return format_number("%.1f us", us);
}

std::string latency_text(const HistogramPercentile& p) { return (p.at_least ? ">= " : "") + latency_text(p.ns); }

std::string misses_text(const LatencySummary& s) {
  if (!s.misses) return "–";
  const std::string at_least = s.misses_exact ? "" : ">= ";
  const double pct = s.miss_percent();
  const std::string p = pct == 0 ? "0 %" : pct < 0.01 ? format_number("%.4f %%", pct) : format_number("%.2f %%", pct);
  return at_least + p + " (" + at_least + std::to_string(*s.misses) + ")";
}

ExportTable headroom_table(const HeadroomMeasurement& m, const std::string& source) {
  ExportTable t;
  t.caption = "Control-loop headroom: " + std::string(to_string(m.kind)) + " on " + m.platform + " (" + m.tool +
              (source.empty() ? "" : ", " + source) + ")";
  t.label = "tab:headroom";
  t.header = {"Phase", "Thread", "Rate (Hz)",        "p50", "p99",           "p99.9",          "p99.99",
              "Max",   "Misses", "Longest miss run", "n",   "Load achieved", "Mean power (W)", "Policy"};
  t.align = "llrrrrrrrrrrrl";
  for (const Phase& p : m.phases)
    for (const ThreadLatency& th : p.threads) {
      const LatencySummary s = summarize(th);
      std::string thread = std::to_string(th.index);
      if (th.cpu) thread += " (CPU " + std::to_string(*th.cpu) + ")";
      std::string load = "–";
      if (p.achieved_rate)
        load = rate_text(*p.achieved_rate) + (p.target_rate ? " of " + rate_text(*p.target_rate) : "") + " " +
               p.rate_unit + (load_not_applied(p) ? " (not applied)" : "");
      std::string policy = th.policy.empty() ? "unknown" : th.policy;
      if (th.priority) policy += " " + std::to_string(*th.priority);
      // A summary without a histogram has no percentiles: the cell says they are not in the file, never ">= 0 us".
      const auto pct = [&](const HistogramPercentile& q) {
        return s.no_distribution ? std::string("not in the file") : latency_text(q);
      };
      t.rows.push_back({p.name, thread, th.period_ns > 0 ? format_number("%.0f", th.rate_hz()) : "–", pct(s.p50),
                        pct(s.p99), pct(s.p999), pct(s.p9999), s.max_ns ? latency_text(*s.max_ns) : "–", misses_text(s),
                        s.longest_miss_run ? std::to_string(*s.longest_miss_run) : "–",
                        s.cycles > 0 || !s.no_distribution ? std::to_string(s.cycles) : "–", load,
                        p.mean_power_w ? format_number("%.2f", *p.mean_power_w) : "–", policy});
    }
  // The deadline each thread was judged against, and every flag, under the table.
  for (const Phase& p : m.phases)
    if (!p.threads.empty()) {
      const ThreadLatency& th = p.threads.front();
      t.notes.push_back("deadline: latency + computation (" + latency_text(th.computation_ns) + ") > " +
                        latency_text(th.deadline_ns) + "; percentiles are nearest-rank over 1 us bins (lower edge)");
      break;
    }
  for (const std::string& f : flags(m)) t.notes.push_back("flag: " + f);
  for (const Phase& p : m.phases)
    for (const std::string& n : p.notes) t.notes.push_back(p.name + ": " + n);
  return t;
}

}  // namespace bs::headroom
