// SPDX-License-Identifier: GPL-3.0-or-later
// The Pipeline tab's settings as `benchscope-cli pipeline --synthetic` arguments for a robot (issue #44): every
// setting spelled out (the robot's defaults may differ), a scale that reads back as the same number, power asked
// of the robot's own sensors, and a model file on the desk refused (the robot does not have it).
#include <QTest>

#include <stdexcept>

#include "vision/pipeline/pipeline_command.h"

#include "../../../support/command_words.h"

using bs::test::has_word;
using bs::test::word_after;

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
    QCOMPARE(word_after(a, "--frames"), std::string("40"));
    QCOMPARE(word_after(a, "--detect-workers"), std::string("3"));
    QCOMPARE(word_after(a, "--detect-scale"), std::string("0.35"));
    QCOMPARE(word_after(a, "--backend"), std::string("opencl"));
    QCOMPARE(word_after(a, "--detector"), std::string("yolo-n"));
    QCOMPARE(word_after(a, "--platform"), std::string("Robot 7"));
    QCOMPARE(word_after(a, "--power"), std::string("auto"));
  }

  void defaults_and_nothing_optional() {
    const auto a = bs::vision::synthetic_pipeline_cli_args({}, "", false);
    QCOMPARE(word_after(a, "--frames"), std::string("20"));
    QCOMPARE(word_after(a, "--detect-scale"), std::string("0.5"));
    QCOMPARE(word_after(a, "--detector"), std::string("hog"));
    QVERIFY(!has_word(a, "--platform") && !has_word(a, "--power"));
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

#include "../../../support/command_words.h"
