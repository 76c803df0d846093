// SPDX-License-Identifier: GPL-3.0-or-later
// Google Benchmark JSON: repetitions, aggregates, counters and their units, error/skipped rows, NaN/Infinity.
#include <QTest>

#include "google_benchmark_json.h"

namespace {
const std::string kData = BENCHSCOPE_TEST_DATA_DIR "/importers/google-benchmark/";

const bs::Measurement* find(const bs::ResultSet& s, const std::string& name, const std::string& metric) {
  for (const auto& m : s.measurements)
    if (m.name == name && m.metric == metric) return &m;
  return nullptr;
}

double aggregate(const bs::Measurement& m, const std::string& name) {
  for (const auto& [key, value] : m.reported_aggregates)
    if (key == name) return value;
  return -1;
}

bool near(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)); }

bs::ImportBatch parse_file(const std::string& name) {
  const bs::CancelToken cancel;
  return bs::GoogleBenchmarkJsonImporter().parse(kData + name, {}, cancel);
}

// A one-row document with the given counters, for unit inference.
std::string with_counters(const std::string& counters) {
  return "{\"context\":{\"host_name\":\"h\"},\"benchmarks\":[{\"name\":\"BM\",\"run_type\":\"iteration\","
         "\"real_time\":2,\"cpu_time\":1,\"time_unit\":\"ns\"," +
         counters + "}]}";
}
}  // namespace

class TestGoogleBenchmarkJson : public QObject {
  Q_OBJECT
 private slots:
  void parses_repetitions_aggregates_and_counters() {
    const auto batch = parse_file("rotation-repetitions.json");
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& s = batch.result_sets[0];
    QCOMPARE(s.platform, std::string("robot-nuc"));
    QCOMPARE(s.device, std::string("CPU (4 x 3500 MHz)"));
    QCOMPARE(s.device_kind, bs::DeviceKind::Cpu);
    QCOMPARE(s.backend, std::string("Google Benchmark"));
    QCOMPARE(s.source_format, std::string("google-benchmark-json"));
    QCOMPARE(s.provenance.tool, std::string("google-benchmark v1.7.1"));
    QCOMPARE(s.provenance.origin, bs::DataOrigin::Measured);
    QCOMPARE(s.provenance.host, std::string("robot-nuc"));
    QCOMPARE(s.provenance.date, std::string("2026-11-21T14:02:11+00:00"));
    const auto* real = find(s, "BM_Rotate/4096", "real_time");
    QVERIFY(real);
    QCOMPARE(real->unit, std::string("s"));
    QCOMPARE(real->values.size(), std::size_t{3});  // one per repetition
    QVERIFY(near(real->values[0], 13.280e-3));       // ms -> s
    QVERIFY(near(real->values[2], 13.442e-3));
    QCOMPARE(real->reported_aggregates.size(), std::size_t{3});  // mean, stddev, cv
    QCOMPARE(real->reported_aggregates[0].first, std::string("mean"));
    QVERIFY(near(aggregate(*real, "mean"), 13.341e-3));
    QVERIFY(near(aggregate(*real, "stddev"), 8.7e-5));
    QVERIFY(near(aggregate(*real, "cv"), 6.5e-3));  // a ratio, not scaled
    const auto* cpu = find(s, "BM_Rotate/4096", "cpu_time");
    QVERIFY(cpu && near(cpu->values[1], 13.296e-3));
    const auto* flops = find(s, "BM_Rotate/4096", "FLOPS");
    QVERIFY(flops);
    QCOMPARE(flops->unit, std::string("FLOP/s"));
    QCOMPARE(flops->values, (std::vector<double>{2.9612e10, 2.9565e10, 2.9255e10}));
    QCOMPARE(find(s, "BM_Rotate/4096", "items_per_second")->unit, std::string("1/s"));
    const auto* copy = find(s, "BM_Copy/1048576", "bytes_per_second");
    QVERIFY(copy);
    QCOMPARE(copy->unit, std::string("B/s"));
    QVERIFY(near(find(s, "BM_Copy/1048576", "real_time")->values[0], 206.4e-6));  // us -> s
    QVERIFY(!find(s, "BM_Rotate/4096", "iterations"));  // bookkeeping, not a counter
    QVERIFY(!find(s, "BM_Broken", "real_time"));
    QCOMPARE(batch.warnings.size(), std::size_t{1});
    QVERIFY(batch.warnings[0].find("OpenCL device not found") != std::string::npos);
    QVERIFY(batch.warnings[0].starts_with(kData + "rotation-repetitions.json:"));
    QVERIFY(batch.warnings[0].find("/benchmarks/7") != std::string::npos);
  }

  void aggregates_only_with_nan_and_skipped_rows() {
    const auto batch = parse_file("aggregates-only-nan.json");
    const bs::ResultSet& s = batch.result_sets.at(0);
    QCOMPARE(s.platform, std::string("jetson-tx2"));
    QCOMPARE(s.device, std::string("CPU (6 x 2035 MHz)"));
    QCOMPARE(s.provenance.tool, std::string("google-benchmark v1.8.3"));
    QVERIFY(s.provenance.note.find("scaling was on") != std::string::npos);
    const std::string run = "BM_RotateNeon/16384/threads:4";
    const auto* real = find(s, run, "real_time");
    QVERIFY(real);
    QVERIFY(real->values.empty());  // --benchmark_report_aggregates_only: no repetitions, only aggregates
    QVERIFY(near(aggregate(*real, "mean"), 4.83125e-3));
    QVERIFY(near(aggregate(*real, "median"), 4.829e-3));
    QVERIFY(near(aggregate(*real, "cv"), 2.5873221216041399e-03));
    const auto* gflops = find(s, run, "GFLOPS");
    QVERIFY(gflops);
    QCOMPARE(gflops->unit, std::string("FLOP/s"));
    QVERIFY(near(aggregate(*gflops, "mean"), 8.1401e9));  // GFLOPS -> FLOP/s
    QVERIFY(near(aggregate(*gflops, "cv"), 2.5798208866475845e-03));
    // Infinity / NaN counters are left out with a warning naming the line; the times of that row stay.
    QVERIFY(find(s, "BM_Idle", "real_time"));
    QVERIFY(!find(s, "BM_Idle", "bytes_per_second"));
    QVERIFY(!find(s, "BM_Idle", "items_per_second"));
    QVERIFY(!find(s, "BM_NeedsGpu", "real_time"));
    QCOMPARE(batch.warnings.size(), std::size_t{3});
    QVERIFY(batch.warnings[0].find(":106:") != std::string::npos);  // "bytes_per_second": Infinity
    QVERIFY(batch.warnings[0].find("/benchmarks/4/bytes_per_second") != std::string::npos);
    QVERIFY(batch.warnings[2].find("no CUDA device") != std::string::npos);
  }

  void counter_units_from_names() {
    const auto batch = bs::parse_google_benchmark_json(
        with_counters("\"flop_count\":5,\"MFLOP/s\":3,\"flops_per_second\":7,\"TFLOPS\":2,\"cache_misses\":9"),
        "u.json");
    const bs::ResultSet& s = batch.result_sets[0];
    QCOMPARE(s.platform, std::string("h"));
    QCOMPARE(s.device, std::string("CPU"));  // no num_cpus / mhz_per_cpu
    QCOMPARE(find(s, "BM", "flop_count")->unit, std::string(""));
    QCOMPARE(find(s, "BM", "MFLOP/s")->unit, std::string("FLOP/s"));
    QCOMPARE(find(s, "BM", "MFLOP/s")->values[0], 3e6);
    QCOMPARE(find(s, "BM", "flops_per_second")->values[0], 7.0);
    QCOMPARE(find(s, "BM", "TFLOPS")->values[0], 2e12);
    QCOMPARE(find(s, "BM", "cache_misses")->unit, std::string(""));
    QCOMPARE(find(s, "BM", "real_time")->values[0], 2e-9);
  }

  void bad_time_unit_names_the_field() {
    try {
      bs::parse_google_benchmark_json(
          "{\"context\":{},\n\"benchmarks\":[{\"name\":\"a\",\"real_time\":1,\"cpu_time\":1,\"time_unit\":\"fortnights\"}]}",
          "g.json");
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
      QCOMPARE(e.location().field, std::string("/benchmarks/0/time_unit"));
      QCOMPARE(e.location().line, std::size_t{2});
    }
  }

  void structural_errors() {
    auto category = [](const std::string& text) {
      try {
        bs::parse_google_benchmark_json(text, "g.json");
      } catch (const bs::ImportError& e) {
        return e.category();
      }
      return bs::ImportErrorCategory::Io;
    };
    QCOMPARE(category("{\"context\":{}}"), bs::ImportErrorCategory::MissingField);
    QCOMPARE(category("{\"benchmarks\":[]}"), bs::ImportErrorCategory::MissingField);
    QCOMPARE(category("{\"context\":{},\"benchmarks\":[]}"), bs::ImportErrorCategory::InvalidValue);  // nothing
    QCOMPARE(category("{\"context\":{},\"benchmarks\":[{\"name\":\"a\",\"cpu_time\":1}]}"),
             bs::ImportErrorCategory::MissingField);
    QCOMPARE(category("{\"context\":{},\"benchmarks\":[{\"name\":\"a\",\"real_time\":-1,\"cpu_time\":1}]}"),
             bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(category("{\"context\":{},\"benchmarks\":[{\"name\":\"a\",\"real_time\":1e999,\"cpu_time\":1}]}"),
             bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(category("{\"context\":{},\"benchmarks\":[{\"name\":\"a\",\"run_type\":\"x\",\"real_time\":1,"
                      "\"cpu_time\":1}]}"),
             bs::ImportErrorCategory::InvalidValue);
    QCOMPARE(category("{\"context\":{},\"benchmarks\":["), bs::ImportErrorCategory::Syntax);
  }
};

QTEST_GUILESS_MAIN(TestGoogleBenchmarkJson)
#include "test_google_benchmark_json.moc"
