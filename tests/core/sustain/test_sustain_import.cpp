// SPDX-License-Identifier: GPL-3.0-or-later
// One way home for a sustained run measured in-process (#52): the Sustained tab and `benchscope-cli sustain
// --workspace` build their import with sustain_import, so the same run is one import whoever stored it, and the
// power trace recorded beside it is part of that import.
#include <QTest>

#include "../../support/home_checks.h"
#include "sustain/sustain_import.h"
#include "sustain/sustain_json.h"

using namespace bs;
using namespace bs::sustain;

namespace {

// Three intervals of the flops load with one clock and one temperature, as run_sustain returns them.
SustainRun sustained_run(double last_rate) {
  return {.platform = "robot-nuc",
          .label = "flops for 3 s",
          .load = "flops",
          .rate_unit = "GFLOPS",
          .interval_s = 1,
          .t_s = {1.0, 2.0, 3.0},
          .rate = {10.5, 10.0, last_rate},
          .clocks = {{"cpu0", 3e9, {3e9, 2e9, 1.8e9}}},
          .temperatures = {{"thermal_zone0 x86_pkg_temp", 95.0, {60, 70, 97}}},
          .power_w = {},
          .power_sensor = {},
          .not_exposed = {},
          .provenance = test::measured_on_robot()};
}

}  // namespace

class TestSustainImport : public QObject {
  Q_OBJECT
 private slots:
  void the_sustained_tab_and_the_cli_store_one_import() {
    test::same_measurement_is_one_import(sustain_import(sustained_run(9.5), std::nullopt, "Sustained tab"),
                                         sustain_import(sustained_run(9.5), std::nullopt, "benchscope-cli sustain"));
  }

  void the_batch_holds_the_run_under_its_record_hash() {
    const HomeBatch home = sustain_import(sustained_run(9.5), std::nullopt, "Sustained tab");
    QCOMPARE(home.content_hash, content_hash(record_to_json(sustained_run(9.5)).dump()));
    QVERIFY(home.content_hash != sustain_import(sustained_run(9.0), std::nullopt, "Sustained tab").content_hash);
    QCOMPARE(home.batch.format, std::string(kSustainFormat));
    QCOMPARE(home.batch.source_path, std::string("Sustained tab (robot-nuc, 2026-12-06T10:00:00Z)"));
    QCOMPARE(home.batch.sustain_runs.size(), std::size_t{1});
    QVERIFY(home.batch.power_traces.empty());
  }

  void the_power_trace_goes_home_with_the_run() {
    test::trace_goes_home_with_it(
        sustain_import(sustained_run(9.5), test::recorded_beside("sustain flops"), "benchscope-cli sustain"),
        [](const Workspace& ws) { return test::import_ids(ws.sustain_runs()); });
  }
};

QTEST_APPLESS_MAIN(TestSustainImport)
#include "test_sustain_import.moc"
