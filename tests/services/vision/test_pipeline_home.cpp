// SPDX-License-Identifier: GPL-3.0-or-later
// One way home for a vision pipeline run measured in-process (#52): the Pipeline tab and `benchscope-cli pipeline
// --workspace` both build their import with pipeline_home, so the same run is one import whoever stored it, and the
// power trace recorded beside it ("Record power", --power) is part of that import.
#include <QTest>

#include "../../support/home_checks.h"
#include "runs/pipeline_json.h"
#include "vision/pipeline_home.h"

using namespace bs;

namespace {

// A synthetic-capture run as measure_synthetic_pipeline returns it.
PipelineRun measured_run(double detect_mean_s) {
  return {.platform = "robot-nuc",
          .device = "CPU (8 threads)",
          .backend = "cpu",
          .demosaic = "fused",
          .detector = "hog",
          .frame_width = 1280,
          .frame_height = 1024,
          .stages = {{"preprocess", 20, 0.0062, 0.001, 0.005, 0.009, 0.0062, 0.0081},
                     {"detect", 20, detect_mean_s, 0.014, 0.1, 0.19, 0.139, 0.18}},
          .throughput_fps = 7.25,
          .provenance = test::measured_on_robot()};
}

}  // namespace

class TestPipelineHome : public QObject {
  Q_OBJECT
 private slots:
  void the_pipeline_tab_and_the_cli_store_one_import() {
    test::same_measurement_is_one_import(pipeline_home(measured_run(0.14), std::nullopt, "Pipeline tab"),
                                         pipeline_home(measured_run(0.14), std::nullopt, "benchscope-cli pipeline"));
  }

  void the_batch_holds_the_run_under_its_pipeline_json_hash() {
    const HomeBatch home = pipeline_home(measured_run(0.14), std::nullopt, "Pipeline tab");
    QCOMPARE(home.content_hash, content_hash(write_pipeline_json(measured_run(0.14))));
    QVERIFY(home.content_hash != pipeline_home(measured_run(0.15), std::nullopt, "Pipeline tab").content_hash);
    QCOMPARE(home.batch.format, std::string(kPipelineJsonFormat));
    QCOMPARE(home.batch.source_path, std::string("Pipeline tab (robot-nuc, 2026-12-06T10:00:00Z)"));
    QCOMPARE(home.batch.pipeline_runs.size(), std::size_t{1});
    QCOMPARE(home.batch.pipeline_runs[0].stages.size(), std::size_t{2});
    QVERIFY(home.batch.power_traces.empty());
  }

  void the_power_trace_goes_home_with_the_run() {
    test::trace_goes_home_with_it(
        pipeline_home(measured_run(0.14), test::recorded_beside("pipeline robot-nuc cpu"), "benchscope-cli pipeline"),
        [](const Workspace& ws) { return test::import_ids(ws.pipeline_runs()); });
  }
};

QTEST_APPLESS_MAIN(TestPipelineHome)
#include "test_pipeline_home.moc"
