// SPDX-License-Identifier: GPL-3.0-or-later
// dnn inference runs in the workspace: every field comes back as stored (unknown figures stay unknown), removal of
// the import removes them, and a version-5 workspace gains the table on opening.
#include <QTemporaryDir>
#include <QTest>

#include "../../support/run_on.h"
#include "store/workspace.h"
#include "workspace_test_support.h"

using namespace bs::test;

namespace {

bs::DnnRun architecture_run() {
  auto r = bs::test::run_on<bs::DnnRun>("robot", "CPU (2 OpenCV threads)", "cpu");
  r.model = "mobilenet-ssd";
  r.model_hash = "builtin:mobilenet-ssd:seed1";
  r.family = "SSD";
  r.architecture_only = true;
  r.input_width = r.input_height = 300;
  r.batch = 2;
  r.flops = 5'029'400'000;
  r.opencv_flops = 36'742'000'000;
  r.forward = {"inference", 20, 0.31, 0.012, 0.29, 0.35, 0.305, 0.33};
  r.device_peak_flops = 153.6e9;
  r.energy_per_inference_j = 4.25;
  r.mean_power_w = 27.4;
  r.provenance.origin = bs::DataOrigin::Measured;
  r.provenance.host = "robot-1";
  r.provenance.date = "2026-11-23T22:00:00Z";
  return r;
}

}  // namespace

class TestDnnRunsStore : public QObject {
  Q_OBJECT
 private slots:
  void round_trip_and_removal() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    bs::DnnRun unknown = architecture_run();
    unknown.model = "yolov8n.onnx";
    unknown.architecture_only = false;
    unknown.family = "YOLOv8";
    unknown.batch = 1;
    unknown.forward = {"inference", 5, 0.7, 0.05, {}, {}, {}, {}};
    unknown.device_peak_flops.reset();
    unknown.energy_per_inference_j.reset();
    unknown.mean_power_w.reset();
    bs::ImportBatch batch;
    batch.source_path = "bench dnn";
    batch.format = "benchscope-dnn-v1";
    batch.dnn_runs = {unknown, architecture_run()};
    const std::int64_t id = ws.add_import(batch, "hash-1");
    const auto runs = ws.dnn_runs();
    QCOMPARE(runs.size(), std::size_t{2});
    const bs::DnnRun& a = runs[0].run;  // ordered by model: mobilenet-ssd first
    const bs::DnnRun want = architecture_run();
    QCOMPARE(a.model, want.model);
    QCOMPARE(a.model_hash, want.model_hash);
    QVERIFY(a.architecture_only);
    QCOMPARE(a.batch, 2);
    QCOMPARE(a.flops, want.flops);
    QCOMPARE(a.opencv_flops, want.opencv_flops);
    QCOMPARE(a.forward.n, std::size_t{20});
    QCOMPARE(a.forward.mean_s, 0.31);
    QCOMPARE(*a.forward.p95_s, 0.33);
    QCOMPARE(*a.device_peak_flops, 153.6e9);
    QCOMPARE(*a.energy_per_inference_j, 4.25);
    QCOMPARE(a.provenance.host, std::string("robot-1"));
    QCOMPARE(a.inferences_per_s(), 2 / 0.31);
    const bs::DnnRun& b = runs[1].run;
    QCOMPARE(b.model, std::string("yolov8n.onnx"));
    QVERIFY(!b.architecture_only);
    QVERIFY(!b.forward.p50_s && !b.energy_per_inference_j && !b.device_peak_flops);
    ws.remove_import(id);
    QVERIFY(ws.dnn_runs().empty());
  }

  void impossible_values_are_refused_whole() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    bs::DnnRun bad = architecture_run();
    bad.forward.mean_s = 0;  // no forward pass takes no time
    bs::ImportBatch batch;
    batch.dnn_runs = {architecture_run(), bad};
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, ws.add_import(batch, "h"));
    QVERIFY(ws.dnn_runs().empty());
    QVERIFY(ws.imports().empty());
  }

  void version_5_workspace_gains_the_table() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("v5.bsw").toStdString();
    QVERIFY(old_workspace(path, "DROP TABLE dnn_runs; PRAGMA user_version = 5;"));
    bs::Workspace ws(path);
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
    bs::ImportBatch batch;
    batch.dnn_runs = {architecture_run()};
    ws.add_import(batch, "h");
    QCOMPARE(ws.dnn_runs().size(), std::size_t{1});
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }
};

QTEST_GUILESS_MAIN(TestDnnRunsStore)
#include "test_dnn_runs_store.moc"
