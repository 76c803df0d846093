// SPDX-License-Identifier: GPL-3.0-or-later
// Scenario (issue #50): a person keeps the GUI open on the lab's workspace and uses the CLI beside it, as
// docs/guide.md suggests.
//  - gui_import_keeps_its_locks: File > Import files… (Ctrl+I, the file dialog answered from the event loop) of a run
//    JSON; the window still holds its POSIX locks on the workspace and its -shm file afterwards, and
//    `benchscope-cli runs` beside it leaves the window's WAL in place (before #50: 0 locks after the import, and the
//    CLI deleted the WAL the window then wrote into), and lists the run the window imported.
//  - battery_edit_is_where_the_cli_reads: 5000 mAh typed into the Battery tab; the Platforms tab's runtime cells,
//    `benchscope-cli platforms --json`, `battery --workspace --json` and the GUI's report give the same minutes
//    (before #50 the CLI kept 3850 mAh: 84.36 against the GUI's 109.56 min).
//  - a_load_never_applied_never_passes: a headroom measurement whose pipeline@30fps phase ran at 9.29 fps, imported;
//    the Headroom tab's flags say "load not applied" (before #50 only a tooltip did), and the Platforms tab's control
//    loop beside that load is "unknown (load not applied ...)" for the NUC, which is then not recommended (before
//    #50 it passed).
#include <unistd.h>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QTableWidget>
#include <QTest>

#include "../../../support/cli_harness.h"
#include "../../../support/headroom_samples.h"
#include "../../../support/process_locks.h"
#include "../../../support/scenario_window.h"
#include "headroom/headroom_view.h"
#include "platform/platform_view.h"

using bs::test::ModalAnswerer;

namespace {

const QString kRunJson = BENCHSCOPE_SOURCE_DIR "/tests/data/importers/run-json/two-runs.json";

// The Platforms table's "Battery runtime (min)" cell of each platform, as shown.
QMap<QString, double> shown_runtimes(QTableWidget* t) {
  QMap<QString, double> out;
  int col = -1;
  for (int c = 0; c < t->columnCount(); ++c)
    if (t->horizontalHeaderItem(c) && t->horizontalHeaderItem(c)->text().startsWith("Battery runtime")) col = c;
  if (col < 0) return out;
  for (int r = 0; r < t->rowCount(); ++r) {
    const QTableWidgetItem* name = t->item(r, 0);
    const QTableWidgetItem* cell = t->item(r, col);
    bool ok = false;
    const double v = cell ? cell->text().split(' ').front().toDouble(&ok) : 0;
    if (name && ok) out[name->text()] = v;
  }
  return out;
}

}  // namespace

class TestScenarioOneTruth : public QObject {
  Q_OBJECT
 private slots:
  void gui_import_keeps_its_locks() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY2(bs::test::open_paper_window(w, dir).isEmpty(), "the paper window did not open");
    const std::string ws = w.workspace()->path();
    const long pid = static_cast<long>(::getpid());
    {
      ModalAnswerer person;
      person.expect("Import files (file dialog)", ModalAnswerer::titled("Import files"),
                    [](QWidget* d) { bs::test::choose_file(d, kRunJson); });
      bs::test::key(&w, Qt::Key_I, Qt::ControlModifier);
      const QString imported = bs::test::wait_for_import(w);
      QVERIFY2(person.done(), qPrintable(person.report()));
      QVERIFY2(imported.startsWith("Imported 1 file(s)"), qPrintable(imported));
    }
    // The window's own connection, in WAL mode after its writes, holds a lock on the file and one on its -shm.
    QVERIFY2(bs::test::posix_locks_on(pid, ws) > 0, "after an import the window holds no lock on the workspace");
    QVERIFY2(bs::test::posix_locks_on(pid, ws + "-shm") > 0, "after an import the window holds no lock on its -shm");
    const bs::test::CliResult listed = bs::test::cli({"runs", QString::fromStdString(ws)});
    QCOMPARE(listed.code, 0);
    QVERIFY2(QFileInfo::exists(QString::fromStdString(ws) + "-wal"), "`benchscope-cli runs` deleted the window's WAL");
    QVERIFY2(!bs::test::holds_deleted_wal(pid, ws), "the window writes into a deleted WAL");
    QVERIFY2(listed.out.contains("Test CPU"), listed.out.constData());
    // An edit made after the CLI ran is where the next process reads it.
    QWidget* tab = bs::test::open_tab(w, "Battery");
    auto* capacity = bs::test::field<QDoubleSpinBox>(tab, "Capacity");
    QVERIFY(capacity);
    bs::test::retype(capacity, "4200");
    bs::test::key(capacity, Qt::Key_Return);
    const bs::test::CliResult battery = bs::test::cli({"battery", "--workspace", QString::fromStdString(ws), "--json"});
    QCOMPARE(battery.code, 0);
    QVERIFY2(battery.out.contains("4200") || battery.out.contains("4.2"), battery.out.constData());
  }

  void battery_edit_is_where_the_cli_reads() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY2(bs::test::open_paper_window(w, dir).isEmpty(), "the paper window did not open");
    const QString ws = QString::fromStdString(w.workspace()->path());
    QWidget* battery_tab = bs::test::open_tab(w, "Battery");
    auto* capacity = bs::test::field<QDoubleSpinBox>(battery_tab, "Capacity");
    QVERIFY(capacity);
    bs::test::retype(capacity, "5000");
    bs::test::key(capacity, Qt::Key_Return);
    QCOMPARE(capacity->value(), 5000.0);
    bs::test::open_tab(w, "Platforms");
    const QMap<QString, double> gui = shown_runtimes(w.platform_view()->table());
    QVERIFY2(gui.contains("NUC") && gui.contains("Jetson TX2"), qPrintable(QStringList(gui.keys()).join(", ")));
    QVERIFY2(std::abs(gui["NUC"] - 109.56) < 0.01, qPrintable(QString::number(gui["NUC"])));
    QVERIFY2(std::abs(gui["Jetson TX2"] - 468.16) < 0.01, qPrintable(QString::number(gui["Jetson TX2"])));

    // benchscope-cli platforms --json on the same file: the same minutes.
    const bs::test::CliResult platforms = bs::test::cli({"platforms", ws, "--json"});
    QCOMPARE(platforms.code, 0);
    const QJsonObject doc = QJsonDocument::fromJson(platforms.out).object();
    int compared = 0;
    for (const QJsonValue& v : doc["platforms"].toArray()) {
      const QJsonObject p = v.toObject();
      const QString name = p["platform"].toString();
      if (!gui.contains(name) || p["battery_runtime_h"].isNull()) continue;
      const double cli_min = p["battery_runtime_h"].toDouble() * 60;
      QVERIFY2(
          std::abs(cli_min - gui[name]) < 0.01,
          qPrintable(QString("%1: the GUI shows %2 min, the CLI says %3 min").arg(name).arg(gui[name]).arg(cli_min)));
      ++compared;
    }
    QCOMPARE(compared, 2);
    // benchscope-cli battery --workspace: the Battery tab's own table, the same minutes.
    const bs::test::CliResult battery = bs::test::cli({"battery", "--workspace", ws, "--json"});
    QCOMPARE(battery.code, 0);
    QVERIFY2(battery.out.contains("109.5") && battery.out.contains("468.1"), battery.out.constData());

    // The GUI's report: page 1's table carries the same numbers.
    const QString pdf = QDir(dir.path()).filePath("report.pdf");
    BS_STEP(bs::test::export_report(w, pdf));
    QString text;
    for (int page = 1; page <= 4; ++page) text += bs::test::pdf_page_text(pdf, page);
    QVERIFY2(text.contains("109.56") && text.contains("468.16"), qPrintable(text.left(3000)));
    const QString cli_pdf = QDir(dir.path()).filePath("cli-report.pdf");
    QCOMPARE(bs::test::cli({"report", ws, "--pdf", cli_pdf, "--quiet"}).code, 0);
    QString cli_text;
    for (int page = 1; page <= 4; ++page) cli_text += bs::test::pdf_page_text(cli_pdf, page);
    QVERIFY2(cli_text.contains("109.56") && cli_text.contains("468.16"), qPrintable(cli_text.left(3000)));
  }

  void a_load_never_applied_never_passes() {
    QTemporaryDir dir;
    const QString ws = bs::test::paper_workspace(dir);
    QVERIFY(!ws.isEmpty());
    // The NUC's loop measured beside pipeline@30fps, which ran at 9.29 fps (as `headroom` or the tab stores it).
    bs::headroom::HeadroomMeasurement m = bs::test::loop_measurement(
        "NUC", {{"idle", bs::test::loop_thread(1000, 5)}, {"pipeline@30fps", bs::test::loop_thread(1000, 20)}});
    bs::headroom::Phase& beside = m.phases[1];
    beside.load = bs::headroom::LoadKind::Pipeline;
    beside.target_rate = 30;
    beside.achieved_rate = 9.29;
    beside.rate_unit = "fps";
    {
      bs::Workspace store(ws.toStdString());
      bs::ImportBatch b;
      b.source_path = "headroom";
      b.format = "benchscope-headroom-v1";
      b.headroom = {m};
      store.add_import(b, "nuc-headroom");
    }
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(ws));
    QVERIFY(bs::test::show_at(w));
    QWidget* tab = bs::test::open_tab(w, "Headroom");
    QVERIFY(tab);
    const QString flags = w.headroom_view()->flags_label()->text();
    QVERIFY2(flags.contains("load not applied: pipeline@30fps ran at 9.29 of 30 fps"), qPrintable(flags));
    QVERIFY2(w.headroom_view()->flags_label()->isVisible(), "the flag is not on screen");

    bs::test::open_tab(w, "Platforms");
    bs::ui::PlatformView* platforms = w.platform_view();
    auto* use_loop = bs::test::widget_with_text<QCheckBox>(platforms, "Control loop:");
    QVERIFY(use_loop);
    bs::test::retype(platforms->loop_edit(), "1kHz,p99.9<=200us,load=pipeline@30fps");
    bs::test::key(platforms->loop_edit(), Qt::Key_Return);
    if (!use_loop->isChecked()) bs::test::click(use_loop);
    const QString summary = platforms->summary_text();
    QVERIFY2(summary.contains("NUC <b>unknown</b> (load not applied: pipeline@30fps ran at 9.29 of 30 fps"),
             qPrintable(summary));
    QVERIFY2(!summary.contains("Recommended: <b>NUC</b>"), qPrintable(summary));
    bs::test::screenshot(&w, "one-truth-load-not-applied");
  }
};

BENCHSCOPE_SCENARIO_MAIN(TestScenarioOneTruth)
#include "test_scenario_one_truth.moc"
