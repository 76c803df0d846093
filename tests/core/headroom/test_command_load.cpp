// SPDX-License-Identifier: GPL-3.0-or-later
// The external-command load: its command line split without a shell, stress-ng's metrics read (the lines as
// stress-ng 0.15 printed them on this machine, and the older "info:" tag), a real process started, heard and stopped
// with its whole process group, one that exits early said so, and a missing program refused with its name.
#include <QTest>

#include "headroom/command_load.h"

using namespace bs::headroom;

class TestCommandLoad : public QObject {
  Q_OBJECT
 private slots:
  void splits_like_a_shell_without_one() {
    QCOMPARE(split_command("stress-ng --cpu 2  --metrics-brief"),
             (std::vector<std::string>{"stress-ng", "--cpu", "2", "--metrics-brief"}));
    QCOMPARE(split_command("sh -c 'echo a b' \"x\\\"y\" z\\ w"),
             (std::vector<std::string>{"sh", "-c", "echo a b", "x\"y", "z w"}));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, split_command("a 'b"));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, split_command("   "));
  }

  void reads_stress_ng_metrics() {
    const std::string out =
        "stress-ng: info:  [32138] dispatching hogs: 1 cpu\n"
        "stress-ng: metrc: [32138] stressor       bogo ops real time  usr time  sys time   bogo ops/s     bogo ops/s\n"
        "stress-ng: metrc: [32138]                           (secs)    (secs)    (secs)   (real time) (usr+sys time)\n"
        "stress-ng: metrc: [32138] cpu                2290      1.51      1.30      0.00      1520.69        1760.56\n"
        "stress-ng: info:  [32138] successful run completed in 1.51s\n";
    StressNgMetrics m = parse_stress_ng_metrics(out);
    QCOMPARE(*m.bogo_ops_per_s, 1520.69);
    QCOMPARE(m.per_stressor, (std::vector<std::string>{"cpu: 1520.69 bogo ops/s"}));
    // Two different stressors: their bogo ops do not add up, so no single rate.
    const std::string two =
        "stress-ng: info:  [7] stressor       bogo ops real time  usr time  sys time   bogo ops/s   bogo ops/s\n"
        "stress-ng: info:  [7]                           (secs)    (secs)    (secs)   (real time) (usr+sys time)\n"
        "stress-ng: info:  [7] cpu                 100      1.00      1.00      0.00       100.00       100.00\n"
        "stress-ng: info:  [7] vm                   50      1.00      0.50      0.50        50.00        50.00\n";
    m = parse_stress_ng_metrics(two);
    QVERIFY(!m.bogo_ops_per_s);
    QCOMPARE(m.per_stressor.size(), std::size_t{2});
    QVERIFY(!parse_stress_ng_metrics("no metrics here\n").bogo_ops_per_s);
  }

  void starts_hears_and_stops_a_process_group() {
    // A shell that forks a child and waits: SIGINT to the group must end both.
    CommandLoad load({"sh", "-c", "echo started; sleep 600 & wait"});
    QCOMPARE(QString::fromStdString(load.name()), QString("sh -c 'echo started; sleep 600 & wait'"));
    load.start();
    QVERIFY(!load.has_exited());
    const LoadReport r = load.stop();
    QVERIFY(!r.achieved_rate);
    for (const std::string& n : r.notes) QVERIFY2(n.find("exited") == std::string::npos, n.c_str());
    // What a command printed is kept: read to its end once it is over.
    CommandLoad talker({"sh", "-c", "echo said && echo to-stderr >&2"});
    talker.start();
    QTRY_VERIFY(talker.has_exited());
    (void)talker.stop();
    QVERIFY2(talker.output().find("said\n") != std::string::npos, talker.output().c_str());
    QVERIFY2(talker.output().find("to-stderr") != std::string::npos, talker.output().c_str());
  }

  void early_exit_and_missing_program() {
    CommandLoad quick({"true"});
    quick.start();
    QTRY_VERIFY(quick.has_exited());  // it ends by itself, before its phase would
    const LoadReport r = quick.stop();
    QVERIFY(!r.notes.empty());
    QVERIFY2(r.notes.front().find("true exited (status 0) before the phase ended") == 0, r.notes.front().c_str());
    CommandLoad missing({"benchscope-no-such-program"});
    try {
      missing.start();
      QFAIL("a missing program started");
    } catch (const std::runtime_error& e) {
      QVERIFY2(QString(e.what()).startsWith("benchscope-no-such-program: cannot start"), e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestCommandLoad)
#include "test_command_load.moc"
