// SPDX-License-Identifier: GPL-3.0-or-later
// Scenarios (issue #43.4): every number's own log and run in sight.
//  - A phase drawn on one of two overlapping logs belongs to that log (on main "Save as phase" put it on every log
//    the selection covered, the other platform's too).
//  - One platform with two logs: the Power legend and tables tell them apart by the log's name; Efficiency, Battery
//    and Platforms say which log they use and let the person pick the other; the choice is kept in the workspace
//    and named in the report dialog.
//  - Two sweeps of one device read apart in the peak table by their run label (F2), and "±" is never elided.
#include <qcustomplot.h>
#include <QComboBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QTest>
#include <set>

#include "../../../support/scenario_window.h"
#include "peaks/peak_table.h"
#include "platform/platform_view.h"
#include "power/power_cursors.h"
#include "power/power_stats_panel.h"
#include "power/power_view.h"
#include "runs/run_json.h"
#include "workspace/workspace_tree.h"

using bs::test::ModalAnswerer;

namespace {

// Phases named `name` per log label.
std::map<QString, int> phases_named(const bs::ui::MainWindow& w, const std::string& name) {
  std::map<QString, int> out;
  for (const bs::StoredPowerTrace& t : w.workspace()->power_trace_summaries())
    for (const bs::TracePhase& p : t.trace.phases)
      if (p.name == name) ++out[QString::fromStdString(t.trace.label)];
  return out;
}

QStringList column(const QTableWidget* table, int col) {
  QStringList out;
  for (int r = 0; r < table->rowCount(); ++r)
    if (const QTableWidgetItem* item = table->item(r, col)) out << item->text();
  return out;
}

// Two sweeps of one CPU, as two run JSON files (measured twice on the same machine, minutes apart).
QString write_sweep(const QString& path, const std::string& date, double seconds) {
  bs::FlopsRun run;
  run.platform = "Lab PC";
  run.device = "Lab CPU";
  run.device_kind = bs::DeviceKind::Cpu;
  run.backend = "CPU SIMD";
  run.kernel = "rotation2d";
  run.variant = "paper";
  run.dims = 4;
  run.iterations = 40000;
  for (int workers : {1, 2, 4, 8})
    run.samples.push_back({workers, {seconds * workers / 8, seconds * workers / 8 * 1.3, seconds * workers / 8 * 0.7}});
  run.provenance.origin = bs::DataOrigin::Measured;
  run.provenance.date = date;
  run.provenance.host = "labpc";
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly)) return {};
  const std::vector<bs::FlopsRun> runs{run};
  f.write(QByteArray::fromStdString(bs::write_run_json(runs)));
  return path;
}

}  // namespace

class TestScenarioLogsApart : public QObject {
  Q_OBJECT
 private slots:
  void a_phase_drawn_on_one_log_stays_on_it() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    BS_STEP(bs::test::open_paper_window(w, dir));
    bs::test::open_tab(w, "Power");
    bs::ui::PowerView* power = w.power_view();
    QCustomPlot* plot = power->plot();
    // The paper's two logs overlap from 0 to 120 s: the NUC's near 2.5 A, the Jetson's near 0.6 A. The person
    // Shift-drags from 30 s to 60 s along the Jetson's trace.
    const auto at = [plot](double t, double amps) {
      return QPointF(plot->xAxis->coordToPixel(t), plot->yAxis->coordToPixel(amps)).toPoint();
    };
    QWindow* window = w.windowHandle();
    const auto in_window = [&](QPoint p) { return plot->mapTo(&w, p); };
    QTest::mousePress(window, Qt::LeftButton, Qt::ShiftModifier, in_window(at(30, 0.6)));
    QTest::mouseMove(window, in_window(at(45, 0.6)));
    QTest::mouseMove(window, in_window(at(60, 0.6)));
    QTest::mouseRelease(window, Qt::LeftButton, Qt::ShiftModifier, in_window(at(60, 0.6)));
    QVERIFY2(power->cursors()->has_selection(), "the Shift + drag did not select a range");
    power->panels()->setCurrentWidget(power->selection_panel());
    ModalAnswerer person;
    QString offered;
    person.expect("Save selection as phase", ModalAnswerer::titled("Save selection as phase"), [&offered](QWidget* d) {
      if (auto* log = d->findChild<QComboBox*>()) offered = log->currentText();
      auto* name = d->findChild<QLineEdit*>();
      if (!name) return;
      bs::test::retype(name, "walk");
      bs::test::key(name, Qt::Key_Return);
    });
    bs::test::click(power->selection_panel()->save_button());
    QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 300), qPrintable(person.report()));
    // The dialog offered the log drawn on; the phase is on the Jetson's log alone.
    QVERIFY2(offered.contains("jetson-current.csv"), qPrintable(offered));
    const auto phases = phases_named(w, "walk");
    QCOMPARE(phases.count("jetson-current.csv") ? phases.at("jetson-current.csv") : 0, 1);
    QVERIFY2(!phases.count("nuc-current.csv"), "the phase landed on the NUC's log too");
    // The phase table names the log, not only the platform.
    QStringList logs = column(power->phase_panel()->table(), 1);
    QVERIFY2(logs.contains("Jetson TX2 — jetson-current.csv"), qPrintable(logs.join(", ")));
    bs::test::screenshot(&w, "phase-on-one-log");
  }

  void a_platforms_two_logs_are_told_apart_and_chosen() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    BS_STEP(bs::test::open_paper_window(w, dir));
    const QString ws = QString::fromStdString(w.workspace()->path());  // opened again at the end
    {
      ModalAnswerer person;
      person.expect("Import files (file dialog)", ModalAnswerer::titled("Import files"),
                    [](QWidget* d) { bs::test::choose_file(d, bs::test::kScenarioData + "/nuc-second-session.csv"); });
      bs::test::key(&w, Qt::Key_I, Qt::ControlModifier);
      QVERIFY2(bs::test::wait_for_import(w).startsWith("Imported 1 file(s)"), qPrintable(bs::test::status(w)));
    }
    // Power: the legend and the table name each log.
    bs::test::open_tab(w, "Power");
    QStringList legend;
    QCustomPlot* plot = w.power_view()->plot();
    for (int i = 0; i < plot->graphCount(); ++i) legend << plot->graph(i)->name();
    QCOMPARE(std::set<QString>(legend.begin(), legend.end()).size(), static_cast<std::size_t>(legend.size()));
    QVERIFY2(legend.contains("NUC — nuc-second-session.csv") && legend.contains("NUC — nuc-current.csv"),
             qPrintable(legend.join(", ")));
    const QStringList rows = column(w.power_view()->table(), 0);
    QVERIFY2(rows.filter("nuc-second-session.csv").size() == 1, qPrintable(rows.join(", ")));
    bs::test::screenshot(&w, "power-two-nuc-logs");

    // Platforms: which log the NUC's numbers come from, and the other one picked by the person.
    QWidget* tab = bs::test::open_tab(w, "Platforms");
    auto* choice = bs::test::field<QComboBox>(tab, "Power log of NUC:");
    QVERIFY2(choice, "the Platforms tab does not say which of the NUC's logs it uses");
    QCOMPARE(choice->currentText(), QString("nuc-current.csv"));
    const double before = [&] {
      for (int r = 0; r < w.platform_view()->table()->rowCount(); ++r)
        if (w.platform_view()->table()->item(r, 0)->text().startsWith("NUC")) return r;
      return -1;
    }();
    QVERIFY(before >= 0);
    BS_STEP(bs::test::pick_next_entry(choice));  // the person picks the second session
    QVERIFY(bs::test::wait_until(
        [&] {
          auto* c = bs::test::field<QComboBox>(bs::test::window_tabs(w)->currentWidget(), "Power log of NUC:");
          return c && c->currentText() == "nuc-second-session.csv";
        },
        200));
    // The NUC's mean power is now the second session's (about 1.9 A x 16 V = 30.4 W, not the paper's 40.5 W).
    bs::ui::PlatformView* view = w.platform_view();
    bool second = false;
    for (int r = 0; r < view->table()->rowCount(); ++r)
      for (int c = 0; c < view->table()->columnCount(); ++c)
        if (view->table()->item(r, 0)->text().startsWith("NUC") &&
            view->table()->horizontalHeaderItem(c)->text().startsWith("Mean power"))
          second = view->table()->item(r, c)->text().startsWith("30.");
    QVERIFY2(second, "the NUC's mean power does not come from the log picked");
    // Efficiency and Battery say the same, from the workspace.
    for (const QString& name : {QStringLiteral("Efficiency"), QStringLiteral("Battery")}) {
      auto* c = bs::test::field<QComboBox>(bs::test::open_tab(w, name), "Power log of NUC:");
      QVERIFY2(c && c->currentText() == "nuc-second-session.csv", qPrintable(name));
    }
    bs::test::screenshot(&w, "battery-chosen-log");
    // The report dialog names it too.
    QString shown;
    {
      ModalAnswerer person;
      person.expect(
          "Export report (the report dialog)",
          [](QWidget* d) { return d->windowTitle() == "Export report" && !qobject_cast<QFileDialog*>(d); },
          [&shown](QWidget* d) {
            if (auto* decision = d->findChild<QLabel*>("reportDecision")) shown = decision->text();
            bs::test::key(d, Qt::Key_Escape);
          });
      bs::test::key(&w, Qt::Key_R, Qt::ControlModifier | Qt::ShiftModifier);
      QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 300), qPrintable(person.report()));
    }
    QVERIFY2(shown.contains("NUC: nuc-second-session.csv"), qPrintable(shown));
    // Kept in the workspace: a window opened on it again uses the same log.
    bs::ui::MainWindow again;
    QVERIFY(again.open_workspace(ws));
    auto* kept = bs::test::field<QComboBox>(again.platform_view()->parentWidget(), "Power log of NUC:");
    QVERIFY(kept);
    QCOMPARE(kept->currentText(), QString("nuc-second-session.csv"));
  }

  void two_sweeps_of_one_device_read_apart_in_the_peak_table() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("sweeps.bsw")));
    QVERIFY(bs::test::show_at(w));
    const QString a = write_sweep(dir.filePath("sweep-a.json"), "2026-11-28T10:00:00Z", 0.002);
    const QString b = write_sweep(dir.filePath("sweep-b.json"), "2026-11-28T10:05:00Z", 0.0021);
    {
      ModalAnswerer person;
      person.expect("Import files (file dialog)", ModalAnswerer::titled("Import files"), [&](QWidget* d) {
        bs::test::choose_files(d, dir.path(), {"sweep-a.json", "sweep-b.json"});
      });
      bs::test::key(&w, Qt::Key_I, Qt::ControlModifier);
      QVERIFY2(bs::test::wait_for_import(w).startsWith("Imported 2 file(s)"), qPrintable(bs::test::status(w)));
    }
    // The person names the second sweep in the tree: select it, F2, type, Enter.
    bs::ui::WorkspaceTree* tree = w.tree();
    qint64 second = 0;
    for (const bs::StoredRun& r : w.workspace()->runs())
      if (r.run.provenance.date == "2026-11-28T10:05:00Z") second = r.id;
    QVERIFY(tree->select_run(second));
    ModalAnswerer person;
    person.expect("Name this run (F2)", ModalAnswerer::titled("Name this run"), [](QWidget* d) {
      auto* field = d->findChild<QLineEdit*>();
      bs::test::retype(field, "after BIOS update");
      bs::test::key(field, Qt::Key_Return);
    });
    bs::test::key(&w, Qt::Key_F2);  // Edit > Rename selected item
    QVERIFY2(bs::test::wait_until([&] { return person.done(); }, 300), qPrintable(person.report()));
    bs::test::open_tab(w, "FLOPS");
    const QAbstractItemModel* model = w.peak_table()->model();
    QStringList rows;
    for (int r = 0; r < model->rowCount(); ++r) {
      QStringList cells;
      for (int c = 0; c < model->columnCount(); ++c) cells << model->index(r, c).data().toString();
      rows << cells.join(" | ");
    }
    QCOMPARE(rows.size(), 2);
    QVERIFY2(rows[0] != rows[1], qPrintable(rows.join("\n")));
    QVERIFY2(rows.join("\n").contains("after BIOS update"), qPrintable(rows.join("\n")));
    // The peak cell shows mean ± SD whole: nothing elided where the "±" is.
    const QAbstractItemModel* m = model;
    for (int r = 0; r < m->rowCount(); ++r)
      for (int c = 0; c < m->columnCount(); ++c) {
        const QString text = m->index(r, c).data().toString();
        if (!text.contains("±")) continue;
        const int width = w.peak_table()->columnWidth(c);
        const int needed = w.peak_table()->fontMetrics().horizontalAdvance(text) + 12;
        QVERIFY2(width >= needed, qPrintable(QString("%1: %2 px for %3 px of text").arg(text).arg(width).arg(needed)));
      }
    bs::test::screenshot(&w, "peak-table-two-sweeps");
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioLogsApart)
#include "test_scenario_logs_apart.moc"
