// SPDX-License-Identifier: GPL-3.0-or-later
// Schema 8 (issue #32): lenses saved per frame or per camera with how they were obtained, a log's platform,
// supply voltage and borrowed voltage channel, phase origins; and the migration of a version-7 file.
#include <QTemporaryDir>
#include <QTest>

#include "store/lens_store.h"
#include "store/log_settings_store.h"
#include "store/workspace.h"
#include "workspace_test_support.h"

using bs::test::RawDb;

namespace {

bs::PowerTrace current_log(const std::string& label) {
  bs::PowerTrace t;
  t.label = label;
  t.time_s = {0, 1, 2, 3};
  t.channels.push_back({"I", bs::PowerQuantity::Current, {1.0, 1.5, 2.0, 1.0}});
  t.phases.push_back({"load", 1, 2});
  return t;
}

bs::PowerTrace voltage_log() {
  bs::PowerTrace t;
  t.label = "bench supply";
  t.platform = "NUC";
  t.time_s = {0, 2, 4};
  t.channels.push_back({"V_out", bs::PowerQuantity::Voltage, {12.0, 12.2, 12.4}});
  return t;
}

// Two logs and two frames in one import.
void fill(bs::Workspace& ws) {
  bs::ImportBatch b;
  b.source_path = "in.csv";
  b.format = "power-csv";
  b.power_traces = {current_log("otii"), voltage_log()};
  b.frames = {bs::test::copied_frame("a", 4, 2, "BGGR"), bs::test::copied_frame("b", 4, 2, "BGGR")};
  ws.add_import(b, "hash-1");
}

}  // namespace

class TestWorkspaceV8 : public QObject {
  Q_OBJECT
 private slots:
  void lens_per_frame_and_camera_survive_reopen() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    std::int64_t a = 0, b = 0;
    {
      bs::Workspace ws(path);
      fill(ws);
      a = ws.frames()[0].id;
      b = ws.frames()[1].id;
      QCOMPARE(bs::camera_key(ws.frames()[0].frame), std::string("4x2 BGGR"));
      bs::save_lens(ws, {a, "", R"({"lens":1})", "checkerboard, 8 images, RMS 0.06 px", ""});
      bs::save_lens(ws, {0, "4x2 BGGR", R"({"lens":2})", "manual", ""});
      bs::save_lens(ws, {a, "", R"({"lens":3})", "line-fit", ""});  // replaces frame a's
      // Neither or both of frame and camera, an unknown frame, no JSON: refused.
      QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::save_lens(ws, {0, "", "{}", "", ""}));
      QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::save_lens(ws, {a, "4x2 BGGR", "{}", "", ""}));
      QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::save_lens(ws, {999, "", "{}", "", ""}));
      QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::save_lens(ws, {a, "", "", "", ""}));
    }
    bs::Workspace ws(path);
    const auto all = bs::saved_lenses(ws);
    QCOMPARE(all.size(), std::size_t{2});
    QCOMPARE(all[0].frame_id, a);
    QCOMPARE(all[0].lens_json, std::string(R"({"lens":3})"));
    QCOMPARE(all[0].obtained, std::string("line-fit"));
    QVERIFY(!all[0].saved_at.empty());
    QVERIFY(all[1].for_camera());
    QCOMPARE(all[1].camera, std::string("4x2 BGGR"));
    // Frame a has its own; frame b falls back to its camera's.
    QCOMPARE(bs::saved_lens_for(ws, ws.frames()[0])->lens_json, std::string(R"({"lens":3})"));
    QCOMPARE(bs::saved_lens_for(ws, ws.frames()[1])->lens_json, std::string(R"({"lens":2})"));
    bs::remove_lens(ws, 0, "4x2 BGGR");
    QVERIFY(!bs::saved_lens_for(ws, ws.frames()[1]));
    QVERIFY(!bs::find_lens(ws, b, {}));
    // Removing the frame's import removes its lens with it.
    ws.remove_import(ws.imports()[0].id);
    QVERIFY(bs::saved_lenses(ws).empty());
  }

  void log_settings_are_checked_and_kept() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    std::int64_t otii = 0, supply = 0;
    {
      bs::Workspace ws(path);
      fill(ws);
      otii = ws.power_trace_summaries()[0].id;
      supply = ws.power_trace_summaries()[1].id;
      bs::set_trace_platform(ws, otii, "Jetson TX2");
      QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::set_trace_platform(ws, otii, "  "));
      QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::set_trace_platform(ws, 999, "x"));
      bs::set_trace_supply_voltage(ws, otii, 16.0);
      QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::set_trace_supply_voltage(ws, otii, -1.0));
      QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, bs::set_trace_supply_voltage(ws, otii, 0.0));
      bs::set_trace_voltage_source(ws, otii, bs::VoltageSource{supply, "V_out"});
      QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError,
                               bs::set_trace_voltage_source(ws, otii, bs::VoltageSource{otii, "I"}));
      QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError,
                               bs::set_trace_voltage_source(ws, otii, bs::VoltageSource{supply, "missing"}));
      bs::add_user_phase(ws, otii, {"my range", 0.5, 2.5});
    }
    bs::Workspace ws(path);
    const auto traces = ws.power_trace_summaries();
    QCOMPARE(traces[0].trace.platform, std::string("Jetson TX2"));
    QCOMPARE(*traces[0].trace.supply_voltage_v, 16.0);
    QCOMPARE(*bs::trace_voltage_source(ws, otii), (bs::VoltageSource{supply, "V_out"}));
    QVERIFY(!bs::trace_voltage_source(ws, supply));
    // Phases by start: the user's range (0.5 s) before the log's "load" (1 s).
    QCOMPARE(traces[0].trace.phases.size(), std::size_t{2});
    QCOMPARE(traces[0].trace.phases[0].name, std::string("my range"));
    QCOMPARE(bs::phase_origins(ws, otii), (std::vector<std::string>{"user", "log"}));
    bs::set_trace_supply_voltage(ws, otii, std::nullopt);
    bs::set_trace_voltage_source(ws, otii, std::nullopt);
    QVERIFY(!ws.power_trace_summaries()[0].trace.supply_voltage_v);
    QVERIFY(!bs::trace_voltage_source(ws, otii));
  }

  void version_7_file_is_migrated() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w7.bsw").toStdString();
    {
      bs::Workspace ws(path);
      fill(ws);
    }
    {
      // What a version-7 BenchScope left: no lenses table, none of the new columns, user_version 7.
      RawDb old(path, false);
      QVERIFY(old.exec("DROP TABLE lenses"));
      QVERIFY(old.exec("ALTER TABLE power_traces DROP COLUMN voltage_trace_id"));
      QVERIFY(old.exec("ALTER TABLE power_traces DROP COLUMN voltage_channel"));
      QVERIFY(old.exec("ALTER TABLE power_phases DROP COLUMN origin"));
      QVERIFY(old.exec("PRAGMA user_version = 7"));
      QCOMPARE(old.scalar("SELECT COUNT(*) FROM pragma_table_info('power_phases') WHERE name = 'origin'"),
               std::string("0"));
    }
    bs::Workspace ws(path);
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);  // migrated through 8 to the current version
    QCOMPARE(RawDb(path).scalar("PRAGMA user_version"), std::to_string(bs::Workspace::kSchemaVersion));
    // The data is all there; the phases that came with the file are the log's; nothing is borrowed; lenses save.
    const auto traces = ws.power_trace_summaries();
    QCOMPARE(traces.size(), std::size_t{2});
    QCOMPARE(bs::phase_origins(ws, traces[0].id), (std::vector<std::string>{"log"}));
    QVERIFY(!bs::trace_voltage_source(ws, traces[0].id));
    QVERIFY(bs::saved_lenses(ws).empty());
    bs::save_lens(ws, {ws.frames()[0].id, "", "{}", "manual", ""});
    QCOMPARE(bs::saved_lenses(ws).size(), std::size_t{1});
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }
};

QTEST_GUILESS_MAIN(TestWorkspaceV8)
#include "test_workspace_v8.moc"
