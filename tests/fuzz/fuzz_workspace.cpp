// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzing what a workspace holds (issue #37): the input's bytes are decoded into rows of the real schema (tables
// and columns as PRAGMA table_info lists them; ids and references small so rows link to each other; values of
// every SQLite type, raw doubles, JSON-ish text, BLOBs) inserted with foreign keys and CHECK constraints off, as a
// hand edit could. Then everything a user can do is done: open, every read, the samples, the pixels, `check`,
// removing the damage. A crash, an exception other than WorkspaceError, or a value read back that breaks the
// import rules (a negative, infinite or NaN quantity on its way to a view) is a finding.
// Same entry points as fuzz_importer.cpp (fuzz_importer.h), so replay_main.cpp replays its corpus.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <sqlite3.h>
#include <unistd.h>

#include "fuzz_importer.h"
#include "store/workspace.h"
#include "store/workspace_check.h"

namespace bs::fuzz {
namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "benchscope fuzz (workspace-rows): %s\n", what.c_str());
  std::abort();
}

std::string scratch_dir() {
  static const std::string dir = [] {
    const char* base = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    return std::string(base) + "/benchscope-fuzz-ws-" + std::to_string(getpid());
  }();
  return dir;
}

// A fresh workspace (the current schema) made once; each input starts from a copy of it.
const std::string& template_path() {
  static const std::string path = [] {
    std::filesystem::create_directories(scratch_dir());
    const std::string p = scratch_dir() + "/template.bsw";
    std::filesystem::remove(p);
    { const Workspace ws(p); }
    return p;
  }();
  return path;
}

class Bytes {
 public:
  Bytes(const std::uint8_t* p, std::size_t n) : p_(p), n_(n) {}
  bool done() const { return i_ >= n_; }
  std::uint8_t byte() { return i_ < n_ ? p_[i_++] : 0; }
  std::string take(std::size_t n) {
    n = std::min(n, n_ - std::min(i_, n_));
    std::string s(reinterpret_cast<const char*>(p_ + i_), n);
    i_ += n;
    return s;
  }
  std::int64_t int64() {
    std::int64_t v = 0;
    const std::string b = take(8);
    std::memcpy(&v, b.data(), b.size());
    return v;
  }
  double real() {
    double v = 0;
    const std::string b = take(8);
    std::memcpy(&v, b.data(), b.size());
    return v;
  }

 private:
  const std::uint8_t* p_;
  std::size_t n_, i_ = 0;
};

// Text that the decoders have a name for, so the fuzzer reaches past "unknown value" quickly.
const char* const kWords[] = {"",
                              "{}",
                              "[]",
                              "[1.5, \"nan\"]",
                              "[[\"mean\", 2]]",
                              "current",
                              "voltage",
                              "power",
                              "copy",
                              "reference",
                              "cpu",
                              "gpu",
                              "other",
                              "little",
                              "big",
                              "nan",
                              "inf",
                              "-1",
                              ("{\"n\": 2, \"mean\": 1, \"sd\": 0, \"min\": 1, \"max\": 1, \"p5\": 1, \"p50\": 1, "
                               "\"p95\": 1, \"p99\": 1, \"integral\": 1}"),
                              "preprocess",
                              "detect",
                              "end-to-end",
                              "[[[[[[[[[[[[[[[[[[[["};

const std::vector<std::string> kTables = {
    "imports",        "devices",      "runs",         "run_samples", "result_sets",   "measurements",    "power_traces",
    "power_channels", "power_phases", "power_chunks", "frames",      "pipeline_runs", "pipeline_stages", "dnn_runs"};

std::vector<std::string> columns_of(sqlite3* db, const std::string& table) {
  std::vector<std::string> cols;
  sqlite3_stmt* st = nullptr;
  sqlite3_prepare_v2(db, ("PRAGMA table_info(" + table + ")").c_str(), -1, &st, nullptr);
  while (sqlite3_step(st) == SQLITE_ROW) cols.emplace_back(reinterpret_cast<const char*>(sqlite3_column_text(st, 1)));
  sqlite3_finalize(st);
  return cols;
}

bool is_reference(const std::string& c) {
  return c == "id" || c == "series" || (c.size() > 3 && c.compare(c.size() - 3, 3, "_id") == 0);
}

void bind_value(sqlite3_stmt* st, int i, const std::string& column, Bytes& in) {
  if (is_reference(column)) {
    sqlite3_bind_int64(st, i, in.byte() % 4 + (column == "series" ? 0 : 1));
    return;
  }
  switch (in.byte() % 7) {
    case 0:
      sqlite3_bind_int64(st, i, static_cast<std::int8_t>(in.byte()));
      break;
    case 1:
      sqlite3_bind_int64(st, i, in.int64());
      break;
    case 2:
      sqlite3_bind_double(st, i, in.real());  // NaN becomes NULL in SQLite; infinities stay
      break;
    case 3:
      sqlite3_bind_text(st, i, kWords[in.byte() % std::size(kWords)], -1, SQLITE_STATIC);
      break;
    case 4: {
      const std::string s = in.take(in.byte() % 48);
      sqlite3_bind_text(st, i, s.data(), static_cast<int>(s.size()), SQLITE_TRANSIENT);
      break;
    }
    case 5: {
      const std::string s = in.take(in.byte() % 64);  // a BLOB: samples, an overview, pixels
      sqlite3_bind_blob(st, i, s.data(), static_cast<int>(s.size()), SQLITE_TRANSIENT);
      break;
    }
    default:
      sqlite3_bind_null(st, i);
  }
}

void write_rows(const std::string& path, Bytes& in) {
  sqlite3* db = nullptr;
  if (sqlite3_open(path.c_str(), &db) != SQLITE_OK) finding("cannot open the scratch workspace");
  sqlite3_exec(db, "PRAGMA foreign_keys = OFF; PRAGMA ignore_check_constraints = ON; BEGIN", nullptr, nullptr, nullptr);
  static std::map<std::string, std::vector<std::string>> columns;
  for (int rows = 0; rows < 64 && !in.done(); ++rows) {
    const std::string& table = kTables[in.byte() % kTables.size()];
    auto& cols = columns[table];
    if (cols.empty()) cols = columns_of(db, table);
    std::string names, marks;
    for (const std::string& c : cols) {
      names += (names.empty() ? "" : ", ") + c;
      marks += marks.empty() ? "?" : ", ?";
    }
    sqlite3_stmt* st = nullptr;
    if (sqlite3_prepare_v2(db, ("INSERT OR REPLACE INTO " + table + "(" + names + ") VALUES (" + marks + ")").c_str(),
                           -1, &st, nullptr) != SQLITE_OK)
      finding("cannot prepare an insert into " + table + ": " + sqlite3_errmsg(db));
    for (std::size_t k = 0; k < cols.size(); ++k) bind_value(st, static_cast<int>(k + 1), cols[k], in);
    sqlite3_step(st);  // a NOT NULL or UNIQUE violation just skips the row
    sqlite3_finalize(st);
  }
  sqlite3_exec(db, "COMMIT", nullptr, nullptr, nullptr);
  sqlite3_close(db);
}

void expect(bool ok, const std::string& what) {
  if (!ok) finding("read back: " + what);
}

bool finite_positive(double v) { return std::isfinite(v) && v > 0; }

// What the views compute from what was read must be a real, non-negative quantity.
void check_values(const Workspace& ws) {
  for (const StoredRun& r : ws.runs()) {
    expect(r.run.iterations > 0 && r.run.dims > 0, "run iterations/dims");
    for (const WorkerSample& s : r.run.samples) {
      expect(s.workers > 0, "run workers");
      for (const double t : s.seconds) {
        expect(finite_positive(t), "run seconds");
        const double flops =
            6.0 * r.run.dims * static_cast<double>(r.run.iterations) * static_cast<double>(s.workers) / t;
        expect(std::isfinite(flops) && flops > 0, "FLOPS of a run");
      }
    }
    if (r.run.reported_peak_flops) expect(finite_positive(*r.run.reported_peak_flops), "reported peak");
  }
  for (const StoredResultSet& s : ws.result_sets())
    for (const Measurement& m : s.set.measurements)
      for (const double v : m.values) expect(!std::isinf(v), "measurement value");
  for (const StoredPowerTrace& t : ws.power_traces()) {
    expect(t.trace.time_s.size() == t.summary.samples, "sample count");
    expect(std::isfinite(t.summary.duration_s) && t.summary.duration_s >= 0, "duration");
    if (t.trace.supply_voltage_v) expect(finite_positive(*t.trace.supply_voltage_v), "supply voltage");
    for (const double x : t.trace.time_s) expect(std::isfinite(x), "time");
    for (const PowerChannel& c : t.trace.channels) {
      expect(c.values.size() == t.summary.samples, "channel length");
      for (const double v : c.values) expect(!std::isinf(v), "channel value");
    }
    for (const ChannelSummary& c : t.summary.channels)
      expect(std::isfinite(c.stats.summary.mean) && c.stats.summary.sd >= 0, "channel summary");
    for (const TracePhase& p : t.trace.phases) expect(p.end_s >= p.start_s, "phase");
  }
  for (const StoredFrame& f : ws.frames()) {
    expect(f.frame.width > 0 && f.frame.height > 0 && (f.frame.channels == 1 || f.frame.channels == 3), "frame");
    try {
      const auto pixels = ws.frame_pixels(f.id);
      expect(pixels.empty() || pixels.size() == f.frame.expected_bytes(), "pixels");
    } catch (const WorkspaceError&) {
    }
  }
  for (const StoredPipelineRun& p : ws.pipeline_runs()) {
    if (p.run.throughput_fps) expect(finite_positive(*p.run.throughput_fps), "throughput");
    for (const StageStats& s : p.run.stages) expect(s.n > 0 && std::isfinite(s.mean_s) && s.mean_s >= 0, "stage");
  }
  for (const StoredDnnRun& d : ws.dnn_runs())
    expect(finite_positive(d.run.forward.mean_s) && std::isfinite(d.run.inferences_per_s()), "dnn run");
}

}  // namespace

const char* importer_id() { return "workspace-rows"; }

void run_one(const std::uint8_t* data, std::size_t size) {
  const std::string path = scratch_dir() + "/input.bsw";
  std::filesystem::remove(path);
  std::filesystem::remove(path + "-wal");
  std::filesystem::remove(path + "-shm");
  std::filesystem::copy_file(template_path(), path);
  Bytes in(data, size);
  write_rows(path, in);
  try {
    (void)check_workspace(path);
    Workspace ws(path);
    check_values(ws);
    for (const WorkspaceDamage& d : ws.damage())
      expect(!d.item.empty() && !d.reason.empty() && !d.table.empty(), "a damage entry without a name");
    if (!ws.damage().empty()) {
      ws.remove_damaged();
      expect(ws.damage().empty() && !ws.read_only(), "damage left after remove_damaged");
      check_values(ws);
    }
  } catch (const WorkspaceError&) {
    // A workspace that cannot be read at all (e.g. rows that make a table unreadable) is refused with a message.
  } catch (const std::exception& e) {
    finding(std::string("unexpected exception: ") + e.what());
  }
}

}  // namespace bs::fuzz

#ifdef BENCHSCOPE_LIBFUZZER
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  bs::fuzz::run_one(data, size);
  return 0;
}
#endif
