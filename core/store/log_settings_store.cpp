// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/log_settings_store.h"

#include <cmath>

#include "analysis/power/borrowed_voltage.h"
#include "store/sqlite_db.h"

namespace bs {

using sqlite::Statement;

namespace {

[[noreturn]] void refuse(const Workspace& ws, const std::string& why) {
  throw WorkspaceError(WorkspaceError::Kind::Constraint, ws.path() + ": " + why);
}

void require_trace(const Workspace& ws, std::int64_t trace_id) {
  Statement st(ws.database(), "SELECT 1 FROM power_traces WHERE id = ?");
  st.bind(1, trace_id);
  if (!st.step()) refuse(ws, "no power log #" + std::to_string(trace_id));
}

bool blank(const std::string& s) { return s.find_first_not_of(" \t\r\n") == std::string::npos; }

}  // namespace

void set_trace_platform(Workspace& ws, std::int64_t trace_id, const std::string& platform) {
  require_trace(ws, trace_id);
  if (blank(platform)) refuse(ws, "a power log's platform cannot be empty");
  Statement(ws.database(), "UPDATE power_traces SET platform = ? WHERE id = ?")
      .bind(1, std::string_view(platform))
      .bind(2, trace_id)
      .run();
}

void set_trace_supply_voltage(Workspace& ws, std::int64_t trace_id, std::optional<double> volts) {
  require_trace(ws, trace_id);
  if (volts && !(std::isfinite(*volts) && *volts > 0))
    refuse(ws, "supply voltage must be > 0 V (got " + std::to_string(*volts) + ")");
  Statement(ws.database(), "UPDATE power_traces SET supply_voltage_v = ? WHERE id = ?")
      .bind(1, volts)
      .bind(2, trace_id)
      .run();
}

void set_trace_voltage_source(Workspace& ws, std::int64_t trace_id, const std::optional<VoltageSource>& source) {
  require_trace(ws, trace_id);
  Statement st(ws.database(), "UPDATE power_traces SET voltage_trace_id = ?, voltage_channel = ? WHERE id = ?");
  if (!source) {
    st.bind_null(1).bind(2, std::string_view("")).bind(3, trace_id).run();
    return;
  }
  if (source->trace_id == trace_id) refuse(ws, "a power log cannot borrow its own voltage");
  require_trace(ws, source->trace_id);
  Statement ch(ws.database(), "SELECT 1 FROM power_channels WHERE trace_id = ? AND name = ? AND quantity = 'voltage'");
  ch.bind(1, source->trace_id).bind(2, std::string_view(source->channel));
  if (!ch.step())
    refuse(ws, "power log #" + std::to_string(source->trace_id) + " has no voltage channel '" + source->channel + "'");
  st.bind(1, source->trace_id).bind(2, std::string_view(source->channel)).bind(3, trace_id).run();
}

std::optional<VoltageSource> trace_voltage_source(const Workspace& ws, std::int64_t trace_id) {
  // Joined with the source: a log removed since lends nothing (and an undone removal brings it back under a new id).
  Statement st(ws.database(),
               "SELECT p.voltage_trace_id, p.voltage_channel FROM power_traces p JOIN power_traces s ON "
               "s.id = p.voltage_trace_id WHERE p.id = ?");
  st.bind(1, trace_id);
  if (!st.step()) return std::nullopt;
  return VoltageSource{st.int64(0), st.text(1)};
}

void apply_voltage_sources(const Workspace& ws, std::vector<StoredPowerTrace>& traces) {
  for (StoredPowerTrace& t : traces) {
    const auto source = trace_voltage_source(ws, t.id);
    if (!source) continue;
    for (const StoredPowerTrace& s : traces)
      if (s.id == source->trace_id && s.samples_loaded) borrow_voltage(t.trace, s.trace, source->channel);
  }
}

void add_user_phase(Workspace& ws, std::int64_t trace_id, const TracePhase& phase) {
  sqlite::Transaction tx(ws.database());
  ws.add_trace_phase(trace_id, phase);
  Statement(ws.database(), "UPDATE power_phases SET origin = 'user' WHERE id = last_insert_rowid()").run();
  tx.commit();
}

std::vector<std::string> phase_origins(const Workspace& ws, std::int64_t trace_id) {
  std::vector<std::string> out;
  // The same order as the workspace reads phases (by start, then id).
  Statement st(ws.database(), "SELECT origin FROM power_phases WHERE trace_id = ? ORDER BY start_s, id");
  st.bind(1, trace_id);
  while (st.step()) out.push_back(st.text(0));
  return out;
}

}  // namespace bs
