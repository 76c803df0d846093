// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli import` on each file of the bad-input corpus, like a user would: exit code 1, exactly one error
// line on stderr naming the file, and the workspace (which already holds a good import) byte-for-byte unchanged
// with no journal left beside it.
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/bad_corpus.h"

#include "../../support/cli_harness.h"

namespace {

using bs::test::bytes_of;
using bs::test::run_cli;

}  // namespace

class TestCliBadCorpus : public QObject {
  Q_OBJECT
 private slots:
  void bad_files_leave_the_workspace_unchanged() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("w.bsw");
    QCOMPARE(run_cli({"import", ws, BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/power", "--quiet"}), 0);
    const QByteArray before = bytes_of(ws);
    QVERIFY(!before.isEmpty());
    const auto cases = bs::test::load_bad_corpus(BENCHSCOPE_TEST_DATA_DIR, dir.path().toStdString());
    for (const auto& c : cases) {
      const QString file = QString::fromStdString(c.path);
      QByteArray err;
      QCOMPARE(run_cli({"import", ws, file}, nullptr, &err), 1);
      const QList<QByteArray> lines = err.trimmed().split('\n');
      QVERIFY2(lines.size() == 1, err.constData());
      QVERIFY2(lines[0].contains(file.toUtf8()), err.constData());
      QVERIFY2(bytes_of(ws) == before, qPrintable(file + " changed the workspace"));
      QVERIFY2(!QFile::exists(ws + "-wal") && !QFile::exists(ws + "-journal"), qPrintable(file));
    }
  }
};

QTEST_GUILESS_MAIN(TestCliBadCorpus)
#include "test_cli_bad_corpus.moc"
