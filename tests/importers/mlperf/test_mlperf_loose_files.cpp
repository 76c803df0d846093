// SPDX-License-Identifier: GPL-3.0-or-later
// MLPerf files a lab downloads, side by side rather than in a submission tree (issue #46): summaries, detail logs,
// spl.txt power logs and system JSONs in one folder, each run's files named with one prefix. They import as the
// library reads the same files (official metric, the checker's power metric), the computer comes from the system
// JSON beside them (never LoadGen's SUT name), the companions are read with their summary and not again on their
// own, and the folder import reports per computer what it took and passed over. Real files: the library's kept
// MLPerf sources under BENCHSCOPE_PUBLIC_DATA_DIR (skipped without them).
#include <QTest>

#include <QTemporaryDir>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "../../support/result_set_lookup.h"
#include "analysis/library/candidates.h"
#include "analysis/library/library.h"
#include "mlperf/mlperf_submission.h"
#include "workspace/import_service.h"
#include "workspace/registry.h"

using bs::test::setting;

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

// The same run as a lab names it after a download (issue #51): "<system>_<net>_<scenario>_summary.txt",
// "..._detail.txt", "..._spl.txt", "..._measurements.json", and "<system>.system.json"; `with` picks the files.
void copy_run_lab_names(const fs::path& root, const std::string& system, const std::string& net,
                        const std::string& scen, const fs::path& to, bool with_detail = true, bool with_spl = true) {
  const fs::path run = root / "results" / system / net / scen / "performance/run_1";
  const std::string stem = system + "_" + net + "_" + scen + "_";
  fs::copy_file(run / "mlperf_log_summary.txt", to / (stem + "summary.txt"));
  if (with_detail && fs::exists(run / "mlperf_log_detail.txt"))
    fs::copy_file(run / "mlperf_log_detail.txt", to / (stem + "detail.txt"));
  if (with_spl && fs::exists(run / "spl.txt")) fs::copy_file(run / "spl.txt", to / (stem + "spl.txt"));
  fs::copy_file(root / "measurements" / system / net / scen / (system + "_" + scen + ".json"),
                to / (stem + "measurements.json"));
  fs::copy_file(root / "systems" / (system + ".json"), to / (system + ".system.json"), fs::copy_options::skip_existing);
}

const bs::Measurement* metric(const bs::ResultSet& s, const std::string& m) {
  for (const auto& x : s.measurements)
    if (x.metric == m) return &x;
  return nullptr;
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
    // The power log is still the result's own (#51): its whole-log mean, flagged, and no MLPerf power metric.
    QVERIFY(metric(b.result_sets.at(0), "mean power"));
    QVERIFY(setting(b.result_sets.at(0), "power window").starts_with("whole log"));
    QVERIFY(!metric(b.result_sets.at(0), "energy per sample"));
    QCOMPARE(setting(b.result_sets.at(0), "power metric"), std::string("(absent)"));
  }

  // Issue #51's done-when: a folder of loose files as a lab names them imports with every computer named (from the
  // system JSONs, "<system>.system.json"), no platform made of a spl.txt (each is its result's own power, in LoadGen's
  // window), origin published (the system JSON names a submitter), and MultiStream at the library's rate.
  void lab_named_folder_imports_as_the_library_reads_it() {
    if (!fs::is_directory(kV30)) QSKIP("the kept MLPerf files are not here: BENCHSCOPE_PUBLIC_DATA_DIR");
    QTemporaryDir dir, ws;
    const fs::path d = dir.path().toStdString();
    copy_run_lab_names(kV30, "Orin_TRT_MaxQ", "resnet50", "SingleStream", d);
    copy_run_lab_names(kV30, "Orin_TRT_MaxQ", "resnet50", "MultiStream", d);
    copy_run_lab_names(kV30, "Orin_TRT", "resnet50", "MultiStream", d);  // a summary alone, no detail or spl kept
    const bs::ImportResult res = bs::import_paths((fs::path(ws.path().toStdString()) / "w.bsw").string(), {d.string()});
    QCOMPARE(res.count(bs::FileOutcome::Kind::Failed), 0);
    QCOMPARE(res.count(bs::FileOutcome::Kind::Imported), 3);
    for (const auto& f : res.files) {
      if (f.kind == bs::FileOutcome::Kind::NotData)
        QVERIFY2(f.reason.starts_with("read with its LoadGen summary"), (f.path + ": " + f.reason).c_str());
      if (f.kind == bs::FileOutcome::Kind::Imported)
        QVERIFY2(f.summary.find("power log") == std::string::npos, f.summary.c_str());  // no spl.txt on its own
    }
    const bs::Library& lib = bs::bundled_library().library;
    const struct {
      const char* file;
      const char* library_id;
      bool power;
    } runs[] = {
        {"Orin_TRT_MaxQ_resnet50_SingleStream_summary.txt", "mlperf-v3.0-orin_trt_maxq-resnet50-singlestream", true},
        {"Orin_TRT_MaxQ_resnet50_MultiStream_summary.txt", "mlperf-v3.0-orin_trt_maxq-resnet50-multistream", true},
        {"Orin_TRT_resnet50_MultiStream_summary.txt", "mlperf-v3.0-orin_trt-resnet50-multistream", false}};
    std::vector<bs::ResultSet> sets;
    for (const auto& run : runs) {
      const bs::ImportBatch b = bs::import_file((d / run.file).string(), bs::CancelToken{});
      const bs::ResultSet& s = b.result_sets.at(0);
      const bs::LibraryResult* r = lib.result(run.library_id);
      QVERIFY(r);
      QCOMPARE(s.platform, r->system);  // "NVIDIA Jetson AGX Orin (MaxQ, TensorRT)": the .system.json's name
      QCOMPARE(s.provenance.origin, bs::DataOrigin::Published);  // NVIDIA's submission, not this lab's run
      QCOMPARE(setting(s, "precision"), r->precision);
      if (run.power) {
        QVERIFY(std::abs(metric(s, "mean power")->values.at(0) - *r->mean_power_w) < 1e-9);
        QCOMPARE(setting(s, "power window"), std::string("(absent)"));  // LoadGen's window, not the whole log
      } else {
        QVERIFY(!metric(s, "mean power"));
      }
      if (r->scenario == "MultiStream") {
        // samples per query / the early-stopping p99 per query, as the library has it (3,656.8 /s for Orin_TRT),
        // not 1 / latency.
        QVERIFY2(std::abs(metric(s, "samples per second")->values.at(0) - *r->throughput_per_s) <
                     1e-9 * *r->throughput_per_s,
                 run.file);
        QCOMPARE(setting(s, "throughput"), r->throughput_statistic);
      }
      QVERIFY2(b.warnings.empty(), b.warnings.empty() ? "" : b.warnings[0].c_str());
      sets.push_back(s);
    }
    // Ranked beside the library's copy, the import equals it: the same class, the same rate.
    bs::CandidateInputs in;
    in.result_sets = sets;
    in.library = {lib.result("mlperf-v3.0-orin_trt-resnet50-multistream")};
    in.lib = &lib;
    const auto classes = bs::rank_candidates(in, {});
    const auto ms = std::find_if(classes.begin(), classes.end(), [](const bs::CandidateClass& c) {
      return c.title() == "resnet50, MultiStream, int8";
    });
    QVERIFY(ms != classes.end());
    QCOMPARE(ms->rows.size(), std::size_t{3});
    int same = 0;
    for (const auto& row : ms->rows)
      if (std::abs(*row.throughput_per_s - 3656.7567036349533) < 1e-6) ++same;
    QCOMPARE(same, 2);  // the import and the library's copy of Orin_TRT
    for (const auto& row : ms->rows)
      QVERIFY2(row.difference.find("throughput") == std::string::npos, row.difference.c_str());
  }

  // Named one by one on the command line (a shell's *), the system JSON and the companions are read with their
  // summary; a system JSON no summary pairs with is passed over with the reason, never aborting the import.
  void named_files_are_read_with_their_summary() {
    if (!fs::is_directory(kV30)) QSKIP("the kept MLPerf files are not here: BENCHSCOPE_PUBLIC_DATA_DIR");
    QTemporaryDir dir, ws;
    const fs::path d = dir.path().toStdString();
    copy_run_lab_names(kV30, "Orin_TRT_MaxQ", "resnet50", "Offline", d);
    fs::copy_file(kV30 / "systems/Orin_NX_TRT.json", d / "Orin_NX_TRT.system.json");
    std::vector<std::string> named;
    for (const auto& e : fs::directory_iterator(d)) named.push_back(e.path().string());
    const bs::ImportResult res = bs::import_paths((fs::path(ws.path().toStdString()) / "w.bsw").string(), named);
    QCOMPARE(res.count(bs::FileOutcome::Kind::Failed), 0);
    QCOMPARE(res.count(bs::FileOutcome::Kind::Imported), 1);
    QVERIFY(res.committed);
    for (const auto& f : res.files)
      if (f.path.ends_with("Orin_NX_TRT.system.json"))
        QVERIFY2(f.reason.starts_with("an MLPerf system description: it holds no result"), f.reason.c_str());
  }

  // A spl.txt without its detail log is still the result's own power, but over the whole log: flagged, and no
  // energy per query (MLPerf's metric needs LoadGen's window and query count).
  void a_power_log_without_its_detail_log_is_the_whole_logs_mean_flagged() {
    if (!fs::is_directory(kV30)) QSKIP("the kept MLPerf files are not here: BENCHSCOPE_PUBLIC_DATA_DIR");
    QTemporaryDir dir;
    const fs::path d = dir.path().toStdString();
    copy_run_lab_names(kV30, "Orin_TRT_MaxQ", "resnet50", "SingleStream", d, /*with_detail=*/false);
    const bs::ImportBatch b =
        bs::import_file((d / "Orin_TRT_MaxQ_resnet50_SingleStream_summary.txt").string(), bs::CancelToken{});
    const bs::ResultSet& s = b.result_sets.at(0);
    QVERIFY(metric(s, "mean power"));
    QVERIFY(!metric(s, "energy per query"));
    QVERIFY(setting(s, "power window").starts_with("whole log"));
    QVERIFY(std::any_of(b.warnings.begin(), b.warnings.end(), [](const std::string& w) {
      return w.find("its mean is over the whole log, not MLPerf's power window") != std::string::npos;
    }));
    // The library's window mean of the same log is a little higher: the whole log includes the idle ends.
    const bs::LibraryResult* r =
        bs::bundled_library().library.result("mlperf-v3.0-orin_trt_maxq-resnet50-singlestream");
    QVERIFY(metric(s, "mean power")->values.at(0) < *r->mean_power_w);
    bs::CandidateInputs in;
    const std::vector<bs::ResultSet> sets{s};
    in.result_sets = sets;
    const auto classes = bs::rank_candidates(in, {});
    QCOMPARE(classes.at(0).rows.at(0).flags.at(0).code, std::string("power_not_in_mlperf_window"));
  }

  // Two files of one role for one summary: neither is taken, and a warning names both.
  void an_ambiguous_companion_is_not_taken() {
    if (!fs::is_directory(kV30)) QSKIP("the kept MLPerf files are not here: BENCHSCOPE_PUBLIC_DATA_DIR");
    QTemporaryDir dir;
    const fs::path d = dir.path().toStdString();
    copy_run_lab_names(kV30, "Orin_TRT_MaxQ", "resnet50", "Offline", d, true, false);
    const fs::path spl = kV30 / "results/Orin_TRT_MaxQ/resnet50/Offline/performance/run_1/spl.txt";
    fs::copy_file(spl, d / "Orin_TRT_MaxQ_resnet50_Offline_spl_a.txt");
    fs::copy_file(spl, d / "Orin_TRT_MaxQ_resnet50_Offline_spl_b.txt");
    const bs::ImportBatch b =
        bs::import_file((d / "Orin_TRT_MaxQ_resnet50_Offline_summary.txt").string(), bs::CancelToken{});
    QVERIFY(!metric(b.result_sets.at(0), "mean power"));
    QVERIFY(std::any_of(b.warnings.begin(), b.warnings.end(), [](const std::string& w) {
      return w.find(
                 "2 files could be its power log (spl) (Orin_TRT_MaxQ_resnet50_Offline_spl_a.txt, "
                 "Orin_TRT_MaxQ_resnet50_Offline_spl_b.txt): none taken") != std::string::npos;
    }));
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
