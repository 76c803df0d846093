// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/workspace.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string_view>

#include <nlohmann/json.hpp>

#include "model/provenance_json.h"
#include "store/power_samples.h"
#include "store/schema.h"
#include "store/sqlite_db.h"
#include "util/host_clock.h"

namespace bs {

using sqlite::Db;
using sqlite::Statement;
using sqlite::Transaction;

namespace {

// Reject what is not an SQLite file before SQLite touches it, so opening never alters a foreign file.
void check_sqlite_header(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw WorkspaceError(WorkspaceError::Kind::Io, path + ": cannot open workspace");
  char magic[16] = {};
  f.read(magic, sizeof magic);
  if (f.gcount() == 0) return;  // an empty file becomes a new workspace
  if (f.gcount() < 16 || std::string_view(magic, 16) != std::string_view("SQLite format 3\0", 16))
    throw WorkspaceError(WorkspaceError::Kind::NotAWorkspace,
                         path + ": is not a BenchScope workspace (not an SQLite database)");
  // A truncated file (a copy cut short, a full disk) can still open, and SQLite only notices when a query happens
  // to read a missing page. The header records the page size (offset 16, big-endian, 1 meaning 65536) and, when
  // the "valid-for" counter (offset 92) equals the change counter (offset 24), the page count (offset 28): a file
  // shorter than that is damaged, unless a WAL file is beside it. A longer file is fine (SQLite does not always
  // shrink it).
  unsigned char hdr[100] = {};
  std::memcpy(hdr, magic, sizeof magic);
  f.read(reinterpret_cast<char*>(hdr) + 16, 84);
  if (f.gcount() < 84)
    throw WorkspaceError(WorkspaceError::Kind::Corrupt, path + ": workspace file is truncated (header incomplete)");
  const auto be32 = [&](int at) {
    return (std::uint32_t{hdr[at]} << 24) | (std::uint32_t{hdr[at + 1]} << 16) | (std::uint32_t{hdr[at + 2]} << 8) |
           std::uint32_t{hdr[at + 3]};
  };
  std::uint64_t page_size = (std::uint32_t{hdr[16]} << 8) | hdr[17];
  if (page_size == 1) page_size = 65536;
  const std::uint64_t pages = be32(28);
  if (be32(92) != be32(24) || pages == 0 || page_size < 512) return;  // no reliable size claim to check
  std::error_code ec;
  // A process killed during a WAL checkpoint can leave page 1 (with the new page count) written before the file
  // grew; the WAL beside it still holds every page and SQLite completes the checkpoint on open. Found by the
  // SIGKILL test (tests/app/workspace/test_import_kill.cpp).
  if (std::filesystem::file_size(path + "-wal", ec) > 0 && !ec) return;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (!ec && size < pages * page_size)
    throw WorkspaceError(WorkspaceError::Kind::Corrupt, path + ": workspace file is truncated (" +
                                                            std::to_string(size) + " bytes, its header says " +
                                                            std::to_string(pages * page_size) + ")");
}

constexpr int kCancelCheckRows = 1000;

// Measurement values are JSON text. JSON has no NaN or infinity (nlohmann writes null), so those are written as
// the strings "nan", "inf", "-inf": a repetition that produced no number keeps its place instead of vanishing.
nlohmann::json number_to_json(double v) {
  if (std::isfinite(v)) return v;
  return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
}

std::optional<double> number_from_json(const nlohmann::json& j) {
  if (j.is_number()) return j.get<double>();
  if (j.is_string()) {
    const auto& s = j.get_ref<const std::string&>();
    if (s == "nan") return std::numeric_limits<double>::quiet_NaN();
    if (s == "inf") return std::numeric_limits<double>::infinity();
    if (s == "-inf") return -std::numeric_limits<double>::infinity();
  }
  return std::nullopt;
}

}  // namespace

struct Workspace::Impl {
  explicit Impl(const std::string& p) : path(p), db(p, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE) {}
  std::string path;
  Db db;
  int version = 0;
};

Workspace::Workspace(const std::string& path) {
  std::error_code ec;
  const bool existed = std::filesystem::exists(path, ec) && std::filesystem::file_size(path, ec) > 0;
  if (existed) check_sqlite_header(path);
  impl_ = std::make_unique<Impl>(path);
  const Db& db = impl_->db;
  std::int64_t app_id = 0;
  std::int64_t version = 0;
  try {
    app_id = db.pragma_int("PRAGMA application_id");
    version = db.pragma_int("PRAGMA user_version");
  } catch (const WorkspaceError& e) {
    throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                         path + ": workspace is damaged and cannot be read (" + std::string(e.what()) + ")");
  }
  if (existed && app_id != store::kApplicationId)
    throw WorkspaceError(WorkspaceError::Kind::NotAWorkspace,
                         path + ": is an SQLite database but not a BenchScope workspace");
  if (version > kSchemaVersion)
    throw WorkspaceError(WorkspaceError::Kind::NewerVersion, path + ": was written by a newer BenchScope (schema " +
                                                                 std::to_string(version) + ", this build reads up to " +
                                                                 std::to_string(kSchemaVersion) + ")");
  db.exec("PRAGMA foreign_keys = ON");
  db.exec("PRAGMA journal_mode = WAL");
  db.exec("PRAGMA synchronous = NORMAL");
  if (version < kSchemaVersion) {
    Transaction tx(db);
    if (!existed) {
      db.exec(("PRAGMA application_id = " + std::to_string(store::kApplicationId)).c_str());
    }
    store::migrate(db, static_cast<int>(version));
    Statement meta(db, "INSERT OR REPLACE INTO meta(key, value) VALUES (?, ?)");
    if (version == 0) {  // a new file, or an empty one that only carries the application id
      meta.bind(1, std::string_view("created_at")).bind(2, std::string_view(bs::utc_timestamp())).run();
      meta.bind(1, std::string_view("created_by")).bind(2, std::string_view("benchscope " BENCHSCOPE_VERSION)).run();
    }
    meta.bind(1, std::string_view("schema_version")).bind(2, std::string_view(std::to_string(kSchemaVersion))).run();
    tx.commit();
  }
  impl_->version = kSchemaVersion;
}

Workspace::~Workspace() = default;
Workspace::Workspace(Workspace&&) noexcept = default;
Workspace& Workspace::operator=(Workspace&&) noexcept = default;

const std::string& Workspace::path() const { return impl_->path; }
int Workspace::schema_version() const { return impl_->version; }

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

}  // namespace

namespace {

void refuse_duplicate(const Db& db, const std::string& content_hash) {
  Statement dup(db, "SELECT path, imported_at FROM imports WHERE content_hash = ?");
  dup.bind(1, std::string_view(content_hash));
  if (dup.step())
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         "already imported from " + dup.text(0) + " on " + dup.text(1));
}

// Inserts one import inside the caller's transaction and returns its id.
std::int64_t insert_import(const Db& db, const ImportBatch& batch, const std::string& content_hash,
                           const CancelToken* cancel) {
  refuse_duplicate(db, content_hash);
  Statement imp(db,
                "INSERT INTO imports(path, format, imported_at, content_hash, run_count, result_set_count) "
                "VALUES (?, ?, ?, ?, ?, ?)");
  imp.bind(1, std::string_view(batch.source_path))
      .bind(2, std::string_view(batch.format))
      .bind(3, std::string_view(bs::utc_timestamp()))
      .bind(4, std::string_view(content_hash))
      .bind(5, static_cast<std::int64_t>(batch.runs.size()))
      .bind(6, static_cast<std::int64_t>(batch.result_sets.size()))
      .run();
  const std::int64_t import_id = sqlite3_last_insert_rowid(db.get());

  DeviceIds devices{db};
  Statement run_st(db,
                   "INSERT INTO runs(import_id, device_id, backend, kernel, variant, iterations, dims, "
                   "reported_peak_flops, theoretical_peak_flops, provenance) VALUES (?,?,?,?,?,?,?,?,?,?)");
  Statement sample_st(db, "INSERT INTO run_samples(run_id, workers, repetition, seconds) VALUES (?,?,?,?)");
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
    run_st.bind(1, import_id)
        .bind(2, devices.get(run.platform, run.device, run.device_kind))
        .bind(3, std::string_view(run.backend))
        .bind(4, std::string_view(run.kernel))
        .bind(5, std::string_view(run.variant))
        .bind(6, run.iterations)
        .bind(7, run.dims)
        .bind(8, run.reported_peak_flops)
        .bind(9, run.theoretical_peak_flops)
        .bind(10, std::string_view(provenance_to_json(run.provenance, true).dump()))
        .run();
    const std::int64_t run_id = sqlite3_last_insert_rowid(db.get());
    for (const WorkerSample& s : run.samples)
      for (std::size_t k = 0; k < s.seconds.size(); ++k) {
        sample_st.bind(1, run_id).bind(2, s.workers).bind(3, static_cast<std::int64_t>(k)).bind(4, s.seconds[k]).run();
        poll();
      }
  }
  Statement set_st(db,
                   "INSERT INTO result_sets(import_id, device_id, backend, source_format, provenance) "
                   "VALUES (?,?,?,?,?)");
  Statement m_st(db,
                 "INSERT INTO measurements(result_set_id, name, metric, unit, vals, aggregates) VALUES (?,?,?,?,?,?)");
  for (const ResultSet& set : batch.result_sets) {
    set_st.bind(1, import_id)
        .bind(2, devices.get(set.platform, set.device, set.device_kind))
        .bind(3, std::string_view(set.backend))
        .bind(4, std::string_view(set.source_format))
        .bind(5, std::string_view(provenance_to_json(set.provenance, true).dump()))
        .run();
    const std::int64_t set_id = sqlite3_last_insert_rowid(db.get());
    for (const Measurement& m : set.measurements) {
      nlohmann::json values = nlohmann::json::array();
      for (double v : m.values) values.push_back(number_to_json(v));
      nlohmann::json aggregates = nlohmann::json::array();
      for (const auto& [name, value] : m.reported_aggregates) aggregates.push_back({name, number_to_json(value)});
      m_st.bind(1, set_id)
          .bind(2, std::string_view(m.name))
          .bind(3, std::string_view(m.metric))
          .bind(4, std::string_view(m.unit))
          .bind(5, std::string_view(values.dump()))
          .bind(6, std::string_view(aggregates.dump()))
          .run();
      poll();
    }
  }
  Statement trace_st(db,
                     "INSERT INTO power_traces(import_id, platform, label, start_time, supply_voltage_v, time_s, "
                     "provenance, total_channel) VALUES (?,?,?,?,?,x'',?,?)");
  Statement channel_st(db, "INSERT INTO power_channels(trace_id, name, quantity, vals) VALUES (?,?,?,x'')");
  Statement phase_st(db, "INSERT INTO power_phases(trace_id, name, start_s, end_s) VALUES (?,?,?,?)");
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
    trace_st.bind(1, import_id)
        .bind(2, std::string_view(t.platform))
        .bind(3, std::string_view(t.label))
        .bind(4, std::string_view(t.start_time))
        .bind(5, t.supply_voltage_v)
        .bind(6, std::string_view(provenance_to_json(t.provenance, true).dump()))
        .bind(7, std::string_view(t.total_channel))
        .run();
    const std::int64_t trace_id = sqlite3_last_insert_rowid(db.get());
    for (const TracePhase& p : t.phases)
      phase_st.bind(1, trace_id).bind(2, std::string_view(p.name)).bind(3, p.start_s).bind(4, p.end_s).run();
    store::write_series(db, trace_id, 0, t.time_s, progress);
    std::vector<std::int64_t> channel_ids;
    for (const PowerChannel& c : t.channels) {
      check();
      const char* q = c.quantity == PowerQuantity::Current   ? "current"
                      : c.quantity == PowerQuantity::Voltage ? "voltage"
                                                             : "power";
      channel_st.bind(1, trace_id).bind(2, std::string_view(c.name)).bind(3, std::string_view(q)).run();
      channel_ids.push_back(sqlite3_last_insert_rowid(db.get()));
      store::write_series(db, trace_id, channel_ids.back(), c.values, progress);
    }
    if (cancel) cancel->report(1.0, "summarising");
    store::write_summary(db, trace_id, channel_ids, summarize_trace(t));
  }
  Statement frame_st(db,
                     "INSERT INTO frames(import_id, label, storage, path, content_hash, source_format, read_options, "
                     "width, height, channels, bit_depth, pattern, synthetic, lens, provenance, byte_order, pixels) "
                     "VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)");
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
    frame_st.bind(1, import_id)
        .bind(2, std::string_view(f.label))
        .bind(3, std::string_view(copy ? "copy" : "reference"))
        .bind(4, std::string_view(abs_path.empty() ? f.provenance.source_file : abs_path))
        .bind(5, std::string_view(content_hash))
        .bind(6, std::string_view(f.source_format))
        .bind(7, std::string_view(f.read_options.empty() ? "{}" : f.read_options))
        .bind(8, f.width)
        .bind(9, f.height)
        .bind(10, f.channels)
        .bind(11, f.bit_depth)
        .bind(12, std::string_view(f.pattern))
        .bind(13, f.synthetic ? 1 : 0)
        .bind(14, std::string_view(f.lens_json))
        .bind(15, std::string_view(provenance_to_json(f.provenance, true).dump()))
        .bind(16, std::string_view(std::endian::native == std::endian::big ? "big" : "little"));
    if (copy)
      frame_st.bind_bytes(17, f.pixels);
    else
      frame_st.bind_null(17);
    frame_st.run();
  }
  Statement pipe_st(db,
                    "INSERT INTO pipeline_runs(import_id, platform, device, backend, demosaic, detector, frame_width, "
                    "frame_height, throughput_fps, provenance) VALUES (?,?,?,?,?,?,?,?,?,?)");
  Statement stage_st(db,
                     "INSERT INTO pipeline_stages(run_id, stage, n, mean_s, sd_s, min_s, max_s, p50_s, p95_s) "
                     "VALUES (?,?,?,?,?,?,?,?,?)");
  for (const PipelineRun& p : batch.pipeline_runs) {
    check();
    pipe_st.bind(1, import_id)
        .bind(2, std::string_view(p.platform))
        .bind(3, std::string_view(p.device))
        .bind(4, std::string_view(p.backend))
        .bind(5, std::string_view(p.demosaic))
        .bind(6, std::string_view(p.detector))
        .bind(7, p.frame_width)
        .bind(8, p.frame_height)
        .bind(9, p.throughput_fps)
        .bind(10, std::string_view(provenance_to_json(p.provenance, true).dump()))
        .run();
    const std::int64_t run_id = sqlite3_last_insert_rowid(db.get());
    for (const StageStats& s : p.stages)
      stage_st.bind(1, run_id)
          .bind(2, std::string_view(s.stage))
          .bind(3, static_cast<std::int64_t>(s.n))
          .bind(4, s.mean_s)
          .bind(5, s.sd_s)
          .bind(6, s.min_s)
          .bind(7, s.max_s)
          .bind(8, s.p50_s)
          .bind(9, s.p95_s)
          .run();
  }
  Statement dnn_st(db,
                   "INSERT INTO dnn_runs(import_id, platform, device, backend, model, model_hash, family, "
                   "architecture_only, input_width, input_height, batch, flops, opencv_flops, n, mean_s, sd_s, min_s, "
                   "max_s, p50_s, p95_s, device_peak_flops, energy_per_inference_j, mean_power_w, provenance) "
                   "VALUES (?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?,?)");
  for (const DnnRun& d : batch.dnn_runs) {
    check();
    dnn_st.bind(1, import_id)
        .bind(2, std::string_view(d.platform))
        .bind(3, std::string_view(d.device))
        .bind(4, std::string_view(d.backend))
        .bind(5, std::string_view(d.model))
        .bind(6, std::string_view(d.model_hash))
        .bind(7, std::string_view(d.family))
        .bind(8, d.architecture_only ? 1 : 0)
        .bind(9, d.input_width)
        .bind(10, d.input_height)
        .bind(11, d.batch)
        .bind(12, d.flops)
        .bind(13, d.opencv_flops)
        .bind(14, static_cast<std::int64_t>(d.forward.n))
        .bind(15, d.forward.mean_s)
        .bind(16, d.forward.sd_s)
        .bind(17, d.forward.min_s)
        .bind(18, d.forward.max_s)
        .bind(19, d.forward.p50_s)
        .bind(20, d.forward.p95_s)
        .bind(21, d.device_peak_flops)
        .bind(22, d.energy_per_inference_j)
        .bind(23, d.mean_power_w)
        .bind(24, std::string_view(provenance_to_json(d.provenance, true).dump()))
        .run();
  }
  check();
  return import_id;
}

}  // namespace

std::int64_t Workspace::add_import(const ImportBatch& batch, const std::string& content_hash,
                                   const CancelToken* cancel) {
  const Db& db = impl_->db;
  refuse_duplicate(db, content_hash);  // before BEGIN, so a duplicate never takes the write lock
  Transaction tx(db);
  const std::int64_t id = insert_import(db, batch, content_hash, cancel);
  tx.commit();
  return id;
}

std::vector<std::int64_t> Workspace::add_imports(const std::vector<HashedBatch>& batches, const CancelToken* cancel) {
  const Db& db = impl_->db;
  Transaction tx(db);
  std::vector<std::int64_t> ids;
  ids.reserve(batches.size());
  for (const HashedBatch& b : batches) ids.push_back(insert_import(db, *b.batch, b.content_hash, cancel));
  tx.commit();
  return ids;
}

void Workspace::remove_import(std::int64_t import_id) {
  Transaction tx(impl_->db);
  Statement(impl_->db, "DELETE FROM imports WHERE id = ?").bind(1, import_id).run();
  tx.commit();
}

namespace {
void require_name(const std::string& what, const std::string& name) {
  if (name.find_first_not_of(" \t") == std::string::npos)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, what + ": the new name is empty");
}
}  // namespace

void Workspace::rename_power_trace(std::int64_t trace_id, const std::string& label) {
  require_name("power log", label);
  Statement(impl_->db, "UPDATE power_traces SET label = ? WHERE id = ?")
      .bind(1, std::string_view(label))
      .bind(2, trace_id)
      .run();
  if (sqlite3_changes(impl_->db.get()) == 0)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, impl_->path + ": no power log #" + std::to_string(trace_id));
}

void Workspace::rename_frame(std::int64_t frame_id, const std::string& label) {
  require_name("frame", label);
  Statement(impl_->db, "UPDATE frames SET label = ? WHERE id = ?")
      .bind(1, std::string_view(label))
      .bind(2, frame_id)
      .run();
  if (sqlite3_changes(impl_->db.get()) == 0)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, impl_->path + ": no frame #" + std::to_string(frame_id));
}

void Workspace::rename_platform(const std::string& from, const std::string& to) {
  require_name("platform '" + from + "'", to);
  if (from == to) return;
  Transaction tx(impl_->db);
  Statement clash(impl_->db,
                  "SELECT a.device FROM devices a JOIN devices b ON a.device = b.device WHERE a.platform = ? AND "
                  "b.platform = ? LIMIT 1");
  clash.bind(1, std::string_view(from)).bind(2, std::string_view(to));
  if (clash.step())
    throw WorkspaceError(WorkspaceError::Kind::Constraint, "platform '" + to + "' already has a device '" +
                                                               clash.text(0) + "' like '" + from +
                                                               "': renaming would merge their runs");
  int changed = 0;
  for (const char* sql :
       {"UPDATE devices SET platform = ? WHERE platform = ?", "UPDATE power_traces SET platform = ? WHERE platform = ?",
        "UPDATE pipeline_runs SET platform = ? WHERE platform = ?"}) {
    Statement(impl_->db, sql).bind(1, std::string_view(to)).bind(2, std::string_view(from)).run();
    changed += sqlite3_changes(impl_->db.get());
  }
  if (changed == 0)
    throw WorkspaceError(WorkspaceError::Kind::Constraint, impl_->path + ": no platform '" + from + "'");
  tx.commit();
}

namespace {
constexpr std::string_view kSettingPrefix = "setting/";
}

void Workspace::set_setting(const std::string& key, const std::string& value) {
  if (key.empty()) throw std::invalid_argument("workspace setting: empty key");
  Statement(impl_->db, "INSERT OR REPLACE INTO meta(key, value) VALUES (?, ?)")
      .bind(1, std::string_view(std::string(kSettingPrefix) + key))
      .bind(2, std::string_view(value))
      .run();
}

void Workspace::remove_setting(const std::string& key) {
  Statement(impl_->db, "DELETE FROM meta WHERE key = ?")
      .bind(1, std::string_view(std::string(kSettingPrefix) + key))
      .run();
}

std::vector<std::pair<std::string, std::string>> Workspace::settings(const std::string& prefix) const {
  std::vector<std::pair<std::string, std::string>> out;
  // Keys sort bytewise (BINARY collation), so the ones with the prefix are contiguous from the prefix on; no LIKE,
  // as keys may hold % or _.
  const std::string full = std::string(kSettingPrefix) + prefix;
  Statement st(impl_->db, "SELECT key, value FROM meta WHERE key >= ? ORDER BY key");
  st.bind(1, std::string_view(full));
  while (st.step()) {
    std::string key = st.text(0);
    if (key.compare(0, full.size(), full) != 0) break;
    out.emplace_back(key.substr(kSettingPrefix.size()), st.text(1));
  }
  return out;
}

std::vector<ImportRecord> Workspace::imports() const {
  std::vector<ImportRecord> out;
  Statement st(
      impl_->db,
      "SELECT id, path, format, imported_at, content_hash, run_count, result_set_count FROM imports ORDER BY id");
  while (st.step())
    out.push_back({st.int64(0), st.text(1), st.text(2), st.text(3), st.text(4), st.int64(5), st.int64(6)});
  return out;
}

std::vector<DeviceRecord> Workspace::devices() const {
  std::vector<DeviceRecord> out;
  Statement st(impl_->db, "SELECT id, platform, device, kind, color_index FROM devices ORDER BY color_index");
  while (st.step())
    out.push_back(
        {st.int64(0), st.text(1), st.text(2), device_kind_from_string(st.text(3)), static_cast<int>(st.int64(4))});
  return out;
}

void Workspace::set_device_color(const std::string& platform, const std::string& device, int color_index) {
  if (color_index < 0)
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         "colour index must be 0 or more, not " + std::to_string(color_index));
  Statement st(impl_->db, "UPDATE devices SET color_index = ? WHERE platform = ? AND device = ?");
  st.bind(1, color_index).bind(2, std::string_view(platform)).bind(3, std::string_view(device)).run();
  if (sqlite3_changes(impl_->db.get()) == 0)
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         impl_->path + ": no device '" + device + "' on platform '" + platform + "'");
}

void Workspace::add_trace_phase(std::int64_t trace_id, const TracePhase& phase) {
  if (phase.name.empty() || !(phase.end_s >= phase.start_s))
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         impl_->path + ": phase '" + phase.name + "' needs a name and an end not before its start");
  Statement probe(impl_->db, "SELECT 1 FROM power_traces WHERE id = ?");
  probe.bind(1, trace_id);
  if (!probe.step())
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         impl_->path + ": no power trace with id " + std::to_string(trace_id));
  Statement st(impl_->db, "INSERT INTO power_phases(trace_id, name, start_s, end_s) VALUES (?,?,?,?)");
  st.bind(1, trace_id).bind(2, std::string_view(phase.name)).bind(3, phase.start_s).bind(4, phase.end_s).run();
}

const sqlite::Db& Workspace::database() const { return impl_->db; }

std::vector<StoredRun> Workspace::runs() const {
  std::vector<StoredRun> out;
  std::map<std::int64_t, std::size_t> index;
  Statement st(impl_->db,
               "SELECT r.id, r.import_id, r.device_id, d.color_index, d.platform, d.device, d.kind, r.backend, "
               "r.kernel, r.variant, r.iterations, r.dims, r.reported_peak_flops, r.theoretical_peak_flops, "
               "r.provenance FROM runs r JOIN devices d ON d.id = r.device_id "
               "ORDER BY d.color_index, r.backend, r.dims, r.id");
  while (st.step()) {
    StoredRun s;
    s.id = st.int64(0);
    s.import_id = st.int64(1);
    s.device_id = st.int64(2);
    s.color_index = static_cast<int>(st.int64(3));
    s.run.platform = st.text(4);
    s.run.device = st.text(5);
    s.run.device_kind = device_kind_from_string(st.text(6));
    s.run.backend = st.text(7);
    s.run.kernel = st.text(8);
    s.run.variant = st.text(9);
    s.run.iterations = st.int64(10);
    s.run.dims = static_cast<int>(st.int64(11));
    s.run.reported_peak_flops = st.optional_real(12);
    s.run.theoretical_peak_flops = st.optional_real(13);
    s.run.provenance = provenance_from_json(nlohmann::json::parse(st.text(14), nullptr, false));
    index[s.id] = out.size();
    out.push_back(std::move(s));
  }
  Statement samples(impl_->db, "SELECT run_id, workers, seconds FROM run_samples ORDER BY run_id, workers, repetition");
  while (samples.step()) {
    const auto it = index.find(samples.int64(0));
    if (it == index.end()) continue;
    auto& list = out[it->second].run.samples;
    const std::int64_t workers = samples.int64(1);
    if (list.empty() || list.back().workers != workers) list.push_back({workers, {}});
    list.back().seconds.push_back(samples.real(2));
  }
  return out;
}

std::vector<StoredResultSet> Workspace::result_sets() const {
  std::vector<StoredResultSet> out;
  std::map<std::int64_t, std::size_t> index;
  Statement st(impl_->db,
               "SELECT s.id, s.import_id, s.device_id, d.color_index, d.platform, d.device, d.kind, s.backend, "
               "s.source_format, s.provenance FROM result_sets s JOIN devices d ON d.id = s.device_id "
               "ORDER BY d.color_index, s.id");
  while (st.step()) {
    StoredResultSet s;
    s.id = st.int64(0);
    s.import_id = st.int64(1);
    s.device_id = st.int64(2);
    s.color_index = static_cast<int>(st.int64(3));
    s.set.platform = st.text(4);
    s.set.device = st.text(5);
    s.set.device_kind = device_kind_from_string(st.text(6));
    s.set.backend = st.text(7);
    s.set.source_format = st.text(8);
    s.set.provenance = provenance_from_json(nlohmann::json::parse(st.text(9), nullptr, false));
    index[s.id] = out.size();
    out.push_back(std::move(s));
  }
  Statement m(
      impl_->db,
      "SELECT result_set_id, name, metric, unit, vals, aggregates FROM measurements ORDER BY result_set_id, id");
  while (m.step()) {
    const auto it = index.find(m.int64(0));
    if (it == index.end()) continue;
    Measurement meas{m.text(1), m.text(2), m.text(3), {}, {}};
    const auto vals = nlohmann::json::parse(m.text(4), nullptr, false);
    if (vals.is_array())
      for (const auto& v : vals)
        if (const auto x = number_from_json(v)) meas.values.push_back(*x);
    const auto aggs = nlohmann::json::parse(m.text(5), nullptr, false);
    if (aggs.is_array())
      for (const auto& a : aggs)
        if (a.is_array() && a.size() == 2 && a[0].is_string())
          if (const auto x = number_from_json(a[1])) meas.reported_aggregates.emplace_back(a[0].get<std::string>(), *x);
    out[it->second].set.measurements.push_back(std::move(meas));
  }
  return out;
}

std::vector<StoredPowerTrace> Workspace::power_trace_summaries() const {
  std::vector<StoredPowerTrace> out;
  std::map<std::int64_t, std::size_t> index;
  Statement st(impl_->db,
               "SELECT id, import_id, platform, label, start_time, supply_voltage_v, provenance, total_channel, "
               "samples, duration_s FROM power_traces ORDER BY id");
  while (st.step()) {
    StoredPowerTrace s;
    s.id = st.int64(0);
    s.import_id = st.int64(1);
    s.trace.platform = st.text(2);
    s.trace.label = st.text(3);
    s.trace.start_time = st.text(4);
    s.trace.supply_voltage_v = st.optional_real(5);
    s.trace.provenance = provenance_from_json(nlohmann::json::parse(st.text(6), nullptr, false));
    s.trace.total_channel = st.text(7);
    s.summary.samples = static_cast<std::size_t>(st.int64(8));
    s.summary.duration_s = st.real(9);
    s.samples_loaded = false;
    index[s.id] = out.size();
    out.push_back(std::move(s));
  }
  Statement ch(impl_->db,
               "SELECT trace_id, name, quantity, summary, overview FROM power_channels ORDER BY trace_id, id");
  while (ch.step()) {
    const auto it = index.find(ch.int64(0));
    if (it == index.end()) continue;
    const std::string q = ch.text(2);
    StoredPowerTrace& s = out[it->second];
    s.trace.channels.push_back({ch.text(1),
                                q == "current"   ? PowerQuantity::Current
                                : q == "voltage" ? PowerQuantity::Voltage
                                                 : PowerQuantity::Power,
                                {}});
    ChannelSummary cs;
    cs.name = s.trace.channels.back().name;
    cs.quantity = s.trace.channels.back().quantity;
    cs.stats = store::channel_stats_from_json(ch.text(3), cs.integral);
    const std::vector<double> pairs = ch.doubles(4);
    for (std::size_t i = 0; i + 1 < pairs.size(); i += 2) {
      cs.overview.t.push_back(pairs[i]);
      cs.overview.v.push_back(pairs[i + 1]);
    }
    s.summary.channels.push_back(std::move(cs));
  }
  Statement ph(impl_->db, "SELECT trace_id, name, start_s, end_s FROM power_phases ORDER BY trace_id, start_s, id");
  while (ph.step()) {
    const auto it = index.find(ph.int64(0));
    if (it == index.end()) continue;
    out[it->second].trace.phases.push_back({ph.text(1), ph.real(2), ph.real(3)});
  }
  return out;
}

void Workspace::load_power_samples(StoredPowerTrace& t, const CancelToken* cancel) const {
  if (t.samples_loaded) return;
  std::vector<std::int64_t> channel_ids;
  Statement ch(impl_->db, "SELECT id FROM power_channels WHERE trace_id = ? ORDER BY id");
  ch.bind(1, t.id);
  while (ch.step()) channel_ids.push_back(ch.int64(0));
  if (channel_ids.size() != t.trace.channels.size())
    throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                         impl_->path + ": power trace " + std::to_string(t.id) + " changed while it was being read");
  const std::size_t n = t.summary.samples;
  store::SampleProgress progress{cancel, "loading samples", 0, n * (1 + channel_ids.size())};
  t.trace.time_s = store::read_series(impl_->db, t.id, 0, n, progress);
  for (std::size_t k = 0; k < channel_ids.size(); ++k)
    t.trace.channels[k].values = store::read_series(impl_->db, t.id, channel_ids[k], n, progress);
  t.samples_loaded = true;
}

std::vector<StoredPowerTrace> Workspace::power_traces() const {
  std::vector<StoredPowerTrace> out = power_trace_summaries();
  for (StoredPowerTrace& t : out) load_power_samples(t);
  return out;
}

std::vector<StoredFrame> Workspace::frames() const {
  std::vector<StoredFrame> out;
  Statement st(impl_->db,
               "SELECT id, import_id, label, storage, path, content_hash, source_format, read_options, width, height, "
               "channels, bit_depth, pattern, synthetic, lens, provenance FROM frames ORDER BY id");
  while (st.step()) {
    StoredFrame s;
    s.id = st.int64(0);
    s.import_id = st.int64(1);
    s.frame.label = st.text(2);
    s.frame.storage = st.text(3) == "copy" ? FrameStorage::Copy : FrameStorage::Reference;
    s.path = st.text(4);
    s.content_hash = st.text(5);
    s.frame.source_format = st.text(6);
    s.frame.read_options = st.text(7);
    s.frame.width = static_cast<int>(st.int64(8));
    s.frame.height = static_cast<int>(st.int64(9));
    s.frame.channels = static_cast<int>(st.int64(10));
    s.frame.bit_depth = static_cast<int>(st.int64(11));
    s.frame.pattern = st.text(12);
    s.frame.synthetic = st.int64(13) != 0;
    s.frame.lens_json = st.text(14);
    s.frame.provenance = provenance_from_json(nlohmann::json::parse(st.text(15), nullptr, false));
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<std::uint8_t> Workspace::frame_pixels(std::int64_t frame_id) const {
  Statement st(impl_->db, "SELECT width, height, channels, bit_depth, byte_order, pixels FROM frames WHERE id = ?");
  st.bind(1, frame_id);
  if (!st.step())
    throw WorkspaceError(WorkspaceError::Kind::Constraint,
                         impl_->path + ": no frame with id " + std::to_string(frame_id));
  Frame geometry;
  geometry.width = static_cast<int>(st.int64(0));
  geometry.height = static_cast<int>(st.int64(1));
  geometry.channels = static_cast<int>(st.int64(2));
  geometry.bit_depth = static_cast<int>(st.int64(3));
  const bool big = st.text(4) == "big";
  std::vector<std::uint8_t> pixels = st.bytes(5);
  if (pixels.empty()) return pixels;  // kept by reference
  if (pixels.size() != geometry.expected_bytes())
    throw WorkspaceError(WorkspaceError::Kind::Corrupt,
                         impl_->path + ": frame " + std::to_string(frame_id) + " has " + std::to_string(pixels.size()) +
                             " bytes of pixels, its geometry needs " + std::to_string(geometry.expected_bytes()));
  // A workspace written on a machine of the other byte order stays readable.
  if (geometry.bit_depth > 8 && big != (std::endian::native == std::endian::big))
    for (std::size_t i = 0; i + 1 < pixels.size(); i += 2) std::swap(pixels[i], pixels[i + 1]);
  return pixels;
}

std::vector<StoredPipelineRun> Workspace::pipeline_runs() const {
  std::vector<StoredPipelineRun> out;
  std::map<std::int64_t, std::size_t> index;
  Statement st(impl_->db,
               "SELECT id, import_id, platform, device, backend, demosaic, detector, frame_width, frame_height, "
               "throughput_fps, provenance FROM pipeline_runs ORDER BY platform, id");
  while (st.step()) {
    StoredPipelineRun s;
    s.id = st.int64(0);
    s.import_id = st.int64(1);
    s.run.platform = st.text(2);
    s.run.device = st.text(3);
    s.run.backend = st.text(4);
    s.run.demosaic = st.text(5);
    s.run.detector = st.text(6);
    s.run.frame_width = static_cast<int>(st.int64(7));
    s.run.frame_height = static_cast<int>(st.int64(8));
    s.run.throughput_fps = st.optional_real(9);
    s.run.provenance = provenance_from_json(nlohmann::json::parse(st.text(10), nullptr, false));
    index[s.id] = out.size();
    out.push_back(std::move(s));
  }
  // Stages in pipeline order (preprocess, detect, end-to-end, then any other), not alphabetically.
  Statement stages(impl_->db,
                   "SELECT run_id, stage, n, mean_s, sd_s, min_s, max_s, p50_s, p95_s FROM pipeline_stages "
                   "ORDER BY run_id, CASE stage WHEN 'preprocess' THEN 0 WHEN 'detect' THEN 1 "
                   "WHEN 'end-to-end' THEN 2 ELSE 3 END, stage");
  while (stages.step()) {
    const auto it = index.find(stages.int64(0));
    if (it == index.end()) continue;
    out[it->second].run.stages.push_back({stages.text(1), static_cast<std::size_t>(stages.int64(2)), stages.real(3),
                                          stages.real(4), stages.optional_real(5), stages.optional_real(6),
                                          stages.optional_real(7), stages.optional_real(8)});
  }
  return out;
}

std::vector<StoredDnnRun> Workspace::dnn_runs() const {
  std::vector<StoredDnnRun> out;
  Statement st(impl_->db,
               "SELECT id, import_id, platform, device, backend, model, model_hash, family, architecture_only, "
               "input_width, input_height, batch, flops, opencv_flops, n, mean_s, sd_s, min_s, max_s, p50_s, p95_s, "
               "device_peak_flops, energy_per_inference_j, mean_power_w, provenance FROM dnn_runs "
               "ORDER BY platform, model, input_width, input_height, backend, id");
  while (st.step()) {
    StoredDnnRun s;
    s.id = st.int64(0);
    s.import_id = st.int64(1);
    DnnRun& d = s.run;
    d.platform = st.text(2);
    d.device = st.text(3);
    d.backend = st.text(4);
    d.model = st.text(5);
    d.model_hash = st.text(6);
    d.family = st.text(7);
    d.architecture_only = st.int64(8) != 0;
    d.input_width = static_cast<int>(st.int64(9));
    d.input_height = static_cast<int>(st.int64(10));
    d.batch = static_cast<int>(st.int64(11));
    d.flops = st.int64(12);
    d.opencv_flops = st.int64(13);
    d.forward = {"inference",          static_cast<std::size_t>(st.int64(14)),
                 st.real(15),          st.real(16),
                 st.optional_real(17), st.optional_real(18),
                 st.optional_real(19), st.optional_real(20)};
    d.device_peak_flops = st.optional_real(21);
    d.energy_per_inference_j = st.optional_real(22);
    d.mean_power_w = st.optional_real(23);
    d.provenance = provenance_from_json(nlohmann::json::parse(st.text(24), nullptr, false));
    out.push_back(std::move(s));
  }
  return out;
}

std::int64_t Workspace::add_pipeline_runs(const std::vector<PipelineRun>& runs, const std::string& label,
                                          const std::string& hash) {
  ImportBatch batch;
  batch.source_path = label;
  batch.format = "benchscope-pipeline-v1";
  batch.pipeline_runs = runs;
  return add_import(batch, hash);
}

void Workspace::save_as(const std::string& new_path) const {
  std::error_code ec;
  if (std::filesystem::exists(new_path, ec))
    throw WorkspaceError(WorkspaceError::Kind::Io, new_path + ": already exists; choose another name");
  try {
    Statement st(impl_->db, "VACUUM INTO ?");
    st.bind(1, std::string_view(new_path));
    st.run();
  } catch (const WorkspaceError& e) {
    // Name the target: the failure is about where the copy goes (directory missing, no permission, disk full).
    throw WorkspaceError(e.kind(), new_path + ": cannot save a copy of the workspace here (" + e.what() + ")");
  }
}

std::string Workspace::integrity_check() const {
  Statement st(impl_->db, "PRAGMA integrity_check");
  std::string result;
  while (st.step()) result += (result.empty() ? "" : "\n") + st.text(0);
  return result;
}

}  // namespace bs
