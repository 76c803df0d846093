// SPDX-License-Identifier: GPL-3.0-or-later
// The workspace as a file: what is opened, what is refused (and left untouched), how old schemas are migrated,
// and copies made with save_as.
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "store/workspace.h"
#include "workspace_test_support.h"

using namespace bs::test;
using Kind = bs::WorkspaceError::Kind;

namespace {

// A closed workspace with a few pages of data (and no -wal file left beside it).
QByteArray make_workspace_bytes(const QString& path) {
  {
    bs::Workspace ws(path.toStdString());
    ws.add_import(batch_of({make_run("A", "OpenCL", 4, 200, 3), make_run("B", "CUDA", 2, 100, 2)}), "h");
  }
  return file_bytes(path);
}

// Opening `path` must throw one of `kinds` and name the file; the file's bytes must be as before.
void expect_refused(const QString& path, std::initializer_list<Kind> kinds) {
  const QByteArray before = file_bytes(path);
  try {
    bs::Workspace ws(path.toStdString());
    // Some damage is only found when the data is read; that must also be an error, not a crash or garbage.
    ws.runs();
    ws.result_sets();
    ws.power_traces();
    ws.imports();
    QFAIL(qPrintable(path + " was accepted"));
  } catch (const bs::WorkspaceError& e) {
    QVERIFY2(std::find(kinds.begin(), kinds.end(), e.kind()) != kinds.end(), e.what());
    QVERIFY2(std::string(e.what()).find(path.toStdString()) != std::string::npos, e.what());
  }
  QVERIFY2(file_bytes(path) == before, qPrintable(path + " was modified"));
}

}  // namespace

class TestWorkspaceFiles : public QObject {
  Q_OBJECT
 private slots:
  void new_file_then_reopen() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("new.bsw").toStdString();
    QVERIFY(!QFile::exists(QString::fromStdString(path)));
    {
      bs::Workspace ws(path);
      QCOMPARE(ws.imports().size(), std::size_t{0});
      ws.add_import(batch_of({make_run("A", "OpenCL", 4, 3, 2)}), "h1");
    }
    {
      bs::Workspace ws(path);
      QCOMPARE(ws.runs().size(), std::size_t{1});
      ws.add_import(batch_of({make_run("B", "OpenCL", 4, 3, 2)}), "h2");
      bs::Workspace moved(std::move(ws));  // the handle moves, the file stays open
      QCOMPARE(moved.runs().size(), std::size_t{2});
    }
    const bs::Workspace ws(path);
    QCOMPARE(ws.imports().size(), std::size_t{2});
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }

  void empty_file_becomes_a_workspace() {
    // An existing empty file (e.g. made by a file dialog) is a new workspace, not a foreign file.
    QTemporaryDir dir;
    const QString path = dir.filePath("empty.bsw");
    QVERIFY(write_file(path, {}));
    bs::Workspace ws(path.toStdString());
    ws.add_import(batch_of({make_run("A", "OpenCL", 4, 1, 1)}), "h");
    QCOMPARE(RawDb(path.toStdString()).scalar("PRAGMA application_id"), std::to_string(0x42534350));
  }

  void rejects_foreign_files_without_touching_them() {
    QTemporaryDir dir;
    QByteArray random(8192, '\0');
    quint32 x = 12345;
    for (auto& c : random) c = static_cast<char>((x = x * 1664525u + 1013904223u) >> 24);
    const struct {
      const char* name;
      QByteArray bytes;
    } cases[] = {
        {"text.bsw", "hello, I am a text file\nwith two lines\n"}, {"random.bsw", random}, {"tiny.bsw", "SQLite"}};
    for (const auto& c : cases) {
      const QString path = dir.filePath(c.name);
      QVERIFY(write_file(path, c.bytes));
      expect_refused(path, {Kind::NotAWorkspace});
    }
  }

  void rejects_foreign_sqlite_database_without_touching_it() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("other.sqlite").toStdString();
    {
      RawDb other(path, false);
      QVERIFY(other.exec("CREATE TABLE t(x); INSERT INTO t VALUES (1);"));
    }
    expect_refused(QString::fromStdString(path), {Kind::NotAWorkspace});
    try {
      bs::Workspace ws(path);
    } catch (const bs::WorkspaceError& e) {
      QVERIFY2(std::string(e.what()).find("not a BenchScope workspace") != std::string::npos, e.what());
    }
    QCOMPARE(RawDb(path).scalar("SELECT COUNT(*) FROM sqlite_schema"), std::string("1"));  // still only its table
  }

  void rejects_damaged_workspaces_without_crashing() {
    QTemporaryDir dir;
    const QByteArray good = make_workspace_bytes(dir.filePath("good.bsw"));
    QVERIFY(good.size() > 8 * 4096);
    QByteArray garbage_after_header("SQLite format 3\0", 16);
    garbage_after_header += QByteArray(4080, '\x5a');
    QByteArray scrambled = good;  // page 1 intact, every later page overwritten
    for (qsizetype i = 4096; i < scrambled.size(); ++i) scrambled[i] = static_cast<char>(0xA5 ^ (i * 7));
    const struct {
      const char* name;
      QByteArray bytes;
    } cases[] = {{"garbage-after-header.bsw", garbage_after_header},
                 {"truncated-half.bsw", good.left(good.size() / 2)},
                 {"truncated-odd.bsw", good.left(good.size() - 1234)},
                 {"truncated-first-page.bsw", good.left(1000)},
                 {"truncated-header.bsw", good.left(50)},
                 {"scrambled.bsw", scrambled}};
    for (const auto& c : cases) {
      const QString path = dir.filePath(c.name);
      QVERIFY(write_file(path, c.bytes));
      expect_refused(path, {Kind::Corrupt, Kind::NotAWorkspace});
    }
  }

  void rejects_newer_schema_without_touching_it() {
    QTemporaryDir dir;
    const QString path = dir.filePath("future.bsw");
    make_workspace_bytes(path);
    QVERIFY(RawDb(path.toStdString(), false).exec("PRAGMA user_version = 99"));
    expect_refused(path, {Kind::NewerVersion});
    try {
      bs::Workspace ws(path.toStdString());
    } catch (const bs::WorkspaceError& e) {
      const std::string want = "was written by a newer BenchScope (schema 99, this build reads up to " +
                               std::to_string(bs::Workspace::kSchemaVersion) + ")";
      QVERIFY2(std::string(e.what()).find(want) != std::string::npos, e.what());
    }
  }

  void version_0_file_is_migrated() {
    // Version 0: an SQLite file that carries only the BenchScope application id, as the migration framework
    // defines it. Opening runs every migration in order.
    QTemporaryDir dir;
    const std::string path = dir.filePath("v0.bsw").toStdString();
    {
      RawDb v0(path, false);
      QVERIFY(v0.exec("PRAGMA application_id = " + std::to_string(0x42534350) + "; PRAGMA user_version = 0;"));
    }
    {
      bs::Workspace ws(path);
      QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
      ws.add_import(batch_of({make_run("A", "OpenCL", 4, 2, 2)}), "h");
    }
    RawDb raw(path);
    QCOMPARE(raw.scalar("PRAGMA user_version"), std::to_string(bs::Workspace::kSchemaVersion));
    for (const std::string& t : workspace_tables())
      QVERIFY2(raw.scalar("SELECT COUNT(*) FROM sqlite_schema WHERE type = 'table' AND name = '" + t + "'") == "1",
               t.c_str());
    QCOMPARE(raw.scalar("SELECT value FROM meta WHERE key = 'schema_version'"),
             std::to_string(bs::Workspace::kSchemaVersion));
    QVERIFY(!raw.scalar("SELECT value FROM meta WHERE key = 'created_at'").empty());
    QCOMPARE(raw.scalar("PRAGMA foreign_key_check"), std::string());
  }

  void version_1_file_is_migrated_with_its_runs() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("v1.bsw").toStdString();
    const auto run = make_run("A", "OpenCL", 4, 5, 3);
    {
      bs::Workspace ws(path);
      ws.add_import(batch_of({run}), "runs");
    }
    {
      // What a version-1 BenchScope left: no power tables, user_version 1.
      RawDb old(path, false);
      QVERIFY(old.exec("DROP TABLE power_channels; DROP TABLE power_traces; PRAGMA user_version = 1;"));
    }
    bs::Workspace ws(path);
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
    QCOMPARE(ws.runs().size(), std::size_t{1});
    QVERIFY(same_run(ws.runs()[0].run, run));
    bs::ImportBatch b;
    b.format = "power-csv";
    b.power_traces.push_back(
        {"NUC", "load", "", {0, 1}, {{"I", bs::PowerQuantity::Current, {2.5, 2.6}}}, 16.0, {}, {}, ""});
    ws.add_import(b, "trace");
    QCOMPARE(ws.power_traces().size(), std::size_t{1});
    QCOMPARE(RawDb(path).scalar("PRAGMA user_version"), std::to_string(bs::Workspace::kSchemaVersion));
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }

  void save_as_copies_everything_and_refuses_overwrite() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("a.bsw").toStdString());
    auto batch = batch_of({make_run("A", "OpenCL", 4, 10, 2), make_run("B", "CUDA", 1, 3, 1)});
    batch.result_sets.push_back(
        {"NUC", "B", bs::DeviceKind::Gpu, "OpenCL", "clpeak-text", {{"float", "bandwidth", "B/s", {3e10}, {}}}, {}});
    batch.power_traces.push_back(
        {"NUC", "idle", "", {0, 1}, {{"P", bs::PowerQuantity::Power, {9.5, 9.4}}}, {}, {}, {}, ""});
    ws.add_import(batch, "h1");
    const auto removed = ws.add_import(batch_of({make_run("C", "OpenCL", 4, 1, 1)}), "h2");
    ws.remove_import(removed);  // device C stays, with its colour
    const std::string copy = dir.filePath("b.bsw").toStdString();
    ws.save_as(copy);
    {
      const bs::Workspace b(copy);
      QCOMPARE(b.integrity_check(), std::string("ok"));
      const auto ra = ws.runs(), rb = b.runs();
      QCOMPARE(rb.size(), ra.size());
      for (std::size_t i = 0; i < ra.size(); ++i) {
        QVERIFY(same_run(rb[i].run, ra[i].run));
        QCOMPARE(rb[i].id, ra[i].id);
        QCOMPARE(rb[i].color_index, ra[i].color_index);
      }
      QCOMPARE(b.result_sets().size(), std::size_t{1});
      QVERIFY(same_set(b.result_sets()[0].set, ws.result_sets()[0].set));
      QCOMPARE(b.power_traces().size(), std::size_t{1});
      QVERIFY(same_bits(b.power_traces()[0].trace.channels[0].values, ws.power_traces()[0].trace.channels[0].values));
      const auto da = ws.devices(), db = b.devices();
      QCOMPARE(db.size(), std::size_t{3});
      for (std::size_t i = 0; i < da.size(); ++i) {
        QCOMPARE(db[i].device, da[i].device);
        QCOMPARE(db[i].color_index, da[i].color_index);
        QCOMPARE(db[i].kind, da[i].kind);
      }
      const auto ia = ws.imports(), ib = b.imports();
      QCOMPARE(ib.size(), std::size_t{1});
      QCOMPARE(ib[0].content_hash, ia[0].content_hash);
      QCOMPARE(ib[0].imported_at, ia[0].imported_at);
      QCOMPARE(ib[0].path, ia[0].path);
      QCOMPARE(RawDb(copy).scalar("PRAGMA application_id"), std::to_string(0x42534350));
    }
    QVERIFY(row_counts(copy) == row_counts(ws.path()));
    // The copy exists now: a second save_as there must fail and leave it as it is.
    const QByteArray copy_bytes = file_bytes(QString::fromStdString(copy));
    try {
      ws.save_as(copy);
      QFAIL("save_as overwrote a file");
    } catch (const bs::WorkspaceError& e) {
      QCOMPARE(e.kind(), Kind::Io);
      QVERIFY2(std::string(e.what()).find(copy) != std::string::npos, e.what());
    }
    QCOMPARE(file_bytes(QString::fromStdString(copy)), copy_bytes);
    const std::string nowhere = dir.filePath("no/such/dir/c.bsw").toStdString();
    try {
      ws.save_as(nowhere);
      QFAIL("save_as into a missing directory");
    } catch (const bs::WorkspaceError& e) {
      QVERIFY2(std::string(e.what()).find(nowhere) != std::string::npos, e.what());
    }
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }

  void integrity_check_reports_damage() {
    QTemporaryDir dir;
    const QString path = dir.filePath("w.bsw");
    make_workspace_bytes(path);
    {
      // Break an index behind SQLite's back: integrity_check must say so instead of "ok".
      RawDb raw(path.toStdString(), false);
      QVERIFY(
          raw.exec("PRAGMA writable_schema = ON; "
                   "UPDATE sqlite_schema SET sql = 'CREATE INDEX runs_by_import ON runs(dims)' "
                   "WHERE name = 'runs_by_import';"));
    }
    const bs::Workspace ws(path.toStdString());
    const std::string result = ws.integrity_check();
    QVERIFY2(result != "ok" && !result.empty(), result.c_str());
  }
};

QTEST_GUILESS_MAIN(TestWorkspaceFiles)
#include "test_workspace_files.moc"
