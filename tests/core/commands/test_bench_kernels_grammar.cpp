// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli bench kernels`'s grammar (#52): settings -> words -> settings is the identity with no option and
// with every option set, and bad words are refused naming the option.
#include <QTest>

#include "commands/bench_kernels_grammar.h"

#include "../../support/command_words.h"
#include "../../support/grammar_under_test.h"

using bs::commands::BenchKernelsSettings;

const bs::test::Grammar<BenchKernelsSettings> grammar{{"bench", "kernels"}, bs::commands::bench_kernels_from_words};

class TestBenchKernelsGrammar : public QObject {
  Q_OBJECT
 private slots:
  void words_come_back() {
    QVERIFY(grammar.round_trip(BenchKernelsSettings{}) == BenchKernelsSettings{});
    QCOMPARE(bs::test::word_after(bs::commands::to_words(BenchKernelsSettings{}), "--runs"), std::string("7"));
    BenchKernelsSettings all;
    all.runs = 3;
    all.workers = 4096;
    all.isa = "avx2";
    all.ceilings_only = true;
    all.power.sensor = "auto";
    all.power.interval_ms = 20;
    all.power.sysfs_root = "/tmp/fixture";
    QVERIFY(grammar.round_trip(all) == all);
    BenchKernelsSettings bare;
    bare.no_ceilings = true;
    QVERIFY(grammar.round_trip(bare) == bare);
  }

  void bad_words_are_refused_by_name() {
    QCOMPARE(grammar.refusal({"--runs", "0"}), QStringLiteral("--runs must be between 1 and 1000"));
    QCOMPARE(grammar.refusal({"--runs", "2.5"}), QStringLiteral("--runs must be between 1 and 1000"));
    QCOMPARE(grammar.refusal({"--workers", "2e6"}), QStringLiteral("--workers must be between 1 and 1e6"));
    QCOMPARE(grammar.refusal({"--no-ceilings", "--ceilings-only"}),
             QStringLiteral("--no-ceilings and --ceilings-only exclude each other"));
    QCOMPARE(grammar.refusal({"--power-interval-ms", "20"}),
             QStringLiteral("--power-interval-ms and --sysfs-root need --power"));
    QCOMPARE(grammar.refusal({"--runs", "x"}), QStringLiteral("--runs expects a number, got 'x'"));
    QCOMPARE(grammar.refusal({"--bogus"}), QStringLiteral("unknown option '--bogus'"));
    QCOMPARE(grammar.refusal({"more"}), QStringLiteral("bench kernels takes no positional argument ('more')"));
  }
};

QTEST_APPLESS_MAIN(TestBenchKernelsGrammar)
#include "test_bench_kernels_grammar.moc"
