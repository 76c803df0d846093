// SPDX-License-Identifier: GPL-3.0-or-later
// `benchscope-cli import` on each file of the bad-input corpus, like a user would: exit code 1, exactly one error
// line on stderr naming the file, and the workspace (which already holds a good import) byte-for-byte unchanged
// with no journal left beside it. The corpus's third-party files (the shared folder's tests/data/bad/) are checked
// in a function of their own, which skips without that folder.
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/bad_corpus.h"

#include "../../support/cli_harness.h"
#include "../../support/public_data.h"

namespace {

using bs::test::bytes_of;
using bs::test::run_cli;

// `import` of each case into a workspace that holds a good import: refused, one line, workspace unchanged. Returns on
// the first case that is not (the failure is recorded).
void check_refused(bool third_party) {
  QTemporaryDir dir;
  const QString ws = dir.filePath("w.bsw");
  QCOMPARE(run_cli({"import", ws, BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/power", "--quiet"}), 0);
  const QByteArray before = bytes_of(ws);
  QVERIFY(!before.isEmpty());
  const auto cases = bs::test::bad_cases(
      bs::test::load_bad_corpus(BENCHSCOPE_TEST_DATA_DIR, BENCHSCOPE_PUBLIC_DATA_DIR, dir.path().toStdString()),
      third_party);
  QVERIFY(!cases.empty());
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

}  // namespace

class TestCliBadCorpus : public QObject {
  Q_OBJECT
 private slots:
  void bad_files_leave_the_workspace_unchanged() { check_refused(false); }

  void third_party_bad_files_leave_the_workspace_unchanged() {
    BENCHSCOPE_REQUIRE_PUBLIC_DATA(bs::test::kThirdPartyBadFolder);
    check_refused(true);
  }
};

QTEST_GUILESS_MAIN(TestCliBadCorpus)
#include "test_cli_bad_corpus.moc"
