// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli sustain`'s grammar (#53): what the desk writes for a robot is what the robot's CLI reads back
// (settings -> words -> settings), every setting spelled out, one --sysfs-root for the sampler and the power
// sensors (so a fixture tree needs no --power), and bad words refused naming the option.
#include <QTest>

#include <algorithm>

#include "commands/remote_commands.h"
#include "commands/sustain_grammar.h"

#include "../../support/command_words.h"
#include "../../support/grammar_under_test.h"

using bs::commands::SustainSettings;
using bs::test::has_word;
using bs::test::word_after;

const bs::test::Grammar<SustainSettings> grammar{{"sustain"}, bs::commands::sustain_from_words};

class TestSustainGrammar : public QObject {
  Q_OBJECT
 private slots:
  void defaults_come_back() {
    QVERIFY(grammar.round_trip(SustainSettings{}) == SustainSettings{});
    const auto words = bs::commands::to_words(SustainSettings{});
    // Spelled out for a robot whose defaults may differ.
    QCOMPARE(word_after(words, "--seconds"), std::string("600"));
    QCOMPARE(word_after(words, "--interval"), std::string("1"));
    QCOMPARE(word_after(words, "--stable-percent"), std::string("97"));
    QCOMPARE(word_after(words, "--throttle-threshold"), std::string("0.8"));
    QVERIFY(!has_word(words, "--power"));
  }

  void every_option_comes_back() {
    SustainSettings s;
    s.load = "dnn:yolo-n@5";
    s.seconds = 1200.5;
    s.interval_s = 2.5;
    s.detector = "mobilenet-ssd";
    s.platform = "Robot 7 (Orin)";
    s.stable_percent = 95.5;
    s.throttle_threshold = 0.75;
    s.sysfs_root = "/tmp/fixture root";
    s.power = {"ina3221:0", 20, "/tmp/fixture root"};
    s.workspace = "results.bsw";
    s.json = true;
    QVERIFY(grammar.round_trip(s) == s);
    // The root is written once, for the sampler and the sensors alike.
    const auto words = bs::commands::to_words(s);
    QCOMPARE(std::count(words.begin(), words.end(), std::string("--sysfs-root")), 1L);
  }

  void a_fixture_root_needs_no_power_sensor() {
    const SustainSettings s = bs::commands::sustain_from_words({"--sysfs-root", "/tmp/x"});
    QCOMPARE(s.sysfs_root, std::optional<std::string>("/tmp/x"));
    QCOMPARE(s.power.sensor, std::string("none"));
    QVERIFY(grammar.round_trip(s) == s);
  }

  void bad_words_are_refused_naming_the_option() {
    QVERIFY(grammar.refusal({"--load", "gpu"}).contains("--load must be flops"));
    QVERIFY(grammar.refusal({"--load", "flops,dnn"}).contains("--load takes one load"));
    QVERIFY(grammar.refusal({"--seconds", "0"}).contains("--seconds must be from 0.1"));
    QVERIFY(grammar.refusal({"--seconds", "ten"}).contains("--seconds"));
    QVERIFY(grammar.refusal({"--interval", "0.001"}).contains("--interval must be from 0.05"));
    QVERIFY(grammar.refusal({"--seconds", "10", "--interval", "20"}).contains("--interval must not be longer"));
    QVERIFY(grammar.refusal({"--stable-percent", "101"}).contains("--stable-percent must be from 1 to 100"));
    QVERIFY(grammar.refusal({"--throttle-threshold", "80"}).contains("--throttle-threshold must be from 0.01 to 1"));
    QVERIFY(grammar.refusal({"--power-interval-ms", "50"}).contains("need --power"));
    QVERIFY(grammar.refusal({"extra"}).contains("no positional argument"));
    QVERIFY(grammar.refusal({"--bogus"}).contains("unknown option '--bogus'"));
  }

  void remote_checks_the_words_through_it() {
    const auto c = bs::commands::find_remote_command({"sustain"});
    QVERIFY(c && c->grammar && c->workspace);
    QVERIFY(bs::test::refusal([&] {
              bs::commands::check_remote_words(*c, {"sustain", "--interval", "0"});
            }).contains("--interval"));
    QCOMPARE(bs::test::refusal([&] {
               bs::commands::check_remote_words(*c, {"sustain", "--load", "pipeline@30", "--seconds", "60"});
             }),
             QStringLiteral("(accepted)"));
  }
};

QTEST_APPLESS_MAIN(TestSustainGrammar)
#include "test_sustain_grammar.moc"
