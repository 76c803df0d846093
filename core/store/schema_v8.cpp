// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/schema_v8.h"

#include "store/schema.h"

#include <nlohmann/json.hpp>

namespace bs::store {

void migrate_lenses_and_log_settings(const sqlite::Db& db) {
  // A lens belongs to one frame (frame_id, camera '') or to every frame of a camera (frame_id NULL, camera named);
  // `lens` is lens_to_json() (lens + view, its "calibration" object included) and `obtained` the one line a view
  // shows ("checkerboard, 8 images, RMS 0.06 px").
  db.exec(R"sql(
    CREATE TABLE IF NOT EXISTS lenses(
      id INTEGER PRIMARY KEY,
      frame_id INTEGER REFERENCES frames(id) ON DELETE CASCADE,
      camera TEXT NOT NULL,
      lens TEXT NOT NULL,
      obtained TEXT NOT NULL,
      saved_at TEXT NOT NULL,
      CHECK((frame_id IS NULL) <> (camera = '')));
    CREATE UNIQUE INDEX IF NOT EXISTS lenses_by_frame ON lenses(frame_id) WHERE frame_id IS NOT NULL;
    CREATE UNIQUE INDEX IF NOT EXISTS lenses_by_camera ON lenses(camera) WHERE frame_id IS NULL;
  )sql");
  if (!has_column(db, "power_traces", "voltage_trace_id"))
    // No REFERENCES: the reader joins on it, so a source log removed later simply stops lending its voltage.
    db.exec("ALTER TABLE power_traces ADD COLUMN voltage_trace_id INTEGER");
  if (!has_column(db, "power_traces", "voltage_channel"))
    db.exec("ALTER TABLE power_traces ADD COLUMN voltage_channel TEXT NOT NULL DEFAULT ''");
  if (!has_column(db, "power_phases", "origin"))
    db.exec("ALTER TABLE power_phases ADD COLUMN origin TEXT NOT NULL DEFAULT 'log' CHECK(origin IN ('log', 'user'))");
}

}  // namespace bs::store
