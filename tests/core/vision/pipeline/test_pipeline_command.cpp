// SPDX-License-Identifier: GPL-3.0-or-later
// The Pipeline tab's settings as `benchscope-cli pipeline --synthetic` arguments for a robot (issue #44): every
// setting spelled out (the robot's defaults may differ), a scale that reads back as the same number, power asked
// of the robot's own sensors, and a model file on the desk refused (the robot does not have it).
#include <QTest>

#include <algorithm>
#include <stdexcept>

#include "vision/pipeline/pipeline_command.h"

namespace {

std::string after(const std::vector<std::string>& args, const std::string& option) {
  const auto it = std::find(args.begin(), args.end(), option);
  return it == args.end() || it + 1 == args.end() ? std::string("(absent)") : *(it + 1);
}

bool has(const std::vector<std::string>& args, const std::string& word) {
  return std::find(args.begin(), args.end(), word) != args.end();
}

}  // namespace

class TestPipelineCommand : public QObject {
  Q_OBJECT
 private slots:
  void every_setting_is_spelled_out() {
    bs::vision::SyntheticPipelineOptions o;
    o.frames = 40;
    o.detection_workers = 3;
    o.detect_scale = 0.35;
    o.backend = "opencl";
    o.detector = "yolo-n";
    const auto a = bs::vision::synthetic_pipeline_cli_args(o, "Robot 7", true);
    QCOMPARE(a.at(0), std::string("pipeline"));
    QCOMPARE(a.at(1), std::string("--synthetic"));
    QCOMPARE(after(a, "--frames"), std::string("40"));
    QCOMPARE(after(a, "--detect-workers"), std::string("3"));
    QCOMPARE(after(a, "--detect-scale"), std::string("0.35"));
    QCOMPARE(after(a, "--backend"), std::string("opencl"));
    QCOMPARE(after(a, "--detector"), std::string("yolo-n"));
    QCOMPARE(after(a, "--platform"), std::string("Robot 7"));
    QCOMPARE(after(a, "--power"), std::string("auto"));
  }

  void defaults_and_nothing_optional() {
    const auto a = bs::vision::synthetic_pipeline_cli_args({}, "", false);
    QCOMPARE(after(a, "--frames"), std::string("20"));
    QCOMPARE(after(a, "--detect-scale"), std::string("0.5"));
    QCOMPARE(after(a, "--detector"), std::string("hog"));
    QVERIFY(!has(a, "--platform") && !has(a, "--power"));
  }

  void a_model_file_on_the_desk_is_refused() {
    bs::vision::SyntheticPipelineOptions o;
    o.detector = "/home/lab/models/ssd.onnx";
    try {
      bs::vision::synthetic_pipeline_cli_args(o, "", false);
      QFAIL("a desk model file went to the robot");
    } catch (const std::invalid_argument& e) {
      QVERIFY2(std::string(e.what()).find("ssd.onnx") != std::string::npos, e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestPipelineCommand)
#include "test_pipeline_command.moc"
