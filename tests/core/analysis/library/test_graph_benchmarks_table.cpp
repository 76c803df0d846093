// SPDX-License-Identifier: GPL-3.0-or-later
// #46: the ROS 2 graph benchmark results of the chosen library computers as one table (the Platforms tab's, its CSV):
// every row in its class, ranked within it only, saying what its value is (ros2_benchmark's "latency" is the first
// message's, its "mean jitter" a maximum), citing its source line, and a plausibility flag as a numbered note.
#include <QTest>

#include "analysis/library/graph_benchmarks_table.h"
#include "analysis/library/library.h"

namespace {

// Columns: Measure, Computer, Value, What the value is, Rank, Benchmark, Input, Release, Tool, Source.
enum Col { kMeasure, kComputer, kValue, kWhat, kRank, kBenchmark, kInput, kRelease, kTool, kSource };

const std::vector<std::string>* row_of(const bs::ExportTable& t, const std::string& computer_prefix,
                                       const std::string& measure) {
  for (const auto& r : t.rows)
    if (r[kComputer].starts_with(computer_prefix) && r[kMeasure] == measure) return &r;
  return nullptr;
}

}  // namespace

class TestGraphBenchmarksTable : public QObject {
  Q_OBJECT
 private slots:
  void orin_rows_say_what_each_value_is() {
    const bs::Library& lib = bs::bundled_library().library;
    const auto chosen = bs::select_library(lib, "orin");
    const auto classes = bs::graph_benchmark_classes(chosen);
    QVERIFY(!classes.empty());
    const bs::ExportTable t = bs::graph_benchmarks_table(classes, lib);
    QCOMPARE(t.header.size(), std::size_t{10});
    QCOMPARE(t.header[kWhat], std::string("What the value is"));
    std::size_t n = 0;
    for (const auto& c : classes) n += c.rows.size();
    QCOMPARE(t.rows.size(), n);  // every result, none dropped or merged
    // The first-message "latency" is said to be one message's, with its unit, and cites the kept file's line.
    const auto* first = row_of(t, "NVIDIA Jetson AGX Orin", "first-message latency, at peak throughput");
    QVERIFY(first);
    QVERIFY2((*first)[kWhat].find("FIRST message only") != std::string::npos, (*first)[kWhat].c_str());
    QCOMPARE((*first)[kValue], std::string("5.93 ms"));
    QCOMPARE((*first)[kTool], std::string("ros2_benchmark"));
    QCOMPARE((*first)[kRelease], std::string("ros2_benchmark run 2023-05"));
    QCOMPARE((*first)[kInput], std::string("HD (1280,720)"));
    QVERIFY2(
        (*first)[kSource].starts_with("https://github.com/") && (*first)[kSource].find(" line ") != std::string::npos,
        (*first)[kSource].c_str());
    // CPU use is a percentage of all cores, never given an SI prefix.
    const auto* cpu = row_of(t, "NVIDIA Jetson AGX Orin", "CPU use, at 30.0fps (one run at a fixed rate)");
    QVERIFY(cpu);
    QCOMPARE((*cpu)[kValue], std::string("9.2 %"));
    // RobotPerf's latency is the run's maximum (c1, its grey-box type kept); its release is not stated, so it is
    // compared with nothing.
    const auto* rp = row_of(t, "NVIDIA Jetson AGX Orin", "latency, grey-box");
    QVERIFY(rp);
    QCOMPARE((*rp)[kTool], std::string("RobotPerf"));
    QVERIFY((*rp)[kWhat].starts_with("the maximum of the run"));
    QCOMPARE((*rp)[kRank], std::string("only result"));
  }

  void ranks_within_a_class_and_numbers_flags() {
    bs::Library lib = bs::bundled_library().library;
    // Two results of one class: the lower CPU use ranks first; a planted flag becomes note [1].
    const bs::LibraryResult* cpu = lib.result("ros2bench-jetson-agx-orin-rectifynode-cpu-30fps");
    QVERIFY(cpu);
    bs::LibraryResult worse = *cpu;
    worse.id = "planted-worse";
    *worse.value = *cpu->value * 2;
    worse.flags.push_back({"implausible_magnitude", "planted for the test"});
    const auto classes = bs::graph_benchmark_classes({&worse, cpu});
    QCOMPARE(classes.size(), std::size_t{1});
    const bs::ExportTable t = bs::graph_benchmarks_table(classes, lib);
    QCOMPARE(t.rows.size(), std::size_t{2});
    QCOMPARE(t.rows[0][kRank], std::string("1"));
    QCOMPARE(t.rows[0][kValue], std::string("9.2 %"));
    QCOMPARE(t.rows[1][kRank], std::string("2"));
    QVERIFY(t.rows[1][kComputer].ends_with(" [1]"));
    QCOMPARE(t.notes.size(), std::size_t{1});
    QCOMPARE(t.notes[0], std::string("[1] implausible_magnitude: planted for the test"));
  }
};

QTEST_MAIN(TestGraphBenchmarksTable)
#include "test_graph_benchmarks_table.moc"
