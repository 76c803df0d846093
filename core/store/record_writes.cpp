// SPDX-License-Identifier: GPL-3.0-or-later
// Each record kind's rows (store/record_writes.h), every row through its table's description (store/tables.h).
#include "store/record_writes.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "store/power_samples.h"
#include "store/sqlite_db.h"
#include "store/tables.h"

namespace bs::store {

using sqlite::Db;
using sqlite::Statement;

// A device's id by (platform, device), inserted with its colour on first sight.
struct DeviceIds {
  explicit DeviceIds(const Db& d) : db(d) {}
  const Db& db;
  Statement find{db, "SELECT id, kind FROM devices WHERE platform = ? AND device = ?"};
  // A new device takes the smallest colour index no device has (a removed device's colour is reused, and two
  // devices never share one while there are free ones; before, COUNT(*) could repeat an index after a removal).
  Statement insert{db,
                   "INSERT INTO devices(platform, device, kind, color_index) VALUES (?, ?, ?, "
                   "(SELECT MIN(c.i) FROM (SELECT 0 AS i UNION SELECT color_index + 1 FROM devices) AS c "
                   " WHERE c.i NOT IN (SELECT color_index FROM devices)))"};
  Statement update_kind{db, "UPDATE devices SET kind = ? WHERE id = ?"};

  std::int64_t get(const std::string& platform, const std::string& device, DeviceKind kind) {
    find.bind(1, std::string_view(platform)).bind(2, std::string_view(device));
    if (find.step()) {
      const std::int64_t id = find.int64(0);
      const bool unknown_kind = find.text(1) == "other";
      find.reset();
      if (unknown_kind && kind != DeviceKind::Other) update_kind.bind(1, to_string(kind)).bind(2, id).run();
      return id;
    }
    find.reset();
    insert.bind(1, std::string_view(platform)).bind(2, std::string_view(device)).bind(3, to_string(kind)).run();
    return sqlite3_last_insert_rowid(db.get());
  }
};

namespace {
constexpr int kCancelCheckRows = 1000;
}  // namespace

ImportWrite::ImportWrite(const Db& db_, std::int64_t import_id_, const ImportBatch& batch_,
                         const std::string& content_hash_, const CancelToken* cancel_)
    : db(db_),
      import_id(import_id_),
      batch(batch_),
      content_hash(content_hash_),
      cancel(cancel_),
      devices(std::make_unique<DeviceIds>(db_)) {}

ImportWrite::~ImportWrite() = default;

void ImportWrite::poll() {
  if (cancel && ++rows % kCancelCheckRows == 0) cancel->throw_if_cancelled();
}

void ImportWrite::check() {
  if (cancel) cancel->throw_if_cancelled();
}

void write_runs(ImportWrite& w, const std::vector<FlopsRun>& runs) {
  Inserter run_st(w.db, runs_table());
  Inserter sample_st(w.db, run_samples_table());
  for (const FlopsRun& run : runs) {
    // A sweep derived from another tool's results has no timings to store; its ResultSet is stored instead.
    for (const WorkerSample& s : run.samples)
      if (s.stated_flops)
        throw std::invalid_argument("a sweep derived from " + run.kernel +
                                    " results is not stored; store its result set");
    const std::int64_t run_id =
        run_st.insert({w.import_id, w.devices->get(run.platform, run.device, run.device_kind)}, run);
    for (const WorkerSample& s : run.samples)
      for (std::size_t k = 0; k < s.seconds.size(); ++k) {
        sample_st.insert({run_id}, {s.workers, static_cast<std::int64_t>(k), s.seconds[k]});
        w.poll();
      }
  }
}

void write_result_sets(ImportWrite& w, const std::vector<ResultSet>& sets) {
  Inserter set_st(w.db, result_sets_table());
  Inserter m_st(w.db, measurements_table());
  for (const ResultSet& set : sets) {
    const std::int64_t set_id =
        set_st.insert({w.import_id, w.devices->get(set.platform, set.device, set.device_kind)}, set);
    for (const Measurement& m : set.measurements) {
      m_st.insert({set_id}, m);
      w.poll();
    }
  }
}

void write_power_logs(ImportWrite& w, const std::vector<PowerTrace>& traces) {
  Inserter trace_st(w.db, power_traces_table());
  Inserter channel_st(w.db, power_channels_table());
  Inserter phase_st(w.db, power_phases_table());
  // Samples go in chunks (store/power_samples.h): cancel is polled and progress reported after each 2 MiB one.
  SampleProgress progress{w.cancel, "storing samples", 0, 0};
  for (const PowerTrace& t : traces) {
    progress.total += t.time_s.size();
    for (const PowerChannel& c : t.channels) progress.total += c.values.size();
  }
  for (const PowerTrace& t : traces) {
    w.check();
    if (w.cancel)
      w.cancel->report(static_cast<double>(progress.done) / std::max<double>(1, progress.total), "summarising");
    // The summary is stored with the trace and its channels (schema 6), so it is computed first.
    StoredPowerTrace row;
    row.trace = trace_metadata(t);
    row.summary = summarize_trace(t);
    const std::int64_t trace_id = trace_st.insert({w.import_id}, row);
    for (const TracePhase& p : t.phases) phase_st.insert({trace_id}, p);
    write_series(w.db, trace_id, 0, t.time_s, progress);
    for (std::size_t k = 0; k < t.channels.size(); ++k) {
      w.check();
      const std::int64_t channel_id = channel_st.insert({trace_id}, row.summary.channels[k]);
      write_series(w.db, trace_id, channel_id, t.channels[k].values, progress);
    }
  }
}

void write_frames(ImportWrite& w, const std::vector<Frame>& frames) {
  Inserter frame_st(w.db, frames_table());
  std::error_code ec;
  const std::string& source = w.batch.source_path;
  const std::string abs_path =
      source.empty() ? std::string() : std::filesystem::absolute(source, ec).lexically_normal().string();
  for (const Frame& f : frames) {
    w.check();
    const bool copy = f.storage == FrameStorage::Copy;
    if (copy && f.pixels.size() != f.expected_bytes())
      throw WorkspaceError(WorkspaceError::Kind::Constraint,
                           f.label + ": frame has " + std::to_string(f.pixels.size()) + " bytes of pixels, its " +
                               std::to_string(f.width) + "x" + std::to_string(f.height) + " geometry needs " +
                               std::to_string(f.expected_bytes()));
    StoredFrame row;
    row.path = abs_path.empty() ? f.provenance.source_file : abs_path;
    row.content_hash = w.content_hash;
    row.frame = f;
    frame_st.insert({w.import_id}, row);
  }
}

void write_pipeline_runs(ImportWrite& w, const std::vector<PipelineRun>& runs) {
  Inserter pipe_st(w.db, pipeline_runs_table());
  Inserter stage_st(w.db, pipeline_stages_table());
  for (const PipelineRun& p : runs) {
    w.check();
    const std::int64_t run_id = pipe_st.insert({w.import_id}, p);
    for (const StageStats& s : p.stages) stage_st.insert({run_id}, s);
  }
}

void write_inference_runs(ImportWrite& w, const std::vector<DnnRun>& runs) {
  Inserter dnn_st(w.db, dnn_runs_table());
  for (const DnnRun& d : runs) {
    w.check();
    dnn_st.insert({w.import_id}, d);
  }
}

void write_headroom(ImportWrite& w, const std::vector<headroom::HeadroomMeasurement>& measurements) {
  Inserter headroom_st(w.db, headroom_table());
  for (const headroom::HeadroomMeasurement& m : measurements) {
    w.check();
    // A result whose bookkeeping fails would be refused when read back: refuse it now, before anything is stored.
    if (const std::string e = m.bookkeeping_error(); !e.empty())
      throw WorkspaceError(WorkspaceError::Kind::Constraint, "headroom measurement (" + m.platform + "): " + e);
    headroom_st.insert({w.import_id}, m);
  }
}

void write_sustained_runs(ImportWrite& w, const std::vector<SustainRun>& runs) {
  Inserter sustain_st(w.db, sustain_table());
  for (const SustainRun& r : runs) {
    w.check();
    sustain_st.insert({w.import_id}, r);
  }
}

}  // namespace bs::store
