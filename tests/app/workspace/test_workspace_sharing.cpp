// SPDX-License-Identifier: GPL-3.0-or-later
// One workspace, shared by a long-lived process and the CLI at once (issue #50), tested as SQLite tests itself: with
// real processes. workspace_holder (tests/support/workspace_holder.cpp) holds the workspace as the GUI does (a
// long-lived connection that edits, an import's second connection, a read-only reader) and reports, after every
// step, whether it still holds its POSIX locks and whether its WAL was deleted under it; benchscope-cli commands
// (list, check, compare, battery, import) run beside it; then it is killed with SIGKILL at random points.
//  - beside_the_cli: every CLI command leaves the holder's locks and WAL in place, and sees the holder's imports.
//  - kill_at_random_points: 20 rounds, each killed after a random number of committed edits (fixed seed) while a
//    CLI command runs; afterwards every edit and import the holder reported committed is in the file,
//    PRAGMA integrity_check says ok, and no round lost a lock or a WAL.
// Before #50 the holder's first import dropped its locks (the header check read the file through a second
// descriptor), and the first CLI command after it deleted its WAL.
#include <csignal>
#include <map>
#include <random>
#include <set>

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/cli_harness.h"
#include "../../support/process_locks.h"
#include "store/workspace.h"

namespace {

using bs::test::kPaper;

const QString kHolder = BENCHSCOPE_BINARY_DIR "/tests/app/workspace_holder";
const QString kTemplate = BENCHSCOPE_SOURCE_DIR "/tests/data/importers/run-json/two-runs.json";
// Each round starts two processes; under ASan that is ~5 s a round on a 2-core machine, and 20 rounds already kill
// the holder after every number of edits the draw can give (1-14).
constexpr int kRounds = 20;

// The holder's report lines so far, split into what it committed and what went wrong.
struct HolderLog {
  std::set<QString> committed;          // "ROUND I"
  std::map<QString, QString> imported;  // "ROUND I" -> file name
  QStringList problems;                 // locks-lost, wal-deleted, error lines
  QByteArray pending;

  void take(const QByteArray& bytes) {
    pending += bytes;
    int end;
    while ((end = pending.indexOf('\n')) >= 0) {
      const QString line = QString::fromUtf8(pending.left(end));
      pending.remove(0, end + 1);
      const QStringList w = line.split(' ');
      if (w.size() >= 3 && w[0] == "committed")
        committed.insert(w[1] + ' ' + w[2]);
      else if (w.size() >= 4 && w[0] == "imported")
        imported[w[1] + ' ' + w[2]] = w[3];
      else if (!line.isEmpty())
        problems << line;
    }
  }
};

class Holder {
 public:
  Holder(const QString& ws, const QString& work, int round) {
    p_.setProcessChannelMode(QProcess::SeparateChannels);
    p_.start(kHolder, {ws, kTemplate, work, QString::number(round)});
  }
  ~Holder() { kill(); }
  bool started() { return p_.waitForStarted(); }
  qint64 pid() const { return p_.processId(); }
  // Reads its reports until it has committed `edits` edits in all (or ended). waitForReadyRead only paces the loop.
  bool wait_for_commits(std::size_t edits) {
    while (log.committed.size() < edits) {
      if (p_.state() != QProcess::Running && p_.bytesAvailable() == 0) return false;
      p_.waitForReadyRead(50);
      log.take(p_.readAllStandardOutput());
    }
    return true;
  }
  void kill() {
    if (p_.state() == QProcess::NotRunning) return;
    ::kill(static_cast<pid_t>(p_.processId()), SIGKILL);
    p_.waitForFinished(-1);
    log.take(p_.readAllStandardOutput());
  }
  QString stderr_text() { return QString::fromUtf8(p_.readAllStandardError()); }
  HolderLog log;

 private:
  QProcess p_;
};

// The workspace after a crash, as the next process finds it: integrity, and every committed edit and import.
void check_after(const QString& ws, const HolderLog& log) {
  const bs::Workspace w(ws.toStdString());
  QCOMPARE(w.integrity_check(), std::string("ok"));
  std::set<QString> stored;
  for (const auto& [key, value] : w.settings("holder/")) {
    const QStringList parts = QString::fromStdString(key).split('/');  // holder/ROUND/edit/I
    if (parts.size() == 4) stored.insert(parts[1] + ' ' + parts[3]);
  }
  for (const QString& c : log.committed) QVERIFY2(stored.count(c), qPrintable("edit " + c + " was lost"));
  std::set<QString> files;
  for (const bs::ImportRecord& r : w.imports()) files.insert(QFileInfo(QString::fromStdString(r.path)).fileName());
  for (const auto& [step, name] : log.imported)
    QVERIFY2(files.count(name), qPrintable("the import of " + name + " (step " + step + ") was lost"));
}

}  // namespace

class TestWorkspaceSharing : public QObject {
  Q_OBJECT
 private slots:
  void beside_the_cli() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("lab.bsw");
    QCOMPARE(bs::test::cli({"import", ws, kPaper, "--quiet"}).code, 0);
    Holder holder(ws, dir.path(), 0);
    QVERIFY(holder.started());
    // Two imports and two read-only readers in: what dropped the locks before #50.
    QVERIFY2(holder.wait_for_commits(6), qPrintable(holder.stderr_text()));
    const long pid = static_cast<long>(holder.pid());
    QVERIFY2(bs::test::posix_locks_on(pid, ws.toStdString()) > 0,
             "the holder holds no lock on the workspace after an import");
    const QList<QStringList> commands = {
        {"runs", ws},
        {"check", ws},
        {"platforms", ws, "--json"},
        {"battery", "--workspace", ws, "--json"},
        {"import", ws, BENCHSCOPE_SOURCE_DIR "/tests/data/importers/pipeline/paper-nuc.json", "--quiet"},
        {"runs", ws},
    };
    for (const QStringList& c : commands) {
      const bs::test::CliResult r = bs::test::cli(c);
      QVERIFY2(r.code == 0, qPrintable(c.join(' ') + ": " + QString::fromUtf8(r.err)));
      QVERIFY2(QFile::exists(ws + "-wal"), qPrintable("`" + c.join(' ') + "` deleted the holder's WAL"));
      QVERIFY2(!bs::test::holds_deleted_wal(pid, ws.toStdString()),
               qPrintable("after `" + c.join(' ') + "` the holder writes into a deleted WAL"));
      QVERIFY2(bs::test::posix_locks_on(pid, ws.toStdString()) > 0,
               qPrintable("after `" + c.join(' ') + "` the holder holds no lock on the workspace"));
    }
    // The holder's imports are in the file where the CLI reads: its runs are listed.
    const bs::test::CliResult listed = bs::test::cli({"runs", ws});
    QVERIFY2(listed.out.contains("Test CPU"), listed.out.constData());
    QVERIFY(holder.wait_for_commits(12));
    holder.kill();
    QVERIFY2(holder.log.problems.isEmpty(), qPrintable(holder.log.problems.join('\n')));
    check_after(ws, holder.log);
  }

  void kill_at_random_points() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("lab.bsw");
    QCOMPARE(bs::test::cli({"import", ws, kPaper, "--quiet"}).code, 0);
    std::mt19937 rng(20260612);
    std::uniform_int_distribution<int> edits(1, 14);
    std::uniform_int_distribution<int> extra_polls(0, 3);
    const QList<QStringList> beside = {{"runs", ws}, {"check", ws}, {"platforms", ws, "--json"}};
    HolderLog all;
    std::size_t edits_checked = 0, imports_checked = 0;
    for (int round = 1; round <= kRounds; ++round) {
      Holder holder(ws, dir.path(), round);
      QVERIFY(holder.started());
      QProcess cli;  // a CLI command beside it, killed or not with it
      cli.start(bs::test::kCli, beside[round % beside.size()]);
      const int kill_after = edits(rng);
      holder.wait_for_commits(static_cast<std::size_t>(kill_after));
      for (int i = extra_polls(rng); i > 0; --i) QTest::qWait(1);  // a little further into its next step
      holder.kill();
      // It may have ended already (waiting on the holder's pipes can take in its end too).
      if (cli.state() != QProcess::NotRunning) QVERIFY(cli.waitForFinished(120000));
      QCOMPARE(cli.exitStatus(), QProcess::NormalExit);
      QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
      QVERIFY2(holder.log.problems.isEmpty(),
               qPrintable(QString("round %1: %2").arg(round).arg(holder.log.problems.join('\n'))));
      QVERIFY2(!holder.log.committed.empty(), qPrintable(holder.stderr_text()));
      check_after(ws, holder.log);
      if (QTest::currentTestFailed()) return;
      edits_checked += holder.log.committed.size();
      imports_checked += holder.log.imported.size();
    }
    qInfo("%d kills: %zu committed edits and %zu imports, all found afterwards; integrity ok each time", kRounds,
          edits_checked, imports_checked);
  }
};

QTEST_GUILESS_MAIN(TestWorkspaceSharing)
#include "test_workspace_sharing.moc"
