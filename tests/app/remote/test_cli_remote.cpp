// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli remote` through a real OpenSSH server on a local port (issue #44): the robot is this machine
// running the built benchscope-cli. A sweep (with power) and a power recording from a fixture sensor tree come
// home with their provenance; a cancel brings the completed part; the faults (server killed mid-run, wrong key,
// unknown host key, CLI missing or too old, garbage on stdout) each give a clear error and leave the workspace as
// it was; and after each, nothing of the job is left running on the robot. Skipped (CTest skip) without sshd.
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTest>

#include <signal.h>

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "../../support/cli_harness.h"
#include "../../support/ssh_robot.h"
#include "../../support/sysfs_fixture.h"
#include "remote/robot_check.h"
#include "store/workspace.h"

using bs::test::kCli;

namespace {

bs::test::SshRobot* g_robot = nullptr;

// The robot's CLI: this build's, or one named by BENCHSCOPE_TEST_ROBOT_CLI: scripts/cross-test gives a wrapper that
// runs the aarch64 build under qemu-user, and BENCHSCOPE_TEST_ROBOT_ARCH ("aarch64") for the robot to report.
const QString kRobotCli = qEnvironmentVariable("BENCHSCOPE_TEST_ROBOT_CLI", kCli);
const QString kRobotArch = qEnvironmentVariable("BENCHSCOPE_TEST_ROBOT_ARCH");

QProcessEnvironment desk_env() {
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.insert("XDG_CONFIG_HOME", g_robot->path("desk-config"));
  env.insert("BENCHSCOPE_NVML_LIBRARY", "none");
  return env;
}

// benchscope-cli remote robot ARGS... with the test's ssh config and the built CLI as the robot's.
QStringList remote_args(const QStringList& args, const QString& config = {}) {
  return QStringList{"remote", "robot"} + args +
         QStringList{"--ssh-config", config.isEmpty() ? g_robot->config() : config, "--remote-cli", kRobotCli};
}

bs::test::CliResult desk(const QStringList& args) {
  QProcess p;
  p.setProcessEnvironment(desk_env());
  p.start(kCli, args);
  if (!p.waitForFinished(300000)) {
    p.kill();
    p.waitForFinished();
    return {-2, p.readAllStandardOutput(), p.readAllStandardError()};
  }
  return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
          p.readAllStandardError()};
}

nlohmann::json job_record(const QString& id) {
  std::ifstream in((g_robot->jobs_dir() + "/" + id + "/job.json").toStdString());
  return nlohmann::json::parse(in, nullptr, false);
}

// No process on this machine (the robot) has the job id on its command line: nothing of the job runs on.
bool nothing_left_of(const QString& id) {
  for (int poll = 0; poll < 300; ++poll) {
    bool found = false;
    for (const QString& name : QDir("/proc").entryList(QDir::Dirs)) {
      QFile f("/proc/" + name + "/cmdline");
      if (!f.open(QIODevice::ReadOnly)) continue;
      const QByteArray cmd = f.readAll().replace('\0', ' ');
      if (cmd.contains(("--id " + id + " ").toUtf8()) && cmd.contains("job run") &&
          bs::test::process_running(name.toLongLong()))
        found = true;
    }
    if (!found) return true;
    QTest::qWait(20);
  }
  return false;
}

// The job's agent and measurement (from its record) have stopped, and no process carries its id.
void verify_nothing_running(const QString& id) {
  const nlohmann::json rec = job_record(id);
  if (rec.is_object()) {
    QVERIFY(bs::test::wait_until_gone(rec.value("agent_pid", 0LL)));
    QVERIFY(bs::test::wait_until_gone(rec.value("child_pid", 0LL)));
  }
  QVERIFY2(nothing_left_of(id), qPrintable("a process of job " + id + " still runs"));
}

// A workspace with one import, to show that a failed remote run leaves its bytes as they were.
QString existing_workspace(const QString& name) {
  const QString ws = g_robot->path(name);
  const auto r = bs::test::cli({"import", ws, BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/gpu-nuc.json"});
  if (r.code != 0) qWarning() << r.err;
  return ws;
}

QString script(const QString& name, const QString& body) {
  const QString path = g_robot->path(name);
  QFile f(path);
  f.open(QIODevice::WriteOnly | QIODevice::Truncate);
  f.write(("#!/bin/sh\n" + body).toUtf8());
  f.close();
  f.setPermissions(QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
  return path;
}

// Starts the desk's command and waits until it has reported `points` sweep points (counting its lines).
bool wait_for_points(QProcess& p, int points, QByteArray& err) {
  for (int i = 0; i < 3000 && err.count(": D = ") < points; ++i) {
    if (!p.waitForReadyRead(100) && p.state() != QProcess::Running) break;
    err += p.readAllStandardError();
  }
  return err.count(": D = ") >= points;
}

const QStringList kLongSweep = {"run",       "flops",     "--backend",  "cpu-scalar",   "--points",
                                "1",         "--workers", "1:20000:1",  "--iterations", "2000",
                                "--repeats", "1",         "--no-warmup"};

}  // namespace

class TestCliRemote : public QObject {
  Q_OBJECT
 private slots:
  void check_describes_the_robot() {
    const auto r = desk(remote_args({"check"}));
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(r.out.contains("robot: reachable; host name"));
    QVERIFY(r.out.contains("BenchScope " BENCHSCOPE_VERSION));
    QVERIFY(r.out.contains("backend cpu-scalar"));
    if (!kRobotArch.isEmpty()) QVERIFY2(r.out.contains(kRobotArch.toUtf8()), r.out.constData());
    // The contact is remembered in the robots list, with what was found.
    const auto list = desk({"remote", "list", "--ssh-config", g_robot->config()});
    QCOMPARE(list.code, 0);
    QVERIFY2(list.out.contains("robot") && list.out.contains("ssh config") && list.out.contains(BENCHSCOPE_VERSION),
             list.out.constData());
  }

  void sweep_with_power_comes_home_with_provenance() {
    QTemporaryDir sys;
    const std::filesystem::path root = sys.path().toStdString();
    bs::test::ina3221_hwmon_channel(root, bs::test::ina3221_hwmon_dir("1-0040", 3), 1, "VDD_IN", 5000, 1000);
    const QString ws = g_robot->path("sweep.bsw");
    const auto r =
        desk(remote_args({"run",         "flops", "--backend",           "cpu-scalar", "--points",     "1",
                          "--workers",   "1,2,4", "--iterations",        "1000",       "--repeats",    "2",
                          "--power",     "auto",  "--power-interval-ms", "20",         "--sysfs-root", sys.path(),
                          "--workspace", ws,      "--platform",          "Robot 7",    "--id",         "sweep-1"}));
    QVERIFY2(r.code == 0, r.err.constData());
    QCOMPARE(r.err.count(": D = 1, W = "), 3);  // each point as it came
    QVERIFY(r.err.contains("power readings streamed"));
    QVERIFY2(r.out.contains("imported 1 run, 1 power log from robot"), r.out.constData());
    QVERIFY(r.out.contains("as platform 'Robot 7'"));
    const bs::Workspace w(ws.toStdString(), bs::Workspace::OpenMode::ReadOnly);
    const auto runs = w.runs();
    QCOMPARE(runs.size(), std::size_t{1});
    QCOMPARE(w.imports().size(), std::size_t{1});  // the run and its power log in one import
    const bs::FlopsRun& run = runs[0].run;
    QCOMPARE(run.platform, std::string("Robot 7"));
    QCOMPARE(run.samples.size(), std::size_t{3});
    QVERIFY(run.samples[0].seconds.size() >= 2);
    const auto setting = [&](const std::string& key) {
      for (const auto& [k, v] : run.provenance.settings)
        if (k == key) return v;
      return std::string();
    };
    QCOMPARE(setting("remote host"), std::string("robot"));
    QCOMPARE(setting("remote BenchScope"), std::string(BENCHSCOPE_VERSION));
    QCOMPARE(setting("remote job"), std::string("sweep-1"));
    QVERIFY(!setting("remote architecture").empty());
    if (!kRobotArch.isEmpty()) QCOMPARE(setting("remote architecture"), kRobotArch.toStdString());
    QVERIFY(setting("remote command").find("run flops --backend cpu-scalar") != std::string::npos);
    QVERIFY(setting("remote devices").find("CPU scalar") != std::string::npos);
    QVERIFY(setting("remote devices").find("VDD_IN") != std::string::npos);
    const auto traces = w.power_traces();
    QCOMPARE(traces.size(), std::size_t{1});
    QCOMPARE(traces[0].trace.platform, std::string("Robot 7"));
    QCOMPARE(traces[0].import_id, runs[0].import_id);
    for (const bs::PowerChannel& c : traces[0].trace.channels)
      if (c.name == traces[0].trace.total_channel)
        for (double v : c.values) QCOMPARE(v, 5.0);  // 5000 mV x 1000 mA
    verify_nothing_running("sweep-1");
    QCOMPARE(QString::fromStdString(job_record("sweep-1").value("status", "")), QString("done"));
    // The robots list says what ran there.
    const auto list = desk({"remote", "list", "--ssh-config", g_robot->config()});
    QVERIFY2(list.out.contains("run flops") && list.out.contains("imported 1 run, 1 power log"), list.out.constData());
    // Fetching it again is recognised as the same results: refused, the workspace unchanged.
    const QByteArray before = bs::test::bytes_of(ws);
    const auto again = desk(remote_args({"fetch", "sweep-1", "--workspace", ws}));
    QCOMPARE(again.code, 1);
    QVERIFY2(again.err.contains("already"), again.err.constData());
    QCOMPARE(bs::test::bytes_of(ws), before);
  }

  void power_recording_from_a_fixture_tree() {
    QTemporaryDir sys;
    const std::filesystem::path root = sys.path().toStdString();
    bs::test::ina3221_hwmon_channel(root, bs::test::ina3221_hwmon_dir("1-0040", 3), 1, "VDD_IN", 12000, 500);
    const QString ws = g_robot->path("power.bsw");
    const auto r = desk(remote_args({"record-power", "--seconds", "0.5", "--interval-ms", "25", "--sysfs-root",
                                     sys.path(), "--workspace", ws, "--id", "power-1"}));
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.out.contains("imported 1 power log from robot"), r.out.constData());
    QVERIFY(r.out.contains("mean 6.000 W"));  // the result event, printed at the desk
    const bs::Workspace w(ws.toStdString(), bs::Workspace::OpenMode::ReadOnly);
    const auto traces = w.power_traces();
    QCOMPARE(traces.size(), std::size_t{1});
    const bs::PowerTrace& t = traces[0].trace;
    QVERIFY(t.time_s.size() >= 10);
    QVERIFY(t.provenance.sensor.find("VDD_IN") != std::string::npos);
    bool remote = false;
    for (const auto& [k, v] : t.provenance.settings) remote |= k == "remote host" && v == "robot";
    QVERIFY(remote);
    for (const bs::PowerChannel& c : t.channels)
      if (c.name == t.total_channel)
        for (double v : c.values) QCOMPARE(v, 6.0);  // 12 V x 0.5 A
    verify_nothing_running("power-1");
  }

  void cancel_brings_the_completed_points() {
    const QString ws = g_robot->path("cancel.bsw");
    QProcess p;
    p.setProcessEnvironment(desk_env());
    p.start(kCli, remote_args(kLongSweep + QStringList{"--workspace", ws, "--id", "cancel-1"}));
    QByteArray err;
    QVERIFY2(wait_for_points(p, 3, err), err.constData());
    p.terminate();  // SIGTERM, as Ctrl+C: the desk asks the robot to stop
    QVERIFY(p.waitForFinished(120000));
    err += p.readAllStandardError();
    const QByteArray out = p.readAllStandardOutput();
    QCOMPARE(p.exitCode(), 1);  // cancelled, as a local run: the completed points are kept
    QVERIFY2(err.contains("job cancel-1 was cancelled"), err.constData());
    QVERIFY2(out.contains("imported 1 run from robot"), out.constData());
    const bs::Workspace w(ws.toStdString(), bs::Workspace::OpenMode::ReadOnly);
    QCOMPARE(w.runs().size(), std::size_t{1});
    const std::size_t points = w.runs()[0].run.samples.size();
    QVERIFY(points >= 3 && points < 20000);
    QCOMPARE(QString::fromStdString(job_record("cancel-1").value("status", "")), QString("cancelled"));
    verify_nothing_running("cancel-1");
  }

  void server_killed_mid_run_leaves_the_workspace_and_the_robot_clean() {
    const QString ws = existing_workspace("killed.bsw");
    const QByteArray before = bs::test::bytes_of(ws);
    QVERIFY(!before.isEmpty());
    QProcess p;
    p.setProcessEnvironment(desk_env());
    p.start(kCli, remote_args(kLongSweep + QStringList{"--workspace", ws, "--id", "killed-1"}));
    QByteArray err;
    QVERIFY2(wait_for_points(p, 2, err), err.constData());
    g_robot->kill_server();
    QVERIFY(p.waitForFinished(120000));
    err += p.readAllStandardError();
    QCOMPARE(p.exitCode(), 1);
    QVERIFY2(err.contains("robot: the connection to the robot was lost"), err.constData());
    QVERIFY(err.contains("Nothing was imported"));
    QVERIFY(err.contains("remote robot fetch killed-1"));
    QCOMPARE(bs::test::bytes_of(ws), before);
    verify_nothing_running("killed-1");
    QCOMPARE(QString::fromStdString(job_record("killed-1").value("status", "")), QString("interrupted"));
    // Back up: what the robot completed before it stopped is fetched and imported.
    QCOMPARE(g_robot->start_sshd(), QString());
    const auto fetched = desk(remote_args({"fetch", "killed-1", "--workspace", ws}));
    QVERIFY2(fetched.out.contains("fetched 1 run from robot"), (fetched.out + fetched.err).constData());
    const bs::Workspace w(ws.toStdString(), bs::Workspace::OpenMode::ReadOnly);
    QCOMPARE(w.imports().size(), std::size_t{2});
  }

  void login_faults_name_the_host_and_what_ssh_said() {
    const QString ws = existing_workspace("faults.bsw");
    const QByteArray before = bs::test::bytes_of(ws);
    const QString fresh = g_robot->path("never.bsw");
    struct Case {
      QString config;
      const char* expected;
      const char* ssh_said;
    };
    for (const Case& c : {Case{g_robot->wrong_key_config(), "robot: the robot refused the login", "Permission denied"},
                          Case{g_robot->unknown_host_config(), "robot: the robot's host key is not known here",
                               "Host key verification failed"}}) {
      for (const QString& target : {ws, fresh}) {
        const auto r = desk(remote_args({"run", "flops", "--workers", "1", "--workspace", target}, c.config));
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(c.expected) && r.err.contains(c.ssh_said), r.err.constData());
      }
      QCOMPARE(bs::test::bytes_of(ws), before);
      QVERIFY(!QFile::exists(fresh));
    }
    // The check says the same, and the robots list remembers the failed contact.
    const auto check = desk(remote_args({"check"}, g_robot->wrong_key_config()));
    QCOMPARE(check.code, 1);
    QVERIFY(check.err.contains("never with a password"));
  }

  void missing_or_old_cli_gives_the_install_command() {
    const QString ws = g_robot->path("cli.bsw");
    const QString install = "sudo apt install ./benchscope-cli_" BENCHSCOPE_VERSION "_";
    auto r = desk(QStringList{"remote", "robot", "run", "flops", "--workspace", ws, "--ssh-config", g_robot->config(),
                              "--remote-cli", "/nonexistent/benchscope-cli"});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("BenchScope's CLI is not installed there"), r.err.constData());
    QVERIFY(r.err.contains(install.toUtf8()));
    const QString old = script("old-cli",
                               "if [ \"$1\" = --version ]; then echo 'benchscope-cli 0.0.1'; exit 0; fi\n"
                               "exec '" +
                                   kRobotCli + "' \"$@\"\n");
    r = desk(QStringList{"remote", "robot", "run", "flops", "--workspace", ws, "--ssh-config", g_robot->config(),
                         "--remote-cli", old});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains("its BenchScope CLI is 0.0.1, older than this desk's " BENCHSCOPE_VERSION),
             r.err.constData());
    QVERIFY(r.err.contains(install.toUtf8()));
    QVERIFY(!QFile::exists(ws));
  }

  void garbage_on_stdout_stops_the_job_and_imports_nothing() {
    const QString ws = existing_workspace("garbage.bsw");
    const QByteArray before = bs::test::bytes_of(ws);
    // The real agent, with a line of garbage slipped into its stream after a few events.
    const QString noisy = script("noisy-cli",
                                 "if [ \"$1\" = job ] && [ \"$2\" = run ]; then\n"
                                 "  '" +
                                     kRobotCli +
                                     "' \"$@\" | awk 'NR == 6 { print \"hello from the robot\" }"
                                     " { print; fflush() }'\n  exit $?\nfi\nexec '" +
                                     kRobotCli + "' \"$@\"\n");
    QProcess p;
    p.setProcessEnvironment(desk_env());
    p.start(kCli, QStringList{"remote", "robot"} + kLongSweep +
                      QStringList{"--workspace", ws, "--id", "garbage-1", "--ssh-config", g_robot->config(),
                                  "--remote-cli", noisy});
    QVERIFY(p.waitForFinished(120000));
    const QByteArray err = p.readAllStandardError();
    QCOMPARE(p.exitCode(), 1);
    QVERIFY2(err.contains("robot: the robot wrote something that is not a BenchScope event on its output (line 6: "
                          "\"hello from the robot\": not JSON)"),
             err.constData());
    QVERIFY(err.contains("Nothing was imported"));
    QCOMPARE(bs::test::bytes_of(ws), before);
    verify_nothing_running("garbage-1");
  }

  // The control loop measured on the robot (issues #44, #45): idle, then beside the FLOPS kernel, run by the robot's
  // CLI; the measurement comes home under the platform named, with the robot's provenance.
  void headroom_comes_home_with_provenance() {
    const QString ws = g_robot->path("headroom.bsw");
    const auto r =
        desk(remote_args({"headroom", "--rate", "500", "--seconds", "0.4", "--settle", "0", "--no-rt", "--load",
                          "flops:1", "--workspace", ws, "--platform", "Robot loop", "--id", "headroom-1"}));
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.err.contains("headroom phase 'idle'"), r.err.constData());  // the robot's phases as they start
    QVERIFY2(r.out.contains("imported 1 headroom measurement from robot"), r.out.constData());
    const bs::Workspace w(ws.toStdString(), bs::Workspace::OpenMode::ReadOnly);
    const auto stored = w.headroom_measurements();
    QCOMPARE(stored.size(), std::size_t{1});
    const auto& m = stored[0].measurement;
    QCOMPARE(m.platform, std::string("Robot loop"));
    QCOMPARE(m.phases.size(), std::size_t{2});
    QVERIFY(!m.realtime());  // --no-rt: a normal thread, and the measurement says so
    std::string host, command, arch;
    for (const auto& [k, v] : m.provenance.settings) {
      if (k == "remote host") host = v;
      if (k == "remote command") command = v;
      if (k == "remote architecture") arch = v;
    }
    QCOMPARE(host, std::string("robot"));
    QVERIFY2(command.find("headroom --rate 500") != std::string::npos, command.c_str());
    QVERIFY(!arch.empty());
    if (!kRobotArch.isEmpty()) QCOMPARE(arch, kRobotArch.toStdString());
    verify_nothing_running("headroom-1");
  }

  // The Pipeline tab's measurement on the robot (issue #44): the robot renders the synthetic capture itself (no
  // frame travels), reports its progress, and the run comes home with the robot's provenance under the platform named.
  void synthetic_pipeline_comes_home_with_provenance() {
    const QString ws = g_robot->path("pipeline.bsw");
    const auto r =
        desk(remote_args({"pipeline", "--synthetic", "--frames", "3", "--detector", "none", "--detect-workers", "1",
                          "--workspace", ws, "--platform", "Robot eyes", "--id", "pipeline-1"}));
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.err.contains("captured 3 of 3 frames"), r.err.constData());  // the robot's progress, as it came
    QVERIFY2(r.out.contains("imported 1 pipeline run from robot"), r.out.constData());
    const bs::Workspace w(ws.toStdString(), bs::Workspace::OpenMode::ReadOnly);
    const auto stored = w.pipeline_runs();
    QCOMPARE(stored.size(), std::size_t{1});
    const bs::PipelineRun& run = stored[0].run;
    QCOMPARE(run.platform, std::string("Robot eyes"));
    QCOMPARE(run.detector, std::string("none"));
    QVERIFY(run.stage(bs::pipeline_stage::kPreprocess));
    QCOMPARE(run.stage(bs::pipeline_stage::kPreprocess)->n, std::size_t{3});
    QVERIFY2(run.provenance.note.find("synthetic paper capture") != std::string::npos, run.provenance.note.c_str());
    std::string host, command, arch;
    for (const auto& [k, v] : run.provenance.settings) {
      if (k == "remote host") host = v;
      if (k == "remote command") command = v;
      if (k == "remote architecture") arch = v;
    }
    QCOMPARE(host, std::string("robot"));
    QVERIFY2(command.find("pipeline --synthetic --frames 3") != std::string::npos, command.c_str());
    if (!kRobotArch.isEmpty()) QCOMPARE(arch, kRobotArch.toStdString());
    verify_nothing_running("pipeline-1");
  }

  // Frame files at the desk (issue #44): `remote HOST pipeline FRAME --lens LENS` carries the frame, its sidecar and
  // the lens into the job's inputs folder on the robot before the job runs; the robot's command names them there,
  // and the run comes home. The robot being this machine, the test checks that the robot read its own copies.
  void desk_frames_are_carried_to_the_robot() {
    const QString frames = g_robot->path("desk-frames");
    QVERIFY(QDir().mkpath(frames));
    const auto made = bs::test::cli({"synth-frame", "--out", frames + "/capture", "--size", "320x256"});
    QVERIFY2(made.code == 0, made.err.constData());
    const QString ws = g_robot->path("carried.bsw");
    const auto r = desk(remote_args({"pipeline", frames + "/capture.raw", "--lens", frames + "/capture.json",
                                     "--frames", "3", "--detector", "none", "--workspace", ws, "--id", "carried-1"}));
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.err.contains("robot: sending " + (frames + "/capture.raw").toUtf8()), r.err.constData());
    QVERIFY2(r.out.contains("imported 1 pipeline run from robot"), r.out.constData());
    const QString inputs = g_robot->jobs_dir() + "/carried-1/inputs";
    // The sidecar named again as --lens goes once.
    QCOMPARE(QDir(inputs + "/1").entryList(QDir::Files), QStringList({"capture.json", "capture.raw"}));
    QCOMPARE(QDir(inputs).entryList(QDir::Dirs | QDir::NoDotAndDotDot), QStringList({"1"}));
    QCOMPARE(QFileInfo(inputs + "/1/capture.raw").size(), QFileInfo(frames + "/capture.raw").size());
    const bs::Workspace w(ws.toStdString(), bs::Workspace::OpenMode::ReadOnly);
    const auto stored = w.pipeline_runs();
    QCOMPARE(stored.size(), std::size_t{1});
    QCOMPARE(stored[0].run.frame_width, 320);
    std::string command, carried;
    for (const auto& [k, v] : stored[0].run.provenance.settings) {
      if (k == "remote command") command = v;
      if (k == "remote inputs from the desk") carried = v;
    }
    QVERIFY2(command.find("/carried-1/inputs/1/capture.raw") != std::string::npos, command.c_str());
    QVERIFY2(carried.find((frames + "/capture.raw -> 1/capture.raw").toStdString()) != std::string::npos,
             carried.c_str());
  }

  // bench dnn --model with the desk's network file: carried, timed on the robot, the same file by its hash.
  void a_desk_model_is_carried_for_bench_dnn() {
    const QString model = BENCHSCOPE_TEST_DATA_DIR "/dnn/yolov8-known.onnx";
    const QString ws = g_robot->path("model.bsw");
    const auto r = desk(remote_args(
        {"bench", "dnn", "--model", model, "--runs", "1", "--backend", "cpu", "--workspace", ws, "--id", "model-1"}));
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY(QFile::exists(g_robot->jobs_dir() + "/model-1/inputs/1/yolov8-known.onnx"));
    const bs::Workspace w(ws.toStdString(), bs::Workspace::OpenMode::ReadOnly);
    const auto runs = w.dnn_runs();
    QCOMPARE(runs.size(), std::size_t{1});
    QCOMPARE(runs[0].run.model_hash, bs::file_content_hash(model.toStdString()));
    QCOMPARE(runs[0].run.model, std::string("yolov8-known.onnx"));  // stored under its own name
  }

  // The robot's side of carrying a file refuses what it must and keeps nothing half-written.
  void a_job_input_is_whole_or_absent() {
    const QString jobs = g_robot->path("put-jobs");
    const auto put = [&](const QStringList& args, const QByteArray& bytes) {
      QProcess p;
      p.start(kCli, QStringList{"job", "put", "--jobs-dir", jobs} + args);
      p.write(bytes);
      p.closeWriteChannel();
      p.waitForFinished(60000);
      return bs::test::CliResult{p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
    };
    for (const char* bad : {"../evil", "1/../evil", "a/b.raw", ".hidden", "1/2/x"}) {
      const auto refused = put({"--id", "put-1", "--name", bad, "--size", "3"}, "abc");
      QVERIFY2(refused.code == 1 && refused.err.contains("is not an input file name"), bad);
    }
    auto r = put({"--id", "put-1", "--name", "frame.raw", "--size", "10"}, "abc");
    QVERIFY2(r.code == 1 && r.err.contains("the desk sent 3 of 10 bytes"), r.err.constData());
    QVERIFY(QDir(jobs + "/put-1/inputs").entryList(QDir::Files).isEmpty());
    r = put({"--id", "put-1", "--name", "2/frame.raw", "--size", "3"}, "abc");
    QVERIFY2(r.code == 0, r.err.constData());
    QFile kept(jobs + "/put-1/inputs/2/frame.raw");
    QVERIFY(kept.open(QIODevice::ReadOnly));
    QCOMPARE(kept.readAll(), QByteArray("abc"));
  }

  // A command whose answer is text (`devices`, `bench vision`) keeps it with the job: the run shows it as it comes,
  // and a fetch prints it again, whole, without pretending there was anything to import.
  void a_text_answer_is_kept_and_fetched_again() {
    const auto r = desk(remote_args({"devices", "--id", "devices-1"}));
    QVERIFY2(r.code == 0, r.err.constData());
    QVERIFY2(r.err.contains("robot: ") && r.err.contains("leaves no results to import"), r.err.constData());
    QVERIFY2(r.err.contains("robot fetch devices-1` prints it again"), r.err.constData());
    const auto f = desk(remote_args({"fetch", "devices-1"}));
    QVERIFY2(f.code == 0, f.err.constData());
    QVERIFY2(f.out.contains("== robot, job devices-1 (devices): its output, as the robot printed it"),
             f.out.constData());
    QVERIFY2(f.out.contains("== end of the output of job devices-1"), f.out.constData());
    // The same text the live run showed, line for line (there each line carried the host's name).
    const QList<QByteArray> lines = f.out.split('\n');
    QVERIFY(lines.size() > 3);
    for (const QByteArray& line : lines.mid(1, lines.size() - 3))
      if (!line.isEmpty()) QVERIFY2(r.err.contains("robot: " + line), line.constData());
  }

  void jobs_lists_what_the_robot_keeps() {
    const auto r = desk(remote_args({"jobs"}));
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("sweep-1") && r.out.contains("done") && r.out.contains("cancel-1"), r.out.constData());
  }
};

namespace {
int cli_remote_main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  bs::test::SshRobot robot;
  if (const QString why = robot.start(); !why.isEmpty()) {
    std::cout << "SKIP: no SSH server to test against: " << why.toStdString() << '\n';
    return bs::test::kSkipCode;
  }
  g_robot = &robot;
  TestCliRemote tc;
  return QTest::qExec(&tc, argc, argv);
}
}  // namespace
BENCHSCOPE_TEST_CUSTOM_MAIN(cli_remote_main)

#include "test_cli_remote.moc"
