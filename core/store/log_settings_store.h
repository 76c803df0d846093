// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the user sets on a stored power log after importing it (issue #32): the platform it belongs to, the supply
// voltage that turns a current-only log into power, or a voltage channel borrowed from another log of the same
// session, and the origin of its phases ("log": came with the file, "user": a range the user saved).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "store/workspace.h"

namespace bs {

// Throws WorkspaceError(Constraint) for an unknown trace or an empty (or blank) name.
void set_trace_platform(Workspace& ws, std::int64_t trace_id, const std::string& platform);
// nullopt clears it. Throws WorkspaceError(Constraint) for an unknown trace or a voltage that is not > 0 and finite.
void set_trace_supply_voltage(Workspace& ws, std::int64_t trace_id, std::optional<double> volts);

// Another stored log's voltage channel, interpolated onto this log's time axis (analysis/power/borrowed_voltage.h).
struct VoltageSource {
  std::int64_t trace_id = 0;
  std::string channel;
  bool operator==(const VoltageSource&) const = default;
};
// nullopt clears it. Throws WorkspaceError(Constraint) for an unknown trace, the trace itself as its source, or a
// source channel that is not a voltage channel of the source trace.
void set_trace_voltage_source(Workspace& ws, std::int64_t trace_id, const std::optional<VoltageSource>& source);
std::optional<VoltageSource> trace_voltage_source(const Workspace& ws, std::int64_t trace_id);
// For each loaded trace (samples in) that borrows a voltage: adds the source's channel on its time axis
// (analysis/power/borrowed_voltage.h). A source that is not among `traces`, or lost its channel, lends nothing.
void apply_voltage_sources(const Workspace& ws, std::vector<StoredPowerTrace>& traces);

// A phase the user saved (the Power tab's "Save as phase…"): stored like add_trace_phase, with origin "user".
void add_user_phase(Workspace& ws, std::int64_t trace_id, const TracePhase& phase);
// "log" or "user" for each stored phase of the trace, in the order power_traces() gives its phases (by start).
std::vector<std::string> phase_origins(const Workspace& ws, std::int64_t trace_id);

}  // namespace bs
