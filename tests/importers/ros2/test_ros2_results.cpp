// SPDX-License-Identifier: GPL-3.0-or-later
// ROS 2 graph benchmarks of robot computers (issue #46): NVIDIA ros2_benchmark result JSON and RobotPerf
// benchmark.yaml, real files from BENCHSCOPE_PUBLIC_DATA_DIR/new/ros2 (SOURCES.md there; skipped without them),
// their values checked by hand against the lines cited, each value's meaning said; the strict YAML subset reader
// refuses a duplicate key naming both lines; impossible values (0 W), free-text hardware and mixed date formats are
// flagged with their line.
#include <QTest>

#include <algorithm>
#include <filesystem>

#include "ros2/robotperf_yaml.h"
#include "ros2/ros2_benchmark_json.h"
#include "ros2/yaml_subset.h"
#include "workspace/registry.h"

#include "../../support/import_errors.h"
#include "../../support/result_set_lookup.h"
#include "../../support/text_lines.h"

using bs::test::any_line_contains;
using bs::test::setting;

namespace {
const std::string kRos2 = BENCHSCOPE_PUBLIC_DATA_DIR "/new/ros2/";

const bs::Measurement* find(const bs::ResultSet& s, const std::string& name, const std::string& metric_start) {
  for (const auto& m : s.measurements)
    if (m.name == name && m.metric.starts_with(metric_start)) return &m;
  return nullptr;
}

}  // namespace

class TestRos2Results : public QObject {
  Q_OBJECT
 private slots:
  void ros2_benchmark_rectify_on_agx_orin() {
    const std::string f = kRos2 + "ros2bench_rectify_agx_orin_2023-05.json";
    if (!std::filesystem::exists(f)) QSKIP("needs BENCHSCOPE_PUBLIC_DATA_DIR/new/ros2 (the shared public data)");
    const bs::ImportBatch b = bs::import_file(f, bs::CancelToken{});
    QCOMPARE(b.format, std::string("ros2-benchmark-json"));
    const bs::ResultSet& s = b.result_sets.at(0);
    QCOMPARE(setting(s, "benchmark"), std::string("image_proc::RectifyNode Benchmark"));
    QCOMPARE(setting(s, "input"), std::string("HD (1280,720)"));
    // The release from the file's facts (TEST_DATETIME 2023-05-25; the workspace path names no ROS 2 distribution),
    // not default_config_version, which is 0.30.0 in every release.
    QCOMPARE(setting(s, "release"), std::string("ros2_benchmark run 2023-05"));
    QCOMPARE(setting(s, "config version"), std::string("0.30.0"));
    QVERIFY(s.platform.starts_with("computer not stated"));  // the hostname is a container's
    const std::string peak = "image_proc::RectifyNode Benchmark at peak throughput";
    // Line 4: "MEAN_FRAME_RATE": 185.2487567630416 (frames per second).
    QCOMPARE(find(s, peak, "frame rate")->values.at(0), 185.2487567630416);
    // Lines 7-8: the first and the last message's latency only, 5.9256 and 6.2355 ms.
    const bs::Measurement* first = find(s, peak, "latency of the FIRST message only");
    QVERIFY(first);
    QVERIFY(std::abs(first->values.at(0) - 5.925618489583333e-3) < 1e-15);
    QVERIFY(find(s, peak, "latency of the LAST message only"));
    // Line 11: "MEAN_JITTER" 0.177 ms is the largest of the runs' means: its metric says so.
    const bs::Measurement* mj = find(s, peak, "frame-to-frame jitter, the LARGEST of the runs' means");
    QVERIFY(mj);
    QVERIFY(std::abs(mj->values.at(0) - 0.17703528109764355e-3) < 1e-15);
    // Line 15: mean CPU use 49.08 % at peak; the 10 fps run (line 32): 3.98 %.
    QCOMPARE(find(s, peak, "CPU use, mean")->values.at(0), 49.080000000000005);
    // A fixed-rate section is one run: its label says so, never "mean of runs".
    const std::string at10 = "image_proc::RectifyNode Benchmark at 10.0fps (one run at a fixed rate)";
    QCOMPARE(find(s, at10, "CPU use, mean")->values.at(0), 3.9816666666666665);
    QVERIFY(find(s, at10, "frame rate (received frames / received duration, one run)"));
    QVERIFY(find(s, "image_proc::RectifyNode Benchmark at 60.0fps (one run at a fixed rate)", "frame rate"));
    QVERIFY(find(s, peak, "CPU use baseline, measured during the run"));
    QVERIFY(any_line_contains(b.warnings, "does not name the computer"));
  }

  // Issue #51: the same node on one board in two releases (2025-10 and 2026-02, both ROS 2 Jazzy) are two releases,
  // and the 2024+ schema's ResourceMetrics keep CPU and GPU use. By hand (ros2bench_rectify_agx_thor_2025-10.json):
  // MEAN_FRAME_RATE 425.98, TEST_DATETIME 2025-10-23, TEST_FILE_PATH /opt/ros/jazzy/...
  void releases_told_apart_and_resource_metrics_kept() {
    const std::string a = kRos2 + "ros2bench_rectify_agx_thor_2025-10.json";
    const std::string b = kRos2 + "isaacbench_rectify_agx_thor_2026-02.json";
    if (!std::filesystem::exists(a)) QSKIP("needs BENCHSCOPE_PUBLIC_DATA_DIR/new/ros2 (the shared public data)");
    const bs::ImportBatch ba = bs::import_file(a, bs::CancelToken{});
    const bs::ImportBatch bb = bs::import_file(b, bs::CancelToken{});
    const bs::ResultSet& sa = ba.result_sets.at(0);
    const bs::ResultSet& sb = bb.result_sets.at(0);
    QCOMPARE(setting(sa, "release"), std::string("ros2_benchmark run 2025-10, ROS 2 jazzy"));
    QCOMPARE(setting(sb, "release"), std::string("ros2_benchmark run 2026-02, ROS 2 jazzy"));
    QCOMPARE(setting(sa, "config version"), setting(sb, "config version"));  // 0.30.0 both: it tells nothing apart
    const std::string peak = "image_proc::RectifyNode Benchmark at peak throughput";
    QVERIFY(find(sa, peak, "CPU use, mean"));
    QVERIFY(find(sa, peak, "GPU use, mean"));
    QVERIFY(find(sb, peak, "CPU use, mean"));
    QVERIFY(!find(sb, peak, "GPU use, mean"));  // the CPU node's 2026 file keeps no device use
    QVERIFY(!any_line_contains(ba.warnings, "ROS 2 distribution is not in the file"));
  }

  // DGX Spark's GPU RectifyNode reaches 2495.99 fps against the harness's publisher_upper_frequency 2500: the peak
  // is the publisher's, flagged.
  void a_peak_at_the_publisher_ceiling_is_flagged() {
    const std::string f = kRos2 + "isaacbench_gpu_rectify_dgx_spark_2026-02.json";
    if (!std::filesystem::exists(f)) QSKIP("needs BENCHSCOPE_PUBLIC_DATA_DIR/new/ros2 (the shared public data)");
    const bs::ImportBatch b = bs::import_file(f, bs::CancelToken{});
    QVERIFY(setting(b.result_sets.at(0), "flag").starts_with("peak at the publisher ceiling"));
    QVERIFY(any_line_contains(b.warnings, "at the harness's publisher ceiling (publisher_upper_frequency 2500.0)"));
    const bs::ImportBatch thor =
        bs::import_file(kRos2 + "isaacbench_gpu_rectify_agx_thor_2026-02.json", bs::CancelToken{});  // 1549.97 fps
    QCOMPARE(setting(thor.result_sets.at(0), "flag"), std::string("(absent)"));
  }

  // A power of 8.97e-44 W is a reading of nothing (flagged like 0 W); one machine under two spellings is one
  // computer; grey-box and black-box values keep their type.
  void robotperf_flags_tiny_power_and_merges_spellings() {
    const std::string yaml =
        "id: a9\nname: a9_test\nresults:\n"
        "- result:\n    hardware: NVIDIA AGX Orin Dev. Kit\n    metric: power\n    metric_unit: W\n"
        "    type: grey\n    value: 8.96831017167883e-44\n"
        "- result:\n    hardware: NVIDIA AGX Orin Developer Kit\n    metric: latency\n    metric_unit: ms\n"
        "    type: black\n    value: 12.5\n";
    const bs::ImportBatch b = bs::kRobotperfYamlFileFormat.parse_text(yaml, "b.yaml", {}, {}, bs::CancelToken{});
    QCOMPARE(b.result_sets.size(), std::size_t{1});
    QCOMPARE(setting(b.result_sets[0], "hardware alias"), std::string("also spelled 'NVIDIA AGX Orin Developer Kit'"));
    QVERIFY(any_line_contains(b.warnings,
                              "b.yaml:9: value: 8.96831017167883e-44 W of power on NVIDIA AGX Orin Dev. Kit is "
                              "impossible (below 0.01 W"));
    QVERIFY(b.result_sets[0].measurements.at(0).name.find("[grey-box]") != std::string::npos);
    QVERIFY(b.result_sets[0].measurements.at(1).name.find("[black-box]") != std::string::npos);
  }

  void robotperf_c1_joint_trajectory_controller() {
    const std::string f = kRos2 + "robotperf_c1_rrbot_joint_trajectory_controller_benchmark.yaml";
    if (!std::filesystem::exists(f)) QSKIP("needs BENCHSCOPE_PUBLIC_DATA_DIR/new/ros2 (the shared public data)");
    const bs::ImportBatch b = bs::import_file(f, bs::CancelToken{});
    QCOMPARE(b.format, std::string("robotperf-yaml"));
    // 19 results of 5 hardware names, in file order.
    QCOMPARE(b.result_sets.size(), std::size_t{5});
    std::size_t n = 0;
    for (const auto& s : b.result_sets) n += s.measurements.size();
    QCOMPARE(n, std::size_t{19});
    const bs::ResultSet& orin = b.result_sets.at(3);
    QCOMPARE(orin.platform, std::string("NVIDIA AGX Orin Dev. Kit"));
    QCOMPARE(setting(orin, "benchmark"), std::string("c1 c1_rrbot_joint_trajectory_controller"));
    // Line 96: latency 1.472075 ms, the run's maximum (the note's max_benchmark 1.472075).
    const auto& lat = orin.measurements.at(0);
    QVERIFY(lat.metric.starts_with("latency: maximum of the run"));
    QVERIFY(std::abs(lat.values.at(0) - 1.472075e-3) < 1e-15);
    QCOMPARE(lat.unit, std::string("s"));
    // Lines 88, 120, 153, 186, 219: "throughput" 10.0 on every machine is the controller's configured update rate.
    QVERIFY(orin.measurements.at(2).metric.starts_with("update rate as configured (the same 10/s on every machine"));
    QCOMPARE(orin.measurements.at(2).values.at(0), 10.0);
    QVERIFY(any_line_contains(b.warnings, "the rate the loop was configured to run at, not a throughput"));
    QVERIFY(lat.name.find("[grey-box]") != std::string::npos);  // the result's type is kept
    // The double-quoted note with \u270B and a line joined by '\' was read whole (no error), and the free-text
    // workstation names and the two date formats are flagged with their lines.
    QVERIFY(any_line_contains(b.warnings, "hardware 'Intel i7-12700H' is free text"));
    QVERIFY(any_line_contains(b.warnings, "dates in two formats"));
    QCOMPARE(setting(orin, "release"), std::string("not stated in the file"));
  }

  // Issue #51: a2's throughput is the note's max_benchmark, not a mean: each value says the statistic its note gives
  // (or that none is given), and a rate that differs between machines is a throughput, not a configured rate.
  void robotperf_a2_statistic_from_each_note() {
    const std::string f = kRos2 + "robotperf_a2_rectify_benchmark.yaml";
    if (!std::filesystem::exists(f)) QSKIP(("needs " + f + " (the shared public data)").c_str());
    const bs::ImportBatch b = bs::import_file(f, bs::CancelToken{});
    QCOMPARE(b.format, std::string("robotperf-yaml"));
    std::size_t n = 0;
    for (const auto& s : b.result_sets) n += s.measurements.size();
    QCOMPARE(n, std::size_t{121});
    const auto orin = std::find_if(b.result_sets.begin(), b.result_sets.end(),
                                   [](const bs::ResultSet& s) { return s.platform == "NVIDIA AGX Orin Dev. Kit"; });
    QVERIFY(orin != b.result_sets.end());
    // Line 72: 36.46251208914602 fps, black-box; the note's mean_benchmark is 30.20, its max_benchmark the value.
    const bs::Measurement& tp = orin->measurements.at(0);
    QCOMPARE(tp.values.at(0), 36.46251208914602);
    QCOMPARE(tp.metric, std::string("throughput: maximum of the run (RobotPerf's value; its note's max_benchmark)"));
    QVERIFY(tp.name.find("[black-box]") != std::string::npos);
    // A black-box latency whose note writes max_latency: the maximum, named so.
    bool max_latency = false, unstated = false;
    for (const auto& s : b.result_sets)
      for (const auto& m : s.measurements) {
        QVERIFY2(!m.metric.starts_with("update rate as configured"), m.name.c_str());
        max_latency = max_latency || m.metric.ends_with("its note's max_latency)");
        unstated = unstated || m.metric.starts_with("throughput: statistic not stated");
      }
    QVERIFY(max_latency);
    QVERIFY(unstated);  // "lost messages 0.00 %" alone gives no statistic
    QVERIFY(!any_line_contains(b.warnings, "configured to run at"));
  }

  void robotperf_statistic_is_the_notes_number_equal_to_the_value() {
    const std::string yaml =
        "id: a9\nname: x\nresults:\n- result:\n    hardware: NVIDIA AGX Orin Dev. Kit\n    metric: throughput\n"
        "    metric_unit: fps\n    note: mean 30.0, max 41.5, min 20\n    value: 30.00\n"
        "- result:\n    hardware: NVIDIA AGX Orin Dev. Kit\n    metric: throughput\n    metric_unit: fps\n"
        "    note: maximum 41.5 (not a statistic word RobotPerf writes)\n    value: 41.5\n"
        "- result:\n    hardware: NVIDIA Jetson Nano\n    metric: latency\n    metric_unit: ms\n"
        "    note: mean_latency 3.1, max_latency 7.25\n    value: 7.25\n";
    const bs::ImportBatch b = bs::kRobotperfYamlFileFormat.parse_text(yaml, "s.yaml");
    QCOMPARE(b.result_sets.at(0).measurements.at(0).metric,
             std::string("throughput: mean of the run (RobotPerf's value; its note's mean)"));
    QVERIFY(b.result_sets.at(0).measurements.at(1).metric.starts_with("throughput: statistic not stated"));
    QCOMPARE(b.result_sets.at(1).measurements.at(0).metric,
             std::string("latency: maximum of the run (RobotPerf's value; its note's max_latency)"));
  }

  void impossible_values_are_flagged_with_their_line() {
    const std::string yaml =
        "id: c1\nname: x\nresults:\n- result:\n    hardware: NVIDIA AGX Orin Dev. Kit\n    metric: power\n"
        "    metric_unit: W\n    value: 0.0\n    timestampt: '2023-07-21 17:24:12'\n";
    const bs::ImportBatch b = bs::kRobotperfYamlFileFormat.parse_text(yaml, "b.yaml");
    QVERIFY(any_line_contains(b.warnings, "b.yaml:8: value: 0.0 W of power on NVIDIA AGX Orin Dev. Kit is impossible"));
  }

  void yaml_subset_reads_what_robotperf_writes_and_refuses_the_rest() {
    const bs::YamlNode n = bs::parse_yaml_subset(
        "a: 'it''s\n  folded\n\n  '\nb: \"x\\u270By\\\n  \\ z\"\nc: plain\n  continued\nd:\n- e: 1\n  f: 2\n- 3\n",
        "t.yaml");
    QCOMPARE(n.find("a")->scalar, std::string("it's folded\n"));
    QCOMPARE(n.find("b")->scalar, std::string("x\xE2\x9C\x8By z"));
    QCOMPARE(n.find("c")->scalar, std::string("plain continued"));
    QCOMPARE(n.find("d")->seq.size(), std::size_t{2});
    QCOMPARE(n.find("d")->seq[0].find("f")->scalar, std::string("2"));
    QCOMPARE(n.find("d")->seq[1].scalar, std::string("3"));
    // A duplicate key: refused, naming its line and the first one.
    auto e = bs::test::import_error_of([] {
      return bs::kRobotperfYamlFileFormat.parse_text(
          "id: c1\nname: x\nresults:\n- result:\n    value: 1\n    metric: latency\n    value: 2\n", "d.yaml");
    });
    QCOMPARE(e.location().file, std::string("d.yaml"));
    QCOMPARE(e.location().line, std::size_t{7});
    QVERIFY(e.reason().find("duplicate key 'value' (first at line 5)") != std::string::npos);
    for (const char* bad : {"a: &x 1\n", "a: [1, 2]\n", "a: |\n  x\n", "a:\n\t- 1\n", "a: 'open\n"}) {
      const std::string text = bad;
      e = bs::test::import_error_of([&] {
        (void)bs::parse_yaml_subset(text, "u.yaml");
        return bs::ImportBatch{};
      });
      QVERIFY2(e.location().line >= 1, bad);
    }
  }
};

QTEST_APPLESS_MAIN(TestRos2Results)
#include "test_ros2_results.moc"
