// SPDX-License-Identifier: GPL-3.0-or-later
// Every command `remote` accepts has a grammar through which the desk checks the words before they go (issue #52),
// and the desk's check is the robot's reading: it refuses what the robot's CLI would refuse, naming the option, and
// lets through what it would run (the job's own --workspace and --events included).
#include <QTest>

#include "commands/remote_commands.h"

#include "../../support/refusal.h"

using bs::commands::check_remote_words;
using bs::commands::find_remote_command;

namespace {

QString refusal(const std::vector<std::string>& words) {
  return bs::test::refusal([&] { check_remote_words(*find_remote_command(words), words); });
}

}  // namespace

class TestRemoteGrammars : public QObject {
  Q_OBJECT
 private slots:
  void every_remote_command_has_a_grammar() {
    for (const auto& c : bs::commands::remote_commands())
      QVERIFY2(c.grammar != nullptr, (c.name + ": has no grammar").c_str());
  }

  void a_grammar_writes_its_command_name_first() {
    for (const auto& c : bs::commands::remote_commands()) {
      // The fewest words a command runs with: a frame-file pipeline needs its frame and lens, record-power a
      // length and a place for the trace.
      std::vector<std::string> args;
      if (c.name == "pipeline") args = {"--synthetic"};
      if (c.name == "record-power") args = {"--seconds", "1", "--out", "trace.csv"};
      const auto words = c.grammar(args);
      const auto name = find_remote_command(words);
      QVERIFY2(name && name->name == c.name, c.name.c_str());
      // Written words read back as themselves (the fixed point of settings -> words -> settings).
      QVERIFY2(c.grammar({words.begin() + c.words, words.end()}) == words, c.name.c_str());
      // And the desk's check takes them with the job's own options added, as the robot runs them.
      QCOMPARE(refusal(words), QStringLiteral("(accepted)"));
    }
  }

  void the_desk_refuses_what_the_robot_would() {
    QCOMPARE(refusal({"headroom", "--rate", "5"}), QStringLiteral("--rate must be from 50 to 10000 Hz"));
    QCOMPARE(refusal({"run", "flops", "--repeats", "0"}), QStringLiteral("--repeats must be between 1 and 1000"));
    QCOMPARE(refusal({"pipeline", "--synthetic", "--bogus"}), QStringLiteral("unknown option '--bogus'"));
    QCOMPARE(refusal({"pipeline", "--synthetic", "--frames", "5"}), QStringLiteral("(accepted)"));
    QCOMPARE(refusal({"devices", "--anything"}), QStringLiteral("unknown option '--anything'"));
    QCOMPARE(refusal({"sensors", "extra"}), QStringLiteral("sensors takes no positional argument ('extra')"));
    QCOMPARE(refusal({"bench", "vision", "--anything"}), QStringLiteral("unknown option '--anything'"));
    QCOMPARE(refusal({"bench", "kernels", "--runs", "0"}), QStringLiteral("--runs must be between 1 and 1000"));
    QCOMPARE(refusal({"bench", "kernels", "--anything"}), QStringLiteral("unknown option '--anything'"));
    QCOMPARE(refusal({"bench", "dnn", "--arch", "resnet"}),
             QStringLiteral("--arch must be mobilenet-ssd or yolo-n (got 'resnet')"));
    QCOMPARE(refusal({"record-power", "--seconds", "1", "--interval-ms", "0"}),
             QStringLiteral("the sample interval must be 1..60000 ms"));
    QCOMPARE(refusal({"record-power"}), QStringLiteral("give either --seconds S or -- COMMAND ARGS..."));
  }

  // The robot's job gives --workspace (and --events to a command that streams its own): record-power, which needs
  // --out or --workspace, passes with neither from the desk, as the robot runs it.
  void the_desk_reads_the_words_with_the_jobs_options() {
    QCOMPARE(refusal({"record-power", "--seconds", "1"}), QStringLiteral("(accepted)"));
    QCOMPARE(refusal({"record-power", "--", "sleep", "1"}), QStringLiteral("(accepted)"));
    const auto job = bs::commands::job_words(*find_remote_command({"record-power"}), {"record-power", "--", "sleep"},
                                             "/jobs/1/result.bsw");
    const std::vector<std::string> expected = {"record-power", "--workspace", "/jobs/1/result.bsw", "--events", "jsonl",
                                               "--",           "sleep"};
    QVERIFY(job == expected);
    QCOMPARE(bs::commands::job_words(*find_remote_command({"bench", "kernels"}), {"bench", "kernels"}, "w.bsw").size(),
             std::size_t{2});  // its text comes home, no results: nothing added
  }
};

QTEST_APPLESS_MAIN(TestRemoteGrammars)
#include "test_remote_grammars.moc"
