// SPDX-License-Identifier: GPL-3.0-or-later
// Pipeline runs in the workspace: every field comes back bit-exact (unknown statistics stay unknown), stages in
// pipeline order, removal cascades, and a version-2 workspace gains the tables on opening.
#include <QTemporaryDir>
#include <QTest>

#include "../../support/run_on.h"
#include "store/home_batch.h"
#include "store/workspace.h"
#include "workspace_test_support.h"

using namespace bs::test;

namespace {

bs::PipelineRun measured_run() {
  auto r = bs::test::run_on<bs::PipelineRun>("robot", "CPU (2 threads)", "cpu");
  r.demosaic = "mhc";
  r.detector = "hog";
  r.frame_width = 1280;
  r.frame_height = 1024;
  r.throughput_fps = 7.25;
  // Stored out of pipeline order on purpose: they must come back as preprocess, detect, end-to-end.
  r.stages = {{"end-to-end", 40, 0.150, 0.02, 0.11, 0.2, 0.149, 0.19},
              {"detect", 40, 0.140, 1.0 / 70, 0.1, 0.19, 0.139, 0.18},
              {"preprocess", 40, 0.00621, 0.00099, 0.005, 0.009, 0.0062, 0.0081}};
  r.provenance.origin = bs::DataOrigin::Measured;
  r.provenance.host = "robot-1";
  r.provenance.date = "2026-11-23T07:00:00Z";
  return r;
}

bs::PipelineRun reconstructed_run() {
  auto r = bs::test::run_on<bs::PipelineRun>("Jetson TX2", "Jetson GPU", "cuda");
  r.stages = {{"preprocess", 500, 0.00648, 0.00243, {}, {}, {}, {}}, {"detect", 500, 0.57, 1.10, {}, {}, {}, {}}};
  r.provenance.origin = bs::DataOrigin::Reconstructed;
  r.provenance.note = "reconstructed from the paper's reported figures";
  return r;
}

// Runs measured in-process on their way home as one import named `label`, the way benchscope-cli pipeline stores
// them (bring_home), under `hash`.
std::int64_t store_measured(bs::Workspace& ws, const std::vector<bs::PipelineRun>& runs, const std::string& label,
                            const std::string& hash) {
  bs::HomeBatch home;
  home.batch.source_path = label;
  home.batch.format = "benchscope-pipeline-v1";
  home.batch.pipeline_runs = runs;
  home.content_hash = hash;
  return bs::bring_home(ws, home);
}

bool same_stage(const bs::StageStats& a, const bs::StageStats& b) {
  return a.stage == b.stage && a.n == b.n && same_bits(a.mean_s, b.mean_s) && same_bits(a.sd_s, b.sd_s) &&
         same_bits(a.min_s, b.min_s) && same_bits(a.max_s, b.max_s) && same_bits(a.p50_s, b.p50_s) &&
         same_bits(a.p95_s, b.p95_s);
}

}  // namespace

class TestPipelineRunsStore : public QObject {
  Q_OBJECT
 private slots:
  void round_trip_keeps_every_field() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("w.bsw").toStdString();
    const bs::PipelineRun a = measured_run(), b = reconstructed_run();
    {
      bs::Workspace ws(path);
      bs::ImportBatch batch;
      batch.format = "benchscope-pipeline-v1";
      batch.source_path = "pipeline-jetson.json";
      batch.pipeline_runs = {b};
      ws.add_import(batch, "h-b");
      store_measured(ws, {a}, "benchscope-cli pipeline", "h-a");
    }
    const bs::Workspace ws(path);
    const auto runs = ws.pipeline_runs();
    QCOMPARE(runs.size(), std::size_t{2});
    // Ordered by platform: "Jetson TX2" < "robot".
    const bs::PipelineRun& jetson = runs[0].run;
    const bs::PipelineRun& robot = runs[1].run;
    QCOMPARE(jetson.platform, std::string("Jetson TX2"));
    QCOMPARE(robot.platform, std::string("robot"));
    QCOMPARE(robot.device, a.device);
    QCOMPARE(robot.backend, a.backend);
    QCOMPARE(robot.demosaic, a.demosaic);
    QCOMPARE(robot.detector, a.detector);
    QCOMPARE(robot.frame_width, 1280);
    QCOMPARE(robot.frame_height, 1024);
    QVERIFY(same_bits(robot.throughput_fps, a.throughput_fps));
    QVERIFY(same_provenance(robot.provenance, a.provenance));
    QCOMPARE(robot.stages.size(), std::size_t{3});
    QVERIFY(same_stage(robot.stages[0], a.stages[2]));
    QVERIFY(same_stage(robot.stages[1], a.stages[1]));
    QVERIFY(same_stage(robot.stages[2], a.stages[0]));
    QVERIFY(robot.stage("detect") == &robot.stages[1]);
    // A published mean and SD without the rest: unknown stays unknown, not zero.
    QVERIFY(!jetson.throughput_fps);
    QCOMPARE(jetson.stages.size(), std::size_t{2});
    QVERIFY(same_stage(jetson.stages[1], b.stages[1]));
    QVERIFY(!jetson.stages[0].p95_s);
    QCOMPARE(jetson.provenance.origin, bs::DataOrigin::Reconstructed);
    const auto imports = ws.imports();
    QCOMPARE(imports.size(), std::size_t{2});
    QCOMPARE(imports[1].format, std::string("benchscope-pipeline-v1"));
    QCOMPARE(imports[1].path, std::string("benchscope-cli pipeline"));
  }

  void same_content_twice_is_refused_and_removal_cascades() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    const auto id = store_measured(ws, {measured_run()}, "first", "same-hash");
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, store_measured(ws, {measured_run()}, "again", "same-hash"));
    QCOMPARE(ws.pipeline_runs().size(), std::size_t{1});
    ws.remove_import(id);
    QVERIFY(ws.pipeline_runs().empty());
    QCOMPARE(RawDb(ws.path()).scalar("SELECT COUNT(*) FROM pipeline_stages"), std::string("0"));
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }

  void bad_statistics_are_refused_whole() {
    QTemporaryDir dir;
    bs::Workspace ws(dir.filePath("w.bsw").toStdString());
    bs::PipelineRun bad = measured_run();
    bad.stages[1].n = 0;  // the schema's CHECK(n > 0)
    QVERIFY_THROWS_EXCEPTION(bs::WorkspaceError, store_measured(ws, {measured_run(), bad}, "bad", "h"));
    QVERIFY(ws.pipeline_runs().empty());  // the good run of the same import is not kept either
    QVERIFY(ws.imports().empty());
  }

  void version_2_workspace_gains_pipeline_tables() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("v2.bsw").toStdString();
    // What a version-2 BenchScope left: no pipeline tables, user_version 2.
    QVERIFY(old_workspace(path, "DROP TABLE pipeline_stages; DROP TABLE pipeline_runs; PRAGMA user_version = 2;"));
    bs::Workspace ws(path);
    QCOMPARE(ws.schema_version(), bs::Workspace::kSchemaVersion);
    QCOMPARE(RawDb(path).scalar("PRAGMA user_version"), std::to_string(bs::Workspace::kSchemaVersion));
    store_measured(ws, {reconstructed_run()}, "paper", "h");
    QCOMPARE(ws.pipeline_runs().size(), std::size_t{1});
    QCOMPARE(ws.integrity_check(), std::string("ok"));
  }
};

QTEST_GUILESS_MAIN(TestPipelineRunsStore)
#include "test_pipeline_runs_store.moc"
