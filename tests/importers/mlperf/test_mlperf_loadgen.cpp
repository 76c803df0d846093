// SPDX-License-Identifier: GPL-3.0-or-later
// MLPerf LoadGen results: real submission folders (third-party: the shared folder's tests/data/importers/mlperf/,
// SOURCES there; the whole suite skips without it) imported through the
// registry as `benchscope-cli import` does, their numbers checked by hand against the summary file's lines (cited
// in the comments), the energy against the PTDaemon log, and broken logs and companions rejected with the place.
#include <QTest>

#include <fstream>
#include <iterator>

#include "mlperf/loadgen_detail.h"
#include "mlperf/mlperf_submission.h"
#include "workspace/registry.h"

#include "../../support/file_text.h"
#include "../../support/import_errors.h"
#include "../../support/near.h"
#include "../../support/public_data.h"
#include "../../support/result_set_lookup.h"

using bs::test::file_text;
using bs::test::near;
using bs::test::setting;

namespace {
const std::string kData = bs::test::public_data("tests/data/importers/mlperf/");
const std::string kOrin =
    kData + "v3.0-nvidia-orin-maxq/results/Orin_TRT_MaxQ/resnet50/SingleStream/performance/run_1/";
const std::string kXavier = kData + "v0.5-nvidia-xavier/results/Xavier/ssd-small/MultiStream/performance/run_1/";

const bs::Measurement& find(const bs::ResultSet& s, const std::string& metric) {
  for (const auto& m : s.measurements)
    if (m.metric == metric) return m;
  throw std::runtime_error("no measurement " + metric);
}

}  // namespace

class TestMlperfLoadgen : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() { BENCHSCOPE_REQUIRE_PUBLIC_DATA("tests/data/importers/mlperf"); }

  void orin_maxq_resnet50_singlestream_with_power() {
    const bs::ImportBatch b = bs::import_file(kOrin + "mlperf_log_summary.txt", bs::CancelToken{});
    QCOMPARE(b.format, std::string("mlperf-loadgen"));
    QCOMPARE(b.result_sets.size(), std::size_t{1});
    const bs::ResultSet& s = b.result_sets[0];
    // systems/Orin_TRT_MaxQ.json: system_name, accelerator_model_name, framework.
    QCOMPARE(s.platform, std::string("NVIDIA Jetson AGX Orin (MaxQ, TensorRT)"));
    QCOMPARE(s.device, std::string("NVIDIA Jetson AGX Orin"));
    QCOMPARE(s.device_kind, bs::DeviceKind::Gpu);
    QCOMPARE(s.backend, std::string("23.02 Jetson CUDA-X AI Developer Preview, TensorRT 8.5.2, CUDA 11.4"));
    QCOMPARE(s.provenance.cpu_model, std::string("12-core ARM Cortex-A78AE CPU"));
    // The system JSON names a submitter (NVIDIA): a published submission, not this lab's measurement (#51).
    QCOMPARE(s.provenance.origin, bs::DataOrigin::Published);
    QCOMPARE(setting(s, "network"), std::string("resnet50"));       // the folder layout
    QCOMPARE(setting(s, "scenario"), std::string("SingleStream"));  // summary line 5
    QCOMPARE(setting(s, "mode"), std::string("PerformanceOnly"));   // line 6
    QCOMPARE(setting(s, "result validity"), std::string("VALID"));  // line 8
    QCOMPARE(setting(s, "precision"), std::string("int8"));         // measurements/.../Orin_TRT_MaxQ_SingleStream.json
    QCOMPARE(setting(s, "division"), std::string("closed"));
    // mlperf_log_detail.txt line 1 and line 8.
    QCOMPARE(s.provenance.tool, std::string("MLPerf LoadGen 3.0 @ f536725011"));
    QCOMPARE(s.provenance.date, std::string("2023-02-24T06:21:48Z"));
    // v3.0's official SingleStream result is line 15's early-stopping estimate, 1637696 ns; line 7's plain
    // "90th percentile latency (ns) : 1637569" stays beside it as the p90 latency (line 28).
    const auto& result = find(s, "result: Early stopping 90th percentile estimate");
    QCOMPARE(result.unit, std::string("s"));
    QVERIFY(near(result.values.at(0), 1637696e-9));
    QVERIFY(near(find(s, "p90 latency").values.at(0), 1637569e-9));
    QCOMPARE(setting(s, "official metric"), std::string("Early stopping 90th percentile estimate (line 15)"));
    QCOMPARE(setting(s, "power kind"), std::string("AC wall"));
    QCOMPARE(result.name, std::string("resnet50 SingleStream"));
    QVERIFY(near(find(s, "mean latency").values.at(0), 1478507e-9));    // line 26
    QVERIFY(near(find(s, "min latency").values.at(0), 826431e-9));      // line 24
    QVERIFY(near(find(s, "max latency").values.at(0), 147144425e-9));   // line 25
    QVERIFY(near(find(s, "p50 latency").values.at(0), 1578304e-9));     // line 27
    QVERIFY(near(find(s, "p99.9 latency").values.at(0), 2019104e-9));   // line 32
    QVERIFY(near(find(s, "queries per second").values.at(0), 676.36));  // line 22, without LoadGen overhead
    QVERIFY(near(find(s, "samples per second").values.at(0), 676.36));  // samples_per_query : 1
    // Power: detail lines 69-70 give the window 06:22:00.638 .. 06:32:00.640 (600.002 s); spl.txt holds 600
    // samples inside it whose Watts average 14.814617 W (awk over the file: sum of field 4 / 600); line 76 gives
    // 400518 queries, so the energy per query is 14.814617 W x 600.002 s / 400518 = 0.0221933 J.
    QVERIFY(near(find(s, "mean power").values.at(0), 14.814617, 1e-6));
    QVERIFY(near(find(s, "energy per query").values.at(0), 14.814617 * 600.002 / 400518, 1e-6));
    QVERIFY(near(find(s, "energy per sample").values.at(0), 0.0221933, 1e-5));
    QCOMPARE(s.provenance.measurement, bs::MeasurementKind::ExternalMeter);
    QVERIFY(b.warnings.empty());
  }

  void xavier_v05_ssd_mobilenet_multistream() {
    const bs::ImportBatch b = bs::import_file(kXavier + "mlperf_log_summary.txt", bs::CancelToken{});
    const bs::ResultSet& s = b.result_sets.at(0);
    QCOMPARE(s.platform, std::string("NVIDIA Jetson AGX Xavier"));
    QCOMPARE(s.device, std::string("NVIDIA Xavier"));
    QCOMPARE(setting(s, "network"), std::string("ssd-small"));
    QCOMPARE(setting(s, "scenario"), std::string("MultiStream"));  // "Scenario : Multi Stream", line 5
    QCOMPARE(setting(s, "mode"), std::string("Performance"));
    QCOMPARE(setting(s, "precision"), std::string("int8"));
    // Line 7: "Samples per query : 102" is v0.5's MultiStream result (streams within the 50 ms latency bound).
    const auto& result = find(s, "result: Samples per query");
    QCOMPARE(result.values.at(0), 102.0);
    QCOMPARE(result.unit, std::string(""));
    // Its rate as the library has it: streams / the 50 ms latency bound ("target_latency (ns): 50000000").
    QVERIFY(near(find(s, "samples per second").values.at(0), 2040.0));
    QCOMPARE(setting(s, "throughput"), std::string("streams / latency bound"));
    // The per-sample block (line 32 on), not the per-query one above it: "Mean latency (ns) : 43945734".
    QVERIFY(near(find(s, "mean latency").values.at(0), 43945734e-9));
    QVERIFY(near(find(s, "p99 latency").values.at(0), 45119072e-9));
    QVERIFY(near(find(s, "p50 latency").values.at(0), 44804798e-9));
    // No power run, and v0.5's detail log has no :::MLLOG lines: no tool version, no energy.
    for (const auto& m : s.measurements) QVERIFY(m.metric != "energy per query");
  }

  void a_folder_walk_imports_results_and_passes_over_the_rest() {
    const bs::FormatImporter imp(bs::kMlperfLoadgenFileFormat);
    const std::string head = file_text(kOrin + "mlperf_log_summary.txt");
    QCOMPARE(imp.sniff(head, kOrin + "mlperf_log_summary.txt"), 95);
    QCOMPARE(imp.sniff(head, "/x/performance/ranging/mlperf_log_summary.txt"), 0);
    QCOMPARE(imp.sniff(head, "/x/compliance/r/TEST01/performance/run_1/mlperf_log_summary.txt"), 0);
    std::string accuracy = head;
    accuracy.replace(accuracy.find("PerformanceOnly"), 15, "AccuracyOnly");
    QCOMPARE(imp.sniff(accuracy, "/x/accuracy/mlperf_log_summary.txt"), 0);
    // The detail log is not a format of its own: in a folder it is skipped, beside its summary.
    QCOMPARE(imp.sniff(file_text(kOrin + "mlperf_log_detail.txt").substr(0, 65536), kOrin + "mlperf_log_detail.txt"),
             0);
  }

  void a_summary_alone_imports_without_companions() {
    const std::string text = file_text(kOrin + "mlperf_log_summary.txt");
    const bs::ImportBatch b = bs::parse_mlperf_summary(text, "own-run/mlperf_log_summary.txt");
    const bs::ResultSet& s = b.result_sets.at(0);
    // #46: the SUT name (line 4, "LWIS_Server") is the harness's, never the computer: not stated, and said so.
    QCOMPARE(s.platform, std::string("computer not stated (own-run/mlperf_log_summary.txt)"));
    QCOMPARE(setting(s, "network"), std::string("network not stated"));
    QVERIFY(near(find(s, "result: Early stopping 90th percentile estimate").values.at(0), 1637696e-9));
    QCOMPARE(b.warnings.size(), std::size_t{2});
    QVERIFY(b.warnings[0].find("'LWIS_Server' is the harness's") != std::string::npos);
    QVERIFY(b.warnings[1].find("never ranked with another") != std::string::npos);
  }

  void an_invalid_result_imports_with_a_warning() {
    std::string text = file_text(kOrin + "mlperf_log_summary.txt");
    text.replace(text.find("Result is : VALID"), 17, "Result is : INVALID");
    const bs::ImportBatch b = bs::parse_mlperf_summary(text, "s.txt");
    QCOMPARE(setting(b.result_sets.at(0), "result validity"), std::string("INVALID"));
    QVERIFY(std::any_of(b.warnings.begin(), b.warnings.end(), [](const std::string& w) {
      return w.starts_with("s.txt:8: LoadGen marked this result INVALID");
    }));
  }

  void broken_companions_are_rejected_with_their_place() {
    const std::string text = file_text(kOrin + "mlperf_log_summary.txt");
    bs::MlperfCompanions with;
    with.detail_text = ":::MLLOG {\"key\": \"power_begin\", \"value\": \"02-24-2023 06:22";  // truncated line
    with.detail_file = "detail.txt";
    auto e = bs::test::import_error_of([&] { return bs::parse_mlperf_summary(text, "s.txt", with); });
    QCOMPARE(e.location().file, std::string("detail.txt"));
    QCOMPARE(e.location().line, std::size_t{1});
    QCOMPARE(e.location().field, std::string("power_begin"));
    with.detail_text = ":::MLLOG {\"key\": \"power_begin\", \"value\": \"tomorrow\"}\n";
    e = bs::test::import_error_of([&] { return bs::parse_mlperf_summary(text, "s.txt", with); });
    QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
    with = {};
    with.system_json = "{\"system_name\": [1]}";
    with.system_file = "systems/x.json";
    e = bs::test::import_error_of([&] { return bs::parse_mlperf_summary(text, "s.txt", with); });
    QCOMPARE(e.category(), bs::ImportErrorCategory::WrongType);
    QCOMPARE(e.location().file, std::string("systems/x.json"));
    // An accuracy-mode summary named directly: not a performance result, said so.
    std::string accuracy = text;
    accuracy.replace(accuracy.find("PerformanceOnly"), 15, "AccuracyOnly");
    e = bs::test::import_error_of([&] { return bs::parse_mlperf_summary(accuracy, "s.txt"); });
    QCOMPARE(e.category(), bs::ImportErrorCategory::Unsupported);
  }

  void power_window_outside_the_log_gives_no_energy_and_a_warning() {
    bs::MlperfCompanions with;
    with.detail_text =
        ":::MLLOG {\"key\": \"power_begin\", \"value\": \"02-25-2023 06:22:00.638\"}\n"
        ":::MLLOG {\"key\": \"power_end\", \"value\": \"02-25-2023 06:32:00.640\"}\n";
    with.detail_file = "detail.txt";
    with.spl_text = file_text(kOrin + "spl.txt");
    with.spl_file = "spl.txt";
    const bs::ImportBatch b = bs::parse_mlperf_summary(file_text(kOrin + "mlperf_log_summary.txt"), "s.txt", with);
    QVERIFY(std::any_of(b.warnings.begin(), b.warnings.end(),
                        [](const std::string& w) { return w.find("no power sample inside") != std::string::npos; }));
    for (const auto& m : b.result_sets.at(0).measurements) QVERIFY(m.metric != "energy per query");
  }
};

QTEST_APPLESS_MAIN(TestMlperfLoadgen)
#include "test_mlperf_loadgen.moc"
