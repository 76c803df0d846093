// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/power/trace_align.h"

#include <algorithm>
#include <set>

namespace bs {

std::optional<double> phase_start(const std::vector<TracePhase>& phases, std::string_view name) {
  for (const TracePhase& p : phases)
    if (p.name == name) return p.start_s;
  return std::nullopt;
}

std::vector<std::optional<double>> align_at_phase(const std::vector<std::vector<TracePhase>>& phases_per_trace,
                                                  std::string_view name, double at_s) {
  std::vector<std::optional<double>> out;
  for (const auto& phases : phases_per_trace) {
    const std::optional<double> start = phase_start(phases, name);
    out.push_back(start ? std::optional<double>(at_s - *start) : std::nullopt);
  }
  return out;
}

std::vector<std::string> shared_phase_names(const std::vector<std::vector<TracePhase>>& phases_per_trace,
                                            std::size_t min_traces) {
  std::vector<std::string> order;
  std::vector<std::size_t> count;
  for (const auto& phases : phases_per_trace) {
    std::set<std::string> seen;  // a name counts once per trace
    for (const TracePhase& p : phases) {
      if (!seen.insert(p.name).second) continue;
      const auto it = std::find(order.begin(), order.end(), p.name);
      if (it == order.end()) {
        order.push_back(p.name);
        count.push_back(1);
      } else {
        ++count[static_cast<std::size_t>(it - order.begin())];
      }
    }
  }
  std::vector<std::string> out;
  for (std::size_t i = 0; i < order.size(); ++i)
    if (count[i] >= min_traces) out.push_back(order[i]);
  return out;
}

}  // namespace bs
