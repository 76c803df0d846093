// SPDX-License-Identifier: GPL-3.0-or-later
// Issue #43.5, the report as a person gets it: the paper's workspace with this machine's sweeps (and, where the shared
// public files are here, two MLPerf submissions: seven platforms), File > Export report (Ctrl+Shift+R), the report
// dialog answered (#43.2: it names the file and shows the decision page 1 states), the PDF read back page by page with
// pdftotext. No word runs past the text area (Appendix A's table was cut at the page's edge), no words print over each
// other, every table is whole (the platforms were seven one-column tables over four pages), and the synthetic capture
// is captioned as synthetic, with its origin.
#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/pdf_readback.h"
#include "../../support/scenario_window.h"
#include "main_window.h"

namespace {

constexpr double kPtPerMm = 72.0 / 25.4;
constexpr double kMarginMm = 15;  // the report's page margins (figures/report_writer.cpp)

}  // namespace

class TestScenarioReport : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QSettings().clear();
    if (QStandardPaths::findExecutable("pdftotext").isEmpty())
      QSKIP("pdftotext (poppler-utils) is needed to read the report back");
  }

  void report_pages_read_back_whole() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("paper.bsw")));
    QStringList paths{BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018",
                      BENCHSCOPE_SOURCE_DIR "/sample_data/measured-dev"};
    const QString mlperf = BENCHSCOPE_PUBLIC_DATA_DIR "/tests/data/importers/mlperf";
    if (QDir(mlperf).exists()) paths << mlperf + "/v0.5-nvidia-xavier" << mlperf + "/v3.0-nvidia-orin-maxq";
    w.import_paths_now(paths);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    w.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&w));

    const QString pdf = dir.filePath("report.pdf");
    const auto answered =
        bs::test::answer_next_modal(&w, [&](QWidget* modal) { bs::test::answer_report_dialog(modal, pdf); });
    bs::test::press(w, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(*answered);
    QVERIFY2(QFile::exists(pdf), "no report written");
    bs::test::keep_for_looking(pdf, "report.pdf");

    const auto pages = bs::test::pdf_words(pdf);
    QVERIFY(pages.size() >= 3);
    QStringList problems;
    for (std::size_t p = 0; p < pages.size(); ++p) {
      const double right = pages[p].size.width() - kMarginMm * kPtPerMm;
      for (const QString& word : bs::test::words_past(pages[p], right))
        problems << QStringLiteral("page %1: %2 runs past the text area").arg(p + 1).arg(word);
      for (const QString& pair : bs::test::overprinted_words(pages[p]))
        problems << QStringLiteral("page %1: %2").arg(p + 1).arg(pair);
    }
    const QString text = bs::test::pdf_flat_text(pdf);
    // Every table in one piece: the platforms side by side in one table, the appendix as one table.
    for (const QString& piece : {QStringLiteral("(platforms 2 to"), QStringLiteral("(part 2 of")})
      if (text.contains(piece)) problems << QStringLiteral("a table is split: '%1'").arg(piece);
    if (text.count("Platforms at a glance") != 1)
      problems << QStringLiteral("'Platforms at a glance' %1 times").arg(text.count("Platforms at a glance"));
    // The capture is the synthetic chart of the paper's sample (its sidecar says so): the caption says so, and where
    // it comes from.
    if (text.contains("Camera frame")) problems << "the synthetic capture is captioned 'Camera frame'";
    if (!text.contains("Synthetic capture") || !text.contains("paper-capture") || !text.contains("synth-frame"))
      problems << "no caption says the capture is synthetic and where it comes from";
    for (const QString& p : problems) qWarning("%s", qPrintable(p));  // every one, not only what QVERIFY2 shows
    QVERIFY2(problems.isEmpty(),
             qPrintable(QStringLiteral("%1 problem(s), the first: %2").arg(problems.size()).arg(problems.value(0))));
  }
};

QTEST_MAIN(TestScenarioReport)
#include "test_scenario_report.moc"
