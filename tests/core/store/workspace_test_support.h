// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Helpers for the workspace tests: sample batches, exact comparison of what comes back, and raw SQLite access to
// look at (or tamper with) a workspace file behind the Workspace class's back.
#include <bit>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <QByteArray>
#include <QFile>
#include <QString>

#include <sqlite3.h>

#include "store/workspace.h"

namespace bs::test {

inline bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same_bits(a[i], b[i])) return false;
  return true;
}

inline bool same_bits(const std::optional<double>& a, const std::optional<double>& b) {
  return a.has_value() == b.has_value() && (!a || same_bits(*a, *b));
}

// Every field, so a column that is written but not read back (or read from the wrong place) fails.
inline bool same_provenance(const Provenance& a, const Provenance& b) {
  return a.origin == b.origin && a.host == b.host && a.cpu_model == b.cpu_model && a.gpu_model == b.gpu_model &&
         a.os == b.os && a.compiler == b.compiler && a.tool == b.tool && a.git_revision == b.git_revision &&
         a.date == b.date && a.note == b.note && a.source_file == b.source_file && a.measurement == b.measurement &&
         a.sensor == b.sensor && a.settings == b.settings;
}

inline bool same_run(const FlopsRun& a, const FlopsRun& b) {
  if (a.platform != b.platform || a.device != b.device || a.device_kind != b.device_kind || a.backend != b.backend ||
      a.kernel != b.kernel || a.variant != b.variant || a.iterations != b.iterations || a.dims != b.dims ||
      !same_bits(a.reported_peak_flops, b.reported_peak_flops) ||
      !same_bits(a.theoretical_peak_flops, b.theoretical_peak_flops) || !same_provenance(a.provenance, b.provenance) ||
      a.samples.size() != b.samples.size())
    return false;
  for (std::size_t i = 0; i < a.samples.size(); ++i)
    if (a.samples[i].workers != b.samples[i].workers || !same_bits(a.samples[i].seconds, b.samples[i].seconds))
      return false;
  return true;
}

inline bool same_set(const ResultSet& a, const ResultSet& b) {
  if (a.platform != b.platform || a.device != b.device || a.device_kind != b.device_kind || a.backend != b.backend ||
      a.source_format != b.source_format || !same_provenance(a.provenance, b.provenance) ||
      a.measurements.size() != b.measurements.size())
    return false;
  for (std::size_t i = 0; i < a.measurements.size(); ++i) {
    const Measurement& x = a.measurements[i];
    const Measurement& y = b.measurements[i];
    if (x.name != y.name || x.metric != y.metric || x.unit != y.unit || !same_bits(x.values, y.values) ||
        x.reported_aggregates.size() != y.reported_aggregates.size())
      return false;
    for (std::size_t k = 0; k < x.reported_aggregates.size(); ++k)
      if (x.reported_aggregates[k].first != y.reported_aggregates[k].first ||
          !same_bits(x.reported_aggregates[k].second, y.reported_aggregates[k].second))
        return false;
  }
  return true;
}

inline Provenance full_provenance(const std::string& tag) {
  Provenance p;
  p.origin = DataOrigin::Measured;
  p.host = "lab-" + tag;
  p.cpu_model = "Intel(R) Core(TM) i7-7567U CPU @ 3.50GHz";
  p.gpu_model = "Intel Iris Plus Graphics 650";
  p.os = "Debian GNU/Linux 12";
  p.compiler = "g++ 12.2.0";
  p.tool = "benchscope 0.1.0";
  p.git_revision = "0123abc";
  p.date = "2018-06-01T00:00:00Z";
  p.note =
      "\xC3\xBCn\xC3\xAF"
      "code, \"quotes\" and \\ backslash " +
      tag;
  p.source_file = tag + ".json";
  return p;
}

// `points` worker counts with `reps` repetitions each. Seconds are not monotonic within a point, so a store that
// sorted repetitions by value instead of keeping their order would be caught.
inline FlopsRun make_run(const std::string& device, const std::string& backend, int dims, int points, int reps) {
  FlopsRun r;
  r.platform = "NUC";
  r.device = device;
  r.device_kind = DeviceKind::Gpu;
  r.backend = backend;
  r.variant = "paper";
  r.iterations = 40000;
  r.dims = dims;
  r.reported_peak_flops = 0.88e12;
  r.provenance = full_provenance(device);
  for (int i = 0; i < points; ++i) {
    WorkerSample s{256 * (i + 1), {}};
    for (int k = 0; k < reps; ++k) s.seconds.push_back(1.0 / 3.0 + 1e-3 * i + 1e-7 * ((k * 7) % reps));
    r.samples.push_back(s);
  }
  return r;
}

// A small 8-bit Bayer frame, as the raw importer gives it, whose pixels (1, 2, 3, ...) the workspace keeps
// (FrameStorage::Copy): the frame the store tests put beside their other records.
inline Frame copied_frame(const std::string& label, int width, int height, const std::string& pattern = "RGGB") {
  Frame f;
  f.label = label;
  f.width = width;
  f.height = height;
  f.pattern = pattern;
  f.source_format = "raw-bayer";
  f.read_options = "{}";
  f.storage = FrameStorage::Copy;
  for (int i = 0; i < width * height; ++i) f.pixels.push_back(static_cast<std::uint8_t>(i + 1));
  return f;
}

// A batch of one kind's records (`kind`: &ImportBatch::runs, &ImportBatch::headroom, ...) as its importer hands it
// to the store: read from `source` in `format`, the two things an import row keeps of where it came from.
template <class Row>
ImportBatch batch_holding(std::vector<Row> ImportBatch::*kind, std::vector<Row> rows, const std::string& source,
                          const std::string& format) {
  ImportBatch b;
  b.source_path = source;
  b.format = format;
  b.*kind = std::move(rows);
  return b;
}

inline ImportBatch batch_of(std::vector<FlopsRun> runs, const std::string& path = "in.json") {
  return batch_holding(&ImportBatch::runs, std::move(runs), path, "benchscope-run-v1");
}

inline QByteArray file_bytes(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  return f.readAll();
}

inline bool write_file(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

// Raw SQLite access, independent of the code under test.
class RawDb {
 public:
  explicit RawDb(const std::string& path, bool read_only = true) {
    sqlite3_open_v2(path.c_str(), &db_, read_only ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE,
                    nullptr);
  }
  ~RawDb() { sqlite3_close(db_); }
  RawDb(const RawDb&) = delete;
  RawDb& operator=(const RawDb&) = delete;

  bool exec(const std::string& sql) { return sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr) == SQLITE_OK; }

  // First column of the first row as text; "<error>" when the statement fails.
  std::string scalar(const std::string& sql) {
    sqlite3_stmt* st = nullptr;
    std::string out = "<error>";
    if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &st, nullptr) == SQLITE_OK) {
      const int rc = sqlite3_step(st);
      if (rc == SQLITE_ROW) {
        const auto* t = sqlite3_column_text(st, 0);
        out = t ? reinterpret_cast<const char*>(t) : "";
      } else if (rc == SQLITE_DONE) {
        out.clear();
      }
    }
    sqlite3_finalize(st);
    return out;
  }

 private:
  sqlite3* db_ = nullptr;
};

// A workspace at `path` as an older BenchScope left it: written by this version, then `downgrade` (SQL that drops
// what the older one did not have and sets its user_version) run behind the Workspace class's back. Whether the SQL
// ran.
inline bool old_workspace(const std::string& path, const std::string& downgrade) {
  { bs::Workspace ws(path); }
  return RawDb(path, false).exec(downgrade);
}

inline const std::vector<std::string>& workspace_tables() {
  static const std::vector<std::string> tables = {"meta",         "imports",      "devices",
                                                  "runs",         "run_samples",  "result_sets",
                                                  "measurements", "power_traces", "power_channels"};
  return tables;
}

// Row count of every table: the strongest "nothing changed" check that does not go through Workspace.
inline std::map<std::string, std::string> row_counts(const std::string& path) {
  RawDb db(path);
  std::map<std::string, std::string> out;
  for (const std::string& t : workspace_tables()) out[t] = db.scalar("SELECT COUNT(*) FROM " + t);
  return out;
}

}  // namespace bs::test
