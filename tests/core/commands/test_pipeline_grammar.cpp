// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli pipeline`'s grammar: what the Pipeline tab writes for a robot (`pipeline --synthetic ...`) and any
// frame-file command line read back as the same settings, every setting of the tab spelled out, a desk model file
// refused before it goes, and bad words refused naming the option.
#include <QTest>

#include "commands/pipeline_grammar.h"

#include "../../support/command_words.h"
#include "../../support/grammar_under_test.h"

using bs::commands::PipelineSettings;
using bs::test::has_word;
using bs::test::word_after;

const bs::test::Grammar<PipelineSettings> grammar{{"pipeline"}, bs::commands::pipeline_from_words};

namespace {

PipelineSettings from_files() {
  PipelineSettings s;
  s.frame_files = {"capture.raw"};
  s.lens = "paper";
  return s;
}

}  // namespace

class TestPipelineGrammar : public QObject {
  Q_OBJECT
 private slots:
  void defaults_come_back() {
    PipelineSettings s;
    s.synthetic = true;
    QVERIFY(grammar.round_trip(s) == s);
    QVERIFY(grammar.round_trip(from_files()) == from_files());
  }

  void every_option_comes_back() {
    PipelineSettings s = from_files();
    s.frame_files = {"a.png", "-odd.png"};
    s.lens = "lens.json";
    s.demosaic = "bilinear";
    s.backend = "opencl";
    s.detector = "model.onnx,model.cfg";
    s.frames = 10'000'000;
    s.policy = "drop-oldest";
    s.queue = 1024;
    s.detect_workers = bs::vision::kMaxDetectionWorkers;
    s.detect_scale = 0.123456789;
    s.pattern = "RGGB";
    s.platform = "Robot 7";
    s.out = "figures";
    s.workspace = "w.bsw";
    s.json = true;
    s.power = {"auto", 50, "/fixture"};
    QVERIFY(grammar.round_trip(s) == s);
  }

  void the_tab_spells_out_every_setting() {
    bs::vision::SyntheticPipelineOptions o;
    o.frames = 40;
    o.detection_workers = 3;
    o.detect_scale = 0.35;
    o.backend = "opencl";
    o.detector = "yolo-n";
    const PipelineSettings s = bs::commands::robot_pipeline_settings(o, "Robot 7", true);
    const auto a = bs::commands::to_words(s);
    QCOMPARE(a.at(1), std::string("--synthetic"));
    QCOMPARE(word_after(a, "--frames"), std::string("40"));
    QCOMPARE(word_after(a, "--detect-workers"), std::string("3"));
    QCOMPARE(word_after(a, "--detect-scale"), std::string("0.35"));
    QCOMPARE(word_after(a, "--backend"), std::string("opencl"));
    QCOMPARE(word_after(a, "--detector"), std::string("yolo-n"));
    QCOMPARE(word_after(a, "--platform"), std::string("Robot 7"));
    QCOMPARE(word_after(a, "--power"), std::string("auto"));
    QVERIFY(grammar.round_trip(s) == s);
    const auto plain = bs::commands::to_words(bs::commands::robot_pipeline_settings({}, "", false));
    QVERIFY(!has_word(plain, "--platform") && !has_word(plain, "--power"));
  }

  void a_model_file_on_the_desk_is_refused() {
    bs::vision::SyntheticPipelineOptions o;
    o.detector = "/home/lab/models/ssd.onnx";
    try {
      bs::commands::robot_pipeline_settings(o, "", false);
      QFAIL("a desk model file went to the robot");
    } catch (const std::invalid_argument& e) {
      QVERIFY2(std::string(e.what()).find("ssd.onnx") != std::string::npos, e.what());
    }
  }

  void bad_words_are_refused_naming_the_option() {
    QCOMPARE(grammar.refusal({"--synthetic", "--queue", "3"}),
             QStringLiteral("--synthetic runs as the Pipeline tab does (fused demosaic, block policy, queues of 2, "
                            "BGGR, no figures): leave out --queue"));
    QCOMPARE(grammar.refusal({"--synthetic", "--frames", "0"}),
             QStringLiteral("--frames must be a whole number from 1 to 1,000,000"));
    QCOMPARE(grammar.refusal({"--synthetic", "--backend", "tpu"}),
             QStringLiteral("--backend must be cpu, opencl or cuda (got 'tpu')"));
    QCOMPARE(grammar.refusal({"--synthetic", "--detect-scale", "1.5"}).left(45),
             QStringLiteral("--detect-scale must be greater than 0 and at "));
    QCOMPARE(grammar.refusal({"--synthetic", "--detect-workers", "0"}),
             QStringLiteral("--detect-workers must be a whole number from 1 to 256 (got '0')"));
    QCOMPARE(grammar.refusal({"f.png"}),
             QStringLiteral("--lens LENS.json is required (or --lens paper for the paper's camera)"));
    QCOMPARE(grammar.refusal({"f.png", "--lens", "paper", "--demosaic", "ahd"}),
             QStringLiteral("--demosaic must be fused, bilinear, mhc or opencv (got 'ahd')"));
    QCOMPARE(grammar.refusal({"f.png", "--lens", "paper", "--backend", "cuda", "--demosaic", "mhc"}),
             QStringLiteral("--backend cuda demosaics bilinearly: use --demosaic bilinear (got 'mhc')"));
    QCOMPARE(grammar.refusal({"f.png", "--lens", "paper", "--pattern", "XYZW"}).left(10), QStringLiteral("--pattern:"));
    QCOMPARE(grammar.refusal({"--synthetic", "--seconds", "3"}), QStringLiteral("unknown option '--seconds'"));
  }
};

QTEST_GUILESS_MAIN(TestPipelineGrammar)
#include "test_pipeline_grammar.moc"
