// SPDX-License-Identifier: GPL-3.0-or-later
#include <QtTest>

#include "google_benchmark_json.h"

class TestGoogleBenchmarkJson : public QObject {
  Q_OBJECT
 private slots:
  void parses_repetitions_aggregates_and_counters() {
    const bs::CancelToken cancel;
    const auto batch = bs::GoogleBenchmarkJsonImporter().parse(
        BENCHSCOPE_TEST_DATA_DIR "/importers/google-benchmark/rotation-repetitions.json", {}, cancel);
    QCOMPARE(batch.result_sets.size(), std::size_t{1});
    const bs::ResultSet& s = batch.result_sets[0];
    QCOMPARE(s.platform, std::string("robot-nuc"));
    QCOMPARE(s.device, std::string("CPU (4 x 3500 MHz)"));
    QCOMPARE(s.provenance.tool, std::string("google-benchmark v1.7.1"));
    auto find = [&](const std::string& name, const std::string& metric) -> const bs::Measurement* {
      for (const auto& m : s.measurements)
        if (m.name == name && m.metric == metric) return &m;
      return nullptr;
    };
    const auto* real = find("BM_Rotate/4096", "real_time");
    QVERIFY(real);
    QCOMPARE(real->unit, std::string("s"));
    QCOMPARE(real->values.size(), std::size_t{3});
    QVERIFY(std::abs(real->values[0] - 13.280e-3) < 1e-12);  // ms -> s
    QCOMPARE(real->reported_aggregates.size(), std::size_t{3});  // mean, stddev, cv
    QCOMPARE(real->reported_aggregates[0].first, std::string("mean"));
    QVERIFY(std::abs(real->reported_aggregates[0].second - 13.341e-3) < 1e-12);
    QCOMPARE(real->reported_aggregates[2].first, std::string("cv"));
    QVERIFY(std::abs(real->reported_aggregates[2].second - 6.5e-3) < 1e-15);  // a ratio, not scaled
    const auto* flops = find("BM_Rotate/4096", "FLOPS");
    QVERIFY(flops);
    QCOMPARE(flops->unit, std::string("FLOP/s"));
    QCOMPARE(flops->values[0], 2.9612e10);
    const auto* copy = find("BM_Copy/1048576", "bytes_per_second");
    QVERIFY(copy);
    QCOMPARE(copy->unit, std::string("B/s"));
    QVERIFY(std::abs(find("BM_Copy/1048576", "real_time")->values[0] - 206.4e-6) < 1e-12);  // us -> s
    QVERIFY(!find("BM_Broken", "real_time"));
    QCOMPARE(batch.warnings.size(), std::size_t{1});
    QVERIFY(batch.warnings[0].find("OpenCL device not found") != std::string::npos);
  }
  void bad_time_unit_names_the_field() {
    try {
      bs::parse_google_benchmark_json(
          R"({"context":{},"benchmarks":[{"name":"a","real_time":1,"cpu_time":1,"time_unit":"fortnights"}]})", "g.json");
      QFAIL("accepted");
    } catch (const bs::ImportError& e) {
      QCOMPARE(e.category(), bs::ImportErrorCategory::InvalidValue);
      QCOMPARE(e.location().field, std::string("/benchmarks/0/time_unit"));
    }
  }
};

QTEST_GUILESS_MAIN(TestGoogleBenchmarkJson)
#include "test_google_benchmark_json.moc"
