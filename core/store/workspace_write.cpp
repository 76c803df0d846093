// SPDX-License-Identifier: GPL-3.0-or-later
// Storing imports: one transaction per call, every row written through its table's description (store/tables.h).
#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "store/power_samples.h"
#include "store/tables.h"
#include "store/workspace_impl.h"
#include "util/host_clock.h"

namespace bs {

using sqlite::Db;
using sqlite::Statement;
using sqlite::Transaction;

namespace {

struct DeviceIds {
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

void refuse_duplicate(const Db& db, const std::string& content_hash) {
  Statement dup(db, "SELECT path, imported_at FROM imports WHERE content_hash = ?");
  dup.bind(1, std::string_view(content_hash));
  if (dup.step())
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         "already imported from " + dup.text(0) + " on " + dup.text(1));
}

constexpr int kCancelCheckRows = 1000;

// Inserts one import inside the caller's transaction and returns its id. Every row goes through its table's
// description (store/tables.h), the same one the reader checks it with.
std::int64_t insert_import(const Db& db, const ImportBatch& batch, const std::string& content_hash,
                           const CancelToken* cancel) {
  refuse_duplicate(db, content_hash);
  ImportRecord record;
  record.path = batch.source_path;
  record.format = batch.format;
  record.imported_at = bs::utc_timestamp();
  record.content_hash = content_hash;
  record.run_count = static_cast<std::int64_t>(batch.runs.size());
  record.result_set_count = static_cast<std::int64_t>(batch.result_sets.size());
  const std::int64_t import_id = store::Inserter(db, store::imports_table()).insert({}, record);

  DeviceIds devices{db};
  store::Inserter run_st(db, store::runs_table());
  store::Inserter sample_st(db, store::run_samples_table());
  int rows = 0;
  auto poll = [&] {
    if (cancel && ++rows % kCancelCheckRows == 0) cancel->throw_if_cancelled();
  };
  for (const FlopsRun& run : batch.runs) {
    // A sweep derived from another tool's results has no timings to store; its ResultSet is stored instead.
    for (const WorkerSample& s : run.samples)
      if (s.stated_flops)
        throw std::invalid_argument("a sweep derived from " + run.kernel +
                                    " results is not stored; store its result set");
    const std::int64_t run_id = run_st.insert({import_id, devices.get(run.platform, run.device, run.device_kind)}, run);
    for (const WorkerSample& s : run.samples)
      for (std::size_t k = 0; k < s.seconds.size(); ++k) {
        sample_st.insert({run_id}, {s.workers, static_cast<std::int64_t>(k), s.seconds[k]});
        poll();
      }
  }
  store::Inserter set_st(db, store::result_sets_table());
  store::Inserter m_st(db, store::measurements_table());
  for (const ResultSet& set : batch.result_sets) {
    const std::int64_t set_id = set_st.insert({import_id, devices.get(set.platform, set.device, set.device_kind)}, set);
    for (const Measurement& m : set.measurements) {
      m_st.insert({set_id}, m);
      poll();
    }
  }
  store::Inserter trace_st(db, store::power_traces_table());
  store::Inserter channel_st(db, store::power_channels_table());
  store::Inserter phase_st(db, store::power_phases_table());
  // Samples go in chunks (store/power_samples.h): cancel is polled and progress reported after each 2 MiB one.
  store::SampleProgress progress{cancel, "storing samples", 0, 0};
  for (const PowerTrace& t : batch.power_traces) {
    progress.total += t.time_s.size();
    for (const PowerChannel& c : t.channels) progress.total += c.values.size();
  }
  const auto check = [&] {
    if (cancel) cancel->throw_if_cancelled();
  };
  for (const PowerTrace& t : batch.power_traces) {
    check();
    if (cancel) cancel->report(static_cast<double>(progress.done) / std::max<double>(1, progress.total), "summarising");
    // The summary is stored with the trace and its channels (schema 6), so it is computed first.
    StoredPowerTrace row;
    row.trace = store::trace_metadata(t);
    row.summary = summarize_trace(t);
    const std::int64_t trace_id = trace_st.insert({import_id}, row);
    for (const TracePhase& p : t.phases) phase_st.insert({trace_id}, p);
    store::write_series(db, trace_id, 0, t.time_s, progress);
    for (std::size_t k = 0; k < t.channels.size(); ++k) {
      check();
      const std::int64_t channel_id = channel_st.insert({trace_id}, row.summary.channels[k]);
      store::write_series(db, trace_id, channel_id, t.channels[k].values, progress);
    }
  }
  store::Inserter frame_st(db, store::frames_table());
  std::error_code ec;
  const std::string abs_path = batch.source_path.empty()
                                   ? std::string()
                                   : std::filesystem::absolute(batch.source_path, ec).lexically_normal().string();
  for (const Frame& f : batch.frames) {
    check();
    const bool copy = f.storage == FrameStorage::Copy;
    if (copy && f.pixels.size() != f.expected_bytes())
      throw WorkspaceError(WorkspaceError::Kind::Constraint,
                           f.label + ": frame has " + std::to_string(f.pixels.size()) + " bytes of pixels, its " +
                               std::to_string(f.width) + "x" + std::to_string(f.height) + " geometry needs " +
                               std::to_string(f.expected_bytes()));
    StoredFrame row;
    row.path = abs_path.empty() ? f.provenance.source_file : abs_path;
    row.content_hash = content_hash;
    row.frame = f;
    frame_st.insert({import_id}, row);
  }
  store::Inserter pipe_st(db, store::pipeline_runs_table());
  store::Inserter stage_st(db, store::pipeline_stages_table());
  for (const PipelineRun& p : batch.pipeline_runs) {
    check();
    const std::int64_t run_id = pipe_st.insert({import_id}, p);
    for (const StageStats& s : p.stages) stage_st.insert({run_id}, s);
  }
  store::Inserter dnn_st(db, store::dnn_runs_table());
  for (const DnnRun& d : batch.dnn_runs) {
    check();
    dnn_st.insert({import_id}, d);
  }
  store::Inserter headroom_st(db, store::headroom_table());
  for (const headroom::HeadroomMeasurement& m : batch.headroom) {
    check();
    // A result whose bookkeeping fails would be refused when read back: refuse it now, before anything is stored.
    if (const std::string e = m.bookkeeping_error(); !e.empty())
      throw WorkspaceError(WorkspaceError::Kind::Constraint, "headroom measurement (" + m.platform + "): " + e);
    headroom_st.insert({import_id}, m);
  }
  store::Inserter sustain_st(db, store::sustain_table());
  for (const SustainRun& r : batch.sustain_runs) {
    check();
    sustain_st.insert({import_id}, r);
  }
  check();
  return import_id;
}

}  // namespace

std::int64_t Workspace::add_import(const ImportBatch& batch, const std::string& content_hash,
                                   const CancelToken* cancel) {
  impl_->require_writable();
  const Db& db = impl_->conn();
  refuse_duplicate(db, content_hash);  // before BEGIN, so a duplicate never takes the write lock
  Transaction tx(db);
  const std::int64_t id = insert_import(db, batch, content_hash, cancel);
  tx.commit();
  return id;
}

std::vector<std::int64_t> Workspace::add_imports(const std::vector<HashedBatch>& batches, const CancelToken* cancel) {
  impl_->require_writable();
  const Db& db = impl_->conn();
  Transaction tx(db);
  std::vector<std::int64_t> ids;
  ids.reserve(batches.size());
  for (const HashedBatch& b : batches) ids.push_back(insert_import(db, *b.batch, b.content_hash, cancel));
  tx.commit();
  return ids;
}

std::int64_t Workspace::add_pipeline_runs(const std::vector<PipelineRun>& runs, const std::string& label,
                                          const std::string& hash) {
  ImportBatch batch;
  batch.source_path = label;
  batch.format = "benchscope-pipeline-v1";
  batch.pipeline_runs = runs;
  return add_import(batch, hash);
}

}  // namespace bs
