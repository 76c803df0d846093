// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/trace_summary.h"

#include "analysis/power/power.h"

namespace bs {

TraceSummary summarize_trace(const PowerTrace& trace, std::size_t overview_columns) {
  TraceSummary s;
  s.samples = trace.time_s.size();
  if (!trace.time_s.empty()) s.duration_s = trace.time_s.back() - trace.time_s.front();
  for (const PowerChannel& c : trace.channels) {
    ChannelSummary cs;
    cs.name = c.name;
    cs.quantity = c.quantity;
    cs.stats = signal_stats(c.values);
    cs.integral = integrate_trapezoid(trace.time_s, c.values);
    if (!trace.time_s.empty() && c.values.size() == trace.time_s.size() && overview_columns > 0)
      cs.overview =
          decimate_min_max(trace.time_s, c.values, trace.time_s.front(), trace.time_s.back(), overview_columns);
    s.channels.push_back(std::move(cs));
  }
  return s;
}

}  // namespace bs
