// SPDX-License-Identifier: GPL-3.0-or-later
// The measuring commands' grammars (#52): `bench dnn`, `bench kernels`, `bench vision` and `run bandwidth`. For each,
// settings -> words -> settings is the identity with no option and with every option set, what a robot's default
// could change is spelled out (dnn: --runs, the input size as WxH; bandwidth: the sizes), and bad words are refused
// naming the option.
#include <QTest>

#include "commands/bench_dnn_grammar.h"
#include "commands/bench_kernels_grammar.h"
#include "commands/bench_vision_grammar.h"
#include "commands/run_bandwidth_grammar.h"

#include "../../support/command_words.h"
#include "../../support/grammar_under_test.h"

using bs::commands::BenchDnnSettings;
using bs::commands::BenchKernelsSettings;
using bs::commands::BenchVisionSettings;
using bs::commands::RunBandwidthSettings;

const bs::test::Grammar<BenchDnnSettings> bench_dnn{{"bench", "dnn"}, bs::commands::bench_dnn_from_words};
const bs::test::Grammar<BenchKernelsSettings> bench_kernels{{"bench", "kernels"},
                                                            bs::commands::bench_kernels_from_words};
const bs::test::Grammar<BenchVisionSettings> bench_vision{{"bench", "vision"}, bs::commands::bench_vision_from_words};
const bs::test::Grammar<RunBandwidthSettings> run_bandwidth{{"run", "bandwidth"},
                                                            bs::commands::run_bandwidth_from_words};

class TestBenchGrammars : public QObject {
  Q_OBJECT
 private slots:
  void bench_dnn_words_come_back() {
    QVERIFY(bench_dnn.round_trip(BenchDnnSettings{}) == BenchDnnSettings{});
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
    QVERIFY(bench_dnn.round_trip(all) == all);
    QCOMPARE(bs::test::word_after(bs::commands::to_words(all), "--input"), std::string("320x256"));
    BenchDnnSettings model;
    model.model = "net.onnx,net.cfg";
    QVERIFY(bench_dnn.round_trip(model) == model);
    QCOMPARE(bs::commands::bench_dnn_from_words({"--input", "64X96"}).input_height, 96);
  }

  void bench_dnn_bad_words_are_refused_by_name() {
    QCOMPARE(bench_dnn.refusal({"--model", "a.onnx", "--arch", "yolo-n"}),
             QStringLiteral("give --model or --arch, not both"));
    QCOMPARE(bench_dnn.refusal({"--arch", "resnet"}),
             QStringLiteral("--arch must be mobilenet-ssd or yolo-n (got 'resnet')"));
    QCOMPARE(bench_dnn.refusal({"--runs", "0"}), QStringLiteral("--runs must be a whole number from 1 to 100,000"));
    QCOMPARE(bench_dnn.refusal({"--batch", "1.5"}), QStringLiteral("--batch must be a whole number from 1 to 256"));
    QCOMPARE(bench_dnn.refusal({"--input", "16x16"}),
             QStringLiteral("--input must be WxH with sides of 32 to 4096 px, e.g. 640x640 (got '16x16')"));
    QCOMPARE(bench_dnn.refusal({"--input", "640x640px"}),
             QStringLiteral("--input must be WxH with sides of 32 to 4096 px, e.g. 640x640 (got '640x640px')"));
    QCOMPARE(bench_dnn.refusal({"--backend", "tpu"}),
             QStringLiteral("--backend must be cpu, opencl, cuda or all (got 'tpu')"));
    QCOMPARE(bench_dnn.refusal({"--bogus"}), QStringLiteral("unknown option '--bogus'"));
    QCOMPARE(bench_dnn.refusal({"more"}), QStringLiteral("bench dnn takes no positional arguments (got 'more')"));
  }

  void bench_kernels_words_come_back() {
    QVERIFY(bench_kernels.round_trip(BenchKernelsSettings{}) == BenchKernelsSettings{});
    QCOMPARE(bs::test::word_after(bs::commands::to_words(BenchKernelsSettings{}), "--runs"), std::string("7"));
    BenchKernelsSettings all;
    all.runs = 3;
    all.workers = 4096;
    all.isa = "avx2";
    all.ceilings_only = true;
    all.power.sensor = "auto";
    all.power.interval_ms = 20;
    all.power.sysfs_root = "/tmp/fixture";
    QVERIFY(bench_kernels.round_trip(all) == all);
    BenchKernelsSettings bare;
    bare.no_ceilings = true;
    QVERIFY(bench_kernels.round_trip(bare) == bare);
  }

  void bench_kernels_bad_words_are_refused_by_name() {
    QCOMPARE(bench_kernels.refusal({"--runs", "0"}), QStringLiteral("--runs must be between 1 and 1000"));
    QCOMPARE(bench_kernels.refusal({"--runs", "2.5"}), QStringLiteral("--runs must be between 1 and 1000"));
    QCOMPARE(bench_kernels.refusal({"--workers", "2e6"}), QStringLiteral("--workers must be between 1 and 1e6"));
    QCOMPARE(bench_kernels.refusal({"--no-ceilings", "--ceilings-only"}),
             QStringLiteral("--no-ceilings and --ceilings-only exclude each other"));
    QCOMPARE(bench_kernels.refusal({"--power-interval-ms", "20"}),
             QStringLiteral("--power-interval-ms and --sysfs-root need --power"));
    QCOMPARE(bench_kernels.refusal({"--runs", "x"}), QStringLiteral("--runs expects a number, got 'x'"));
    QCOMPARE(bench_kernels.refusal({"--bogus"}), QStringLiteral("unknown option '--bogus'"));
    QCOMPARE(bench_kernels.refusal({"more"}), QStringLiteral("bench kernels takes no positional argument ('more')"));
  }

  void bench_vision_words_come_back() {
    QVERIFY(bench_vision.round_trip(BenchVisionSettings{}) == BenchVisionSettings{});
    BenchVisionSettings all;
    all.frames = 50;
    all.threads = 4;
    all.power.sensor = "auto";
    all.power.interval_ms = 20;
    all.power.sysfs_root = "/tmp/fixture";
    QVERIFY(bench_vision.round_trip(all) == all);
  }

  void bench_vision_bad_words_are_refused_by_name() {
    QCOMPARE(bench_vision.refusal({"--frames", "0"}), QStringLiteral("--frames must be between 1 and 100000"));
    QCOMPARE(bench_vision.refusal({"--threads", "2000"}), QStringLiteral("--threads must be between 1 and 1024"));
    QCOMPARE(bench_vision.refusal({"--bogus"}), QStringLiteral("unknown option '--bogus'"));
    QCOMPARE(bench_vision.refusal({"more"}), QStringLiteral("bench vision takes no positional argument ('more')"));
  }

  void run_bandwidth_words_come_back() {
    QVERIFY(run_bandwidth.round_trip(RunBandwidthSettings{}) == RunBandwidthSettings{});
    const auto words = bs::commands::to_words(RunBandwidthSettings{});
    QCOMPARE(bs::test::word_after(words, "--mib"), std::string("128"));  // spelled out: a robot's default may differ
    QCOMPARE(bs::test::word_after(words, "--repeats"), std::string("10"));
    RunBandwidthSettings all;
    all.backend = "opencl";
    all.device = "1";
    all.mib_per_array = 512;
    all.repeats = 3;
    all.workspace = "lab.bsw";
    all.json = all.quiet = true;
    QVERIFY(run_bandwidth.round_trip(all) == all);
  }

  void run_bandwidth_bad_words_are_refused_by_name() {
    QCOMPARE(run_bandwidth.refusal({"--mib", "0"}),
             QStringLiteral("--mib must be a whole number of MiB per array, 1 to 16384"));
    QCOMPARE(run_bandwidth.refusal({"--mib", "1.5"}),
             QStringLiteral("--mib must be a whole number of MiB per array, 1 to 16384"));
    QCOMPARE(run_bandwidth.refusal({"--repeats", "1001"}), QStringLiteral("--repeats must be between 1 and 1000"));
    QCOMPARE(run_bandwidth.refusal({"--bogus"}), QStringLiteral("unknown option '--bogus'"));
    QCOMPARE(run_bandwidth.refusal({"extra"}), QStringLiteral("run bandwidth takes no positional argument ('extra')"));
  }
};

QTEST_APPLESS_MAIN(TestBenchGrammars)
#include "test_bench_grammars.moc"
