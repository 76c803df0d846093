// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli bench vision`'s grammar (#52): settings -> words -> settings is the identity with no option and with
// every option set, and bad words are refused naming the option.
#include <QTest>

#include "commands/bench_vision_grammar.h"

#include "../../support/grammar_under_test.h"

using bs::commands::BenchVisionSettings;

const bs::test::Grammar<BenchVisionSettings> grammar{{"bench", "vision"}, bs::commands::bench_vision_from_words};

class TestBenchVisionGrammar : public QObject {
  Q_OBJECT
 private slots:
  void words_come_back() {
    QVERIFY(grammar.round_trip(BenchVisionSettings{}) == BenchVisionSettings{});
    BenchVisionSettings all;
    all.frames = 50;
    all.threads = 4;
    all.power.sensor = "auto";
    all.power.interval_ms = 20;
    all.power.sysfs_root = "/tmp/fixture";
    QVERIFY(grammar.round_trip(all) == all);
  }

  void bad_words_are_refused_by_name() {
    QCOMPARE(grammar.refusal({"--frames", "0"}), QStringLiteral("--frames must be between 1 and 100000"));
    QCOMPARE(grammar.refusal({"--threads", "2000"}), QStringLiteral("--threads must be between 1 and 1024"));
    QCOMPARE(grammar.refusal({"--bogus"}), QStringLiteral("unknown option '--bogus'"));
    QCOMPARE(grammar.refusal({"more"}), QStringLiteral("bench vision takes no positional argument ('more')"));
  }
};

QTEST_APPLESS_MAIN(TestBenchVisionGrammar)
#include "test_bench_vision_grammar.moc"
