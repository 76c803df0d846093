// SPDX-License-Identifier: GPL-3.0-or-later
// Apex.AI performance_test logs: a real CSV log (2020, version 80ff298, latencies in ms) and a real JSON log (2022,
// version eff2a50, latencies in s) from the shared public-data folder (new/headroom/SOURCES.md), with their numbers
// read by hand below; the project's fixtures of running totals and a 2.x CSV (tests/data/headroom/SOURCES); mixed
// per-interval and cumulative rows refused at the row where they change.
#include <QTest>

#include <algorithm>
#include <cmath>

#include "headroom/imported_latency.h"
#include "headroom/performance_test_csv.h"
#include "headroom/performance_test_json.h"
#include "workspace/registry.h"

#include "../../support/import_errors.h"
#include "headroom_test_files.h"

using bs::headroom::LatencyKind;
// The headroom importers' test helpers (headroom_test_files.h, import_errors.h).
using namespace bs::test;

namespace {

bool near(double a, double b, double relative) { return std::abs(a - b) <= relative * std::abs(b); }

}  // namespace

class TestPerformanceTestImport : public QObject {
  Q_OBJECT
 private slots:
  // CSV log, 1 publisher / 1 subscriber of Array1k at "Publishing rate: 1000" over CycloneDDS, rows on lines 22 to
  // 141 (120 one-second intervals, T_experiment 11.010294 .. 130.129303 after "Ignore seconds from beginning: 10").
  // By hand: received 999 or 1000 per row (119943 in all, = sent), "latency_min (ms)" lowest 0.01789, "latency_max
  // (ms)" highest 0.3302 on line 27 (T = 16.015295), received-weighted mean 0.11824 ms; pooled SD 0.018727 ms with
  // "latency_variance (ms)" read as s^2 x 1000 (line 22: 1.406e-08 -> SD 3.75 us, consistent with its 0.1162 ..
  // 0.182 ms range; read as ms^2 it would be 0.12 us).
  void real_csv_log() {
    REQUIRE_REAL_FILE("perftest_csv_x86_zbook_cyclonedds_Array1k_1000Hz.log");
    const auto b = parse_with(bs::kPerformanceTestCsvFileFormat,
                              kHeadroomReal + "perftest_csv_x86_zbook_cyclonedds_Array1k_1000Hz.log");
    QVERIFY(b.warnings.empty());
    const auto& m = b.headroom.at(0);
    QCOMPARE(m.kind, LatencyKind::MessageLatency);
    QCOMPARE(m.tool, std::string("performance_test"));
    QCOMPARE(setting(b, "Performance Test Version"), std::string("80ff298"));
    QCOMPARE(setting(b, "RMW Implementation"), std::string("rmw_cyclonedds_cpp"));
    QCOMPARE(setting(b, "Publishing rate"), std::string("1000"));
    QCOMPARE(setting(b, "latency unit"), std::string("ms"));
    QCOMPARE(setting(b, "rows"), std::string("per interval"));
    const auto& t = only_thread(b);
    QVERIFY(bs::headroom_import::summary_only(t));
    QCOMPARE(t.histogram.cycles, std::uint64_t{119943});
    QCOMPARE(t.histogram.min_ns, std::optional<std::int64_t>(17890));
    QCOMPARE(t.histogram.max_ns, std::optional<std::int64_t>(330200));
    QVERIFY(near(*t.mean_ns, 118240.583, 1e-6));
    QVERIFY(near(*t.sd_ns, 18726.59, 1e-5));
    QCOMPARE(t.period_ns, std::int64_t{0});  // message latency: no loop period
    QVERIFY(has_note(b, "120 intervals pooled"));
    QVERIFY(has_note(b, "largest latency 0.3302 ms in the interval ending at T = 16.02 s"));
    QVERIFY(m.bookkeeping_error().empty());
  }

  // JSON log, Array1k at "rate": 100 on a Raspberry Pi 4 RT, idle, single-threaded executor, intra-process: 115 rows
  // of "latency_n": 100.0 (one 101; 11501 in all; "num_samples_received" says 99 per row, 11386 in all: the
  // statistics count is the one the latencies have), "latency_min" lowest 3.3888e-05 s, "latency_max" highest
  // 0.000153776 s (row 89, experiment_start 95.23 s), pooled mean 35.442 us and SD 2.310 us, in seconds, not ms.
  void real_json_log() {
    REQUIRE_REAL_FILE("perftest_rpi4rt_idle_ste_intra_Array1k_100Hz_prio90.json");
    const auto b = parse_with(bs::kPerformanceTestJsonFileFormat,
                              kHeadroomReal + "perftest_rpi4rt_idle_ste_intra_Array1k_100Hz_prio90.json");
    QVERIFY(b.warnings.empty());
    QCOMPARE(b.headroom.at(0).kind, LatencyKind::MessageLatency);
    QCOMPARE(setting(b, "perf_test_version"), std::string("eff2a50"));
    QCOMPARE(setting(b, "rate"), std::string("100"));
    QCOMPARE(setting(b, "latency unit"), std::string("s"));
    const auto& t = only_thread(b);
    QCOMPARE(t.histogram.cycles, std::uint64_t{11501});
    QCOMPARE(t.histogram.min_ns, std::optional<std::int64_t>(33888));
    QCOMPARE(t.histogram.max_ns, std::optional<std::int64_t>(153776));
    QVERIFY(near(*t.mean_ns, 35442.40266, 1e-6));
    QVERIFY(near(*t.sd_ns, 2309.996, 1e-5));
    QVERIFY(has_note(b, "115 intervals pooled"));
  }

  void running_totals_take_the_last_row() {
    const auto b = parse_with(bs::kPerformanceTestCsvFileFormat, kHeadroomFixtures + "perftest-running-totals.csv");
    QCOMPARE(setting(b, "rows"), std::string("running totals"));
    const auto& t = only_thread(b);
    QCOMPARE(t.histogram.cycles, std::uint64_t{500});
    QCOMPARE(t.histogram.min_ns, std::optional<std::int64_t>(37000));
    QCOMPARE(t.histogram.max_ns, std::optional<std::int64_t>(121000));
    QVERIFY(near(*t.mean_ns, 41200, 1e-9));
    // variance 2.7e-09 (s^2 x 1000) over n = 500: sqrt(2.7e-12 x 500 / 499) s
    QVERIFY(near(*t.sd_ns, std::sqrt(2.7e-12 * 500.0 / 499.0) * 1e9, 1e-9));
    QVERIFY(has_note(b, "the last row is the whole run"));
  }

  void json_fixtures_per_interval_and_running_totals() {
    const auto a = parse_with(bs::kPerformanceTestJsonFileFormat, kHeadroomFixtures + "perftest-per-interval.json");
    QCOMPARE(only_thread(a).histogram.cycles, std::uint64_t{150});  // latency_n 50 x 3
    QCOMPARE(only_thread(a).histogram.max_ns, std::optional<std::int64_t>(91000));
    QCOMPARE(setting(a, "rows"), std::string("per interval"));
    const auto b = parse_with(bs::kPerformanceTestJsonFileFormat, kHeadroomFixtures + "perftest-running-totals.json");
    QCOMPARE(setting(b, "rows"), std::string("running totals"));
    QCOMPARE(only_thread(b).histogram.cycles, std::uint64_t{150});  // the last row's latency_n
    QVERIFY(near(*only_thread(b).mean_ns, 36330, 1e-9));
  }

  void csv_of_2x_without_trailing_commas() {
    const auto b = parse_with(bs::kPerformanceTestCsvFileFormat, kHeadroomFixtures + "perftest-2x-per-interval.csv");
    const auto& t = only_thread(b);
    QCOMPARE(t.histogram.cycles, std::uint64_t{299});
    QCOMPARE(t.histogram.max_ns, std::optional<std::int64_t>(241000));
    QVERIFY(near(*t.mean_ns, (100 * 41400.0 + 99 * 40900.0 + 100 * 43100.0) / 299.0, 1e-9));
  }

  void mixed_rows_are_refused_naming_the_row() {
    const bs::CancelToken cancel;
    auto e = import_error_of([&] {
      return bs::kPerformanceTestCsvFileFormat.parse(BENCHSCOPE_TEST_DATA_DIR "/bad/headroom-perftest-mixed.csv", {},
                                                     {}, cancel);
    });
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().line, std::size_t{10});  // the fourth row, the first running total
    QVERIFY(std::string(e.what()).find("mixed per-interval and cumulative rows") != std::string::npos);
    e = import_error_of([&] {
      return bs::kPerformanceTestJsonFileFormat.parse(BENCHSCOPE_TEST_DATA_DIR "/bad/headroom-perftest-mixed.json", {},
                                                      {}, cancel);
    });
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().field, std::string("/analysis_results/3"));
    QVERIFY(e.location().line > 1);
  }

  void running_totals_without_a_rate() {
    // No "Publishing rate": counts that rise steadily to several times the first are running totals.
    std::string text =
        "---EXPERIMENT-START---\nT_experiment,T_loop,received,sent,latency_min (ms),latency_max "
        "(ms),latency_mean (ms),latency_variance (ms)\n";
    for (int k = 1; k <= 4; ++k)
      text += std::to_string(k) + ".0,1.0," + std::to_string(50 * k) + "," + std::to_string(50 * k) +
              ",0.03,0.05,0.04,1e-09\n";
    const auto b = bs::kPerformanceTestCsvFileFormat.parse_text(text, "p.csv");
    QCOMPARE(only_thread(b).histogram.cycles, std::uint64_t{200});
  }

  void last_row_cut_is_left_out_with_a_warning() {
    const std::string text =
        "Publishing rate: 10\n---EXPERIMENT-START---\nT_experiment,T_loop,received,sent,"
        "latency_min (ms),latency_max (ms),latency_mean (ms),latency_variance (ms)\n"
        "1.0,1.0,10,10,0.03,0.05,0.04,1e-09\n2.0,1.0,10,10,0.03,0.0";
    const auto b = bs::kPerformanceTestCsvFileFormat.parse_text(text, "p.csv");
    QCOMPARE(only_thread(b).histogram.cycles, std::uint64_t{10});
    QVERIFY(has_warning(b, "p.csv:5: the last row is cut short"));
  }

  void csv_errors_name_the_line() {
    const std::string head =
        "---EXPERIMENT-START---\nT_experiment,T_loop,received,sent,latency_min (ms),latency_max "
        "(ms),latency_mean (ms),latency_variance (ms)\n";
    auto e = import_error_of([&] {
      return bs::kPerformanceTestCsvFileFormat.parse_text(head + "1.0,1.0,10,10,0.03,x,0.04,1e-09\n", "p.csv");
    });
    QCOMPARE(e.location().line, std::size_t{3});
    QCOMPARE(e.location().field, std::string("latency_max"));
    e = import_error_of([&] {
      return bs::kPerformanceTestCsvFileFormat.parse_text(head + "1.0,1.0,10,10,0.06,0.05,0.04,1e-09\n", "p.csv");
    });
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(e.location().line, std::size_t{3});
    e = import_error_of([&] {
      return bs::kPerformanceTestCsvFileFormat.parse_text("---EXPERIMENT-START---\nT_experiment,T_loop\n", "p.csv");
    });
    QCOMPARE(e.category(), bs::ImportErrorCategory::MissingField);
  }

  void each_file_is_sniffed_as_its_format() {
    each_is_sniffed_as(kHeadroomFixtures, {{"perftest-running-totals.csv", "performance-test-csv"},
                                           {"perftest-2x-per-interval.csv", "performance-test-csv"}});
    if (std::filesystem::exists(kHeadroomReal + "perftest_csv_x86_zbook_cyclonedds_Array1k_1000Hz.log"))
      each_is_sniffed_as(kHeadroomReal,
                         {{"perftest_csv_x86_zbook_cyclonedds_Array1k_1000Hz.log", "performance-test-csv"},
                          {"perftest_rpi4rt_idle_ste_intra_Array1k_100Hz_prio90.json", "performance-test-json"},
                          {"cyclictest_2.8_x86_6thr.json", "cyclictest-json"},
                          {"cyclictest_2.8_x86_6thr_h400.hist", "cyclictest-text"},
                          {"cyclictest_old_4thr_h400_q.txt", "cyclictest-text"}});
  }
};

QTEST_APPLESS_MAIN(TestPerformanceTestImport)
#include "test_performance_test_import.moc"
