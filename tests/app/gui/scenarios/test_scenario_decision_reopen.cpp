// SPDX-License-Identifier: GPL-3.0-or-later
// Scenario (issue #43.2): a person sets a 10 W power budget in the Platforms tab (the Jetson TX2 is recommended),
// quits, starts BenchScope again, opens the workspace and exports the report. On main the budget was gone after
// reopening and page 1 said "Recommended: NUC - no constraints were set"; the report dialog neither showed nor asked
// for the constraints. Now the budget comes back, the report dialog shows it, page 1 states it (read back with
// pdftotext), and `benchscope-cli platforms` / `report` on the workspace use it too; before quitting, Edit > Undo
// takes the budget back (the workspace forgets it) and Redo sets it again.
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QLabel>
#include <QProcess>
#include <QTableWidget>
#include <QTest>

#include "../../../support/scenario_window.h"
#include "platform/platform_view.h"

using bs::test::ModalAnswerer;

namespace {

// The spin box right of the "Power budget ≤" check box, on its row: where a person looks for the number.
QDoubleSpinBox* budget_field(QWidget* view, QCheckBox* box) {
  QDoubleSpinBox* best = nullptr;
  const QPoint at = box->mapTo(view, QPoint(box->width(), box->height() / 2));
  int best_dx = 1 << 30;
  for (QDoubleSpinBox* s : view->findChildren<QDoubleSpinBox*>()) {
    const QPoint p = s->mapTo(view, QPoint(0, s->height() / 2));
    if (std::abs(p.y() - at.y()) > 8 || p.x() < at.x()) continue;
    if (p.x() - at.x() < best_dx) {
      best_dx = p.x() - at.x();
      best = s;
    }
  }
  return best;
}

QString run_cli(const QStringList& args, QString* err = nullptr) {
  QProcess p;
  p.start(QStringLiteral(BENCHSCOPE_BINARY_DIR "/app/cli/benchscope-cli"), args);
  if (!p.waitForFinished(300000)) return QStringLiteral("(benchscope-cli did not finish)");
  if (err) *err = QString::fromUtf8(p.readAllStandardError());
  return QString::fromUtf8(p.readAllStandardOutput());
}

}  // namespace

class TestScenarioDecisionReopen : public QObject {
  Q_OBJECT
 private slots:
  void budget_survives_reopening_and_reaches_page_one() {
    QTemporaryDir dir;
    QString ws;  // the paper's workspace, opened again below
    {
      bs::ui::MainWindow w;
      BS_STEP(bs::test::open_paper_window(w, dir));
      ws = QString::fromStdString(w.workspace()->path());
      QWidget* tab = bs::test::open_tab(w, "Platforms");
      QVERIFY(tab);
      auto* use_budget = bs::test::widget_with_text<QCheckBox>(tab, QStringLiteral("Power budget ≤"));
      QVERIFY(use_budget);
      bs::test::click(use_budget);
      QDoubleSpinBox* budget = budget_field(tab, use_budget);
      QVERIFY(budget);
      bs::test::retype(budget, "10");
      bs::test::key(budget, Qt::Key_Return);
      QVERIFY2(w.platform_view()->summary_text().contains("Recommended: <b>Jetson TX2</b>"),
               qPrintable(w.platform_view()->summary_text()));
      bs::test::screenshot(&w, "decision-budget-set");
      // Edit > Undo (Ctrl+Z) takes the budget back (and the workspace forgets it); Redo sets it again. The undo
      // history is the window's: it does not outlive the session, the decision in the workspace does.
      // Ctrl+Z in the budget field undoes the typing there (the field's own undo): the person clicks the table first.
      bs::test::click(w.platform_view()->table()->viewport());
      bs::test::key(&w, Qt::Key_Z, Qt::ControlModifier);
      QVERIFY(!use_budget->isChecked());
      QVERIFY2(!run_cli({"platforms", ws}).contains("recommendation: Jetson TX2"), "undo did not reach the workspace");
      bs::test::key(&w, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
      QVERIFY(use_budget->isChecked());
      QVERIFY2(run_cli({"platforms", ws}).contains("recommendation: Jetson TX2"), "redo did not reach the workspace");
      bs::test::key(&w, Qt::Key_Q, Qt::ControlModifier);  // File > Quit
      QVERIFY(bs::test::wait_until([&] { return !w.isVisible(); }, 200));
    }
    // BenchScope again; File > Open workspace…
    bs::ui::MainWindow w;
    w.new_untitled_workspace();  // what a start without arguments opens
    QVERIFY(bs::test::show_at(w));
    {
      ModalAnswerer person;
      person.expect("Open workspace (file dialog)", ModalAnswerer::titled("Open workspace"),
                    [&ws](QWidget* d) { bs::test::choose_file(d, ws); });
      bs::test::key(&w, Qt::Key_O, Qt::ControlModifier);
      QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 500), qPrintable(person.report()));
    }
    QCOMPARE(QString::fromStdString(w.workspace()->path()), ws);
    QWidget* tab = bs::test::open_tab(w, "Platforms");
    auto* use_budget = bs::test::widget_with_text<QCheckBox>(tab, QStringLiteral("Power budget ≤"));
    QVERIFY(use_budget);
    QVERIFY2(use_budget->isChecked(), "the power budget was not kept with the workspace");
    QCOMPARE(budget_field(tab, use_budget)->value(), 10.0);
    QVERIFY2(w.platform_view()->summary_text().contains("Recommended: <b>Jetson TX2</b>"),
             qPrintable(w.platform_view()->summary_text()));
    bs::test::screenshot(&w, "decision-reopened");

    // File > Export report: the dialog shows the decision page 1 will state, then writes the PDF.
    const QString pdf = dir.filePath("report.pdf");
    QString shown;
    BS_STEP(bs::test::export_report(w, pdf, &shown));
    QVERIFY2(shown.contains("a power budget of 10 W") && shown.contains("Jetson TX2"), qPrintable(shown));
    const QString page1 = bs::test::pdf_page_text(pdf, 1).simplified();
    QVERIFY2(page1.contains("Recommended under a power budget of 10 W: Jetson TX2"), qPrintable(page1));
    QVERIFY2(!page1.contains("no constraints were set"), qPrintable(page1));

    // The command line reads the same workspace the same way.
    const QString platforms = run_cli({"platforms", ws});
    QVERIFY2(platforms.contains("recommendation: Jetson TX2"), qPrintable(platforms));
    QVERIFY2(platforms.contains("a power budget of 10 W"), qPrintable(platforms));
    const QString cli_pdf = dir.filePath("cli-report.pdf");
    run_cli({"report", ws, "--pdf", cli_pdf, "--quiet"});
    const QString cli_page1 = bs::test::pdf_page_text(cli_pdf, 1).simplified();
    QVERIFY2(cli_page1.contains("Recommended under a power budget of 10 W: Jetson TX2"), qPrintable(cli_page1));
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioDecisionReopen)
#include "test_scenario_decision_reopen.moc"
