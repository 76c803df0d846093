// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli run flops`'s grammar: what the Kernel Runner writes for a robot reads back as the same sweep, and
// bad words are refused naming the option.
#include <QTest>

#include "commands/run_flops_grammar.h"

#include "../../support/command_words.h"
#include "../../support/grammar_under_test.h"

using bs::commands::RunFlopsSettings;
using bs::test::word_after;

const bs::test::Grammar<RunFlopsSettings> grammar{{"run", "flops"}, bs::commands::run_flops_from_words};

class TestRunFlopsGrammar : public QObject {
  Q_OBJECT
 private slots:
  void defaults_come_back() { QVERIFY(grammar.round_trip(RunFlopsSettings{}) == RunFlopsSettings{}); }

  void every_option_comes_back() {
    RunFlopsSettings s;
    s.workers = "1,2,4:64:4";
    s.points = "1,2,4";
    s.iterations = 1'000'000'000'000;
    s.repeats = 1000;
    s.warmup = false;
    s.variant = "paper";
    s.backend = "opencl";
    s.device = "1";
    s.isa = "avx2";
    s.out = "run.json";
    s.workspace = "w.bsw";
    s.events = "jsonl";
    s.json = true;
    s.quiet = true;
    s.power = {"auto", 10, "/fixture"};
    QVERIFY(grammar.round_trip(s) == s);
  }

  void the_sweep_is_spelled_out() {
    const auto a = bs::commands::to_words(RunFlopsSettings{});
    QCOMPARE(word_after(a, "--backend"), std::string("cpu"));
    QCOMPARE(word_after(a, "--workers"), std::string("1,2,4,8,16,32,64,128,256"));
    QCOMPARE(word_after(a, "--iterations"), std::string("40000"));
    QCOMPARE(word_after(a, "--repeats"), std::string("3"));
  }

  void bad_words_are_refused_naming_the_option() {
    QVERIFY(grammar.refusal({"--workers", "4:1"}).startsWith(QStringLiteral("--workers/--points: ")));
    QVERIFY(grammar.refusal({"--points", "0"}).startsWith(QStringLiteral("--workers/--points: ")));
    QCOMPARE(grammar.refusal({"--iterations", "0.5"}), QStringLiteral("--iterations must be a whole number >= 1"));
    QCOMPARE(grammar.refusal({"--repeats", "1001"}), QStringLiteral("--repeats must be between 1 and 1000"));
    QCOMPARE(grammar.refusal({"--variant", "fast"}), QStringLiteral("--variant must be paper or throughput"));
    QCOMPARE(grammar.refusal({"bandwidth"}), QStringLiteral("expected 'run flops'"));
    QCOMPARE(grammar.refusal({"--mib", "3"}), QStringLiteral("unknown option '--mib'"));
    // Read like every grammar's --events (commands/events_words.h): a robot's job streams jsonl, nothing else.
    QCOMPARE(grammar.refusal({"--events", "xml"}), QStringLiteral("--events takes jsonl (got 'xml')"));
  }
};

QTEST_APPLESS_MAIN(TestRunFlopsGrammar)
#include "test_run_flops_grammar.moc"
