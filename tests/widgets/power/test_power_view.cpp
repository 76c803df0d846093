// SPDX-License-Identifier: GPL-3.0-or-later
// The Power tab: the paper's figure 4 (supply current of the NUC and the Jetson against time, one time axis,
// labelled axes, a legend) by default, power on request, and a long trace drawn through the min/max decimation
// with its true extremes kept.
#include <qcustomplot.h>
#include <QComboBox>
#include <QDateTime>
#include <QTableWidget>
#include <QTest>
#include <cmath>

#include "../../support/paper_sample.h"
#include "power/power_view.h"

namespace {

std::vector<bs::StoredPowerTrace> stored(const std::vector<bs::PowerTrace>& traces) {
  std::vector<bs::StoredPowerTrace> out;
  for (const auto& t : traces) out.push_back({static_cast<std::int64_t>(out.size() + 1), 1, t, {}, true});
  return out;
}

std::pair<double, double> value_range(const QCPGraph* g) {
  double lo = 1e300, hi = -1e300;
  for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it)
    lo = std::min(lo, it->value), hi = std::max(hi, it->value);
  return {lo, hi};
}

}  // namespace

class TestPowerView : public QObject {
  Q_OBJECT
 private slots:
  void figure_4_current_over_time() {
    std::vector<bs::FlopsRun> runs;
    std::vector<bs::PowerTrace> traces;
    bs::test::load_paper_sample(runs, traces);
    bs::ui::PowerView view;
    view.resize(1200, 700);
    view.set_data(stored(traces), bs::peak_table(runs), {});
    QCustomPlot* plot = view.plot();
    QCOMPARE(plot->graphCount(), 2);
    QVERIFY(view.quantity() == bs::ui::PowerView::Quantity::Current);
    QCOMPARE(plot->xAxis->label(), QString("Time (s)"));
    QCOMPARE(plot->yAxis->label(), QString("Current (A)"));
    QVERIFY(plot->legend->visible());
    QStringList names;
    for (int g = 0; g < 2; ++g) names << plot->graph(g)->name();
    names.sort();
    QCOMPARE(names, QStringList({"Jetson TX2", "NUC"}));
    // Both logs start at 0 s on the shared axis (the first drawn point lies in the first pixel column: the
    // decimation keeps a column's extremes, not its first sample), and the whole 120 s are in view.
    for (int g = 0; g < 2; ++g) QVERIFY(plot->graph(g)->data()->at(0)->key <= 119.9 / 200);
    QCOMPARE(plot->xAxis->range().lower, 0.0);
    QVERIFY(std::abs(plot->xAxis->range().upper - 119.9) < 1e-9);
    // Amps, not watts: the NUC's current peaks near 3.136 A (104.64 GFLOPS/W at 16 V with 5.25 TFLOPS).
    const int nuc = plot->graph(0)->name() == "NUC" ? 0 : 1;
    QVERIFY(std::abs(value_range(plot->graph(nuc)).second - 5.25e12 / (16 * 104.64e9)) < 0.001);
    view.set_quantity(bs::ui::PowerView::Quantity::Power);
    QCOMPARE(plot->yAxis->label(), QString("Power (W)"));
    QVERIFY(std::abs(value_range(plot->graph(nuc)).second - 16 * 5.25e12 / (16 * 104.64e9)) < 0.02);
    QCOMPARE(view.table()->rowCount(), 2);
  }

  void long_trace_is_decimated_exactly() {
    // 2 million samples at 10 kHz with one spike up and one down: drawn as a few thousand points that still reach
    // both spikes.
    bs::PowerTrace t;
    t.platform = "long";
    t.label = "long";
    t.supply_voltage_v = 12;
    const std::size_t n = 2'000'000;
    std::vector<double> amps(n);
    for (std::size_t i = 0; i < n; ++i)
      t.time_s.push_back(static_cast<double>(i) * 1e-4), amps[i] = 1 + 0.1 * std::sin(i * 0.001);
    amps[1'234'567] = 9.5;
    amps[345'678] = 0.05;
    t.channels.push_back({"current", bs::PowerQuantity::Current, amps});
    bs::ui::PowerView view;
    view.resize(1000, 600);
    view.set_data(stored({t}), {}, {});
    const QCPGraph* g = view.plot()->graph(0);
    const int columns = std::max(200, view.plot()->axisRect()->width());
    QVERIFY(g->dataCount() <= 2 * columns + 2);
    QVERIFY(g->dataCount() > columns);  // every column has samples
    const auto [lo, hi] = value_range(g);
    QCOMPARE(hi, 9.5);
    QCOMPARE(lo, 0.05);
  }
  void missing_samples_are_not_drawn_as_zero() {
    // A 4 W rail and its 10 W total, every fifth total sample missing (NaN): the plot shows the total without a
    // single point at 0 W or NaN, and the table's mean is the total's, 10 W, over the present samples.
    bs::PowerTrace t;
    t.platform = "gaps";
    t.label = "gaps";
    std::vector<double> rail, total;
    for (int i = 0; i < 1000; ++i) {
      t.time_s.push_back(i * 0.01);
      rail.push_back(4);
      total.push_back(i % 5 == 2 ? std::nan("") : 10.0);
    }
    t.channels.push_back({"rail", bs::PowerQuantity::Power, rail});
    t.channels.push_back({"total", bs::PowerQuantity::Power, total});
    t.total_channel = "total";
    bs::ui::PowerView view;
    view.resize(1000, 600);
    view.set_data(stored({t}), {}, {});
    view.set_quantity(bs::ui::PowerView::Quantity::Power);
    const QCPGraph* g = view.plot()->graph(0);
    QVERIFY(g->dataCount() > 0);
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it) QCOMPARE(it->value, 10.0);
    QCOMPARE(view.table()->item(0, 3)->text(), QStringLiteral("10.00 ± 0.00"));
  }
  // Issue #17: a log with wall-clock times keeps its absolute start, and the Power tab can plot against the time of
  // day: two logs recorded an hour apart sit an hour apart; the table's statistics are the same as on the relative
  // axis for the same samples.
  void wall_clock_axis() {
    const auto make = [](const std::string& platform, const std::string& start, double watts) {
      bs::PowerTrace t;
      t.platform = platform;
      t.label = platform;
      t.start_time = start;
      for (int i = 0; i <= 100; ++i) t.time_s.push_back(i * 0.5);
      t.channels.push_back({"power", bs::PowerQuantity::Power, std::vector<double>(t.time_s.size(), watts)});
      return t;
    };
    bs::ui::PowerView view;
    view.resize(1000, 600);
    view.set_data(stored({make("NUC", "2026-11-20T10:00:00Z", 40), make("Jetson", "2026-11-20T11:00:00.500Z", 9)}), {},
                  {});
    view.set_quantity(bs::ui::PowerView::Quantity::Power);
    const QString relative_mean = view.table()->item(0, 3)->text();
    QVERIFY(view.set_wall_clock(true));
    const double ten_o_clock = QDateTime(QDate(2026, 11, 20), QTime(10, 0), Qt::UTC).toMSecsSinceEpoch() / 1000.0;
    QCOMPARE(view.plot()->xAxis->range().lower, ten_o_clock);
    QCOMPARE(view.plot()->xAxis->range().upper, ten_o_clock + 3600.5 + 50);
    QCOMPARE(view.plot()->graph(1)->data()->constBegin()->key, ten_o_clock + 3600.5);
    QVERIFY(view.plot()->xAxis->label().contains("UTC"));
    QVERIFY(!view.plot()->xAxis->ticker().dynamicCast<QCPAxisTickerDateTime>().isNull());
    QCOMPARE(view.table()->item(0, 3)->text(), relative_mean);  // the whole NUC log is in view either way
    // scripts/screenshots collects docs/screenshots/power-wall-clock.png from here.
    if (const QByteArray shots = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !shots.isEmpty())
      view.grab().save(QString::fromLocal8Bit(shots) + "/power-wall-clock.png");
    QVERIFY(!view.set_wall_clock(false));
    QCOMPARE(view.plot()->xAxis->range().lower, 0.0);
    // A log without an absolute start: the option is off and stays off.
    view.set_data(stored({make("NUC", "", 40)}), {}, {});
    QVERIFY(!view.set_wall_clock(true));
    QCOMPARE(view.plot()->xAxis->label(), QString("Time (s)"));
  }
};

QTEST_MAIN(TestPowerView)
#include "test_power_view.moc"
