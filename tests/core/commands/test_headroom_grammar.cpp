// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli headroom`'s grammar: what the Headroom tab writes for a robot is what the robot's CLI reads back
// (settings -> words -> settings), every setting spelled out (the robot's defaults may differ), loads and an
// external command as single words (no shell on the way), and bad words refused naming the option.
#include <QTest>

#include "commands/headroom_grammar.h"

#include "../../support/command_words.h"
#include "../../support/grammar_under_test.h"

using bs::commands::HeadroomSettings;
using bs::test::has_word;
using bs::test::word_after;

const bs::test::Grammar<HeadroomSettings> grammar{{"headroom"}, bs::commands::headroom_from_words};

namespace {

void compare(const HeadroomSettings& a, const HeadroomSettings& b) {
  const auto& p = a.config.probe;
  const auto& q = b.config.probe;
  QCOMPARE(q.rate_hz, p.rate_hz);
  QCOMPARE(q.threads, p.threads);
  QCOMPARE(q.computation_ns, p.computation_ns);
  QCOMPARE(q.deadline_ns, p.deadline_ns);
  QCOMPARE(q.cpus, p.cpus);
  QCOMPARE(q.realtime, p.realtime);
  if (p.realtime) QCOMPARE(q.priority, p.priority);  // a normal thread has no priority to send
  QCOMPARE(q.limit_ns, p.limit_ns);
  QCOMPARE(b.config.phase_s, a.config.phase_s);
  QCOMPARE(b.config.settle_s, a.config.settle_s);
  QCOMPARE(b.config.idle_phase, a.config.idle_phase);
  QCOMPARE(b.config.platform, a.config.platform);
  QCOMPARE(b.loads, a.loads);
  QCOMPARE(b.load_command, a.load_command);
  QCOMPARE(b.detector, a.detector);
  QCOMPARE(b.frames, a.frames);
  QVERIFY(b.power == a.power);
  QCOMPARE(b.workspace, a.workspace);
  QCOMPARE(b.json, a.json);
}

}  // namespace

class TestHeadroomGrammar : public QObject {
  Q_OBJECT
 private slots:
  void defaults_come_back() { compare(HeadroomSettings{}, grammar.round_trip(HeadroomSettings{})); }

  void every_option_comes_back() {
    HeadroomSettings s;
    s.config.probe.rate_hz = 333.5;
    s.config.probe.threads = 3;
    s.config.probe.computation_ns = 12'345;
    s.config.probe.deadline_ns = 800'001;
    s.config.probe.cpus = {2, 3, 17};
    s.config.probe.priority = 99;
    s.config.probe.limit_ns = 4'000'000'000;
    s.config.phase_s = 0.1;
    s.config.settle_s = 600;
    s.config.idle_phase = false;
    s.config.platform = "Robot 7 (Orin)";
    s.loads = "pipeline@30fps,dnn:yolo-n@5";
    s.load_command = "stress-ng --cpu 2 --metrics-brief";
    s.detector = "mobilenet-ssd";
    s.frames = {"a.png", "-odd name.raw"};
    s.power = {"ina3221:0", 20, "/tmp/fixture root"};
    s.workspace = "results.bsw";
    s.json = true;
    compare(s, grammar.round_trip(s));
  }

  void a_normal_thread_sends_no_priority() {
    HeadroomSettings s;
    s.config.probe.realtime = false;
    const auto words = bs::commands::to_words(s);
    QVERIFY(has_word(words, "--no-rt"));
    QVERIFY(!has_word(words, "--priority"));  // asked of SCHED_FIFO only
    compare(s, grammar.round_trip(s));
  }

  void every_setting_is_spelled_out() {
    HeadroomSettings s;
    s.config.probe.computation_ns = 12'500;
    s.config.phase_s = 0.5;
    s.config.settle_s = 0;
    s.load_command = "stress-ng --cpu 2";
    s.power.sensor = "auto";
    const auto a = bs::commands::to_words(s);
    QCOMPARE(word_after(a, "--rate"), std::string("1000"));
    QCOMPARE(word_after(a, "--threads"), std::string("1"));
    QCOMPARE(word_after(a, "--computation-us"), std::string("12.5"));
    QCOMPARE(word_after(a, "--seconds"), std::string("0.5"));
    QCOMPARE(word_after(a, "--settle"), std::string("0"));
    QCOMPARE(word_after(a, "--priority"), std::string("80"));
    QCOMPARE(word_after(a, "--limit-us"), std::string("10000"));
    QCOMPARE(word_after(a, "--detector"), std::string("hog"));
    QCOMPARE(word_after(a, "--load-command"), std::string("stress-ng --cpu 2"));  // one word: the robot splits it
    QCOMPARE(word_after(a, "--power"), std::string("auto"));
    QVERIFY(!has_word(a, "--no-idle") && !has_word(a, "--load") && !has_word(a, "--platform") &&
            !has_word(a, "--workspace") && !has_word(a, "--json") && !has_word(a, "--"));
  }

  void bad_words_are_refused_naming_the_option() {
    QCOMPARE(grammar.refusal({"--rate", "20000"}), QStringLiteral("--rate must be from 50 to 10000 Hz"));
    QCOMPARE(grammar.refusal({"--threads", "1.5"}), QStringLiteral("--threads must be a whole number from 1 to 64"));
    QCOMPARE(grammar.refusal({"--seconds", "ten"}), QStringLiteral("--seconds expects a number, got 'ten'"));
    QCOMPARE(grammar.refusal({"--cpu", "1,,2"}),
             QStringLiteral("--cpu takes CPU numbers separated by commas (got '1,,2')"));
    QCOMPARE(grammar.refusal({"--no-idle"}), QStringLiteral("--no-idle needs at least one --load or --load-command"));
    QCOMPARE(grammar.refusal({"--sysfs-root", "/x"}),
             QStringLiteral("--power-interval-ms and --sysfs-root need --power"));
    QCOMPARE(grammar.refusal({"--power", "auto", "--power-interval-ms", "0"}),
             QStringLiteral("the sample interval must be 1..60000 ms"));
    QCOMPARE(grammar.refusal({"--frames", "3"}), QStringLiteral("unknown option '--frames'"));
    QCOMPARE(grammar.refusal({"--load"}), QStringLiteral("--load needs a value"));
  }
};

QTEST_APPLESS_MAIN(TestHeadroomGrammar)
#include "test_headroom_grammar.moc"
