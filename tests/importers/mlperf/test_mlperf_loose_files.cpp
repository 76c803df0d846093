// SPDX-License-Identifier: GPL-3.0-or-later
// MLPerf files a lab downloads, side by side rather than in a submission tree (issue #46): summaries, detail logs,
// spl.txt power logs and system JSONs in one folder, each run's files named with one prefix. They import as the
// library reads the same files (official metric, the checker's power metric), the computer comes from the system
// JSON beside them (never LoadGen's SUT name), the companions are read with their summary and not again on their
// own, and the folder import reports per computer what it took and passed over. Real files: the library's kept
// MLPerf sources under BENCHSCOPE_PUBLIC_DATA_DIR (skipped without them).
#include <QTest>

#include <QTemporaryDir>

#include <filesystem>
#include <fstream>

#include "analysis/library/library.h"
#include "common/import_service.h"
#include "common/importer.h"
#include "mlperf/mlperf_submission.h"

namespace {
namespace fs = std::filesystem;

const fs::path kKept = BENCHSCOPE_PUBLIC_DATA_DIR "/resources/library/sources";
const fs::path kV11 = kKept / "mlcommons+inference_results_v1.1/closed/NVIDIA";
const fs::path kV30 = kKept / "mlcommons+inference_results_v3.0/closed/NVIDIA";

// Copies one run's three files, its measurements JSON and its system JSON into `to` as a lab's loose download
// names them: the run's files and its measurements JSON under one prefix, the system JSON under its own name.
void copy_run(const fs::path& root, const std::string& system, const std::string& net, const std::string& scen,
              const fs::path& to) {
  const fs::path run = root / "results" / system / net / scen / "performance/run_1";
  const std::string prefix = system + "-" + net + "-" + scen + "-";
  for (const char* f : {"mlperf_log_summary.txt", "mlperf_log_detail.txt", "spl.txt"})
    fs::copy_file(run / f, to / (prefix + f));
  const std::string measurements = system + "_" + scen + ".json";
  fs::copy_file(root / "measurements" / system / net / scen / measurements, to / (prefix + measurements));
  fs::copy_file(root / "systems" / (system + ".json"), to / (system + ".json"), fs::copy_options::skip_existing);
}

const bs::Measurement* metric(const bs::ResultSet& s, const std::string& m) {
  for (const auto& x : s.measurements)
    if (x.metric == m) return &x;
  return nullptr;
}

std::string setting(const bs::ResultSet& s, const std::string& key) {
  for (const auto& [k, v] : s.provenance.settings)
    if (k == key) return v;
  return "(absent)";
}

}  // namespace

class TestMlperfLooseFiles : public QObject {
  Q_OBJECT
 private slots:
  void loose_files_import_as_the_library_reads_them() {
    if (!fs::is_directory(kV11) || !fs::is_directory(kV30))
      QSKIP("the kept MLPerf files are not here: BENCHSCOPE_PUBLIC_DATA_DIR/resources/library/sources");
    QTemporaryDir dir;
    const fs::path d = dir.path().toStdString();
    copy_run(kV11, "Xavier_NX_TRT_MaxQ", "ssd-mobilenet", "SingleStream", d);
    copy_run(kV30, "Orin_TRT_MaxQ", "retinanet", "SingleStream", d);
    const bs::Library& lib = bs::bundled_library().library;
    const struct {
      const char* file;
      const char* library_id;
      const char* computer;
      const char* network;
    } runs[] = {
        {"Xavier_NX_TRT_MaxQ-ssd-mobilenet-SingleStream-mlperf_log_summary.txt",
         "mlperf-v1.1-xavier_nx_trt_maxq-ssd-mobilenet-singlestream", "Auvidea JNX30 Xavier NX (MaxQ, TensorRT)",
         "ssd-mobilenet"},
        {"Orin_TRT_MaxQ-retinanet-SingleStream-mlperf_log_summary.txt",
         "mlperf-v3.0-orin_trt_maxq-retinanet-singlestream", "NVIDIA Jetson AGX Orin (MaxQ, TensorRT)", "retinanet"}};
    for (const auto& run : runs) {
      const bs::ImportBatch b = bs::import_file((d / run.file).string(), bs::CancelToken{});
      const bs::ResultSet& s = b.result_sets.at(0);
      const bs::LibraryResult* r = lib.result(run.library_id);
      QVERIFY(r);
      QCOMPARE(s.platform, std::string(run.computer));  // the system JSON's system_name, not "LWIS_Server"
      QCOMPARE(setting(s, "network"), std::string(run.network));
      // The official result and the checker's power metric, as the library has them from the same files.
      const bs::Measurement* official = nullptr;
      for (const auto& m : s.measurements)
        if (m.metric.starts_with("result: ")) official = &m;
      QVERIFY(official);
      QVERIFY(std::abs(official->values.at(0) - r->official->value) < 1e-12);
      QVERIFY(std::abs(metric(s, "mean power")->values.at(0) - *r->mean_power_w) < 1e-9);
      const double per_query = metric(s, "energy per query")->values.at(0);
      const double lib_per_query =
          r->power_metric->unit == "mJ/query" ? r->power_metric->value / 1000 : r->power_metric->value;
      QVERIFY2(std::abs(per_query - lib_per_query) < 1e-9 * lib_per_query, run.file);
      QCOMPARE(setting(s, "power kind"), std::string("AC wall"));
      // The precision from the measurements JSON with its prefix, as the library has it from the same commit.
      QCOMPARE(setting(s, "precision"), r->precision);
      QVERIFY2(b.warnings.empty(), b.warnings.empty() ? "" : b.warnings[0].c_str());
    }
    // The folder: two results, their detail logs, power logs, measurements and system JSONs read with them
    // (passed over on their own), and a per-computer report.
    QTemporaryDir ws;
    const bs::ImportResult res = bs::import_paths((fs::path(ws.path().toStdString()) / "w.bsw").string(), {d.string()});
    QCOMPARE(res.count(bs::FileOutcome::Kind::Imported), 2);
    QCOMPARE(res.count(bs::FileOutcome::Kind::NotData), 8);
    for (const auto& f : res.files)
      if (f.kind == bs::FileOutcome::Kind::NotData)
        QVERIFY2(f.reason.starts_with("read with its LoadGen summary"), (f.path + ": " + f.reason).c_str());
    const auto report = bs::per_computer_report(res);
    QVERIFY(std::find(report.begin(), report.end(),
                      "Auvidea JNX30 Xavier NX (MaxQ, TensorRT): took 1, passed over 4") != report.end());
    QVERIFY(std::find(report.begin(), report.end(), "NVIDIA Jetson AGX Orin (MaxQ, TensorRT): took 1, passed over 4") !=
            report.end());
  }

  void without_a_system_json_the_computer_is_not_stated() {
    if (!fs::is_directory(kV30)) QSKIP("the kept MLPerf files are not here: BENCHSCOPE_PUBLIC_DATA_DIR");
    QTemporaryDir dir;
    const fs::path d = dir.path().toStdString();
    copy_run(kV30, "Orin_TRT_MaxQ", "resnet50", "Offline", d);
    fs::remove(d / "Orin_TRT_MaxQ.json");
    const bs::ImportBatch b =
        bs::import_file((d / "Orin_TRT_MaxQ-resnet50-Offline-mlperf_log_summary.txt").string(), bs::CancelToken{});
    QVERIFY(b.result_sets.at(0).platform.starts_with("computer not stated"));
    QVERIFY(b.warnings.at(0).find("'LWIS_Server' is the harness's") != std::string::npos);
  }

  // A measurements JSON belongs to a loose summary only when its name carries the summary's prefix, or when the two
  // are alone in their folder: its own name ("Orin_TRT_MaxQ_SingleStream.json") is the same for every network.
  void a_measurements_json_is_taken_only_when_it_is_the_summarys() {
    if (!fs::is_directory(kV30)) QSKIP("the kept MLPerf files are not here: BENCHSCOPE_PUBLIC_DATA_DIR");
    QTemporaryDir dir;
    const fs::path d = dir.path().toStdString();
    copy_run(kV30, "Orin_TRT_MaxQ", "retinanet", "SingleStream", d);
    const std::string summary = (d / "Orin_TRT_MaxQ-retinanet-SingleStream-mlperf_log_summary.txt").string();
    // Alone with its summary under the plain name MLPerf gives it: taken.
    fs::rename(d / "Orin_TRT_MaxQ-retinanet-SingleStream-Orin_TRT_MaxQ_SingleStream.json",
               d / "Orin_TRT_MaxQ_SingleStream.json");
    bs::ImportBatch b = bs::import_file(summary, bs::CancelToken{});
    QCOMPARE(setting(b.result_sets.at(0), "precision"), std::string("int8"));
    // A second run in the folder with a plain-named measurements JSON of its own: neither is known to be whose.
    copy_run(kV30, "Orin_TRT_MaxQ", "resnet50", "Offline", d);
    fs::rename(d / "Orin_TRT_MaxQ-resnet50-Offline-Orin_TRT_MaxQ_Offline.json", d / "Orin_TRT_MaxQ_Offline.json");
    b = bs::import_file(summary, bs::CancelToken{});
    QCOMPARE(setting(b.result_sets.at(0), "precision"), std::string("(absent)"));
    QVERIFY(std::any_of(b.warnings.begin(), b.warnings.end(), [](const std::string& w) {
      return w.find("no measurements JSON") != std::string::npos &&
             w.find("2 measurements description(s) beside it, none named with its prefix") != std::string::npos;
    }));
  }

  void a_detail_log_without_power_window_is_warned_of() {
    if (!fs::is_directory(kV30)) QSKIP("the kept MLPerf files are not here: BENCHSCOPE_PUBLIC_DATA_DIR");
    QTemporaryDir dir;
    const fs::path d = dir.path().toStdString();
    copy_run(kV30, "Orin_TRT_MaxQ", "resnet50", "Offline", d);
    // The detail log without its power_begin / power_end lines.
    const fs::path detail = d / "Orin_TRT_MaxQ-resnet50-Offline-mlperf_log_detail.txt";
    std::ifstream in(detail);
    std::string kept, line;
    while (std::getline(in, line))
      if (line.find("\"power_begin\"") == std::string::npos && line.find("\"power_end\"") == std::string::npos)
        kept += line + "\n";
    in.close();
    std::ofstream(detail, std::ios::trunc) << kept;
    const bs::ImportBatch b =
        bs::import_file((d / "Orin_TRT_MaxQ-resnet50-Offline-mlperf_log_summary.txt").string(), bs::CancelToken{});
    QVERIFY(std::any_of(b.warnings.begin(), b.warnings.end(), [&](const std::string& w) {
      return w.find("without LoadGen's power_begin/power_end in " + detail.string()) != std::string::npos;
    }));
    QVERIFY(!metric(b.result_sets.at(0), "mean power"));
  }

  void names_say_the_network() {
    QCOMPARE(bs::network_from_name("Orin_TRT_MaxQ-retinanet-SingleStream"), std::string("retinanet"));
    QCOMPARE(bs::network_from_name("results/X/resnet/Offline"), std::string("resnet50"));
    QCOMPARE(bs::network_from_name("ssd-small"), std::string("ssd-mobilenet"));
    QCOMPARE(bs::network_from_name("run-a"), std::string());
  }
};

QTEST_APPLESS_MAIN(TestMlperfLooseFiles)
#include "test_mlperf_loose_files.moc"
