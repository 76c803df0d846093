// SPDX-License-Identifier: GPL-3.0-or-later
// Names of runs in legends and tables (core/report/run_names): runs that read apart keep their plain name; runs that
// would read the same get what differs between them (date and time at the coarsest precision that separates them,
// host, N), and a counter only when nothing differs; a renamed run shows its label.
#include <QTest>

#include "report/run_names.h"

namespace {

using Names = std::vector<std::string>;

bs::RunIdentity id(std::string base, std::string date, std::string host = "nuc", std::string detail = "N = 40000",
                   std::string label = {}) {
  return {std::move(base), std::move(label), std::move(date), std::move(host), std::move(detail)};
}

const std::string kDash = " \xE2\x80\x94 ";  // the em dash between a run's name and its label

}  // namespace

class TestRunNames : public QObject {
  Q_OBJECT
 private slots:
  void names_that_read_apart_stay_plain() {
    // Different bases: nothing is added even though dates, hosts and N differ.
    QCOMPARE(bs::distinct_names({id("NUC GPU · OpenCL · D=4", "2026-11-26T14:03:12Z", "a", "N = 1"),
                                 id("GTX1080Ti · CUDA · D=4", "2026-11-25T09:00:00Z", "b", "N = 2")}),
             (Names{"NUC GPU · OpenCL · D=4", "GTX1080Ti · CUDA · D=4"}));
    QCOMPARE(bs::distinct_names({}), Names{});
    QCOMPARE(bs::distinct_names({id("EPYC · CPU SIMD · D=4", "")}), Names{"EPYC · CPU SIMD · D=4"});
  }

  void the_date_at_the_coarsest_precision_that_separates() {
    // Different days: the day alone.
    QCOMPARE(bs::distinct_names({id("EPYC", "2026-11-25T14:03:12Z"), id("EPYC", "2026-11-26T14:03:12Z")}),
             (Names{"EPYC (2026-11-25)", "EPYC (2026-11-26)"}));
    // One day, different minutes: the time without the day.
    QCOMPARE(bs::distinct_names({id("EPYC", "2026-11-26T14:03:12Z"), id("EPYC", "2026-11-26T15:40:01Z")}),
             (Names{"EPYC (14:03)", "EPYC (15:40)"}));
    // One minute: the seconds.
    QCOMPARE(bs::distinct_names({id("EPYC", "2026-11-26T14:03:12Z"), id("EPYC", "2026-11-26T14:03:48Z")}),
             (Names{"EPYC (14:03:12)", "EPYC (14:03:48)"}));
    // Different days but one of them twice at different times: the minute with the day.
    QCOMPARE(bs::distinct_names({id("EPYC", "2026-11-25T14:03:12Z"), id("EPYC", "2026-11-26T14:03:12Z"),
                                 id("EPYC", "2026-11-26T16:10:00Z")}),
             (Names{"EPYC (2026-11-25 14:03)", "EPYC (2026-11-26 14:03)", "EPYC (2026-11-26 16:10)"}));
  }

  void host_then_detail_when_the_date_does_not_separate() {
    // The same second on two hosts: the host, and no date (it is the same for both).
    QCOMPARE(bs::distinct_names(
                 {id("EPYC", "2026-11-26T14:03:12Z", "robot-1"), id("EPYC", "2026-11-26T14:03:12Z", "robot-2")}),
             (Names{"EPYC (robot-1)", "EPYC (robot-2)"}));
    // Same date and host: N.
    QCOMPARE(bs::distinct_names({id("EPYC", "2026-11-26T14:03:12Z", "nuc", "N = 40000"),
                                 id("EPYC", "2026-11-26T14:03:12Z", "nuc", "N = 80000")}),
             (Names{"EPYC (N = 40000)", "EPYC (N = 80000)"}));
    // Nothing differs: a counter, the last resort.
    QCOMPARE(bs::distinct_names({id("EPYC", "2026-11-26T14:03:12Z"), id("EPYC", "2026-11-26T14:03:12Z")}),
             (Names{"EPYC (run 1)", "EPYC (run 2)"}));
    // Eight sweeps on one day, two at the same minute: the seconds separate all eight, nothing else is added.
    std::vector<bs::RunIdentity> eight;
    for (int k = 0; k < 8; ++k)
      eight.push_back(id("EPYC", "2026-11-26T14:0" + std::to_string(k / 2) + ":1" + std::to_string(k) + "Z"));
    const Names names = bs::distinct_names(eight);
    QCOMPARE(names.front(), std::string("EPYC (14:00:10)"));
    QCOMPARE(names.back(), std::string("EPYC (14:03:17)"));
  }

  void only_the_runs_that_collide_get_more() {
    // Two EPYC runs collide; the NUC run next to them keeps its plain name.
    QCOMPARE(bs::distinct_names({id("EPYC", "2026-11-25T10:00:00Z"), id("NUC", "2026-11-25T10:00:00Z"),
                                 id("EPYC", "2026-11-26T10:00:00Z")}),
             (Names{"EPYC (2026-11-25)", "NUC", "EPYC (2026-11-26)"}));
  }

  void a_renamed_run_shows_its_label() {
    // The label separates: nothing else is added, and the unlabelled run keeps its plain name.
    QCOMPARE(bs::distinct_names({id("EPYC", "2026-11-26T14:03:12Z", "nuc", "N = 1", "fan at 100 %"),
                                 id("EPYC", "2026-11-26T15:03:12Z")}),
             (Names{"EPYC" + kDash + "fan at 100 %", "EPYC"}));
    // A label on a lone run is shown too.
    QCOMPARE(bs::distinct_names({id("EPYC", "", "", "", "after BIOS update")}),
             Names{"EPYC" + kDash + "after BIOS update"});
    // Two runs with the same label still read apart by what differs.
    QCOMPARE(bs::distinct_names({id("EPYC", "2026-11-25T14:03:12Z", "nuc", "N = 1", "hot"),
                                 id("EPYC", "2026-11-26T14:03:12Z", "nuc", "N = 1", "hot")}),
             (Names{"EPYC" + kDash + "hot (2026-11-25)", "EPYC" + kDash + "hot (2026-11-26)"}));
  }

  void what_tells_a_run_apart_for_a_table_column() {
    // Issue #43.4: the peak table says the base in its own columns; its Run column shows only what is added.
    QCOMPARE(bs::distinguishing_parts({id("EPYC", "2026-11-26T14:03:12Z"), id("EPYC", "2026-11-26T15:40:01Z"),
                                       id("GTX", "2026-11-26T15:40:01Z")}),
             (Names{"14:03", "15:40", ""}));
    QCOMPARE(bs::distinguishing_parts({id("EPYC", "2026-11-26T14:03:12Z", "nuc", "N = 40000", "fan at 100 %"),
                                       id("EPYC", "2026-11-26T14:03:12Z")}),
             (Names{"fan at 100 %", ""}));
    QCOMPARE(bs::distinguishing_parts({id("EPYC", "2026-11-26T14:03:12Z", "nuc", "N = 40000", "after BIOS update"),
                                       id("EPYC", "2026-11-26T14:05:12Z", "nuc", "N = 40000", "after BIOS update")}),
             (Names{"after BIOS update (14:03)", "after BIOS update (14:05)"}));
  }

  void identity_of_a_flops_run() {
    bs::FlopsRun run;
    run.iterations = 12345;
    run.provenance.date = "2026-11-26T14:03:12Z";
    run.provenance.host = "robot-1";
    const bs::RunIdentity r = bs::run_identity(run, "EPYC · CPU SIMD · D=4", "mine");
    QCOMPARE(r.base, std::string("EPYC · CPU SIMD · D=4"));
    QCOMPARE(r.label, std::string("mine"));
    QCOMPARE(r.date, std::string("2026-11-26T14:03:12Z"));
    QCOMPARE(r.host, std::string("robot-1"));
    QCOMPARE(r.detail, std::string("N = 12345"));
  }
};

QTEST_GUILESS_MAIN(TestRunNames)
#include "test_run_names.moc"
