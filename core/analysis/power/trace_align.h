// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Putting traces from different files and platforms on one time axis: each trace is drawn at its own time plus an
// offset (seconds). Offsets are typed or dragged in the Power tab, or computed here so that the same phase (or
// marker) starts at the same moment on every trace.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/power_trace.h"

namespace bs {

// Start (seconds from the trace's first sample) of the first phase named `name`; nullopt when there is none.
std::optional<double> phase_start(const std::vector<TracePhase>& phases, std::string_view name);

// Per trace, the offset that puts the start of its phase `name` at `at_s` on the shared axis: at_s - start.
// nullopt for a trace without that phase (its offset is left as it was).
std::vector<std::optional<double>> align_at_phase(const std::vector<std::vector<TracePhase>>& phases_per_trace,
                                                  std::string_view name, double at_s = 0);

// Phase names present in at least `min_traces` of the traces, in first-seen order: what alignment can use.
std::vector<std::string> shared_phase_names(const std::vector<std::vector<TracePhase>>& phases_per_trace,
                                            std::size_t min_traces = 2);

}  // namespace bs
