// SPDX-License-Identifier: GPL-3.0-or-later
// Removing an import can be undone: the snapshot taken before removal restores the same content (runs, result
// sets, power logs with phases and missing samples, pipeline runs, frame pixels, inference runs, headroom
// measurements). Renames from the workspace tree.
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <limits>

#include "../../support/headroom_samples.h"
#include "../../support/sample_records.h"
#include "headroom/headroom_json.h"
#include "store/import_snapshot.h"
#include "workspace_test_support.h"

using namespace bs;
using namespace bs::test;

class TestImportSnapshot : public QObject {
  Q_OBJECT
 private slots:
  void remove_then_restore_gives_back_everything() {
    QTemporaryDir dir;
    Workspace ws(dir.filePath("w.bsw").toStdString());
    ImportBatch batch = batch_of({make_run("NUC GPU", "OpenCL", 4, 5, 3), make_run("NUC CPU", "CPU SIMD", 1, 3, 2)});
    PowerTrace trace;
    trace.platform = "NUC";
    trace.label = "load";
    trace.time_s = {0, 0.5, 1.0, 1.5};
    trace.channels = {{"current", PowerQuantity::Current, {2.0, std::numeric_limits<double>::quiet_NaN(), 2.5, 2.25}}};
    trace.supply_voltage_v = 16.0;
    trace.phases = {{"kernel", 0.5, 1.5}};
    batch.power_traces.push_back(trace);
    const Frame frame = copied_frame("cap", 4, 2);
    batch.frames.push_back(frame);
    const std::int64_t id = ws.add_import(batch, "hash-1");
    const auto runs_before = ws.runs();
    const auto frames_before = ws.frames();

    const ImportSnapshot snap = snapshot_import(ws, id);
    QCOMPARE(snap.batch.runs.size(), std::size_t{2});
    QCOMPARE(snap.batch.power_traces.size(), std::size_t{1});
    QCOMPARE(snap.batch.frames.size(), std::size_t{1});
    ws.remove_import(id);
    QVERIFY(ws.runs().empty() && ws.power_traces().empty() && ws.frames().empty());

    QVERIFY(restore_import(ws, snap) > 0);
    const auto runs = ws.runs();
    QCOMPARE(runs.size(), runs_before.size());
    for (std::size_t i = 0; i < runs.size(); ++i) QVERIFY(same_run(runs[i].run, runs_before[i].run));
    const auto traces = ws.power_traces();
    QCOMPARE(traces.size(), std::size_t{1});
    QVERIFY(same_bits(traces[0].trace.time_s, trace.time_s));
    QVERIFY(same_bits(traces[0].trace.channels.at(0).values, trace.channels[0].values));  // NaN stays missing
    QCOMPARE(traces[0].trace.phases.size(), std::size_t{1});
    QCOMPARE(traces[0].trace.phases[0].name, std::string("kernel"));
    const auto frames = ws.frames();
    QCOMPARE(frames.size(), std::size_t{1});
    QCOMPARE(frames[0].frame.label, std::string("cap"));
    QCOMPARE(ws.frame_pixels(frames[0].id), frame.pixels);
    QCOMPARE(ws.imports().size(), std::size_t{1});
    QCOMPARE(ws.imports()[0].content_hash, std::string("hash-1"));
    QVERIFY_THROWS_EXCEPTION(WorkspaceError, snapshot_import(ws, 12345));
  }

  // Undoing the removal of an import gave back its runs and logs but dropped its inference runs and headroom
  // measurements (the snapshot did not take them).
  void inference_runs_and_headroom_come_back() {
    QTemporaryDir dir;
    Workspace ws(dir.filePath("w.bsw").toStdString());
    ImportBatch batch;
    batch.source_path = "robot job";
    batch.format = "benchscope-headroom-v1";
    batch.dnn_runs.push_back(bs::test::sample_inference_run("robot"));
    batch.headroom.push_back(
        loop_measurement("robot", {{"idle", loop_thread(500, 40)}, {"pipeline@30fps", loop_thread(500, 60, {1500})}}));
    const std::int64_t id = ws.add_import(batch, "hash-h");
    const auto headroom_before = ws.headroom_measurements();
    QCOMPARE(headroom_before.size(), std::size_t{1});
    const ImportSnapshot snap = snapshot_import(ws, id);
    QCOMPARE(snap.batch.dnn_runs.size(), std::size_t{1});
    QCOMPARE(snap.batch.headroom.size(), std::size_t{1});
    ws.remove_import(id);
    QVERIFY(ws.dnn_runs().empty() && ws.headroom_measurements().empty());
    QVERIFY(restore_import(ws, snap) > 0);
    QCOMPARE(ws.dnn_runs().size(), std::size_t{1});
    QCOMPARE(ws.dnn_runs()[0].run.model, std::string("mobilenet-ssd"));
    const auto headroom_after = ws.headroom_measurements();
    QCOMPARE(headroom_after.size(), std::size_t{1});
    QCOMPARE(headroom_after[0].measurement.phases.size(), std::size_t{2});
    QCOMPARE(headroom::to_json(headroom_after[0].measurement).dump(),
             headroom::to_json(headroom_before[0].measurement).dump());
  }

  void renames() {
    QTemporaryDir dir;
    Workspace ws(dir.filePath("w.bsw").toStdString());
    ImportBatch batch = batch_of({make_run("NUC GPU", "OpenCL", 4, 5, 3)});
    PowerTrace trace;
    trace.platform = "NUC";
    trace.label = "log";
    trace.time_s = {0, 1};
    trace.channels = {{"current", PowerQuantity::Current, {1.0, 1.0}}};
    batch.power_traces.push_back(trace);
    ws.add_import(batch, "h");
    const std::string platform = ws.runs().at(0).run.platform;
    ws.rename_power_trace(ws.power_traces().at(0).id, "idle, lid closed");
    QCOMPARE(ws.power_traces().at(0).trace.label, std::string("idle, lid closed"));
    QVERIFY_THROWS_EXCEPTION(WorkspaceError, ws.rename_power_trace(ws.power_traces().at(0).id, "  "));
    QVERIFY_THROWS_EXCEPTION(WorkspaceError, ws.rename_power_trace(9999, "x"));
    ws.rename_platform(platform, "RobotPC");
    QCOMPARE(ws.runs().at(0).run.platform, std::string("RobotPC"));
    QCOMPARE(ws.devices().at(0).platform, std::string("RobotPC"));
    QVERIFY_THROWS_EXCEPTION(WorkspaceError, ws.rename_platform("nobody", "x"));
    // A rename that would merge two devices' runs is refused, and nothing changes.
    ws.add_import(batch_of({make_run("NUC GPU", "OpenCL", 1, 3, 1)}, "b.json"), "h2");
    try {
      ws.rename_platform("NUC", "RobotPC");  // both have a device "NUC GPU"
      QFAIL("merged");
    } catch (const WorkspaceError& e) {
      QVERIFY2(QString(e.what()).contains("merge"), e.what());
    }
    QCOMPARE(ws.devices().size(), std::size_t{2});
  }
};

QTEST_GUILESS_MAIN(TestImportSnapshot)
#include "test_import_snapshot.moc"
