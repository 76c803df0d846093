// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/schema_v10.h"

namespace bs::store {

void migrate_decision_and_chosen_logs(const sqlite::Db& db) {
  // NULL constraint: not set. `battery` names a preset (built-in or the workspace's); '' follows the Battery tab.
  // `loop` is the control-loop requirement as typed (headroom/loop_requirement.h syntax); '': none.
  db.exec(R"sql(
    CREATE TABLE IF NOT EXISTS decision(
      id INTEGER PRIMARY KEY CHECK(id = 1),
      power_budget_w REAL CHECK(power_budget_w IS NULL OR power_budget_w > 0),
      min_fps REAL CHECK(min_fps IS NULL OR min_fps > 0),
      min_runtime_min REAL CHECK(min_runtime_min IS NULL OR min_runtime_min > 0),
      battery TEXT NOT NULL DEFAULT '',
      extra_load_w REAL NOT NULL DEFAULT 0 CHECK(extra_load_w >= 0),
      mission TEXT NOT NULL DEFAULT '',
      candidates TEXT NOT NULL DEFAULT '',
      loop TEXT NOT NULL DEFAULT '',
      saved_at TEXT NOT NULL);
    CREATE TABLE IF NOT EXISTS chosen_logs(
      platform TEXT PRIMARY KEY CHECK(length(trim(platform)) > 0),
      trace_id INTEGER NOT NULL REFERENCES power_traces(id) ON DELETE CASCADE);
    CREATE INDEX IF NOT EXISTS chosen_logs_by_trace ON chosen_logs(trace_id);
  )sql");
}

}  // namespace bs::store
