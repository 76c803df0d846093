// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/decision_store.h"

#include <cmath>
#include <stdexcept>

#include "headroom/loop_requirement.h"
#include "store/sqlite_db.h"
#include "sustain/sustain_requirement.h"
#include "util/host_clock.h"
#include "util/text.h"

namespace bs {

using sqlite::Statement;

namespace {

[[noreturn]] void refuse(const Workspace& ws, const std::string& why) {
  throw WorkspaceError(WorkspaceError::Kind::Constraint, ws.path() + ": " + why);
}

bool positive(const std::optional<double>& v) { return !v || (std::isfinite(*v) && *v > 0); }

std::string number(double v) { return format_number("%.4g", v); }

// A stored value the CHECKs would refuse (a file edited by hand) is refused when read, naming its column and value:
// never taken as another number, never dropped as if it had not been set (the recommendation would change silently).
[[noreturn]] void damaged(const Workspace& ws, const std::string& column, const std::string& why) {
  throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                       ws.path() + ": the Platforms tab's stored decision: decision." + column + ": " + why);
}

// The sustained requirement's workspace setting (store/decision_store.h: StoredDecision::sustained).
constexpr const char* kSustainedKey = "decision/sustained";

// NULL: not set. `zero_ok`: 0 is allowed (the parallel load), else the value must be > 0.
std::optional<double> read_number(const Workspace& ws, const Statement& st, int column, const char* name,
                                  bool zero_ok) {
  const int type = st.type(column);
  if (type == SQLITE_NULL) return std::nullopt;
  if (type != SQLITE_INTEGER && type != SQLITE_FLOAT) damaged(ws, name, "'" + st.text(column) + "' is not a number");
  const double v = st.real(column);
  if (!std::isfinite(v) || v < 0 || (v == 0 && !zero_ok))
    damaged(ws, name, number(v) + (zero_ok ? " is not a number >= 0" : " is not a number > 0"));
  return v;
}

}  // namespace

Constraints StoredDecision::constraints() const {
  Constraints c;
  c.power_budget_w = power_budget_w;
  c.min_fps = min_fps;
  if (min_runtime_min) c.min_runtime_h = *min_runtime_min / 60.0;
  return c;
}

std::string describe_constraints(const Constraints& c) {
  std::string out;
  const auto add = [&](const std::string& s) { out += (out.empty() ? "" : ", ") + s; };
  if (c.power_budget_w) add("a power budget of " + number(*c.power_budget_w) + " W");
  if (c.min_fps) add("at least " + number(*c.min_fps) + " fps");
  if (c.min_runtime_h) add("at least " + number(*c.min_runtime_h * 60) + " min on the battery");
  return out;
}

std::string describe_constraints(const StoredDecision& d) {
  std::string out = describe_constraints(d.constraints());
  // In the words of the report's heading (figures/report_writer.cpp); a requirement that no longer parses (a
  // hand-edited file) is quoted as stored, never dropped from the account.
  const auto add = [&out](const char* what, const std::string& text, const auto& words_of) {
    if (text.empty()) return;
    std::string words;
    try {
      words = std::string(what) + " " + words_of(text);
    } catch (const std::invalid_argument&) {
      words = std::string(what) + " \"" + text + "\" (unreadable)";
    }
    out += (out.empty() ? "" : ", ") + words;
  };
  add("control loop", d.loop,
      [](const std::string& t) { return headroom::describe(headroom::parse_loop_requirement(t)); });
  add("sustained", d.sustained,
      [](const std::string& t) { return sustain::describe(sustain::parse_sustain_requirement(t)); });
  return out;
}

std::optional<StoredDecision> stored_decision(const Workspace& ws) {
  Statement st(ws.database(),
               "SELECT power_budget_w, min_fps, min_runtime_min, battery, extra_load_w, mission, candidates, loop "
               "FROM decision WHERE id = 1");
  if (!st.step()) return std::nullopt;
  StoredDecision d;
  d.power_budget_w = read_number(ws, st, 0, "power_budget_w", false);
  d.min_fps = read_number(ws, st, 1, "min_fps", false);
  d.min_runtime_min = read_number(ws, st, 2, "min_runtime_min", false);
  d.battery = st.text(3);
  d.extra_load_w = read_number(ws, st, 4, "extra_load_w", true).value_or(0.0);
  d.mission = st.text(5);
  d.candidates = st.text(6);
  d.loop = st.text(7);
  if (!d.loop.empty()) {
    try {
      headroom::parse_loop_requirement(d.loop);
    } catch (const std::invalid_argument& e) {
      damaged(ws, "loop", "'" + d.loop + "': " + e.what());
    }
  }
  for (const auto& [key, value] : ws.settings(kSustainedKey))
    if (key == kSustainedKey) d.sustained = value;
  if (!d.sustained.empty()) {
    try {
      sustain::parse_sustain_requirement(d.sustained);
    } catch (const std::invalid_argument& e) {
      throw WorkspaceError(WorkspaceError::Kind::Corrupt, ws.path() +
                                                              ": the Platforms tab's stored decision: the setting " +
                                                              kSustainedKey + ": '" + d.sustained + "': " + e.what());
    }
  }
  return d;
}

void set_stored_decision(Workspace& ws, const std::optional<StoredDecision>& decision) {
  // The row and the sustained requirement's setting change together or not at all.
  sqlite::Transaction tx(ws.database());
  if (!decision) {
    Statement(ws.database(), "DELETE FROM decision").run();
    ws.remove_setting(kSustainedKey);
    tx.commit();
    return;
  }
  const StoredDecision& d = *decision;
  if (!positive(d.power_budget_w) || !positive(d.min_fps) || !positive(d.min_runtime_min))
    refuse(ws, "a constraint must be a number > 0");
  if (!(std::isfinite(d.extra_load_w) && d.extra_load_w >= 0)) refuse(ws, "the parallel load must be >= 0 W");
  if (!d.loop.empty()) {
    try {
      headroom::parse_loop_requirement(d.loop);
    } catch (const std::invalid_argument& e) {
      refuse(ws, std::string("the control-loop requirement: ") + e.what());
    }
  }
  if (!d.sustained.empty()) {
    try {
      sustain::parse_sustain_requirement(d.sustained);
    } catch (const std::invalid_argument& e) {
      refuse(ws, std::string("the sustained requirement: ") + e.what());
    }
  }
  Statement(ws.database(),
            "INSERT OR REPLACE INTO decision(id, power_budget_w, min_fps, min_runtime_min, battery, extra_load_w, "
            "mission, candidates, loop, saved_at) VALUES (1, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .bind(1, d.power_budget_w)
      .bind(2, d.min_fps)
      .bind(3, d.min_runtime_min)
      .bind(4, std::string_view(d.battery))
      .bind(5, d.extra_load_w)
      .bind(6, std::string_view(d.mission))
      .bind(7, std::string_view(d.candidates))
      .bind(8, std::string_view(d.loop))
      .bind(9, std::string_view(utc_timestamp()))
      .run();
  if (d.sustained.empty())
    ws.remove_setting(kSustainedKey);
  else
    ws.set_setting(kSustainedKey, d.sustained);
  tx.commit();
}

std::map<std::string, std::int64_t> chosen_logs(const Workspace& ws) {
  // Joined with the logs: a choice whose log has gone (or moved to another platform) chooses nothing.
  Statement st(ws.database(),
               "SELECT c.platform, c.trace_id FROM chosen_logs c JOIN power_traces t ON t.id = c.trace_id "
               "AND t.platform = c.platform");
  std::map<std::string, std::int64_t> out;
  while (st.step()) out[st.text(0)] = st.int64(1);
  return out;
}

void set_chosen_log(Workspace& ws, const std::string& platform, std::optional<std::int64_t> trace_id) {
  if (platform.find_first_not_of(" \t\r\n") == std::string::npos) refuse(ws, "a chosen log needs its platform");
  if (!trace_id) {
    Statement(ws.database(), "DELETE FROM chosen_logs WHERE platform = ?").bind(1, std::string_view(platform)).run();
    return;
  }
  Statement probe(ws.database(), "SELECT platform FROM power_traces WHERE id = ?");
  probe.bind(1, *trace_id);
  if (!probe.step()) refuse(ws, "no power log #" + std::to_string(*trace_id));
  if (probe.text(0) != platform)
    refuse(ws, "power log #" + std::to_string(*trace_id) + " belongs to " + probe.text(0) + ", not " + platform);
  Statement(ws.database(), "INSERT OR REPLACE INTO chosen_logs(platform, trace_id) VALUES (?, ?)")
      .bind(1, std::string_view(platform))
      .bind(2, *trace_id)
      .run();
}

std::vector<std::size_t> chosen_logs_first(std::span<const std::string> platforms, std::span<const std::int64_t> ids,
                                           const std::map<std::string, std::int64_t>& chosen) {
  std::vector<std::size_t> order;
  std::vector<bool> placed(platforms.size(), false);
  for (std::size_t i = 0; i < platforms.size(); ++i) {
    if (placed[i]) continue;
    // The first log of a platform stands where the platform's chosen log goes: before its siblings.
    const auto it = chosen.find(platforms[i]);
    if (it != chosen.end())
      for (std::size_t k = i; k < platforms.size() && k < ids.size(); ++k)
        if (!placed[k] && platforms[k] == platforms[i] && ids[k] == it->second) {
          order.push_back(k);
          placed[k] = true;
          break;
        }
    if (!placed[i]) {
      order.push_back(i);
      placed[i] = true;
    }
  }
  return order;
}

void order_chosen_logs_first(const Workspace& ws, std::vector<StoredPowerTrace>& traces) {
  const auto chosen = chosen_logs(ws);
  if (chosen.empty()) return;
  std::vector<std::string> platforms;
  std::vector<std::int64_t> ids;
  for (const StoredPowerTrace& t : traces) {
    platforms.push_back(t.trace.platform);
    ids.push_back(t.id);
  }
  std::vector<StoredPowerTrace> ordered;
  ordered.reserve(traces.size());
  for (std::size_t i : chosen_logs_first(platforms, ids, chosen)) ordered.push_back(std::move(traces[i]));
  traces = std::move(ordered);
}

}  // namespace bs
