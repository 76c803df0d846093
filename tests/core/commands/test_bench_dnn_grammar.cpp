// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli bench dnn`'s grammar (#52): settings -> words -> settings is the identity with no option and with
// every option set, the input size is written as WxH, and bad words are refused naming the option.
#include <QTest>

#include "commands/bench_dnn_grammar.h"

#include "../../support/command_words.h"
#include "../../support/grammar_under_test.h"

using bs::commands::BenchDnnSettings;

const bs::test::Grammar<BenchDnnSettings> grammar{{"bench", "dnn"}, bs::commands::bench_dnn_from_words};

class TestBenchDnnGrammar : public QObject {
  Q_OBJECT
 private slots:
  void words_come_back() {
    QVERIFY(grammar.round_trip(BenchDnnSettings{}) == BenchDnnSettings{});
    const auto words = bs::commands::to_words(BenchDnnSettings{});
    QCOMPARE(bs::test::word_after(words, "--runs"), std::string("20"));  // spelled out: a robot's default may differ
    QVERIFY(!bs::test::has_word(words, "--input"));                      // the network's own size
    BenchDnnSettings all;
    all.arch = "yolo-n";
    all.input_width = 320;
    all.input_height = 256;
    all.batch = 4;
    all.runs = 5;
    all.backend = "cpu";
    all.platform = "nuc";
    all.workspace = "lab.bsw";
    all.json = true;
    all.power.sensor = "auto";
    all.power.interval_ms = 50;
    QVERIFY(grammar.round_trip(all) == all);
    QCOMPARE(bs::test::word_after(bs::commands::to_words(all), "--input"), std::string("320x256"));
    BenchDnnSettings model;
    model.model = "net.onnx,net.cfg";
    QVERIFY(grammar.round_trip(model) == model);
    QCOMPARE(bs::commands::bench_dnn_from_words({"--input", "64X96"}).input_height, 96);
  }

  void bad_words_are_refused_by_name() {
    QCOMPARE(grammar.refusal({"--model", "a.onnx", "--arch", "yolo-n"}),
             QStringLiteral("give --model or --arch, not both"));
    QCOMPARE(grammar.refusal({"--arch", "resnet"}),
             QStringLiteral("--arch must be mobilenet-ssd or yolo-n (got 'resnet')"));
    QCOMPARE(grammar.refusal({"--runs", "0"}), QStringLiteral("--runs must be a whole number from 1 to 100,000"));
    QCOMPARE(grammar.refusal({"--batch", "1.5"}), QStringLiteral("--batch must be a whole number from 1 to 256"));
    QCOMPARE(grammar.refusal({"--input", "16x16"}),
             QStringLiteral("--input must be WxH with sides of 32 to 4096 px, e.g. 640x640 (got '16x16')"));
    QCOMPARE(grammar.refusal({"--input", "640x640px"}),
             QStringLiteral("--input must be WxH with sides of 32 to 4096 px, e.g. 640x640 (got '640x640px')"));
    QCOMPARE(grammar.refusal({"--backend", "tpu"}),
             QStringLiteral("--backend must be cpu, opencl, cuda or all (got 'tpu')"));
    QCOMPARE(grammar.refusal({"--bogus"}), QStringLiteral("unknown option '--bogus'"));
    QCOMPARE(grammar.refusal({"more"}), QStringLiteral("bench dnn takes no positional arguments (got 'more')"));
  }
};

QTEST_APPLESS_MAIN(TestBenchDnnGrammar)
#include "test_bench_dnn_grammar.moc"
