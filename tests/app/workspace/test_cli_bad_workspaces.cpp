// SPDX-License-Identifier: GPL-3.0-or-later
// The crafted-workspace corpus (tests/data/bad-workspaces, issue #37) through benchscope-cli as a user runs it:
// a damaged item is left out with one warning naming it (exit 0) and nothing is written to the file; a workspace
// that cannot be read gives one error line (exit 1); `check` reports every case; no command prints a negative,
// infinite or NaN quantity.
#include <QDir>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>
#include <algorithm>
#include <set>

#include "../../support/bad_workspaces.h"
#include "../../support/cli_harness.h"

namespace {

using bs::test::bytes_of;
using bs::test::cli;

// A quantity printed as negative, infinite or NaN: "-1.10 TFLOPS", "inf FLOPS", "nan W". A leading '-' after a
// space, '(' or '|' followed by a digit is a negative number; words like "non-finite" do not match.
QString impossible_quantity(const QByteArray& out) {
  static const QRegularExpression bad(R"((^|[\s(|=])(-\d|(-?inf(inity)?|nan)\b))",
                                      QRegularExpression::CaseInsensitiveOption | QRegularExpression::MultilineOption);
  const auto m = bad.match(QString::fromUtf8(out));
  return m.hasMatch() ? QString::fromUtf8(out).mid(std::max(0, static_cast<int>(m.capturedStart()) - 60), 120)
                      : QString();
}

bool contains_all(const QByteArray& text, const std::vector<std::string>& parts) {
  for (const std::string& p : parts)
    if (!text.contains(QByteArray::fromStdString(p))) return false;
  return true;
}

}  // namespace

class TestCliBadWorkspaces : public QObject {
  Q_OBJECT
  QTemporaryDir dir_;
  QString base_;

 private slots:
  void initTestCase() {
    base_ = dir_.filePath("paper.bsw");
    const auto r = cli({"import", base_, BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018",
                        BENCHSCOPE_TEST_DATA_DIR "/importers/clpeak/gtx1080ti.txt", "--quiet"});
    QVERIFY2(r.code == 0, r.err.constData());
    const auto c = cli({"check", base_});
    QVERIFY2(c.code == 0, c.out.constData());  // the corpus starts from a sound workspace
  }

  void corpus_has_every_kind() {
    const auto cases = bs::test::load_bad_workspaces(BENCHSCOPE_TEST_DATA_DIR);
    QVERIFY(cases.size() >= 20);
    std::set<std::string> kinds;
    for (const auto& c : cases) kinds.insert(c.expect);
    QVERIFY((kinds == std::set<std::string>{"damaged", "check", "error", "ok"}));
  }

  void each_case_as_the_manifest_says_data() {
    QTest::addColumn<int>("index");
    const auto cases = bs::test::load_bad_workspaces(BENCHSCOPE_TEST_DATA_DIR);
    for (std::size_t i = 0; i < cases.size(); ++i) QTest::newRow(cases[i].name.c_str()) << static_cast<int>(i);
  }

  void each_case_as_the_manifest_says() {
    QFETCH(int, index);
    const auto c = bs::test::load_bad_workspaces(BENCHSCOPE_TEST_DATA_DIR).at(static_cast<std::size_t>(index));
    const QString ws =
        QString::fromStdString(bs::test::make_bad_workspace(c, base_.toStdString(), dir_.path().toStdString()));
    const QByteArray before = bytes_of(ws);

    for (const char* command : {"platforms", "peaks", "power", "frames"}) {
      const auto r = cli({command, ws});
      const QString where = QString("%1 %2: exit %3\n%4\n%5")
                                .arg(command, ws)
                                .arg(r.code)
                                .arg(QString::fromUtf8(r.out), QString::fromUtf8(r.err));
      QVERIFY2(impossible_quantity(r.out).isEmpty(), qPrintable(where + "\n>> " + impossible_quantity(r.out)));
      if (c.expect == "error") {
        QVERIFY2(r.code == 1, qPrintable(where));
        QVERIFY2(r.err.trimmed().split('\n').size() == 1, qPrintable(where));
        QVERIFY2(r.err.contains(ws.toUtf8()) && contains_all(r.err, c.contains), qPrintable(where));
        continue;
      }
      QVERIFY2(r.code == 0, qPrintable(where));
      // `frames` never loads a power log's samples, so damage inside them is not found there.
      if (c.expect == "damaged" && !(c.in_samples && std::string(command) == "frames")) {
        // One warning per damaged item, naming the workspace, the item, the column and the category.
        QVERIFY2(r.err.contains("warning: " + ws.toUtf8() + ": " + QByteArray::fromStdString(c.item)),
                 qPrintable(where));
        QVERIFY2(contains_all(r.err, c.contains), qPrintable(where));
        QVERIFY2(r.err.contains(QByteArray::fromStdString("[" + c.category + "]")), qPrintable(where));
      } else if (c.expect != "damaged") {
        QVERIFY2(!r.err.contains("warning"), qPrintable(where));
      }
    }
    // Nothing was written to the file (no journal change, no repair) by reading it; an older schema ("ok") is
    // migrated when opened for writing.
    const bool untouchable = c.expect != "ok";
    if (untouchable) QVERIFY2(bytes_of(ws) == before, qPrintable(ws + " was written to"));

    const auto check = cli({"check", ws});
    const QString where = QString("check %1: exit %2\n%3").arg(ws).arg(check.code).arg(QString::fromUtf8(check.out));
    if (c.expect == "ok") {
      QVERIFY2(check.code == 0, qPrintable(where));
    } else {
      QVERIFY2(check.code == 1, qPrintable(where));
      QVERIFY2(contains_all(check.out, c.contains), qPrintable(where));
      if (!c.item.empty()) QVERIFY2(check.out.contains(QByteArray::fromStdString(c.item)), qPrintable(where));
    }
    QVERIFY2(!untouchable || bytes_of(ws) == before, qPrintable("check wrote to " + ws));
  }

  // A damaged workspace refuses writes until the user removes the damage; then it is sound and writable.
  void remove_damaged_makes_it_writable() {
    const auto cases = bs::test::load_bad_workspaces(BENCHSCOPE_TEST_DATA_DIR);
    const auto it =
        std::find_if(cases.begin(), cases.end(), [](const auto& c) { return c.name == "run-samples-workers-negated"; });
    QVERIFY(it != cases.end());
    const QString ws =
        QString::fromStdString(bs::test::make_bad_workspace(*it, base_.toStdString(), dir_.path().toStdString()));
    const auto refused = cli({"import", ws, BENCHSCOPE_TEST_DATA_DIR "/importers/clpeak/nuc-iris650-crlf.txt"});
    QCOMPARE(refused.code, 1);
    QVERIFY2(refused.err.contains("damaged item") && refused.err.contains("--remove-damaged"), refused.err.constData());
    const auto removed = cli({"check", ws, "--remove-damaged"});
    QVERIFY2(removed.code == 0 && removed.out.contains("removed 1 damaged item"), removed.out.constData());
    const auto imported = cli({"import", ws, BENCHSCOPE_TEST_DATA_DIR "/importers/clpeak/nuc-iris650-crlf.txt"});
    QVERIFY2(imported.code == 0, imported.err.constData());
    const auto peaks = cli({"peaks", ws});
    QVERIFY2(peaks.code == 0 && peaks.err.isEmpty(), peaks.err.constData());
  }
};

QTEST_GUILESS_MAIN(TestCliBadWorkspaces)
#include "test_cli_bad_workspaces.moc"
