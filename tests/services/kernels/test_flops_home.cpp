// SPDX-License-Identifier: GPL-3.0-or-later
// One way home for a FLOPS sweep measured in-process (#52): the Kernel Runner (MainWindow::store_measured_runs) and
// `benchscope-cli run flops --workspace` both build their import with flops_home, so the same sweep is one import
// whoever stored it, and the power trace recorded beside it is part of that import.
#include <QTest>

#include "../../support/home_checks.h"
#include "kernels/flops_home.h"
#include "runs/run_json.h"

using namespace bs;

namespace {

// A two-point sweep as run_sweep returns it: one repeat timing per worker count.
std::vector<FlopsRun> sweep(double first_seconds) {
  FlopsRun r;
  r.platform = "robot-nuc";
  r.device = "Intel Core i7-8650U";
  r.device_kind = DeviceKind::Cpu;
  r.backend = "CPU SIMD (AVX2)";
  r.samples = {{1, {first_seconds, 0.51}}, {2, {0.52, 0.53}}};
  r.provenance = test::measured_on_robot();
  return {r};
}

}  // namespace

class TestFlopsHome : public QObject {
  Q_OBJECT
 private slots:
  void the_kernel_runner_and_run_flops_store_one_import() {
    test::same_measurement_is_one_import(flops_home(sweep(0.5), std::nullopt, "Kernel Runner"),
                                         flops_home(sweep(0.5), std::nullopt, "benchscope-cli run flops"));
  }

  void the_batch_holds_the_runs_under_their_run_json_hash() {
    const HomeBatch home = flops_home(sweep(0.5), std::nullopt, "Kernel Runner");
    QCOMPARE(home.content_hash, content_hash(write_run_json(sweep(0.5))));
    QVERIFY(home.content_hash != flops_home(sweep(0.25), std::nullopt, "Kernel Runner").content_hash);
    QCOMPARE(home.batch.format, std::string("benchscope-run-v1"));
    QCOMPARE(home.batch.source_path, std::string("Kernel Runner (robot-nuc, 2026-12-06T10:00:00Z)"));
    QCOMPARE(home.batch.runs.size(), std::size_t{1});
    QCOMPARE(home.batch.runs[0].samples[0].seconds[0], 0.5);
    QVERIFY(home.batch.power_traces.empty());
  }

  void the_power_trace_goes_home_with_the_runs() {
    test::trace_goes_home_with_it(flops_home(sweep(0.5), test::recorded_beside("Kernel Runner CPU"), "Kernel Runner"),
                                  [](const Workspace& ws) { return test::import_ids(ws.runs()); });
  }

  void a_sweep_without_runs_is_refused() {
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, flops_home({}, std::nullopt, "benchscope-cli run flops"));
  }
};

QTEST_APPLESS_MAIN(TestFlopsHome)
#include "test_flops_home.moc"
