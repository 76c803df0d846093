// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/schema.h"

#include <string>
#include <vector>

#include "store/power_samples.h"
#include "store/schema_v10.h"
#include "store/schema_v8.h"

namespace bs::store {
namespace {

// Version 0 -> 1: imports, devices (with their stable colour), FLOPS runs and their samples, and the result sets
// of other benchmark tools. Samples are a WITHOUT ROWID table: the key is the data, which halves its size.
void migrate_0_to_1(const sqlite::Db& db) {
  db.exec(R"sql(
    CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
    CREATE TABLE imports(
      id INTEGER PRIMARY KEY,
      path TEXT NOT NULL,
      format TEXT NOT NULL,
      imported_at TEXT NOT NULL,
      content_hash TEXT NOT NULL UNIQUE,
      run_count INTEGER NOT NULL,
      result_set_count INTEGER NOT NULL);
    CREATE TABLE devices(
      id INTEGER PRIMARY KEY,
      platform TEXT NOT NULL,
      device TEXT NOT NULL,
      kind TEXT NOT NULL,
      color_index INTEGER NOT NULL,
      UNIQUE(platform, device));
    CREATE TABLE runs(
      id INTEGER PRIMARY KEY,
      import_id INTEGER NOT NULL REFERENCES imports(id) ON DELETE CASCADE,
      device_id INTEGER NOT NULL REFERENCES devices(id),
      backend TEXT NOT NULL,
      kernel TEXT NOT NULL,
      variant TEXT NOT NULL,
      iterations INTEGER NOT NULL CHECK(iterations > 0),
      dims INTEGER NOT NULL CHECK(dims > 0),
      reported_peak_flops REAL,
      theoretical_peak_flops REAL,
      provenance TEXT NOT NULL);
    CREATE INDEX runs_by_import ON runs(import_id);
    CREATE TABLE run_samples(
      run_id INTEGER NOT NULL REFERENCES runs(id) ON DELETE CASCADE,
      workers INTEGER NOT NULL,
      repetition INTEGER NOT NULL,
      seconds REAL NOT NULL CHECK(seconds > 0),
      PRIMARY KEY(run_id, workers, repetition)) WITHOUT ROWID;
    CREATE TABLE result_sets(
      id INTEGER PRIMARY KEY,
      import_id INTEGER NOT NULL REFERENCES imports(id) ON DELETE CASCADE,
      device_id INTEGER NOT NULL REFERENCES devices(id),
      backend TEXT NOT NULL,
      source_format TEXT NOT NULL,
      provenance TEXT NOT NULL);
    CREATE INDEX result_sets_by_import ON result_sets(import_id);
    CREATE TABLE measurements(
      id INTEGER PRIMARY KEY,
      result_set_id INTEGER NOT NULL REFERENCES result_sets(id) ON DELETE CASCADE,
      name TEXT NOT NULL,
      metric TEXT NOT NULL,
      unit TEXT NOT NULL,
      vals TEXT NOT NULL,
      aggregates TEXT NOT NULL);
    CREATE INDEX measurements_by_set ON measurements(result_set_id);
  )sql");
}

// Version 1 -> 2: current/power logs. Channel values are a BLOB of native doubles: a 10-million-sample trace
// is one row, read and written without parsing.
void migrate_1_to_2(const sqlite::Db& db) {
  db.exec(R"sql(
    CREATE TABLE power_traces(
      id INTEGER PRIMARY KEY,
      import_id INTEGER NOT NULL REFERENCES imports(id) ON DELETE CASCADE,
      platform TEXT NOT NULL,
      label TEXT NOT NULL,
      start_time TEXT NOT NULL,
      supply_voltage_v REAL,
      time_s BLOB NOT NULL,
      provenance TEXT NOT NULL);
    CREATE INDEX power_traces_by_import ON power_traces(import_id);
    CREATE TABLE power_channels(
      id INTEGER PRIMARY KEY,
      trace_id INTEGER NOT NULL REFERENCES power_traces(id) ON DELETE CASCADE,
      name TEXT NOT NULL,
      quantity TEXT NOT NULL CHECK(quantity IN ('current', 'voltage', 'power')),
      vals BLOB NOT NULL);
    CREATE INDEX power_channels_by_trace ON power_channels(trace_id);
  )sql");
}

// Version 2 -> 3: camera frames. A frame is kept by reference (path + content hash of the file, read again and
// checked on open; pixels NULL) or as a copy (pixels BLOB: row-major samples, 16-bit ones in the writer's byte
// order, which `byte_order` records). read_options is the importer's JSON to read a referenced file again.
void migrate_2_to_3(const sqlite::Db& db) {
  db.exec(R"sql(
    CREATE TABLE IF NOT EXISTS frames(
      id INTEGER PRIMARY KEY,
      import_id INTEGER NOT NULL REFERENCES imports(id) ON DELETE CASCADE,
      label TEXT NOT NULL,
      storage TEXT NOT NULL CHECK(storage IN ('reference', 'copy')),
      path TEXT NOT NULL,
      content_hash TEXT NOT NULL,
      source_format TEXT NOT NULL,
      read_options TEXT NOT NULL,
      width INTEGER NOT NULL CHECK(width > 0),
      height INTEGER NOT NULL CHECK(height > 0),
      channels INTEGER NOT NULL CHECK(channels IN (1, 3)),
      bit_depth INTEGER NOT NULL CHECK(bit_depth BETWEEN 1 AND 16),
      pattern TEXT NOT NULL,
      synthetic INTEGER NOT NULL CHECK(synthetic IN (0, 1)),
      lens TEXT NOT NULL,
      provenance TEXT NOT NULL,
      byte_order TEXT NOT NULL CHECK(byte_order IN ('little', 'big')),
      pixels BLOB,
      CHECK((storage = 'copy') = (pixels IS NOT NULL)));
    CREATE INDEX IF NOT EXISTS frames_by_import ON frames(import_id);
  )sql");
}

// Version 3 -> 4: vision pipeline runs (paper section 4.2) and their per-stage statistics, in seconds. Statistics
// a publication does not give (min, max, percentiles of a reconstructed run) are NULL, never invented.
void migrate_3_to_4(const sqlite::Db& db) {
  db.exec(R"sql(
    CREATE TABLE IF NOT EXISTS pipeline_runs(
      id INTEGER PRIMARY KEY,
      import_id INTEGER NOT NULL REFERENCES imports(id) ON DELETE CASCADE,
      platform TEXT NOT NULL,
      device TEXT NOT NULL,
      backend TEXT NOT NULL,
      demosaic TEXT NOT NULL,
      detector TEXT NOT NULL,
      frame_width INTEGER NOT NULL CHECK(frame_width >= 0),
      frame_height INTEGER NOT NULL CHECK(frame_height >= 0),
      throughput_fps REAL,
      provenance TEXT NOT NULL);
    CREATE INDEX IF NOT EXISTS pipeline_runs_by_import ON pipeline_runs(import_id);
    CREATE TABLE IF NOT EXISTS pipeline_stages(
      run_id INTEGER NOT NULL REFERENCES pipeline_runs(id) ON DELETE CASCADE,
      stage TEXT NOT NULL,
      n INTEGER NOT NULL CHECK(n > 0),
      mean_s REAL NOT NULL CHECK(mean_s >= 0),
      sd_s REAL NOT NULL CHECK(sd_s >= 0),
      min_s REAL, max_s REAL, p50_s REAL, p95_s REAL,
      PRIMARY KEY(run_id, stage)) WITHOUT ROWID;
  )sql");
}

// Version 4 -> 5: a power trace names its total channel (the board's input rail, jtop's "Power TOT"), and keeps its
// named phases (PTDaemon marks, detected level changes, a run's markers, selections the user saved).
void migrate_4_to_5(const sqlite::Db& db) {
  if (!has_column(db, "power_traces", "total_channel"))
    db.exec("ALTER TABLE power_traces ADD COLUMN total_channel TEXT NOT NULL DEFAULT ''");
  db.exec(R"sql(
    CREATE TABLE IF NOT EXISTS power_phases(
      id INTEGER PRIMARY KEY,
      trace_id INTEGER NOT NULL REFERENCES power_traces(id) ON DELETE CASCADE,
      name TEXT NOT NULL,
      start_s REAL NOT NULL,
      end_s REAL NOT NULL CHECK(end_s >= start_s));
    CREATE INDEX IF NOT EXISTS power_phases_by_trace ON power_phases(trace_id);
  )sql");
}

// Version 5 -> 6: samples in chunks and a summary cached with each trace (store/power_samples.h), so a workspace
// holding a 100-million-sample log opens in a moment and loads its samples lazily. Schema 5's one-BLOB traces are
// rewritten as chunks and summarised here, one trace at a time, and their BLOBs emptied; the columns stay (NOT
// NULL, empty) so an older reader fails on the schema version, not on a missing column.
void migrate_5_to_6(const sqlite::Db& db) {
  if (!has_column(db, "power_traces", "samples")) db.exec("ALTER TABLE power_traces ADD COLUMN samples INTEGER");
  if (!has_column(db, "power_traces", "duration_s")) db.exec("ALTER TABLE power_traces ADD COLUMN duration_s REAL");
  if (!has_column(db, "power_channels", "summary")) db.exec("ALTER TABLE power_channels ADD COLUMN summary TEXT");
  if (!has_column(db, "power_channels", "overview")) db.exec("ALTER TABLE power_channels ADD COLUMN overview BLOB");
  db.exec(R"sql(
    CREATE TABLE IF NOT EXISTS power_chunks(
      id INTEGER PRIMARY KEY,
      trace_id INTEGER NOT NULL REFERENCES power_traces(id) ON DELETE CASCADE,
      series INTEGER NOT NULL CHECK(series >= 0),
      first INTEGER NOT NULL CHECK(first >= 0),
      vals BLOB NOT NULL);
    CREATE UNIQUE INDEX IF NOT EXISTS power_chunks_by_series ON power_chunks(trace_id, series, first);
  )sql");
  // Traces not converted yet (samples NULL): all of them on a schema 5 file, none when this ran before.
  std::vector<std::int64_t> pending;
  {
    sqlite::Statement st(db, "SELECT id FROM power_traces WHERE samples IS NULL ORDER BY id");
    while (st.step()) pending.push_back(st.int64(0));
  }
  SampleProgress quiet;
  for (const std::int64_t id : pending) {
    PowerTrace t;
    {
      sqlite::Statement st(db, "SELECT time_s FROM power_traces WHERE id = ?");
      st.bind(1, id);
      if (st.step()) t.time_s = st.doubles(0);
    }
    std::vector<std::int64_t> channel_ids;
    {
      sqlite::Statement st(db, "SELECT id, name, quantity, vals FROM power_channels WHERE trace_id = ? ORDER BY id");
      st.bind(1, id);
      while (st.step()) {
        channel_ids.push_back(st.int64(0));
        const std::string q = st.text(2);
        t.channels.push_back({st.text(1),
                              q == "current"   ? PowerQuantity::Current
                              : q == "voltage" ? PowerQuantity::Voltage
                                               : PowerQuantity::Power,
                              st.doubles(3)});
      }
    }
    db.exec(("DELETE FROM power_chunks WHERE trace_id = " + std::to_string(id)).c_str());
    write_series(db, id, 0, t.time_s, quiet);
    for (std::size_t k = 0; k < t.channels.size(); ++k)
      write_series(db, id, channel_ids[k], t.channels[k].values, quiet);
    write_summary(db, id, channel_ids, summarize_trace(t));
    sqlite::Statement(db, "UPDATE power_traces SET time_s = x'' WHERE id = ?").bind(1, id).run();
    sqlite::Statement(db, "UPDATE power_channels SET vals = x'' WHERE trace_id = ?").bind(1, id).run();
  }
}

// Version 6 -> 7: dnn inference runs (`bench dnn`): one row per model x device x input, seconds per forward pass, FLOPs
// and the energy per inference when power was recorded. Self-contained and idempotent (CREATE ... IF NOT EXISTS) so
// that it can be renumbered next to other migrations of the same version.
void migrate_add_dnn_runs(const sqlite::Db& db) {
  db.exec(R"sql(
    CREATE TABLE IF NOT EXISTS dnn_runs(
      id INTEGER PRIMARY KEY,
      import_id INTEGER NOT NULL REFERENCES imports(id) ON DELETE CASCADE,
      platform TEXT NOT NULL,
      device TEXT NOT NULL,
      backend TEXT NOT NULL,
      model TEXT NOT NULL,
      model_hash TEXT NOT NULL,
      family TEXT NOT NULL,
      architecture_only INTEGER NOT NULL CHECK(architecture_only IN (0, 1)),
      input_width INTEGER NOT NULL CHECK(input_width > 0),
      input_height INTEGER NOT NULL CHECK(input_height > 0),
      batch INTEGER NOT NULL CHECK(batch > 0),
      flops INTEGER NOT NULL CHECK(flops >= 0),
      opencv_flops INTEGER NOT NULL CHECK(opencv_flops >= 0),
      n INTEGER NOT NULL CHECK(n > 0),
      mean_s REAL NOT NULL CHECK(mean_s > 0),
      sd_s REAL NOT NULL CHECK(sd_s >= 0),
      min_s REAL, max_s REAL, p50_s REAL, p95_s REAL,
      device_peak_flops REAL,
      energy_per_inference_j REAL,
      mean_power_w REAL,
      provenance TEXT NOT NULL);
    CREATE INDEX IF NOT EXISTS dnn_runs_by_import ON dnn_runs(import_id);
  )sql");
}

// Version 8 -> 9 (issue #45): headroom measurements. One row per measurement; its phases, threads and histograms
// are one JSON document (read whole, never queried inside), the platform a column so that renaming moves it.
void migrate_add_headroom(const sqlite::Db& db) {
  db.exec(R"sql(
    CREATE TABLE IF NOT EXISTS headroom_measurements(
      id INTEGER PRIMARY KEY,
      import_id INTEGER NOT NULL REFERENCES imports(id) ON DELETE CASCADE,
      platform TEXT NOT NULL,
      kind TEXT NOT NULL CHECK(kind IN ('wakeup', 'loop', 'message')),
      tool TEXT NOT NULL,
      data TEXT NOT NULL);
    CREATE INDEX IF NOT EXISTS headroom_by_import ON headroom_measurements(import_id);
  )sql");
}

// Version 10 -> 11 (issue #53): sustained runs. One row per run; its intervals, clocks and temperatures are one JSON
// document (read whole, never queried inside), the platform a column so that renaming moves it.
void migrate_add_sustain_runs(const sqlite::Db& db) {
  db.exec(R"sql(
    CREATE TABLE IF NOT EXISTS sustain_runs(
      id INTEGER PRIMARY KEY,
      import_id INTEGER NOT NULL REFERENCES imports(id) ON DELETE CASCADE,
      platform TEXT NOT NULL,
      label TEXT NOT NULL,
      load TEXT NOT NULL,
      data TEXT NOT NULL);
    CREATE INDEX IF NOT EXISTS sustain_runs_by_import ON sustain_runs(import_id);
  )sql");
}

using Migration = void (*)(const sqlite::Db&);
constexpr Migration kMigrations[] = {migrate_0_to_1,          migrate_1_to_2,
                                     migrate_2_to_3,          migrate_3_to_4,
                                     migrate_4_to_5,          migrate_5_to_6,
                                     migrate_add_dnn_runs,    migrate_lenses_and_log_settings,
                                     migrate_add_headroom,    migrate_decision_and_chosen_logs,
                                     migrate_add_sustain_runs};
static_assert(std::size(kMigrations) == static_cast<std::size_t>(Workspace::kSchemaVersion),
              "one migration per schema version");

}  // namespace

bool has_column(const sqlite::Db& db, const char* table, const char* column) {
  sqlite::Statement cols(db, (std::string("SELECT 1 FROM pragma_table_info('") + table + "') WHERE name = ?").c_str());
  cols.bind(1, std::string_view(column));
  return cols.step();
}

void migrate(const sqlite::Db& db, int from_version) {
  for (int v = from_version; v < Workspace::kSchemaVersion; ++v) {
    kMigrations[v](db);
    db.exec(("PRAGMA user_version = " + std::to_string(v + 1)).c_str());
  }
}

}  // namespace bs::store
