// SPDX-License-Identifier: GPL-3.0-or-later
// Crash safety: `benchscope-cli import` is killed with SIGKILL at random moments (fixed seed, 24 times) while it
// writes power logs into one workspace. After every kill the workspace must open, pass PRAGMA integrity_check, and
// hold each import whole or not at all: every import row has its trace, every trace all of its samples.
#include <csignal>
#include <random>

#include <QElapsedTimer>
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

    // One complete import tells how long a round takes; kills are spread over that time.
    QStringList args{"import", ws};
    args << files << "--quiet";
    QElapsedTimer clock;
    clock.start();
    QCOMPARE(QProcess::execute(kCli, args), 0);
    const qint64 full_ms = std::max<qint64>(clock.elapsed(), 50);
    std::size_t imports = 0;
    check_workspace(ws, &imports);
    QCOMPARE(imports, std::size_t{kFiles});

    std::mt19937 rng(20181121);
    std::uniform_int_distribution<qint64> when(0, full_ms * 6 / 5);
    int killed_mid_way = 0;
    for (int round = 1; round <= kKills; ++round) {
      for (const QString& f : files) stamp_round(f, round);
      QProcess p;
      p.start(kCli, args);
      QVERIFY(p.waitForStarted());
      const qint64 delay = when(rng);
      if (!p.waitForFinished(static_cast<int>(delay))) {
        ::kill(static_cast<pid_t>(p.processId()), SIGKILL);
        QVERIFY(p.waitForFinished(10000));
        ++killed_mid_way;
      }
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
