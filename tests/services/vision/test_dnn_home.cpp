// SPDX-License-Identifier: GPL-3.0-or-later
// One way home for inference runs measured in-process (#52): `benchscope-cli bench dnn --workspace` stores the
// runs of one bench (a network on each target) and the power trace recorded beside them as one import built by
// dnn_home, so the same bench stored again is refused.
#include <QTest>

#include "../../support/home_checks.h"
#include "vision/dnn_home.h"

using namespace bs;

namespace {

// One network on one target as bench dnn measures it.
DnnRun inference_run(const std::string& backend, double mean_s) {
  return {.platform = "robot-nuc",
          .device = backend == "cpu" ? "CPU (8 OpenCV threads)" : "Intel UHD Graphics 620",
          .backend = backend,
          .model = "mobilenet-ssd",
          .model_hash = "builtin:mobilenet-ssd:seed1",
          .family = "SSD",
          .architecture_only = true,
          .input_width = 300,
          .input_height = 300,
          .flops = 2'514'700'000,
          .forward = {"inference", 20, mean_s, 0.002, mean_s - 0.004, mean_s + 0.006, mean_s, mean_s + 0.004},
          .device_peak_flops = {},
          .energy_per_inference_j = {},
          .mean_power_w = {},
          .provenance = test::measured_on_robot()};
}

std::vector<DnnRun> bench(double cpu_mean_s) {
  return {inference_run("cpu", cpu_mean_s), inference_run("opencl", 0.021)};
}

}  // namespace

class TestDnnHome : public QObject {
  Q_OBJECT
 private slots:
  void the_same_bench_is_one_import() {
    test::same_measurement_is_one_import(dnn_home(bench(0.031), std::nullopt, "benchscope-cli bench dnn"),
                                         dnn_home(bench(0.031), std::nullopt, "benchscope-cli bench dnn"));
    QVERIFY(dnn_home(bench(0.031), std::nullopt, "benchscope-cli bench dnn").content_hash !=
            dnn_home(bench(0.032), std::nullopt, "benchscope-cli bench dnn").content_hash);
  }

  void the_batch_holds_every_run_of_the_bench() {
    const HomeBatch home = dnn_home(bench(0.031), std::nullopt, "benchscope-cli bench dnn");
    QCOMPARE(home.batch.format, std::string(kDnnFormat));
    QCOMPARE(home.batch.source_path, std::string("benchscope-cli bench dnn (robot-nuc, 2026-12-06T10:00:00Z)"));
    QCOMPARE(home.batch.dnn_runs.size(), std::size_t{2});
    QCOMPARE(home.batch.dnn_runs[1].backend, std::string("opencl"));
    QVERIFY(home.batch.power_traces.empty());
  }

  void the_power_trace_goes_home_with_the_runs() {
    test::trace_goes_home_with_it(
        dnn_home(bench(0.031), test::recorded_beside("bench dnn robot-nuc"), "benchscope-cli bench dnn"),
        [](const Workspace& ws) { return test::import_ids(ws.dnn_runs()); });
  }

  void a_bench_without_runs_is_refused() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, dnn_home({}, std::nullopt, "benchscope-cli bench dnn"));
  }
};

QTEST_APPLESS_MAIN(TestDnnHome)
#include "test_dnn_home.moc"
