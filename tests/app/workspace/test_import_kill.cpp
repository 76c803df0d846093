// SPDX-License-Identifier: GPL-3.0-or-later
// Crash safety: `benchscope-cli import` is killed with SIGKILL at random points of its work (fixed seed, 24 times)
// while it writes power logs into one workspace. The points are counted in bytes the process has read and written
// (Linux /proc/<pid>/io), not in time, so where the kills land does not depend on how loaded the machine is. After
// every kill the workspace must open, pass PRAGMA integrity_check, and hold each import whole or not at all: every
// import row has its trace, every trace all of its samples.
#include <algorithm>
#include <csignal>
#include <random>

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include "store/workspace.h"

namespace {

const QString kCli = BENCHSCOPE_BINARY_DIR "/app/cli/benchscope-cli";
constexpr int kFiles = 6;
constexpr int kRows = 60000;
constexpr int kKills = 24;

// The first line is a fixed-width comment that each round rewrites, so every round's files are new content
// (the workspace skips bytes it has seen before).
void write_log(const QString& path, int file) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly));
  QByteArray text = "# round: 000000\n# platform: NUC\n# supply_voltage_V: 16\ntime_s,current_A\n";
  text.reserve(kRows * 20);
  for (int i = 0; i < kRows; ++i)
    text += QByteArray::number(i * 0.001, 'f', 3) + ',' +
            QByteArray::number(2.5 + 0.001 * ((i * 37 + file) % 500), 'f', 3) + '\n';
  QVERIFY(f.write(text) == text.size());
}

void stamp_round(const QString& path, int round) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::ReadWrite));
  QVERIFY(f.seek(9));
  QVERIFY(f.write(QByteArray::number(round).rightJustified(6, '0')) == 6);
}

// The invariants a crash must never break.
void check_workspace(const QString& ws, std::size_t* imports_out) {
  bs::Workspace w(ws.toStdString());  // throws (fails the test) when it cannot be opened
  QCOMPARE(w.integrity_check(), std::string("ok"));
  const auto imports = w.imports();
  const auto traces = w.power_traces();
  QCOMPARE(traces.size(), imports.size());
  for (const auto& imp : imports) {
    const auto it = std::find_if(traces.begin(), traces.end(), [&](const auto& t) { return t.import_id == imp.id; });
    QVERIFY2(it != traces.end(), qPrintable(QString::fromStdString(imp.path) + " has no trace"));
    QCOMPARE(it->trace.time_s.size(), std::size_t{kRows});
    QVERIFY(!it->trace.channels.empty());
    for (const auto& ch : it->trace.channels) QCOMPARE(ch.values.size(), std::size_t{kRows});
  }
  *imports_out = imports.size();
}

// The bytes a process has read and written so far (rchar + wchar of /proc/<pid>/io): its work done, the same on a
// fast and a loaded machine. -1 when it cannot be read (the process is gone).
qint64 io_bytes(qint64 pid) {
  QFile f(QString("/proc/%1/io").arg(pid));
  if (!f.open(QIODevice::ReadOnly)) return -1;
  qint64 total = 0;
  bool seen = false;
  for (const QByteArray& line : f.readAll().split('\n'))
    if (line.startsWith("rchar:") || line.startsWith("wchar:")) {
      total += line.mid(6).trimmed().toLongLong();
      seen = true;
    }
  return seen ? total : -1;
}

struct Round {
  bool killed = false;  // killed while it ran
  int exit_code = -1;   // when it ended by itself
  qint64 most_io = 0;   // the most I/O seen while it ran
};

// Runs the CLI until it ends, or until it has done `kill_at` bytes of I/O (0: never) and is then killed (SIGKILL).
Round run_and_kill_at(const QStringList& args, qint64 kill_at) {
  Round r;
  QProcess p;
  p.start(kCli, args);
  if (!p.waitForStarted()) return r;
  const qint64 pid = p.processId();
  // Polled: waitForFinished(1) only paces the loop; the decision to kill looks at the work done.
  while (!p.waitForFinished(1)) {
    const qint64 io = io_bytes(pid);
    r.most_io = std::max(r.most_io, io);
    if (kill_at > 0 && io >= kill_at) {
      ::kill(static_cast<pid_t>(pid), SIGKILL);
      p.waitForFinished(-1);
      r.killed = p.exitStatus() == QProcess::CrashExit;
      return r;
    }
  }
  r.exit_code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
  return r;
}

}  // namespace

class TestImportKill : public QObject {
  Q_OBJECT
 private slots:
  void sigkill_never_leaves_a_half_import() {
    QTemporaryDir dir;
    QStringList files;
    for (int i = 0; i < kFiles; ++i) {
      files << dir.filePath(QString("log-%1.csv").arg(i));
      write_log(files.back(), i);
    }
    const QString ws = dir.filePath("w.bsw");

    // One complete import tells how much I/O a round does; kills are spread over that much work.
    QStringList args{"import", ws};
    args << files << "--quiet";
    const Round full = run_and_kill_at(args, 0);
    QCOMPARE(full.exit_code, 0);
    const qint64 full_io = full.most_io;
    if (full_io <= 0) QSKIP("/proc/<pid>/io is not readable here: no way to count the work done");
    std::size_t imports = 0;
    check_workspace(ws, &imports);
    QCOMPARE(imports, std::size_t{kFiles});

    std::mt19937 rng(20181121);
    std::uniform_int_distribution<qint64> where(full_io / 50, full_io * 49 / 50);
    int killed_mid_way = 0;
    for (int round = 1; round <= kKills; ++round) {
      for (const QString& f : files) stamp_round(f, round);
      if (run_and_kill_at(args, where(rng)).killed) ++killed_mid_way;
      std::size_t now = 0;
      check_workspace(ws, &now);
      QVERIFY(now >= imports && now <= imports + kFiles);
      imports = now;
    }
    // Most kills must have hit a running import, or the test proves nothing.
    QVERIFY2(killed_mid_way >= kKills / 2,
             qPrintable(QString("only %1 kills hit a running import").arg(killed_mid_way)));
    qInfo("%d of %d kills hit a running import; the workspace holds %zu whole imports", killed_mid_way, kKills,
          imports);
  }
};

QTEST_GUILESS_MAIN(TestImportKill)
#include "test_import_kill.moc"
