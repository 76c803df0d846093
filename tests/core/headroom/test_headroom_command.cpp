// SPDX-License-Identifier: GPL-3.0-or-later
// The Headroom tab's settings as `benchscope-cli headroom` arguments for a robot (issue #44): every setting spelled
// out (the robot's defaults may differ), numbers that read back as the same values, real-time or --no-rt, loads
// and an external command as single arguments (no shell on the way), power asked of the robot's own sensors.
#include <QTest>

#include "headroom/headroom_command.h"

#include "../../support/command_words.h"

using bs::test::has_word;
using bs::test::word_after;

class TestHeadroomCommand : public QObject {
  Q_OBJECT
 private slots:
  void every_setting_is_spelled_out() {
    bs::headroom::RunConfig c;
    c.probe.rate_hz = 250;
    c.probe.threads = 2;
    c.probe.computation_ns = 12'500;
    c.probe.priority = 90;
    c.phase_s = 0.5;
    c.settle_s = 0;
    c.platform = "Robot 7";
    const auto a = bs::headroom::headroom_cli_args(c, "pipeline@30fps,dnn", "stress-ng --cpu 2", true);
    QCOMPARE(a.front(), std::string("headroom"));
    QCOMPARE(word_after(a, "--rate"), std::string("250"));
    QCOMPARE(word_after(a, "--threads"), std::string("2"));
    QCOMPARE(word_after(a, "--computation-us"), std::string("12.5"));
    QCOMPARE(word_after(a, "--seconds"), std::string("0.5"));
    QCOMPARE(word_after(a, "--settle"), std::string("0"));
    QCOMPARE(word_after(a, "--priority"), std::string("90"));
    QCOMPARE(word_after(a, "--limit-us"), std::string("10000"));
    QCOMPARE(word_after(a, "--load"), std::string("pipeline@30fps,dnn"));
    QCOMPARE(word_after(a, "--load-command"), std::string("stress-ng --cpu 2"));  // one argument: the robot splits it
    QCOMPARE(word_after(a, "--platform"), std::string("Robot 7"));
    QCOMPARE(word_after(a, "--power"), std::string("auto"));
    QVERIFY(!has_word(a, "--no-rt") && !has_word(a, "--no-idle") && !has_word(a, "--deadline-us") &&
            !has_word(a, "--cpu"));
  }

  void normal_thread_deadline_pinning_and_nothing_optional() {
    bs::headroom::RunConfig c;
    c.probe.realtime = false;
    c.probe.deadline_ns = 800'000;
    c.probe.cpus = {2, 3};
    c.idle_phase = false;
    const auto a = bs::headroom::headroom_cli_args(c, "", "", false);
    QVERIFY(has_word(a, "--no-rt"));
    QVERIFY(!has_word(a, "--priority"));  // asked of SCHED_FIFO only
    QCOMPARE(word_after(a, "--deadline-us"), std::string("800"));
    QCOMPARE(word_after(a, "--cpu"), std::string("2,3"));
    QVERIFY(has_word(a, "--no-idle"));
    QVERIFY(!has_word(a, "--load") && !has_word(a, "--load-command") && !has_word(a, "--platform") &&
            !has_word(a, "--power"));
  }
};

QTEST_APPLESS_MAIN(TestHeadroomCommand)
#include "test_headroom_command.moc"

#include "../../support/command_words.h"
