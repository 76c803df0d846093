// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "analysis/power/trace_summary.h"
#include "model/error_category.h"
#include "model/import_limits.h"
#include "store/import_batch.h"
#include "util/cancel.h"

namespace bs {

namespace sqlite {
class Db;
}

class WorkspaceError : public std::runtime_error {
 public:
  enum class Kind { Io, NotAWorkspace, Corrupt, NewerVersion, Constraint };
  WorkspaceError(Kind kind, std::string message) : std::runtime_error(message), kind_(kind) {}
  Kind kind() const noexcept { return kind_; }

 private:
  Kind kind_;
};

struct ImportRecord {
  std::int64_t id = 0;
  std::string path;          // as given at import time
  std::string format;        // importer id
  std::string imported_at;   // ISO 8601 UTC
  std::string content_hash;  // hex digest of the file bytes; the same file is not imported twice
  std::int64_t run_count = 0;
  std::int64_t result_set_count = 0;
};

// A device is identified by (platform, device). Its colour index is assigned once, when it first appears, so the
// same device keeps the same colour in every view and every session.
struct DeviceRecord {
  std::int64_t id = 0;
  std::string platform;
  std::string device;
  DeviceKind kind = DeviceKind::Other;
  int color_index = 0;
};

// What every stored record's row adds to the record: the row's id and the import that brought it (removing that
// import removes the row). Each kind's Stored struct below is this plus its record, under the record's own name.
struct StoredRow {
  std::int64_t id = 0;
  std::int64_t import_id = 0;
};

// A record measured on a device: the device's row and colour come with it.
struct StoredDeviceRow : StoredRow {
  std::int64_t device_id = 0;
  int color_index = 0;
};

struct StoredRun : StoredDeviceRow {
  FlopsRun run;
};

struct StoredResultSet : StoredDeviceRow {
  ResultSet set;
};

struct StoredPowerTrace : StoredRow {
  PowerTrace trace;            // from power_trace_summaries(): everything but time_s and the channels' values
  TraceSummary summary;        // cached at import: sample count, duration, whole-log statistics, overview per channel
  bool samples_loaded = true;  // false from power_trace_summaries() until load_power_samples()
};

// A frame's record; frame.pixels is filled only by frame_pixels() (copies) or by re-reading the file
// (references, importers/frames/frame_store.h).
struct StoredFrame : StoredRow {
  std::string path;          // absolute path of the file at import time
  std::string content_hash;  // of that file; a referenced file must still hash the same
  Frame frame;
};

struct StoredPipelineRun : StoredRow {
  PipelineRun run;
};

struct StoredDnnRun : StoredRow {
  DnnRun run;
};

struct StoredHeadroom : StoredRow {
  headroom::HeadroomMeasurement measurement;
};

struct StoredSustainRun : StoredRow {
  SustainRun run;
};

// An item a workspace holds that breaks the import rules when read back (a value out of range, negative, not
// finite, of the wrong type, an unknown enumeration, JSON beyond the limits, sample chunks that do not add up).
// Every read leaves the item out; the workspace names it (CLI: a warning, GUI: a banner) and refuses writes until
// the user removes it (Workspace::remove_damaged) or the import it came with.
struct WorkspaceDamage {
  std::string item;     // "run #4 (NUC / NUC GPU, OpenCL rotation2d)", "power trace #2 'idle' (Jetson TX2)"
  std::string table;    // the table of the item's own row ("runs"), which removing the item deletes
  std::int64_t id = 0;  // that row's id
  ImportErrorCategory category = ImportErrorCategory::InvalidValue;
  std::string reason;  // "run_samples.workers: -256 is outside 1 .. 1099511627776"
};
// "run #4 (NUC / NUC GPU, OpenCL rotation2d): run_samples.workers: -256 is outside 1 .. 1099511627776
// [invalid-value]"
std::string describe(const WorkspaceDamage& d);

// One SQLite file holds a whole workspace: schema version + migrations, foreign keys on, WAL journal, and one
// transaction per import so a crash or a cancel leaves either all of an import or none of it.
class Workspace {
 public:
  // 2: power traces, 3: frames, 4: pipeline runs, 5: trace phases, 6: trace samples in chunks + cached summary,
  // 7: dnn inference runs, 8: saved lenses, a log's borrowed voltage channel, phase origins (store/schema_v8.h),
  // 9: headroom measurements (control-loop latency histograms per phase and thread), 10: the Platforms tab's decision
  // and each platform's chosen power log (store/schema_v10.h), 11: sustained runs (rate, clocks and temperatures
  // per interval, #53)
  static constexpr int kSchemaVersion = 11;

  // Opens `path`, creating an empty workspace if the file does not exist. Older schemas are migrated; a newer
  // schema, a file that is not a workspace or a corrupt one throws WorkspaceError with a clear message.
  //
  // Every entity is read once on opening, with the import rules (store/row_map.h); what breaks them is listed by
  // damage(), left out of every read, and makes the workspace read-only until the user removes it.
  // ReadOnly opens an existing file without writing to it at all (no journal change, no migration on the file:
  // an older schema is migrated in memory), for `benchscope-cli check`.
  enum class OpenMode { ReadWrite, ReadOnly };
  explicit Workspace(const std::string& path, OpenMode mode = OpenMode::ReadWrite);
  ~Workspace();
  Workspace(Workspace&&) noexcept;
  Workspace& operator=(Workspace&&) noexcept;
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;

  const std::string& path() const;
  int schema_version() const;

  // The damaged items found so far (all of them after opening, except sample values, which are checked when the
  // samples load), in the order found.
  const std::vector<WorkspaceDamage>& damage() const;
  // True while damaged (or opened ReadOnly): every write throws WorkspaceError (Corrupt naming the damage; when
  // opened ReadOnly, Constraint),
  // except remove_import() and remove_damaged(), which are the user's word.
  bool read_only() const;
  // Deletes every damaged item with everything that belongs to it (a device with its runs and result sets) in one
  // transaction, then reads the workspace again; writable once nothing damaged is left. Returns how many items
  // were removed.
  std::size_t remove_damaged();

  // Stores everything in `batch` in one transaction and returns the new import id. `content_hash` identifies the
  // file bytes; when an import with the same hash exists, throws WorkspaceError(Constraint) naming that import.
  // On any error or cancellation nothing is stored.
  std::int64_t add_import(const ImportBatch& batch, const std::string& content_hash,
                          const CancelToken* cancel = nullptr);
  // One file's batch and the hash of its bytes, for add_imports().
  struct HashedBatch {
    const ImportBatch* batch = nullptr;
    std::string content_hash;
  };
  // Stores several files' batches in ONE transaction (all of them or none) and returns their import ids in order.
  // A hash already in the workspace, or given twice, throws WorkspaceError(Constraint) and nothing is stored.
  std::vector<std::int64_t> add_imports(const std::vector<HashedBatch>& batches, const CancelToken* cancel = nullptr);
  void remove_import(std::int64_t import_id);  // removes the import and everything it brought

  // Renames offered by the workspace tree. Each throws WorkspaceError(Constraint) for an unknown id/name or an
  // empty new name.
  void rename_power_trace(std::int64_t trace_id, const std::string& label);
  void rename_frame(std::int64_t frame_id, const std::string& label);
  // Moves every device, power log and pipeline run of platform `from` to `to`. Throws Constraint when `to` already
  // has a device of the same name: that would merge two devices' runs, which is not a rename.
  void rename_platform(const std::string& from, const std::string& to);

  std::vector<ImportRecord> imports() const;
  std::vector<DeviceRecord> devices() const;
  // A device's colour is a property of the device, shown the same in every view and export: the user may pick
  // another palette entry for it. Throws WorkspaceError(Constraint) for an unknown device or a negative index.
  void set_device_color(const std::string& platform, const std::string& device, int color_index);
  std::vector<StoredRun> runs() const;  // ordered by device colour index, backend, dims, id
  std::vector<StoredResultSet> result_sets() const;
  std::vector<StoredPowerTrace> power_traces() const;  // with every sample (eager)
  // Lazy loading: each trace's metadata, phases, channel names and cached summary, no samples. Reads a few KB per
  // trace whatever its length (a 100-million-sample log included).
  std::vector<StoredPowerTrace> power_trace_summaries() const;
  // Fills time_s and every channel's values of `t` (from power_trace_summaries()) chunk by chunk, straight into
  // place; polls `cancel` and reports progress through it (CancelToken::report) between chunks. Gives the same
  // samples, bit for bit, as power_traces().
  void load_power_samples(StoredPowerTrace& t, const CancelToken* cancel = nullptr) const;
  // Adds a named phase to a stored trace (the Power tab's "Save as phase…"); power_traces() returns it with the
  // trace's other phases, ordered by start. Throws WorkspaceError(Constraint) for an unknown trace id, an empty name
  // or an end before the start.
  void add_trace_phase(std::int64_t trace_id, const TracePhase& phase);
  std::vector<StoredFrame> frames() const;  // in import order, without pixels
  // The pixels of a frame stored as a copy, in this host's byte order; empty for a frame kept by reference.
  // Throws WorkspaceError(Corrupt) when the BLOB's size does not match the recorded geometry.
  std::vector<std::uint8_t> frame_pixels(std::int64_t frame_id) const;
  std::vector<StoredPipelineRun> pipeline_runs() const;       // ordered by platform, then id
  std::vector<StoredDnnRun> dnn_runs() const;                 // ordered by platform, model, input, backend, id
  std::vector<StoredHeadroom> headroom_measurements() const;  // ordered by platform, then id
  std::vector<StoredSustainRun> sustain_runs() const;         // ordered by platform, then id

  // Small named settings kept in the workspace file itself (the meta table, under a "setting/" prefix that keeps
  // them apart from the schema's own keys), e.g. user-edited battery presets: they travel with the data.
  void set_setting(const std::string& key, const std::string& value);
  void remove_setting(const std::string& key);
  // Every setting whose key starts with `prefix`, ordered by key.
  std::vector<std::pair<std::string, std::string>> settings(const std::string& prefix = {}) const;

  // Writes a consistent copy (VACUUM INTO). Refuses to overwrite an existing file.
  void save_as(const std::string& new_path) const;
  // "ok" when PRAGMA integrity_check finds nothing, else its messages joined by newlines.
  std::string integrity_check() const;
  // The limits reads apply (the import limits); tests and the check command may lower them.
  const ImportLimits& limits() const;

  // The state behind the interface, shared by the store's own sources (store/workspace_impl.h) and nothing else.
  struct Impl;

  // The open database, for the store's own extension files (store/lens_store.h, store/log_settings_store.h),
  // which keep their tables' SQL beside their API instead of growing this class.
  const sqlite::Db& database() const;

 private:
  std::unique_ptr<Impl> impl_;
};

// Hex digest of a file's bytes (64-bit FNV-1a, streamed), used to recognise a file imported before.
std::string file_content_hash(const std::string& path);
// The same digest of bytes in memory (for results produced in-process, e.g. a kernel sweep).
std::string content_hash(std::string_view bytes);

}  // namespace bs
