// SPDX-License-Identifier: GPL-3.0-or-later
// The Battery tab on the paper's sample data: 84.36 / 360.48 min with the paper's pack and model; edits recompute
// at once (capacity, depth of discharge, extra load, model, mission); a preset saved from the view lives in the
// workspace and comes back after reopening it; the plot has a state-of-charge and a voltage curve per platform.
#include <qcustomplot.h>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/paper_sample.h"
#include "power/battery_view.h"
#include "store/workspace.h"

namespace {

QString runtime_of(const QTableWidget* t, const QString& platform) {
  int col = -1;
  for (int c = 0; c < t->columnCount(); ++c)
    if (t->horizontalHeaderItem(c)->text() == "Runtime (min)") col = c;
  for (int r = 0; r < t->rowCount(); ++r)
    if (t->item(r, 0)->text() == platform) return t->item(r, col)->text();
  return {};
}

const bs::PlatformBattery& row(const bs::ui::BatteryView& view, const std::string& platform) {
  for (const auto& r : view.rows())
    if (r.platform == platform) return r;
  throw std::runtime_error("no row for " + platform);
}

std::vector<bs::PowerTrace> paper_traces() {
  std::vector<bs::FlopsRun> runs;
  std::vector<bs::PowerTrace> traces;
  bs::test::load_paper_sample(runs, traces);
  return traces;
}

}  // namespace

class TestBatteryView : public QObject {
  Q_OBJECT
 private slots:
  void paper_numbers_and_edits() {
    bs::ui::BatteryView view;
    view.resize(1400, 800);
    view.set_data(paper_traces());
    QTableWidget* t = view.table();
    QCOMPARE(t->rowCount(), 2);
    QVERIFY(view.preset_box()->currentText().startsWith("paper-4s-3850"));
    QCOMPARE(view.volts_box()->value(), 14.8);
    QCOMPARE(view.capacity_box()->value(), 3850.0);
    QCOMPARE(runtime_of(t, "NUC"), QString("84.36"));
    QCOMPARE(runtime_of(t, "Jetson TX2"), QString("360.48"));
    // Capacity scales the constant-power runtime in proportion, at once.
    const double nuc_s = row(view, "NUC").result.runtime_s;
    view.capacity_box()->setValue(7700);
    QCOMPARE(runtime_of(t, "NUC"), QString::number(nuc_s * 2 / 60, 'f', 2));
    QVERIFY(std::abs(row(view, "NUC").result.runtime_s - 2 * nuc_s) < 1e-6);
    view.capacity_box()->setValue(3850);
    view.dod_box()->setValue(80);
    QCOMPARE(runtime_of(t, "Jetson TX2"), QString::number(row(view, "Jetson TX2").result.runtime_s / 60, 'f', 2));
    QVERIFY(std::abs(row(view, "Jetson TX2").result.runtime_s / 60 - 360.48 * 0.8) < 0.01);
    view.dod_box()->setValue(100);
    // 225 W of servos in parallel: the computer's share hardly matters any more.
    view.extra_load_box()->setValue(225);
    const double nuc_min = runtime_of(t, "NUC").toDouble(), jetson_min = runtime_of(t, "Jetson TX2").toDouble();
    QVERIFY(std::abs(nuc_min - 14.8 * 3.85 / (225 + 40.52) * 60) < 0.05);
    QVERIFY(jetson_min > nuc_min && jetson_min < nuc_min * 1.2);
    // The LiPo model under that heavy load: voltage sag through the internal resistance ends it at the cut-off,
    // before the constant-power model's time.
    view.model_box()->setCurrentIndex(1);
    QVERIFY(runtime_of(t, "NUC").toDouble() < nuc_min);
    QCOMPARE(row(view, "NUC").result.stop_reason, std::string("cut-off voltage reached"));
    view.model_box()->setCurrentIndex(0);
    view.extra_load_box()->setValue(0);
    // A mission: phases on top of the computer.
    view.mission_edit()->setText("idle:60:10,walk:30:100");
    emit view.mission_edit()->editingFinished();
    QVERIFY(std::abs(row(view, "NUC").mission.mean_load_w() - (40.52 + (60 * 10 + 30 * 100) / 90.0)) < 0.01);
    QVERIFY(runtime_of(t, "NUC").toDouble() < 84.36);
    view.mission_edit()->setText("walk:soon:100");
    emit view.mission_edit()->editingFinished();
    QVERIFY(view.error_text().contains("soon"));
    QCOMPARE(t->rowCount(), 0);
    view.mission_edit()->clear();
    emit view.mission_edit()->editingFinished();
    QVERIFY(view.error_text().isEmpty());
    QCOMPARE(runtime_of(t, "NUC"), QString("84.36"));
    // The plot: state of charge and pack voltage per platform, in minutes.
    QCustomPlot* plot = view.plot();
    QCOMPARE(plot->graphCount(), 4);
    QCOMPARE(plot->xAxis->label(), QString("Time (min)"));
    QCOMPARE(plot->yAxis->label(), QString("State of charge (%)"));
    QVERIFY(plot->yAxis2->label().contains("(V)"));
    for (int g = 0; g < plot->graphCount(); ++g) {
      if (!plot->graph(g)->name().startsWith("NUC: state of charge")) continue;
      QCOMPARE(plot->graph(g)->data()->at(0)->value, 100.0);
      QVERIFY(std::abs(plot->graph(g)->data()->at(plot->graph(g)->dataCount() - 1)->key - 84.36) < 0.01);
      QVERIFY(plot->graph(g)->data()->at(plot->graph(g)->dataCount() - 1)->value < 0.01);
    }
  }

  void presets_saved_in_the_workspace() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath("w.bsw").toStdString();
    {
      bs::Workspace ws(path);
      bs::ui::BatteryView view;
      QVERIFY(!view.save_preset("no workspace"));
      view.set_workspace(&ws);
      view.set_data(paper_traces());
      view.capacity_box()->setValue(5000);
      view.extra_load_box()->setValue(60);
      view.dod_box()->setValue(80);
      QVERIFY(view.save_preset("robot pack"));
      QVERIFY(view.preset_box()->currentText().startsWith("robot pack"));
      QVERIFY(view.preset_box()->currentText().contains("workspace"));
    }
    bs::Workspace ws(path);
    bs::ui::BatteryView view;
    view.set_workspace(&ws);
    view.set_data(paper_traces());
    // The workspace brings back the setup last shown: the saved preset.
    QVERIFY(view.preset_box()->currentText().startsWith("robot pack"));
    QCOMPARE(view.capacity_box()->value(), 5000.0);
    QVERIFY(view.select_preset("paper-4s-3850"));
    QCOMPARE(runtime_of(view.table(), "NUC"), QString("84.36"));
    QVERIFY(view.select_preset("robot pack"));
    QCOMPARE(view.capacity_box()->value(), 5000.0);
    QCOMPARE(view.extra_load_box()->value(), 60.0);
    QCOMPARE(view.dod_box()->value(), 80.0);
    QVERIFY(std::abs(runtime_of(view.table(), "NUC").toDouble() - 14.8 * 5.0 * 0.8 / (40.52 + 60) * 60) < 0.05);
    QVERIFY(!view.select_preset("no such pack"));
  }

  // Issue #23.2: an edit survives what the user does next (an import or a kernel run reloads the views with the same
  // workspace), shows as "modified", is saved with the workspace and comes back when it is opened again.
  void edits_survive_reloads_and_reopening() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const std::string path = dir.filePath("w.bsw").toStdString();
    {
      bs::Workspace ws(path);
      bs::ui::BatteryView view;
      view.set_workspace(&ws);
      view.set_data(paper_traces());
      QVERIFY(!view.modified());
      QVERIFY(!view.preset_box()->currentText().contains("modified"));
      const double paper_nuc_s = row(view, "NUC").result.runtime_s;  // 84.36 min
      QSignalSpy changed(&view, &bs::ui::BatteryView::setup_changed);
      view.capacity_box()->setValue(5000);
      QVERIFY(changed.count() >= 1);
      QVERIFY(view.modified());
      QVERIFY(view.preset_box()->currentText().startsWith("paper-4s-3850"));
      QVERIFY(view.preset_box()->currentText().contains("modified"));
      // What MainWindow::reload() does after any import, failed or not, and after a kernel run.
      view.set_workspace(&ws);
      view.set_data(paper_traces());
      QCOMPARE(view.capacity_box()->value(), 5000.0);
      QVERIFY(view.preset_box()->currentText().contains("modified"));
      // Constant power: the runtime scales with the capacity, 5000 / 3850 of the paper's 84.36 min.
      QVERIFY(std::abs(row(view, "NUC").result.runtime_s - paper_nuc_s * 5000 / 3850) < 1e-6);
      // Back to the preset's own value: no longer modified.
      view.capacity_box()->setValue(3850);
      QVERIFY(!view.modified());
      view.dod_box()->setValue(90);
    }
    bs::Workspace ws(path);
    bs::ui::BatteryView view;
    view.set_workspace(&ws);
    view.set_data(paper_traces());
    QCOMPARE(view.dod_box()->value(), 90.0);
    QVERIFY(view.modified());
    QVERIFY(std::abs(runtime_of(view.table(), "NUC").toDouble() - 84.36 * 0.9) < 0.01);
  }
};

QTEST_MAIN(TestBatteryView)
#include "test_battery_view.moc"
