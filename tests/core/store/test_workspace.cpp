// SPDX-License-Identifier: GPL-3.0-or-later
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include "store/workspace.h"

namespace {

bs::FlopsRun make_run(const std::string& device, int dims, int points, int reps) {
  bs::FlopsRun r;
  r.platform = "NUC";
  r.device = device;
  r.device_kind = bs::DeviceKind::Gpu;
  r.backend = "OpenCL";
  r.variant = "paper";
  r.iterations = 40000;
  r.dims = dims;
  r.reported_peak_flops = 0.88e12;
  r.provenance.origin = bs::DataOrigin::Measured;
  r.provenance.host = "lab-pc";
  r.provenance.note = "ünïcode ok";
  r.provenance.source_file = "in.json";
  for (int i = 0; i < points; ++i) {
    bs::WorkerSample s{256 * (i + 1), {}};
    for (int k = 0; k < reps; ++k) s.seconds.push_back(0.1 + 1e-3 * i + 1e-7 * k + 1.0 / 3.0);
    r.samples.push_back(s);
  }
  return r;
}

bs::ImportBatch batch_of(std::vector<bs::FlopsRun> runs) {
  bs::ImportBatch b;
  b.source_path = "in.json";
  b.format = "benchscope-run-v1";
  b.runs = std::move(runs);
  return b;
}

QByteArray bytes_of(const QString& path) {
  QFile f(path);
  f.open(QIODevice::ReadOnly);
  return f.readAll();
}

}  // namespace

class TestWorkspace : public QObject {
  Q_OBJECT
 private slots:
  void round_trip_is_exact() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    const auto a = make_run("NUC GPU", 4, 50, 3);
    auto b = make_run("NUC GPU", 1, 5, 1);
    b.reported_peak_flops.reset();
    b.theoretical_peak_flops = 1.5e12;
    {
      bs::Workspace ws(path);
      QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
      ws.add_import(batch_of({a, b}), "hash1");
    }
    const bs::Workspace ws(path);  // reopen
    const auto runs = ws.runs();
    QCOMPARE(runs.size(), std::size_t{2});
    const auto& ra = runs[0].run.dims == 4 ? runs[0].run : runs[1].run;
    const auto& rb = runs[0].run.dims == 4 ? runs[1].run : runs[0].run;
    QCOMPARE(ra.samples.size(), a.samples.size());
    for (std::size_t i = 0; i < a.samples.size(); ++i) {
      QCOMPARE(ra.samples[i].workers, a.samples[i].workers);
      QVERIFY(ra.samples[i].seconds == a.samples[i].seconds);  // bit-exact doubles
    }
    QCOMPARE(*ra.reported_peak_flops, 0.88e12);
    QVERIFY(!rb.reported_peak_flops.has_value());
    QCOMPARE(*rb.theoretical_peak_flops, 1.5e12);
    QCOMPARE(ra.provenance.note, std::string("ünïcode ok"));
    QCOMPARE(ra.provenance.origin, bs::DataOrigin::Measured);
    QCOMPARE(ra.device_kind, bs::DeviceKind::Gpu);
    QCOMPARE(ws.imports().size(), std::size_t{1});
    QCOMPARE(ws.imports()[0].run_count, std::int64_t{2});
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }

  void result_sets_round_trip() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    bs::ImportBatch batch;
    batch.format = "clpeak-text";
    bs::ResultSet set;
    set.platform = "NVIDIA CUDA";
    set.device = "GTX 1080 Ti";
    set.device_kind = bs::DeviceKind::Gpu;
    set.backend = "OpenCL";
    set.source_format = "clpeak-text";
    set.measurements.push_back({"float4", "single-precision compute", "FLOP/s", {1.1e13, 1.2e13}, {{"mean", 1.15e13}}});
    batch.result_sets.push_back(set);
    ws.add_import(batch, "h");
    const auto sets = ws.result_sets();
    QCOMPARE(sets.size(), std::size_t{1});
    QCOMPARE(sets[0].set.measurements.size(), std::size_t{1});
    QVERIFY(sets[0].set.measurements[0].values == set.measurements[0].values);
    QCOMPARE(sets[0].set.measurements[0].reported_aggregates.size(), std::size_t{1});
    QCOMPARE(sets[0].set.measurements[0].reported_aggregates[0].second, 1.15e13);
  }

  void colours_are_stable_across_reopen_and_removal() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    std::int64_t first_import = 0;
    {
      bs::Workspace ws(path);
      first_import = ws.add_import(batch_of({make_run("A", 4, 2, 1)}), "h1");
      ws.add_import(batch_of({make_run("B", 4, 2, 1)}), "h2");
    }
    bs::Workspace ws(path);
    ws.remove_import(first_import);
    ws.add_import(batch_of({make_run("C", 4, 2, 1)}), "h3");
    const auto devices = ws.devices();
    QCOMPARE(devices.size(), std::size_t{3});
    QCOMPARE(devices[0].device, std::string("A"));
    QCOMPARE(devices[1].color_index, 1);
    QCOMPARE(devices[2].device, std::string("C"));
    QCOMPARE(devices[2].color_index, 2);
    QCOMPARE(ws.runs().size(), std::size_t{2});  // A's run went with its import
  }

  void duplicate_import_is_rejected_and_changes_nothing() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    ws.add_import(batch_of({make_run("A", 4, 3, 1)}), "same");
    try {
      ws.add_import(batch_of({make_run("B", 4, 3, 1)}), "same");
      QFAIL("duplicate accepted");
    } catch (const bs::WorkspaceError& e) {
      QCOMPARE(e.kind(), bs::WorkspaceError::Kind::Constraint);
      QVERIFY(std::string(e.what()).find("in.json") != std::string::npos);
    }
    QCOMPARE(ws.runs().size(), std::size_t{1});
    QCOMPARE(ws.devices().size(), std::size_t{1});
  }

  void cancelled_import_leaves_nothing() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    bs::CancelToken cancel;
    cancel.cancel();
    QVERIFY_THROWS_EXCEPTION(bs::Cancelled, ws.add_import(batch_of({make_run("A", 4, 2000, 2)}), "h", &cancel));
    QCOMPARE(ws.runs().size(), std::size_t{0});
    QCOMPARE(ws.imports().size(), std::size_t{0});
    QCOMPARE(ws.devices().size(), std::size_t{0});
    ws.add_import(batch_of({make_run("A", 4, 2, 1)}), "h");  // and the workspace still works
    QCOMPARE(ws.runs().size(), std::size_t{1});
  }

  void rejects_foreign_and_damaged_files_without_touching_them() {
    QTemporaryDir dir;
    struct Case {
      const char* name;
      QByteArray bytes;
      bs::WorkspaceError::Kind kind;
    };
    QByteArray garbage_db("SQLite format 3\0", 16);
    garbage_db += QByteArray(4080, '\x5a');
    const Case cases[] = {{"text.bsw", "hello, I am a text file\n", bs::WorkspaceError::Kind::NotAWorkspace},
                          {"random.bsw", QByteArray(4096, '\x07'), bs::WorkspaceError::Kind::NotAWorkspace},
                          {"garbage-db.bsw", garbage_db, bs::WorkspaceError::Kind::Corrupt}};
    for (const Case& c : cases) {
      const QString path = dir.filePath(c.name);
      QFile f(path);
      QVERIFY(f.open(QIODevice::WriteOnly));
      f.write(c.bytes);
      f.close();
      try {
        bs::Workspace ws(path.toStdString());
        QFAIL(c.name);
      } catch (const bs::WorkspaceError& e) {
        QCOMPARE(e.kind(), c.kind);
        QVERIFY2(std::string(e.what()).find(c.name) != std::string::npos, e.what());
      }
      QCOMPARE(bytes_of(path), c.bytes);
    }
  }

  void rejects_newer_schema_and_foreign_sqlite() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("new.bsw").toStdString();
    { bs::Workspace ws(path); }
    {
      // Simulate a future BenchScope by bumping the schema version with the sqlite3 C API via a raw workspace.
      QVERIFY(QProcess::execute("sqlite3", {QString::fromStdString(path), "PRAGMA user_version = 99;"}) == 0);
    }
    try {
      bs::Workspace ws(path);
      QFAIL("newer schema accepted");
    } catch (const bs::WorkspaceError& e) {
      QCOMPARE(e.kind(), bs::WorkspaceError::Kind::NewerVersion);
      QVERIFY(std::string(e.what()).find("newer") != std::string::npos);
    }
    const std::string other = dir.filePath("other.db").toStdString();
    QVERIFY(QProcess::execute("sqlite3", {QString::fromStdString(other), "CREATE TABLE t(x);"}) == 0);
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::Workspace{other});
  }

  void save_as_copies_and_refuses_overwrite() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("a.bsw").toStdString());
    ws.add_import(batch_of({make_run("A", 4, 10, 2)}), "h");
    const std::string copy = dir.filePath("b.bsw").toStdString();
    ws.save_as(copy);
    const bs::Workspace b(copy);
    QCOMPARE(b.runs().size(), std::size_t{1});
    QVERIFY(b.runs()[0].run.samples[3].seconds == ws.runs()[0].run.samples[3].seconds);
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, ws.save_as(copy));
  }

  void power_traces_round_trip_and_v1_migrates() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    bs::PowerTrace t;
    t.platform = "NUC";
    t.label = "load";
    t.supply_voltage_v = 16;
    t.time_s = {0, 0.1, 0.25};
    t.channels.push_back({"current_A", bs::PowerQuantity::Current, {2.5, 2.6, 1.0 / 3.0}});
    t.channels.push_back({"power_W", bs::PowerQuantity::Power, {40, 41.6, 16.0 / 3.0}});
    t.provenance.origin = bs::DataOrigin::Reconstructed;
    {
      bs::Workspace ws(path);
      ws.add_import(batch_of({make_run("A", 4, 2, 1)}), "runs");
      // Make it a version-1 workspace, as an older BenchScope left it: no power tables, user_version 1.
      QCOMPARE(QProcess::execute("sqlite3", {QString::fromStdString(path),
                                             "DROP TABLE power_channels; DROP TABLE power_traces; PRAGMA user_version = 1;"}),
               0);
    }
    bs::Workspace ws(path);  // migrates 1 -> 2 and keeps the data
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
    QCOMPARE(ws.runs().size(), std::size_t{1});
    bs::ImportBatch b;
    b.format = "power-csv";
    b.power_traces.push_back(t);
    ws.add_import(b, "trace");
    const auto traces = ws.power_traces();
    QCOMPARE(traces.size(), std::size_t{1});
    const bs::PowerTrace& r = traces[0].trace;
    QCOMPARE(r.platform, std::string("NUC"));
    QCOMPARE(*r.supply_voltage_v, 16.0);
    QVERIFY(r.time_s == t.time_s);
    QCOMPARE(r.channels.size(), std::size_t{2});
    QVERIFY(r.channels[0].values == t.channels[0].values);  // bit-exact
    QCOMPARE(r.channels[1].quantity, bs::PowerQuantity::Power);
    QCOMPARE(r.provenance.origin, bs::DataOrigin::Reconstructed);
    ws.remove_import(traces[0].import_id);
    QCOMPARE(ws.power_traces().size(), std::size_t{0});
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }

  void content_hash_depends_on_bytes() {
    QTemporaryDir dir;
    auto write = [&](const char* name, const char* text) {
      QFile f(dir.filePath(name));
      f.open(QIODevice::WriteOnly);
      f.write(text);
      return dir.filePath(name).toStdString();
    };
    const auto h1 = bs::file_content_hash(write("a", "abc"));
    QCOMPARE(h1.size(), std::size_t{16});
    QCOMPARE(bs::file_content_hash(write("b", "abc")), h1);
    QVERIFY(bs::file_content_hash(write("c", "abd")) != h1);
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, bs::file_content_hash(dir.filePath("missing").toStdString()));
  }
};

QTEST_GUILESS_MAIN(TestWorkspace)
#include "test_workspace.moc"
