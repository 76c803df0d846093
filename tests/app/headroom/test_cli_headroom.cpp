// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli headroom` as a user runs it: short phases (idle and beside the FLOPS kernel) as a normal thread,
// stored in a workspace whose bookkeeping holds for every thread (checked here from the stored sparse histogram,
// independently of the code that wrote it), the non-real-time flag on every output, clear usage errors, an
// external command that dies early said so, and `platforms --require-loop` reading the measurement (a platform
// without one unknown). No latency or time is asserted.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <QProcess>
#include <cmath>
#include <filesystem>

#include "../../support/cli_harness.h"
#include "../../support/sysfs_fixture.h"
#include "store/workspace.h"

namespace {

using bs::test::cli;
using bs::test::kPaper;

// cycles == sum of the sparse [bin, count] pairs + overflows, for one thread of the --json document.
bool books_hold(const QJsonObject& thread) {
  const QJsonObject h = thread["histogram"].toObject();
  qint64 sum = 0;
  for (const auto pair : h["counts"].toArray()) sum += pair.toArray()[1].toInteger();
  return h["cycles"].toInteger() == sum + h["overflows"].toInteger() && h["cycles"].toInteger() > 0;
}

}  // namespace

class TestCliHeadroom : public QObject {
  Q_OBJECT
 private slots:
  void measures_stores_and_flags() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("w.bsw");
    const auto r = cli({"headroom", "--rate", "500", "--seconds", "0.3", "--settle", "0", "--threads", "2", "--no-rt",
                        "--load", "flops:8", "--platform", "NUC", "--workspace", ws, "--json"});
    QVERIFY2(r.code == 0, r.err.constData());
    const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
    QCOMPARE(doc["realtime"].toBool(), false);
    QVERIFY(doc["flags"].toArray().first().toString().startsWith("non-real-time"));
    const QJsonArray phases = doc["phases"].toArray();
    QCOMPARE(phases.size(), 2);
    QCOMPARE(phases[0].toObject()["name"].toString(), QString("idle"));
    QCOMPARE(phases[1].toObject()["name"].toString(), QString("flops:8"));
    QCOMPARE(phases[1].toObject()["rate_unit"].toString(), QString("GFLOPS"));
    for (const auto p : phases) {
      QCOMPARE(p.toObject()["threads"].toArray().size(), 2);
      for (const auto t : p.toObject()["threads"].toArray()) {
        QVERIFY(books_hold(t.toObject()));
        QCOMPARE(t.toObject()["policy"].toString(), QString("SCHED_OTHER"));
        QCOMPARE(t.toObject()["period_ns"].toInteger(), 2'000'000);
        QVERIFY(t.toObject()["summary"].toObject().contains("p99.9_ns"));
      }
    }
    QVERIFY2(r.err.contains("not comparable with real-time"), r.err.constData());
    bool said = false;  // the provenance says what was obtained, not only what was asked
    for (const auto kv : doc["provenance"].toObject()["settings"].toArray())
      said |= kv.toArray()[0].toString() == "realtime obtained" &&
              kv.toArray()[1].toString().startsWith("no (SCHED_OTHER)");
    QVERIFY(said);
    // The stored measurement reads back whole, its books holding.
    bs::Workspace w(ws.toStdString());
    const auto stored = w.headroom_measurements();
    QCOMPARE(stored.size(), std::size_t{1});
    QCOMPARE(QString::fromStdString(stored[0].measurement.platform), QString("NUC"));
    QCOMPARE(QString::fromStdString(stored[0].measurement.bookkeeping_error()), QString());
  }

  // With a fixture power sensor (a constant 3.96 W on the board's input rail) every phase gets its mean power, and
  // the trace is stored in the same import as the measurement.
  void power_per_phase() {
    QTemporaryDir sys, dir;
    const std::filesystem::path root = sys.path().toStdString();
    bs::test::ina3221x_channel(root, "6-0040", 0, "POM_5V_IN", 3960, 792, 5000);
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("BENCHSCOPE_NVML_LIBRARY", "none");  // the fixture's sensor only, whatever GPU is here
    p.setProcessEnvironment(env);
    const QString ws = dir.filePath("p.bsw");
    p.start(bs::test::kCli,
            {"headroom", "--seconds", "0.4", "--settle", "0", "--no-rt", "--rate", "200", "--load", "flops:4",
             "--power", "auto", "--sysfs-root", sys.path(), "--power-interval-ms", "5", "--workspace", ws, "--json"});
    QVERIFY(p.waitForFinished(300000));
    const QByteArray out = p.readAllStandardOutput();
    QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
    const QJsonArray phases = QJsonDocument::fromJson(out).object()["phases"].toArray();
    QCOMPARE(phases.size(), 2);
    for (const auto ph : phases) {
      QVERIFY2(std::fabs(ph.toObject()["mean_power_w"].toDouble() - 3.96) < 1e-6, out.constData());
      QVERIFY(ph.toObject()["power_sensor"].toString().contains("POM_5V_IN"));
    }
    bs::Workspace w(ws.toStdString());
    QCOMPARE(w.headroom_measurements().size(), std::size_t{1});
    QCOMPARE(w.power_trace_summaries().size(), std::size_t{1});
    QCOMPARE(w.power_trace_summaries()[0].import_id, w.headroom_measurements()[0].import_id);
  }

  void prints_the_table() {
    const auto r = cli({"headroom", "--seconds", "0.2", "--no-rt", "--rate", "200"});
    QVERIFY2(r.code == 0, r.err.constData());
    for (const char* text : {"NON-REAL-TIME", "p99.9", "Longest miss run", "idle", "kernel ", "probe CPU time"})
      QVERIFY2(r.out.contains(text), (std::string(text) + " missing in:\n" + r.out.toStdString()).c_str());
  }

  void usage_errors_name_the_option() {
    auto r = cli({"headroom", "--rate", "20000"});
    QCOMPARE(r.code, 2);
    QVERIFY(r.err.contains("--rate must be from 50 to 10000 Hz"));
    r = cli({"headroom", "--load", "pipeline,warp-drive"});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains("load 'warp-drive': unknown load 'warp-drive'"), r.err.constData());
    r = cli({"headroom", "--computation-us", "1000"});
    QCOMPARE(r.code, 2);
    QVERIFY(r.err.contains("below the period (1000 us)"));
    r = cli({"headroom", "--load-command", "stress-ng 'unclosed"});
    QCOMPARE(r.code, 2);
    QVERIFY(r.err.contains("unclosed '"));
  }

  void a_command_that_dies_early_is_said() {
    const auto r = cli(
        {"headroom", "--seconds", "0.3", "--settle", "0", "--no-rt", "--no-idle", "--load-command", "true", "--json"});
    QVERIFY2(r.code == 0, r.err.constData());
    const QJsonObject phase = QJsonDocument::fromJson(r.out).object()["phases"].toArray()[0].toObject();
    QCOMPARE(phase["name"].toString(), QString("true"));
    QCOMPARE(phase["load"].toString(), QString("command"));
    bool said = false;
    for (const auto n : phase["notes"].toArray())
      said |= n.toString().contains("exited (status 0) before the phase ended");
    QVERIFY2(said, r.out.constData());
  }

  void platforms_require_loop() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("w.bsw");
    QCOMPARE(cli({"import", ws, kPaper}).code, 0);
    QCOMPARE(
        cli({"headroom", "--rate", "500", "--seconds", "0.3", "--no-rt", "--platform", "NUC", "--workspace", ws}).code,
        0);
    const auto r =
        cli({"platforms", ws, "--require-loop", "500Hz,p99.9<=100ms,max-consecutive-misses<=1000", "--json"});
    QVERIFY2(r.code == 0, r.err.constData());
    const QJsonObject loop = QJsonDocument::fromJson(r.out).object()["control_loop"].toObject();
    QCOMPARE(loop["described"].toString(), QString("500 Hz, p99.9 <= 100000 us, max consecutive misses <= 1000, in "
                                                   "every phase"));
    QString nuc, jetson, jetson_reason;
    for (const auto v : loop["platforms"].toArray()) {
      const QJsonObject p = v.toObject();
      if (p["platform"] == "NUC") nuc = p["status"].toString();
      if (p["platform"] == "Jetson TX2") jetson = p["status"].toString(), jetson_reason = p["reason"].toString();
    }
    QVERIFY2(nuc == "passes" || nuc == "FAILS", qPrintable(nuc));  // measured: a verdict, whichever it is
    QCOMPARE(jetson, QString("unknown"));
    QCOMPARE(jetson_reason, QString("no headroom measurement"));
    // Unknown is never passing: the Jetson no longer meets every constraint.
    for (const auto v : QJsonDocument::fromJson(r.out).object()["platforms"].toArray())
      if (v.toObject()["platform"] == "Jetson TX2") QCOMPARE(v.toObject()["meets_constraints"].toBool(), false);
    const auto text = cli({"platforms", ws, "--require-loop", "500Hz,p99.9<=100ms"});
    QVERIFY2(text.out.contains("control loop: 500 Hz, p99.9 <= 100000 us") && text.out.contains("unknown"),
             text.out.constData());
    const auto bad = cli({"platforms", ws, "--require-loop", "p99<=1us"});
    QCOMPARE(bad.code, 2);
    QVERIFY(bad.err.contains("no loop rate"));
  }

  // Issue #50.4: a load that falls more than 5 % short of its target was not applied: the loop result beside it is
  // unknown, whatever its numbers. pipeline@1000fps cannot be reached on any machine this runs on (the pipeline's
  // 1280x1024 frames take milliseconds each), so it always falls short.
  void a_load_short_of_its_target_is_not_applied() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("w.bsw");
    QCOMPARE(cli({"import", ws, kPaper}).code, 0);
    const auto measured = cli({"headroom", "--rate", "500", "--seconds", "0.5", "--settle", "0", "--no-rt", "--no-idle",
                               "--load", "pipeline@1000fps", "--platform", "NUC", "--workspace", ws});
    QVERIFY2(measured.code == 0, measured.err.constData());
    QVERIFY2(measured.out.contains("flag: load not applied: pipeline@1000fps ran at"), measured.out.constData());
    QVERIFY2(measured.out.contains("of 1000 fps (not applied)"), measured.out.constData());
    const auto r = cli({"platforms", ws, "--require-loop", "500Hz,p99.9<=1000ms,load=pipeline@1000fps", "--json"});
    QVERIFY2(r.code == 0, r.err.constData());
    const QJsonObject doc = QJsonDocument::fromJson(r.out).object();
    QString status, reason;
    for (const auto v : doc["control_loop"].toObject()["platforms"].toArray())
      if (v.toObject()["platform"] == "NUC")
        status = v.toObject()["status"].toString(), reason = v.toObject()["reason"].toString();
    QCOMPARE(status, QString("unknown"));
    QVERIFY2(reason.startsWith("load not applied: pipeline@1000fps ran at"), qPrintable(reason));
    for (const auto v : doc["platforms"].toArray())
      if (v.toObject()["platform"] == "NUC") QCOMPARE(v.toObject()["meets_constraints"].toBool(), false);
  }
};

QTEST_GUILESS_MAIN(TestCliHeadroom)
#include "test_cli_headroom.moc"
