// SPDX-License-Identifier: GPL-3.0-or-later
// The bundled library of published results: it loads, holds >= 30 sourced results for >= 8 computers, every value
// agrees with the line of the kept source file it names (third-party files in the shared folder's
// resources/library/sources: that check skips without them), plausibility runs on every entry (and catches a
// planted error), malformed libraries are refused with the entry named; candidates are ranked like with like only.
#include <QTest>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "analysis/library/candidates.h"
#include "analysis/library/library.h"
#include "util/resources.h"

#include "../../../support/public_data.h"

namespace {

std::vector<std::string> file_lines(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bs::LibraryResult inference(const std::string& computer, const std::string& net, double thr,
                            std::optional<double> power) {
  bs::LibraryResult r;
  r.id = computer + net;
  r.kind = "mlperf-inference";
  r.computer = computer;
  r.network = net;
  r.scenario = "SingleStream";
  r.precision = "int8";
  r.throughput_per_s = thr;
  r.latency_s = 1 / thr;
  r.latency_statistic = "p90";
  r.throughput_statistic = "queries per second";
  r.mean_power_w = power;
  return r;
}

}  // namespace

class TestLibrary : public QObject {
  Q_OBJECT
 private slots:
  void bundled_library_has_sourced_results() {
    const bs::BundledLibrary& b = bs::bundled_library();
    QVERIFY2(b.error.empty(), b.error.c_str());
    const bs::Library& lib = b.library;
    QVERIFY(lib.results.size() >= 30);
    std::set<std::string> computers;
    for (const auto& r : lib.results) computers.insert(r.computer);
    QVERIFY(computers.size() >= 8);
    for (const char* want : {"jetson-agx-orin", "jetson-orin-nx", "jetson-agx-xavier", "jetson-xavier-nx", "jetson-tx2",
                             "raspberry-pi-4", "raspberry-pi-5", "intel-icl-i3-1005g1"})
      QVERIFY2(computers.count(want), want);
    QVERIFY(lib.computer("orin") && lib.computer("pi5") && lib.computer("PI5"));
    for (const auto& r : lib.results) {
      QVERIFY2(!r.source.url.empty() && !r.source.kept.empty() && !r.source.lines.empty(), r.id.c_str());
      QVERIFY2(!r.round.empty() && !r.software.empty(), r.id.c_str());
    }
  }

  // Every value's cited line in the kept file holds the value (the library is never typed by hand).
  void every_cited_line_holds_its_number() {
    // The kept files are not in the project: "kept" names them relative to resources/library/ of the shared folder.
    BENCHSCOPE_REQUIRE_PUBLIC_DATA("resources/library/sources");
    const bs::Library& lib = bs::bundled_library().library;
    const std::filesystem::path root = bs::test::public_data("resources/library");
    int checked = 0;
    for (const auto& r : lib.results) {
      const auto lines = file_lines(root / r.source.kept);
      QVERIFY2(!lines.empty(), (r.id + ": kept file missing: " + r.source.kept).c_str());
      for (const auto& [what, no] : r.source.lines) {
        QVERIFY2(no >= 1 && static_cast<std::size_t>(no) <= lines.size(), r.id.c_str());
        const std::string& line = lines[static_cast<std::size_t>(no - 1)];
        // The number the entry derives from this line, as the line writes it.
        std::optional<double> v;
        if (what.find("percentile latency (ns)") != std::string::npos && r.latency_s) v = *r.latency_s * 1e9;
        if ((what.starts_with("QPS") || what == "Samples per second") && r.throughput_per_s) v = *r.throughput_per_s;
        if (r.kind == "clpeak" && r.value) v = *r.value / 1e9;
        if (r.kind == "hpl" && r.value) v = *r.value / 1e9;
        if (r.kind == "tensorrt-timing" && r.latency_s) v = *r.latency_s * 1e3;
        if (!v) continue;
        bool found = false;
        std::istringstream words(line);
        for (std::string w; words >> w;) {
          while (!w.empty() && !std::isdigit(static_cast<unsigned char>(w.back()))) w.pop_back();
          while (!w.empty() && !std::isdigit(static_cast<unsigned char>(w.front()))) w.erase(0, 1);
          if (w.empty()) continue;
          try {
            if (std::abs(std::stod(w) - *v) <= 1e-6 * std::abs(*v)) found = true;
          } catch (...) {
          }
        }
        QVERIFY2(found, (r.id + ": line " + std::to_string(no) + " '" + line + "' does not hold " + what).c_str());
        ++checked;
      }
    }
    QVERIFY(checked >= 40);
  }

  // Orin MaxQ ResNet-50 SingleStream: the same numbers the importer reads from the same summary (by hand: line 7,
  // 90th percentile 1637569 ns; line 22, 676.36 queries per second).
  void orin_maxq_entry_matches_its_summary() {
    const bs::Library& lib = bs::bundled_library().library;
    const bs::LibraryResult* r = lib.result("mlperf-v3.0-orin_trt_maxq-resnet50-singlestream");
    QVERIFY(r);
    QCOMPARE(r->precision, std::string("int8"));
    QCOMPARE(*r->latency_s, 1637569e-9);
    QCOMPARE(*r->throughput_per_s, 676.36);
    QVERIFY(std::abs(*r->mean_power_w - 14.814617) < 1e-5);
    QVERIFY(r->flags.empty());
  }

  void plausibility_runs_on_entries() {
    const bs::Library& lib = bs::bundled_library().library;
    // Every entry was checked on load; a planted impossible peak and power are flagged.
    bs::LibraryResult peak = *lib.result("clpeak-jetson-nano-single-precision-compute");
    QVERIFY(peak.flags.empty());  // 230.95 GFLOPS of the 235.9 GFLOPS Tegra X1 GPU
    peak.value = *peak.value * 10;
    QVERIFY(!bs::check_library_result(peak, lib).empty());
    bs::LibraryResult inf = *lib.result("mlperf-v3.0-orin_trt_maxq-resnet50-singlestream");
    inf.energy_per_sample_j = *inf.energy_per_sample_j * 10;  // no longer power / rate
    const auto flags = bs::check_library_result(inf, lib);
    QVERIFY(!flags.empty());
    QCOMPARE(flags[0].code, std::string("energy_power_mismatch"));
    inf = *lib.result("mlperf-v3.0-orin_trt_maxq-resnet50-singlestream");
    inf.mean_power_w = 1e6;
    QVERIFY(!bs::check_library_result(inf, lib).empty());
  }

  void malformed_libraries_are_refused_naming_the_entry() {
    const std::string ok = read(bs::find_resource("library/library.json"));
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, bs::parse_library("[1]", "x.json"));
    std::string bad = ok;
    bad.replace(bad.find("\"origin\": \"published\""), 21, "\"origin\": \"measured\"");
    try {
      (void)bs::parse_library(bad, "x.json");
      QFAIL("a library result claiming to be measured was accepted");
    } catch (const std::runtime_error& e) {
      QVERIFY2(std::string(e.what()).find("results[0]") != std::string::npos, e.what());
      QVERIFY2(std::string(e.what()).find("origin") != std::string::npos, e.what());
    }
    bad = ok;
    bad.replace(bad.find("\"computer\": \"jetson-agx-orin\""), 28, "\"computer\": \"jetson-agx-orim\"");
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, bs::parse_library(bad, "x.json"));
  }

  void select_by_alias_and_id() {
    const bs::Library& lib = bs::bundled_library().library;
    const auto orin_pi5 = bs::select_library(lib, "orin, pi5");
    QVERIFY(!orin_pi5.empty());
    for (const auto* r : orin_pi5) QVERIFY(r->computer == "jetson-agx-orin" || r->computer == "raspberry-pi-5");
    QCOMPARE(bs::select_library(lib, "mlperf-v3.0-orin_trt-resnet50-offline").size(), std::size_t{1});
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, bs::select_library(lib, "orin,pi6"));
  }

  // Like with like: a class per network, scenario and precision; ranking inside a class only, constraints first.
  void candidates_compare_like_with_like() {
    bs::Library lib;
    lib.computers = {{"a", "Board A", {}}, {"b", "Board B", {}}, {"c", "Board C", {}}};
    lib.results = {inference("a", "resnet50", 600, 15), inference("b", "resnet50", 300, 8),
                   inference("c", "resnet50", 900, std::nullopt), inference("a", "ssd-small", 1000, 15)};
    bs::CandidateInputs in;
    in.lib = &lib;
    for (const auto& r : lib.results) in.library.push_back(&r);
    bs::PipelineRun own;
    own.platform = "NUC";
    own.detector = "pedestrian detector (paper)";
    own.provenance.origin = bs::DataOrigin::Reconstructed;
    own.stages = {{"detect", 20, 0.17, 0.19, {}, {}, {}, {}}};
    in.pipelines = std::span<const bs::PipelineRun>(&own, 1);
    const auto classes = bs::rank_candidates(in, {.power_budget_w = 10});
    QCOMPARE(classes.size(), std::size_t{3});
    QCOMPARE(classes[0].network, std::string("pedestrian detector (paper)"));  // own rows first
    QCOMPARE(classes[0].rows[0].origin, bs::DataOrigin::Reconstructed);
    const auto& res = classes[1];
    QCOMPARE(res.title(), std::string("resnet50, SingleStream, int8"));
    QCOMPARE(res.rows.size(), std::size_t{3});
    QCOMPARE(res.rows[0].platform, std::string("Board B"));  // the only one within 10 W
    QVERIFY(res.rows[0].recommended);
    QCOMPARE(res.rows[1].platform, std::string("Board C"));  // fastest, but its power is unknown: fails the budget
    QVERIFY(!res.rows[1].meets_all);
    QVERIFY(res.rows[1].difference.find("no power") != std::string::npos);
    QCOMPARE(classes[2].network, std::string("ssd-mobilenet"));  // v0.5's "ssd-small", spelled as later rounds
    for (const auto& k : classes)
      for (const auto& r : k.rows)
        QVERIFY(r.origin == bs::DataOrigin::Published || r.origin == bs::DataOrigin::Reconstructed);
    const bs::ExportTable t = bs::candidates_table(classes, true);
    QCOMPARE(t.rows.size(), std::size_t{5});
    QCOMPARE(t.header[3], std::string("Origin"));
    QCOMPARE(t.rows[1][3], std::string("published"));
  }
};

QTEST_APPLESS_MAIN(TestLibrary)
#include "test_library.moc"
