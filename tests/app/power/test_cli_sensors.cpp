// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope-cli sensors / record-power / run flops --power on fixture sysfs trees (no hardware needed).
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <csignal>

#include "../../support/sysfs_fixture.h"

namespace {

const QString kCli = BENCHSCOPE_BINARY_DIR "/app/cli/benchscope-cli";

struct Result {
  int code;
  QByteArray out, err;
};

// NVML off: the tests see the fixture tree only, whatever GPU the machine has.
void no_nvml(QProcess& p) {
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("BENCHSCOPE_NVML_LIBRARY", "none");
  p.setProcessEnvironment(env);
}

Result cli(const QStringList& args) {
  QProcess p;
  no_nvml(p);
  p.start(kCli, args);
  p.waitForFinished(120000);
  return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
          p.readAllStandardError()};
}

QByteArray bytes_of(const QString& path) {
  QFile f(path);
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// A Jetson Nano's INA3221 (JetPack 4 layout) drawing a constant 3.96 W on its input rail.
void nano(const QString& root) {
  const std::filesystem::path r = root.toStdString();
  bs::test::ina3221x_channel(r, "6-0040", 0, "POM_5V_IN", 3960, 792, 5000);
  bs::test::ina3221x_channel(r, "6-0040", 1, "POM_5V_GPU", 0, 0, 5000);
  bs::test::ina3221x_channel(r, "6-0040", 2, "POM_5V_CPU", 1068, 213, 5000);
}

}  // namespace

class TestCliSensors : public QObject {
  Q_OBJECT
 private slots:
  void no_sensor_at_all() {
    QTemporaryDir dir;
    const Result r = cli({"sensors", "--sysfs-root", dir.path()});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.startsWith("no power sensors found"), r.out.constData());
    const Result rec =
        cli({"record-power", "--sysfs-root", dir.path(), "--out", dir.filePath("x.csv"), "--seconds", "0.1"});
    QCOMPARE(rec.code, 2);
    QVERIFY(rec.err.contains("no power sensors found"));
  }

  void lists_sensors_as_table_and_json() {
    QTemporaryDir dir;
    nano(dir.path());
    const std::filesystem::path r = dir.path().toStdString();
    bs::test::rapl_package(r, 0, 1000, 262143328850);
    const Result table = cli({"sensors", "--sysfs-root", dir.path()});
    QCOMPARE(table.code, 0);
    QVERIFY(table.out.contains("ina3221:6-0040:POM_5V_IN") && table.out.contains("rapl:package-0"));
    const Result json = cli({"sensors", "--sysfs-root", dir.path(), "--json"});
    QCOMPARE(json.code, 0);
    const QJsonArray list = QJsonDocument::fromJson(json.out).object()["sensors"].toArray();
    QCOMPARE(list.size(), 4);
    QCOMPARE(list[0].toObject()["id"].toString(), QString("rapl:package-0"));
    QCOMPARE(list[0].toObject()["unit"].toString(), QString("uJ"));
    QCOMPARE(list[1].toObject()["label"].toString(), QString("POM_5V_IN"));
    QVERIFY(list[1].toObject()["board_total"].toBool());
    QVERIFY(list[1].toObject()["readable"].toBool());
  }

  void record_for_seconds_and_import_back() {
    QTemporaryDir dir;
    nano(dir.path());
    const QString csv = dir.filePath("nano.csv");
    const Result r =
        cli({"record-power", "--sysfs-root", dir.path(), "--out", csv, "--seconds", "0.5", "--interval-ms", "50"});
    QCOMPARE(r.code, 0);
    // Constant 3.96 W: the whole recording's mean power is exactly that.
    QVERIFY2(r.out.contains("mean 3.960 W"), r.out.constData());
    const QByteArray text = bytes_of(csv);
    QVERIFY(text.startsWith("# benchscope power recording v1\n"));
    QVERIFY(text.contains("# kind: ina3221"));
    QVERIFY(text.contains("# total_channel: POM_5V_IN"));
    QVERIFY(text.contains("# start_time: 20"));
    QVERIFY(text.contains("time_s,POM_5V_IN power (W),POM_5V_GPU power (W),POM_5V_CPU power (W)"));
    QVERIFY(text.contains(",3.96,0,1.068\n"));
    const Result imp = cli({"import", dir.filePath("w.bsw"), csv});
    QVERIFY2(imp.code == 0, imp.err.constData());
    const Result power = cli({"power", csv});
    QVERIFY2(power.code == 0, power.err.constData());
  }

  void record_while_a_command_runs_passes_its_status_on() {
    QTemporaryDir dir;
    nano(dir.path());
    const QString csv = dir.filePath("cmd.csv");
    const Result r = cli({"record-power", "--sysfs-root", dir.path(), "--out", csv, "--interval-ms", "20", "--", "sh",
                          "-c", "sleep 0.2; exit 3"});
    QCOMPARE(r.code, 3);
    QVERIFY(bytes_of(csv).contains("# phase: sh = 0."));
    QCOMPARE(cli({"record-power", "--sysfs-root", dir.path(), "--out", csv, "--", "/no/such/program"}).code, 127);
    QCOMPARE(cli({"record-power", "--sysfs-root", dir.path(), "--out", csv}).code,
             2);  // neither --seconds nor a command
  }

  void ctrl_c_keeps_what_was_recorded() {
    QTemporaryDir dir;
    nano(dir.path());
    const QString csv = dir.filePath("int.csv");
    QProcess p;
    no_nvml(p);
    p.start(kCli, {"record-power", "--sysfs-root", dir.path(), "--out", csv, "--seconds", "60", "--interval-ms", "20"});
    QVERIFY(p.waitForStarted());
    // Once it says it is recording, Ctrl+C is handled (before that the default action would kill it).
    p.setReadChannel(QProcess::StandardError);
    QByteArray said;
    while (!said.contains("recording power from") && p.waitForReadyRead(10000)) said += p.readAllStandardError();
    QVERIFY(said.contains("recording power from"));
    QTest::qWait(500);
    ::kill(static_cast<pid_t>(p.processId()), SIGINT);
    QVERIFY(p.waitForFinished(10000));
    QCOMPARE(p.exitCode(), 130);
    const QByteArray text = bytes_of(csv);
    QVERIFY(text.count('\n') > 12);  // ~25 samples in 0.5 s (fewer on a loaded machine), plus 10 comment lines
  }

  void run_flops_with_power_gives_energy_per_point() {
    QTemporaryDir dir;
    nano(dir.path());
    const QString json = dir.filePath("run.json");
    const Result r = cli({"run",
                          "flops",
                          "--backend",
                          "cpu",
                          "--points",
                          "4",
                          "--workers",
                          "64,128",
                          "--iterations",
                          "20000",
                          "--repeats",
                          "2",
                          "--power",
                          "auto",
                          "--power-interval-ms",
                          "10",
                          "--sysfs-root",
                          dir.path(),
                          "--out",
                          json,
                          "--workspace",
                          dir.filePath("w.bsw"),
                          "--quiet"});
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.contains("energy per sweep point (on-board sensor: ina3221 POM_5V_IN"), r.out.constData());
    QVERIFY(r.out.contains("warm-up D=4") && r.out.contains("point W=128 D=4"));
    // Mean power of every phase is the fixture's constant 3.96 W.
    QVERIFY(r.out.contains("3.960"));
    const QByteArray csv = bytes_of(dir.filePath("run.power.csv"));
    QVERIFY(csv.contains("# phase: point W=64 D=4 = "));
    QVERIFY(csv.contains("# measurement: on-board sensor"));
  }
};

QTEST_GUILESS_MAIN(TestCliSensors)
#include "test_cli_sensors.moc"
