// SPDX-License-Identifier: GPL-3.0-or-later
// Scenario (issue #43): the README's "A first session", step by step, as a new user does it.
//  1. `benchscope sample_data/paper-2018` (what `scripts/dev gui` runs): the FLOPS tab shows the paper's runs with
//     the peak table under the plot.
//  2. Drag own files onto the window: a meter CSV that names no platform; the import asks which platform (on main
//     this question opened under the progress dialog and the session stopped here).
//  3. The Kernel Runner: a small sweep runs, fills the plot and lands in the workspace.
//  4. The Platforms tab: a 10 W power budget recommends the Jetson TX2.
//  5. File > Reproduce paper figures (Ctrl+Shift+E) and File > Export report (Ctrl+Shift+R): files written, and the
//     report's page 1 states the recommendation under the budget.
#include <QCheckBox>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QLineEdit>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSpinBox>
#include <QTest>

#include "../../../support/scenario_window.h"
#include "kernels/kernel_runner.h"
#include "peaks/flops_plot.h"
#include "peaks/peak_table.h"
#include "platform/platform_view.h"
#include "workspace/workspace_tree.h"

using bs::test::ModalAnswerer;

namespace {

// A drag of `paths` from a file manager, dropped on the window: the events Qt's drag and drop delivers.
void drop_files(QWidget* window, const QStringList& paths) {
  QMimeData mime;
  QList<QUrl> urls;
  for (const QString& p : paths) urls << QUrl::fromLocalFile(p);
  mime.setUrls(urls);
  const QPoint at = window->rect().center();
  QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(window, &enter);
  QDropEvent drop(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(window, &drop);
}

}  // namespace

class TestScenarioFirstSession : public QObject {
  Q_OBJECT
 private slots:
  void the_readme_first_session() {
    QTemporaryDir dir;
    // 1. The window as `benchscope sample_data/paper-2018` opens it: an untitled workspace holding the paper's data.
    bs::ui::MainWindow w;
    w.import_paths_now({bs::test::kPaper});
    QVERIFY(bs::test::show_at(w));
    QCOMPARE(w.tree()->run_count(), 13);
    QCOMPARE(w.flops_plot()->series_count(), 13);
    QCOMPARE(w.peak_table()->model()->rowCount(), 13);
    bs::test::screenshot(&w, "first-session-1-flops");

    // 2. Own files dropped on the window: the question about the meter's platform is answered.
    ModalAnswerer person;
    person.expect("Platform of meter-no-platform.csv", ModalAnswerer::titled("Platform of meter-no-platform.csv"),
                  [](QWidget* d) {
                    auto* combo = d->findChild<QComboBox*>();
                    if (!combo) return;
                    bs::test::retype(combo, "NUC");
                    bs::test::key(combo, Qt::Key_Return);
                  });
    drop_files(&w, {bs::test::kScenarioData + "/meter-no-platform.csv"});
    const QString imported = bs::test::wait_for_import(w);
    QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 100) && person.blocked.isEmpty(),
             qPrintable(person.report()));
    QVERIFY2(imported.startsWith("Imported 1 file(s)") && !imported.contains("cancelled"), qPrintable(imported));

    // 3. The Kernel Runner (its dock's tab on the left): a short CPU sweep, typed in, Run.
    auto* runner_dock = w.findChild<QDockWidget*>("kernelRunnerDock");
    QVERIFY(runner_dock);
    runner_dock->raise();
    bs::ui::KernelRunner* runner = w.kernel_runner();
    QVERIFY(bs::test::wait_until([&] { return runner->isVisible(); }, 100));
    auto* workers = bs::test::field<QLineEdit>(runner, "Workers");
    auto* dims = bs::test::field<QLineEdit>(runner, "D");
    auto* iterations = bs::test::field<QSpinBox>(runner, "N");
    auto* repeats = bs::test::field<QSpinBox>(runner, "Repeats");
    QVERIFY(workers && dims && iterations && repeats);
    bs::test::retype(workers, "1,2");
    bs::test::retype(dims, "1");
    bs::test::retype(iterations, "1000");
    bs::test::retype(repeats, "2");
    const int runs_before = w.tree()->run_count();
    bs::test::click(bs::test::widget_with_text<QPushButton>(runner, "Run"));
    QVERIFY2(bs::test::wait_until([&] { return w.tree()->run_count() > runs_before; }, 6000),
             qPrintable(bs::test::status(w)));
    QVERIFY2(bs::test::status(w).startsWith("Stored"), qPrintable(bs::test::status(w)));

    // 4. Platforms: a 10 W power budget.
    QWidget* tab = bs::test::open_tab(w, "Platforms");
    auto* use_budget = bs::test::widget_with_text<QCheckBox>(tab, QStringLiteral("Power budget ≤"));
    QVERIFY(use_budget);
    bs::test::click(use_budget);
    QVERIFY2(w.platform_view()->summary_text().contains("Recommended: <b>Jetson TX2</b>"),
             qPrintable(w.platform_view()->summary_text()));
    bs::test::screenshot(&w, "first-session-4-platforms");

    // 5. The paper's figures, then the report.
    const QString figures = dir.filePath("figures");
    {
      ModalAnswerer person5;
      person5.expect("Reproduce paper figures (export dialog)", ModalAnswerer::titled("Reproduce"), [&](QWidget* d) {
        for (QLineEdit* e : d->findChildren<QLineEdit*>())
          if (e->isVisible() && e->text().endsWith("figures")) bs::test::retype(e, figures);
        if (QAbstractButton* ok = bs::test::button(d, QDialogButtonBox::Ok)) bs::test::click(ok);
      });
      person5.expect("Paper figures (what was written)", ModalAnswerer::titled("Paper figures"), [](QWidget* d) {
        if (QAbstractButton* ok = bs::test::button(d, "OK")) bs::test::click(ok);
      });
      bs::test::key(&w, Qt::Key_E, Qt::ControlModifier | Qt::ShiftModifier);
      QVERIFY2(bs::test::wait_until([&] { return person5.done(); }, 3000), qPrintable(person5.report()));
    }
    QVERIFY2(QFileInfo::exists(figures + "/figures.json"), qPrintable(QDir(figures).entryList().join(", ")));
    const QString pdf = dir.filePath("report.pdf");
    BS_STEP(bs::test::export_report(w, pdf));
    const QString page1 = bs::test::pdf_page_text(pdf, 1).simplified();
    QVERIFY2(page1.contains("Recommended under a power budget of 10 W: Jetson TX2"), qPrintable(page1));
    bs::test::screenshot(&w, "first-session-5-done");
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioFirstSession)
#include "test_scenario_first_session.moc"
