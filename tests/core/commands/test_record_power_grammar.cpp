// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli record-power`'s grammar (#52): settings -> words -> settings is the identity, timed and with a
// command after "--" (whose own options stay its own), and bad words are refused naming the option.
#include <QTest>

#include "commands/record_power_grammar.h"

#include "../../support/command_words.h"
#include "../../support/grammar_under_test.h"

using bs::commands::RecordPowerSettings;

const bs::test::Grammar<RecordPowerSettings> grammar{{"record-power"}, bs::commands::record_power_from_words};

class TestRecordPowerGrammar : public QObject {
  Q_OBJECT
 private slots:
  void words_come_back() {
    RecordPowerSettings timed;
    timed.out = "trace.csv";
    timed.seconds = 2.5;
    QVERIFY(grammar.round_trip(timed) == timed);
    const auto words = bs::commands::to_words(timed);
    QCOMPARE(bs::test::word_after(words, "--interval-ms"), std::string("100"));  // a robot's default may differ
    QCOMPARE(bs::test::word_after(words, "--sensor"), std::string("auto"));
    RecordPowerSettings all;
    all.out = "trace.csv";
    all.workspace = "lab.bsw";
    all.sensor = "VDD_IN,VDD_GPU";
    all.interval_ms = 20;
    all.sysfs_root = "/tmp/fixture";
    all.command = {"sh", "-c", "sleep 1", "--quiet", "--"};  // the command's words, options and "--" too
    all.quiet = true;
    all.events = "jsonl";
    QVERIFY(grammar.round_trip(all) == all);
  }

  void the_command_after_dashes_is_untouched() {
    const RecordPowerSettings s = bs::commands::record_power_from_words(
        {"--workspace", "w.bsw", "--", "benchscope-cli", "run", "flops", "--bogus"});
    QVERIFY(s.command == (std::vector<std::string>{"benchscope-cli", "run", "flops", "--bogus"}));
    QVERIFY(!s.seconds);
  }

  void bad_words_are_refused_by_name() {
    QCOMPARE(grammar.refusal({"--seconds", "1"}), QStringLiteral("--out FILE.csv or --workspace W.bsw is required"));
    QCOMPARE(grammar.refusal({"--out", "x.csv"}), QStringLiteral("give either --seconds S or -- COMMAND ARGS..."));
    QCOMPARE(grammar.refusal({"--out", "x.csv", "--seconds", "1", "--", "sleep"}),
             QStringLiteral("give either --seconds S or -- COMMAND ARGS..."));
    QCOMPARE(grammar.refusal({"--out", "x.csv", "--seconds", "0"}), QStringLiteral("--seconds must be > 0"));
    QCOMPARE(grammar.refusal({"--out", "x.csv", "--seconds", "700000"}), QStringLiteral("--seconds must be > 0"));
    QCOMPARE(grammar.refusal({"--out", "x.csv", "--seconds", "1", "--interval-ms", "60001"}),
             QStringLiteral("the sample interval must be 1..60000 ms"));
    QCOMPARE(grammar.refusal({"--out", "x.csv", "--seconds", "1", "--events", "xml"}),
             QStringLiteral("--events takes jsonl (got 'xml')"));
    QCOMPARE(grammar.refusal({"--out", "x.csv", "sleep"}),
             QStringLiteral("unexpected argument 'sleep' (a command goes after --)"));
    QCOMPARE(grammar.refusal({"--bogus"}), QStringLiteral("unknown option '--bogus'"));
  }
};

QTEST_APPLESS_MAIN(TestRecordPowerGrammar)
#include "test_record_power_grammar.moc"
