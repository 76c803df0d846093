// SPDX-License-Identifier: GPL-3.0-or-later
// The Efficiency tab on the paper's sample data: the table shows the paper's 104.64 / 41.26 GFLOPS/W and
// 40.52 / 9.48 W, says which run gave each peak, and the bar chart has one bar per platform and variant.
#include <qcustomplot.h>
#include <QTableWidget>
#include <QTest>

#include "../../support/paper_sample.h"
#include "platform/efficiency_view.h"

namespace {

int column(const QTableWidget* t, const QString& header_start) {
  for (int c = 0; c < t->columnCount(); ++c)
    if (t->horizontalHeaderItem(c)->text().startsWith(header_start)) return c;
  return -1;
}

int row_of(const QTableWidget* t, const QString& platform) {
  for (int r = 0; r < t->rowCount(); ++r)
    if (t->item(r, 0)->text() == platform) return r;
  return -1;
}

}  // namespace

class TestEfficiencyView : public QObject {
  Q_OBJECT
 private slots:
  void paper_sample() {
    std::vector<bs::FlopsRun> runs;
    std::vector<bs::PowerTrace> traces;
    bs::test::load_paper_sample(runs, traces);
    bs::ui::EfficiencyView view;
    view.resize(1400, 800);
    view.set_data(runs, traces);
    QTableWidget* t = view.table();
    QCOMPARE(t->rowCount(), 2);  // the NUC and the Jetson have current logs
    const int nuc = row_of(t, "NUC"), jetson = row_of(t, "Jetson TX2");
    QVERIFY(nuc >= 0 && jetson >= 0);
    const int paper = column(t, "GFLOPS/W paper"), power = column(t, "Mean power (W)"),
              peak = column(t, "Peak (GFLOPS)"), from = column(t, "Peak from"), supply = column(t, "Supply (V)"),
              at_mean = column(t, "GFLOPS/W\npeak / mean"), energy = column(t, "Energy (J/GFLOP)");
    QVERIFY(paper > 0 && power > 0 && peak > 0 && from > 0 && supply > 0 && at_mean > 0 && energy > 0);
    // The NUC's peak (5.25 TFLOPS, 5.9x its GPU's vendor peak) is flagged, and so is every ratio made from it.
    QCOMPARE(t->item(nuc, paper)->text(), QString("⚠ 104.64"));
    QVERIFY(t->item(nuc, paper)->toolTip().contains("Iris Plus Graphics 650"));
    QCOMPARE(t->item(jetson, paper)->text(), QString("41.26"));
    QVERIFY(t->item(nuc, power)->text().startsWith("40.52 ± "));
    QVERIFY(t->item(jetson, power)->text().startsWith("9.48 ± "));
    QVERIFY(t->item(jetson, power)->text().endsWith("(n = 1200)"));
    QCOMPARE(t->item(nuc, peak)->text(), QString("⚠ 5250.00"));
    QVERIFY(!t->item(nuc, power)->text().startsWith("⚠"));  // the NUC's power log itself is plausible
    QVERIFY(t->item(nuc, from)->text().contains("OpenCL"));
    QVERIFY(t->item(jetson, from)->text().contains("CUDA"));
    QCOMPARE(t->item(nuc, supply)->text(), QString("16.0"));
    // The honest variant divides by the mean power, which is below V x max current: a larger number.
    const auto number = [&](int r, int c) { return t->item(r, c)->text().remove(QStringLiteral("⚠ ")).toDouble(); };
    QVERIFY(number(nuc, at_mean) > 104.64);
    QCOMPARE(number(nuc, at_mean),
             std::round(5250.0 / view.rows()[static_cast<std::size_t>(nuc)].power_w.mean * 100) / 100);
    QVERIFY(t->item(jetson, energy)->text().toDouble() > 0);
    // The chart: two variants x two platforms, values equal to the table's, platforms on the axis.
    QCustomPlot* plot = view.plot();
    QCOMPARE(plot->plottableCount(), 2);
    auto* bars = qobject_cast<QCPBars*>(plot->plottable(0));
    QVERIFY(bars);
    QCOMPARE(bars->dataCount(), 2);
    QCOMPARE(std::round(bars->data()->at(nuc)->value * 100) / 100, 104.64);
    QCOMPARE(std::round(bars->data()->at(jetson)->value * 100) / 100, 41.26);
    QVERIFY(plot->yAxis->label().contains("GFLOPS/W"));
    QVERIFY(plot->legend->visible());
    QCOMPARE(plot->legend->itemCount(), 2);
  }

  void no_logs_no_rows() {
    std::vector<bs::FlopsRun> runs;
    std::vector<bs::PowerTrace> traces;
    bs::test::load_paper_sample(runs, traces);
    bs::ui::EfficiencyView view;
    view.set_data(runs, {});
    QCOMPARE(view.table()->rowCount(), 0);
    QCOMPARE(qobject_cast<QCPBars*>(view.plot()->plottable(0))->dataCount(), 0);
  }
};

QTEST_MAIN(TestEfficiencyView)
#include "test_efficiency_view.moc"
