// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli run bandwidth`'s grammar (#52): settings -> words -> settings is the identity with no option and with
// every option set, the sizes are spelled out for a robot, and bad words are refused naming the option.
#include <QTest>

#include "commands/run_bandwidth_grammar.h"

#include "../../support/command_words.h"
#include "../../support/grammar_under_test.h"

using bs::commands::RunBandwidthSettings;

const bs::test::Grammar<RunBandwidthSettings> grammar{{"run", "bandwidth"}, bs::commands::run_bandwidth_from_words};

class TestRunBandwidthGrammar : public QObject {
  Q_OBJECT
 private slots:
  void words_come_back() {
    QVERIFY(grammar.round_trip(RunBandwidthSettings{}) == RunBandwidthSettings{});
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
    QVERIFY(grammar.round_trip(all) == all);
  }

  void bad_words_are_refused_by_name() {
    QCOMPARE(grammar.refusal({"--mib", "0"}),
             QStringLiteral("--mib must be a whole number of MiB per array, 1 to 16384"));
    QCOMPARE(grammar.refusal({"--mib", "1.5"}),
             QStringLiteral("--mib must be a whole number of MiB per array, 1 to 16384"));
    QCOMPARE(grammar.refusal({"--repeats", "1001"}), QStringLiteral("--repeats must be between 1 and 1000"));
    QCOMPARE(grammar.refusal({"--bogus"}), QStringLiteral("unknown option '--bogus'"));
    QCOMPARE(grammar.refusal({"extra"}), QStringLiteral("run bandwidth takes no positional argument ('extra')"));
  }
};

QTEST_APPLESS_MAIN(TestRunBandwidthGrammar)
#include "test_run_bandwidth_grammar.moc"
