// SPDX-License-Identifier: GPL-3.0-or-later
// The Power tab's cursors, selection statistics, phases and overlays (issue #19):
// - the selection's numbers and the per-phase table are exactly what `benchscope-cli power` prints for the same
//   range cut between samples (the test runs both);
// - cursor statistics against analytic integrals (a ramp in W, a sine in A);
// - keys A / B / Esc and Shift + drag place and clear the cursors; "Copy as table" text; a selection saved as a
//   phase reaches the workspace;
// - overlay offsets, typed and aligned at a phase; the battery pack comes from the workspace's Battery tab setup.
// Set BENCHSCOPE_SCREENSHOT_DIR to also save the tab (1600x1000) with a selection, an overlay and shaded phases.
#include <qcustomplot.h>
#include <QApplication>
#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QDir>
#include <QPushButton>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>
#include <nlohmann/json.hpp>

#include "../../support/cli_harness.h"
#include "../../support/paper_sample.h"
#include "analysis/power/range_table.h"
#include "power/power_cursors.h"
#include "power/power_overlay.h"
#include "power/power_stats_panel.h"
#include "power/power_view.h"
#include "store/battery_preset_store.h"
#include "store/log_settings_store.h"

namespace {

std::vector<bs::StoredPowerTrace> stored(const std::vector<bs::PowerTrace>& traces) {
  std::vector<bs::StoredPowerTrace> out;
  for (const auto& t : traces) out.push_back({0, 1, t, {}, true});  // id 0: not in a workspace
  return out;
}

const bs::PowerTrace& by_platform(const std::vector<bs::PowerTrace>& traces, const std::string& platform) {
  for (const auto& t : traces)
    if (t.platform == platform) return t;
  throw std::runtime_error("no trace of " + platform);
}

// Cells of a row of the panel's table.
std::vector<std::string> row_cells(const QTableWidget* t, int row) {
  std::vector<std::string> out;
  for (int c = 0; c < t->columnCount(); ++c) out.push_back(t->item(row, c)->text().toStdString());
  return out;
}

int column(const QTableWidget* t, const QString& header) {
  for (int c = 0; c < t->columnCount(); ++c)
    if (t->horizontalHeaderItem(c)->text() == header) return c;
  return -1;
}

double cell_number(const QTableWidget* t, int row, const QString& header) {
  const int c = column(t, header);
  return c < 0 ? std::nan("") : t->item(row, c)->text().toDouble();
}

void save_shot(QWidget* w, const QString& name) {
  const QString dir = qEnvironmentVariable("BENCHSCOPE_SCREENSHOT_DIR");
  if (dir.isEmpty()) return;
  QDir().mkpath(dir);
  for (int k = 0; k < 5; ++k) QApplication::processEvents();
  QVERIFY(w->grab().save(dir + "/" + name));
}

}  // namespace

class TestPowerSelection : public QObject {
  Q_OBJECT
 private slots:
  void gui_and_cli_agree_between_samples() {
    // The NUC's 10 Hz log at 16 V; the range 12.34 .. 57.891 s starts and ends between samples.
    const QString file = BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/power/nuc-current.csv";
    const bs::PowerTrace nuc = by_platform(bs::test::load_paper_sample().traces, "NUC");
    bs::ui::PowerView view;
    view.resize(1600, 1000);
    view.set_data(stored({nuc}), {}, {});
    view.set_quantity(bs::ui::PowerView::Quantity::Power);
    view.cursors()->set(12.34, 57.891);
    QCOMPARE(view.selection_stats().size(), std::size_t{1});
    const bs::PowerStats& g = view.selection_stats()[0].second;
    QByteArray out, err;
    QCOMPARE(bs::test::run_cli({"power", file, "--from", "12.34", "--to", "57.891", "--json"}, &out, &err), 0);
    const nlohmann::json c = nlohmann::json::parse(out.toStdString())["traces"][0];
    // Exactly equal, not nearly: one implementation (PowerIndex) behind both, and JSON keeps every double.
    QCOMPARE(c["n"].get<std::size_t>(), g.n);
    QVERIFY(c["duration_s"].get<double>() == g.duration_s);
    QVERIFY(std::abs(g.duration_s - (57.891 - 12.34)) < 1e-12);  // interpolated ends, not whole samples
    QVERIFY(c["energy_j"].get<double>() == *g.energy_j);
    QVERIFY(c["charge_c"].get<double>() == *g.charge_c);
    QVERIFY(c["mean_power_w"].get<double>() == *g.mean_power_w);
    for (const char* key : {"mean", "sd", "min", "max", "p5", "p50", "p95", "p99"}) {
      const double gui = std::string(key) == "mean"  ? g.power_w->summary.mean
                         : std::string(key) == "sd"  ? g.power_w->summary.sd
                         : std::string(key) == "min" ? g.power_w->summary.min
                         : std::string(key) == "max" ? g.power_w->summary.max
                         : std::string(key) == "p5"  ? g.power_w->pct.p5
                         : std::string(key) == "p50" ? g.power_w->pct.p50
                         : std::string(key) == "p95" ? g.power_w->pct.p95
                                                     : g.power_w->pct.p99;
      QVERIFY2(c["power_w"][key].get<double>() == gui, key);
    }
    // The per-phase table: the CLI's --phases rows are the Phases tab's rows, cell for cell (the tab has the trace
    // name as its second column).
    view.set_detected_phases(true);
    const QTableWidget* phases = view.phase_panel()->table();
    QVERIFY(phases->rowCount() >= 2);  // the log's load steps
    QCOMPARE(bs::test::run_cli({"power", file, "--phases"}, &out, &err), 0);
    QStringList cli_rows;
    bool in_table = false;
    for (const QString& line : QString::fromUtf8(out).split('\n')) {
      if (line.trimmed().startsWith("phase "))
        in_table = true;
      else if (in_table && !line.trimmed().isEmpty() && !line.startsWith("---"))
        cli_rows << line.simplified();
    }
    QCOMPARE(cli_rows.size(), phases->rowCount());
    for (int r = 0; r < phases->rowCount(); ++r) {
      std::vector<std::string> gui = row_cells(phases, r);
      gui.erase(gui.begin() + 1);  // the trace column
      QStringList joined;
      for (const std::string& s : gui) joined << QString::fromStdString(s);
      QCOMPARE(joined.join(' '), cli_rows[r]);
    }
  }

  void cursor_statistics_against_analytic_values() {
    // A ramp P(t) = 2 + 0.5 t W and a current sine I(t) = 1 + 0.5 sin t A at 12 V, both at 100 Hz for 20 s.
    bs::PowerTrace ramp, sine;
    ramp.platform = "ramp";
    sine.platform = "sine";
    sine.supply_voltage_v = 12;
    std::vector<double> p, i;
    for (int k = 0; k <= 2000; ++k) {
      const double t = k * 0.01;
      ramp.time_s.push_back(t);
      sine.time_s.push_back(t);
      p.push_back(2 + 0.5 * t);
      i.push_back(1 + 0.5 * std::sin(t));
    }
    ramp.channels.push_back({"P", bs::PowerQuantity::Power, p});
    sine.channels.push_back({"I", bs::PowerQuantity::Current, i});
    bs::ui::PowerView view;
    view.resize(1600, 1000);
    view.set_data(stored({ramp, sine}), {}, {});
    view.set_quantity(bs::ui::PowerView::Quantity::Power);
    const double a = 3.3333, b = 7.7777;  // between samples
    view.cursors()->set(b, a);            // B before A: the selection is still a..b
    const QTableWidget* t = view.selection_panel()->table();
    QCOMPARE(t->rowCount(), 2);
    const double ramp_j = 2 * (b - a) + 0.25 * (b * b - a * a);
    QVERIFY(std::abs(*view.selection_stats()[0].second.energy_j - ramp_j) < 1e-12);
    QVERIFY(std::abs(cell_number(t, 0, "energy (J)") - ramp_j) < 1e-4);
    QVERIFY(std::abs(cell_number(t, 0, "energy (Wh)") - ramp_j / 3600) < 1e-6);
    QVERIFY(std::abs(cell_number(t, 0, "duration (s)") - (b - a)) < 1e-4);
    QVERIFY(std::abs(cell_number(t, 0, "mean power (W)") - ramp_j / (b - a)) < 1e-4);
    QVERIFY(std::abs(cell_number(t, 0, "p2p (W)") - 0.5 * (7.77 - 3.34)) < 1e-4);  // samples 3.34 .. 7.77 s
    QCOMPARE(t->item(0, column(t, "charge (C)"))->text(), QString("-"));           // a power log: no current, no charge
    // The sine: charge ∫ I dt = (b − a) + 0.5 (cos a − cos b); trapezoids at 10 ms are within 1e-5 of it.
    const double charge = (b - a) + 0.5 * (std::cos(a) - std::cos(b));
    QVERIFY(std::abs(*view.selection_stats()[1].second.charge_c - charge) < 1e-5);
    QVERIFY(std::abs(cell_number(t, 1, "charge (mAh)") - charge / 3.6) < 1e-4);
    QVERIFY(std::abs(cell_number(t, 1, "energy (J)") - 12 * charge) < 1e-3);
    // Copy as table: tab-separated, units in the headers, one line per trace.
    const QString tsv = view.selection_panel()->tsv();
    QVERIFY(tsv.startsWith("trace\tn\tduration (s)\tmean (W)\tSD (W)\tmin (W)\tmax (W)\tp2p (W)\tp5 (W)"));
    QCOMPARE(tsv.count('\n'), 3);
    view.selection_panel()->copy_button()->click();
    if (QApplication::clipboard()->text() != QString())  // no clipboard on some platforms
      QCOMPARE(QApplication::clipboard()->text(), tsv);
    save_shot(&view, "power-selection.png");
  }

  void keys_and_shift_drag_place_the_cursors() {
    bs::PowerTrace t;
    t.platform = "flat";
    for (int k = 0; k <= 100; ++k) t.time_s.push_back(k);
    t.channels.push_back({"P", bs::PowerQuantity::Power, std::vector<double>(101, 5.0)});
    bs::ui::PowerView view;
    view.resize(1200, 800);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.set_data(stored({t}), {}, {});
    QCustomPlot* plot = view.plot();
    plot->replot();
    const QRect r = plot->axisRect()->rect();
    const QPoint p1(r.left() + r.width() / 4, r.center().y()), p2(r.left() + r.width() * 3 / 4, r.center().y());
    QTest::mouseMove(plot, p1);
    QTest::keyClick(plot, Qt::Key_A);
    QVERIFY(view.cursors()->a());
    QVERIFY(std::abs(*view.cursors()->a() - plot->xAxis->pixelToCoord(p1.x())) < 1e-9);
    QTest::mouseMove(plot, p2);
    QTest::keyClick(plot, Qt::Key_B);
    QVERIFY(view.cursors()->has_selection());
    QCOMPARE(view.selection_panel()->table()->rowCount(), 1);
    QTest::keyClick(plot, Qt::Key_Escape);
    QVERIFY(!view.cursors()->a() && !view.cursors()->b());
    QCOMPARE(view.selection_panel()->table()->rowCount(), 0);
    // Shift + drag: A at the press, B at the release; the axis does not pan meanwhile.
    const QCPRange before = plot->xAxis->range();
    QTest::mousePress(plot, Qt::LeftButton, Qt::ShiftModifier, p1);
    QTest::mouseMove(plot, p2);
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::ShiftModifier, p2);
    QCOMPARE(plot->xAxis->range(), before);
    QVERIFY(std::abs(view.cursors()->from() - plot->xAxis->pixelToCoord(p1.x())) < 1e-9);
    QVERIFY(std::abs(view.cursors()->to() - plot->xAxis->pixelToCoord(p2.x())) < 1e-9);
    QCOMPARE(view.selection_panel()->table()->rowCount(), 1);
    // Every control explains itself.
    for (QWidget* w : view.findChildren<QWidget*>())
      if (qobject_cast<QPushButton*>(w) || qobject_cast<QComboBox*>(w) || qobject_cast<QCheckBox*>(w))
        QVERIFY2(!w->toolTip().isEmpty(), qPrintable(w->objectName() + " " + w->metaObject()->className()));
  }

  void selection_saved_as_phase_in_the_workspace_and_battery_from_it() {
    QTemporaryDir dir;
    const std::string path = (dir.path() + "/ws.bsw").toStdString();
    bs::PowerTrace t;
    t.platform = "P";
    t.label = "p";
    for (int k = 0; k <= 100; ++k) t.time_s.push_back(k * 0.1);
    t.channels.push_back({"P", bs::PowerQuantity::Power, std::vector<double>(101, 7.4)});
    {
      bs::Workspace ws(path);
      bs::ImportBatch batch;
      batch.power_traces.push_back(t);
      ws.add_import(batch, "hash-1");
      // The Battery tab's current setup: a 2S pack, half of it usable.
      bs::BatterySetup setup = bs::builtin_battery_setups().front();
      setup.pack.cells_series = 2;
      setup.depth_of_discharge = 0.5;
      ws.set_setting("battery-tab/current", bs::battery_setup_to_json(setup));
    }
    bs::Workspace ws(path);
    bs::ui::PowerView view;
    view.resize(1200, 800);
    view.set_workspace(&ws);
    view.set_data(ws.power_traces(), {}, {});
    QCOMPARE(view.battery_volts(), 7.4);
    QCOMPARE(view.battery_ah(), bs::builtin_battery_setups().front().pack.capacity_ah * 0.5);
    view.set_quantity(bs::ui::PowerView::Quantity::Power);
    // 7.4 V x (Ah / 2) / 7.4 W = Ah / 2 hours.
    QVERIFY(std::abs(view.table()->item(0, 7)->text().toDouble() - view.battery_ah() * 60) < 0.01);
    view.cursors()->set(2.25, 6.5);
    QCOMPARE(view.save_selection_as_phase("kick"), 1);
    QCOMPARE(view.phase_panel()->table()->rowCount(), 1);
    // Issue #32.8: a phase the user saved is listed with origin "user" (it said "log"), and stays so.
    QCOMPARE(view.phase_panel()->table()->item(0, 2)->text(), QString("user"));
    QCOMPARE(bs::phase_origins(bs::Workspace(path), bs::Workspace(path).power_traces()[0].id),
             (std::vector<std::string>{"user"}));
    const std::vector<bs::StoredPowerTrace> back = bs::Workspace(path).power_traces();
    QCOMPARE(back[0].trace.phases.size(), std::size_t{1});
    QCOMPARE(back[0].trace.phases[0].name, std::string("kick"));
    QCOMPARE(back[0].trace.phases[0].start_s, 2.25);
    QCOMPARE(back[0].trace.phases[0].end_s, 6.5);
  }

  void overlay_offsets_and_alignment_at_a_phase() {
    // Two platforms; each log's "benchmark" phase starts at a different time of its own.
    bs::PowerTrace a, b;
    a.platform = "A";
    b.platform = "B";
    for (int k = 0; k <= 400; ++k) {
      a.time_s.push_back(k * 0.1);
      b.time_s.push_back(k * 0.1);
    }
    std::vector<double> pa, pb;
    for (double t : a.time_s) pa.push_back(t >= 5 && t < 25 ? 20 : 5), pb.push_back(t >= 12 && t < 32 ? 9 : 3);
    a.channels.push_back({"P", bs::PowerQuantity::Power, pa});
    b.channels.push_back({"P", bs::PowerQuantity::Power, pb});
    a.phases = {{"benchmark", 5, 25}};
    b.phases = {{"warm-up", 0, 12}, {"benchmark", 12, 32}};
    bs::ui::PowerView view;
    view.resize(1600, 1000);
    view.set_data(stored({a, b}), {}, {});
    view.set_quantity(bs::ui::PowerView::Quantity::Power);
    // Typed offset: B 2.5 s later on the shared axis.
    view.overlay()->set_offset(1, 2.5);
    QVERIFY(std::abs(view.plot()->graph(1)->data()->constBegin()->key - 2.5) < 0.2);  // first pixel column's point
    // Aligned at "benchmark": both phases start at 0 s; the selection 0 .. 20 s is each trace's benchmark.
    QCOMPARE(view.overlay()->phase_box()->findText("benchmark") >= 0, true);
    QCOMPARE(view.overlay()->align_at("benchmark"), 2);
    QCOMPARE(view.overlay()->offset(0), -5.0);
    QCOMPARE(view.overlay()->offset(1), -12.0);
    view.cursors()->set(0.0, 20.0);
    QCOMPARE(view.selection_stats().size(), std::size_t{2});
    const bs::PowerStats& sa = view.selection_stats()[0].second;
    const bs::PowerStats& sb = view.selection_stats()[1].second;
    QCOMPARE(sa.from_s, 5.0);
    QCOMPARE(sb.from_s, 12.0);
    QVERIFY(sa.power_w->summary.mean > 19 && sb.power_w->summary.mean > 8.5);  // the loads, side by side
    QVERIFY(sa.energy_j == bs::power_stats(a, {.from_s = 5.0, .to_s = 25.0}).energy_j);
    // Phases side by side: the benchmark rows of both traces next to each other.
    const QTableWidget* ph = view.phase_panel()->table();
    QCOMPARE(ph->rowCount(), 3);
    QCOMPARE(ph->item(0, 0)->text(), QString("benchmark"));
    QCOMPARE(ph->item(1, 0)->text(), QString("benchmark"));
    QCOMPARE(ph->item(2, 0)->text(), QString("warm-up"));
    // Hiding a trace takes it out of the plot and the tables.
    view.overlay()->set_visible(1, false);
    QVERIFY(!view.plot()->graph(1)->visible());
    QCOMPARE(view.selection_panel()->table()->rowCount(), 1);
  }

  void ctrl_drag_shifts_one_trace_in_time() {
    // Two flat logs, 5 W and 10 W: Ctrl + drag on the 10 W line shifts that trace by the distance dragged.
    bs::PowerTrace low, high;
    low.platform = "low";
    high.platform = "high";
    for (int k = 0; k <= 100; ++k) low.time_s.push_back(k), high.time_s.push_back(k);
    low.channels.push_back({"P", bs::PowerQuantity::Power, std::vector<double>(101, 5.0)});
    high.channels.push_back({"P", bs::PowerQuantity::Power, std::vector<double>(101, 10.0)});
    bs::ui::PowerView view;
    view.resize(1200, 800);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.set_data(stored({low, high}), {}, {});
    view.set_quantity(bs::ui::PowerView::Quantity::Power);
    QCustomPlot* plot = view.plot();
    plot->replot();
    const QCPRange before = plot->xAxis->range();
    const QPoint p1(static_cast<int>(plot->xAxis->coordToPixel(40)), static_cast<int>(plot->yAxis->coordToPixel(10)));
    const QPoint p2 = p1 + QPoint(200, 30);  // the vertical part of the drag is ignored
    QTest::mousePress(plot, Qt::LeftButton, Qt::ControlModifier, p1);
    QTest::mouseMove(plot, p2);
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::ControlModifier, p2);
    const double expected = plot->xAxis->pixelToCoord(p2.x()) - plot->xAxis->pixelToCoord(p1.x());
    QVERIFY(expected > 5);
    QVERIFY2(std::abs(view.overlay()->offset(1) - expected) < 1e-9,
             qPrintable(QString::number(view.overlay()->offset(1))));
    QCOMPARE(view.overlay()->offset(0), 0.0);
    QCOMPARE(plot->xAxis->range(), before);  // no pan while a trace moves
    // The moved trace's statistics follow: the selection 0 .. 10 s now lies before its first sample.
    view.cursors()->set(0.0, 10.0);
    QCOMPARE(view.selection_stats().size(), std::size_t{2});
    QCOMPARE(view.selection_stats()[0].second.duration_s, 10.0);
    QCOMPARE(view.selection_stats()[1].second.power_w.has_value(), false);
    // A second drag continues from the new offset; a Ctrl + press away from every line moves nothing.
    QTest::mousePress(plot, Qt::LeftButton, Qt::ControlModifier,
                      QPoint(p1.x(), static_cast<int>(plot->yAxis->coordToPixel(7.5))));
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::ControlModifier,
                        QPoint(p1.x(), static_cast<int>(plot->yAxis->coordToPixel(7.5))));
    QVERIFY(std::abs(view.overlay()->offset(1) - expected) < 1e-9);
    QCOMPARE(view.overlay()->offset(0), 0.0);
  }

  void screenshots_of_the_paper_platforms() {
    if (qEnvironmentVariable("BENCHSCOPE_SCREENSHOT_DIR").isEmpty()) QSKIP("BENCHSCOPE_SCREENSHOT_DIR not set");
    std::vector<bs::FlopsRun> runs;
    std::vector<bs::PowerTrace> traces;
    bs::test::load_paper_sample(runs, traces);
    bs::ui::PowerView view;
    view.resize(1600, 1000);
    view.set_data(stored(traces), bs::peak_table(runs), {});
    view.set_quantity(bs::ui::PowerView::Quantity::Power);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.cursors()->set(21.05, 48.73);
    view.panels()->setCurrentIndex(0);
    save_shot(&view, "power-cursors.png");
    // The Jetson shifted onto the NUC: aligned at each log's first load step (found from level changes), the
    // selection over that step, their statistics side by side.
    view.set_detected_phases(true);
    QCOMPARE(view.overlay()->align_at("load"), 2);
    view.set_detected_phases(false);  // offsets stay; the plot without the shading
    view.cursors()->set(0.0, 5.0);
    view.plot()->xAxis->setRange(-3, 30);
    view.panels()->setCurrentIndex(3);
    save_shot(&view, "power-overlay.png");
    view.panels()->setCurrentIndex(0);
    save_shot(&view, "power-overlay-selection.png");
    view.overlay()->set_offset(0, 0), view.overlay()->set_offset(1, 0);
    view.cursors()->clear();
    view.set_detected_phases(true);
    view.plot()->xAxis->setRange(0, 40);
    int load_labels = 0;
    for (int k = 0; k < view.plot()->itemCount(); ++k)
      if (auto* text = qobject_cast<QCPItemText*>(view.plot()->item(k)); text && text->text() == "load") ++load_labels;
    QVERIFY(load_labels > 10);  // every detected phase is named, not every second one
    view.panels()->setCurrentIndex(1);
    save_shot(&view, "power-phases.png");
  }
};

QTEST_MAIN(TestPowerSelection)
#include "test_power_selection.moc"
