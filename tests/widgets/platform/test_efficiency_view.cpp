// SPDX-License-Identifier: GPL-3.0-or-later
// The Efficiency tab on the paper's sample data: the table shows the paper's 104.64 / 41.26 GFLOPS/W and
// 40.52 / 9.48 W, says which run gave each peak, and the bar chart has one bar per platform and variant.
#include <qcustomplot.h>
#include <QTableWidget>
#include <QTest>

#include "../../support/figure_checks.h"
#include "../../support/paper_sample.h"
#include "../../support/table_cells.h"
#include "chart_marks.h"
#include "platform/efficiency_view.h"

using bs::test::column_starting;
using bs::test::row_of;

class TestEfficiencyView : public QObject {
  Q_OBJECT
 private slots:
  void paper_sample() {
    auto [runs, traces, pipelines] = bs::test::load_paper_sample();
    bs::ui::EfficiencyView view;
    view.resize(1400, 800);
    view.set_data(runs, traces);
    QTableWidget* t = view.table();
    // The NUC and the Jetson have current logs; the desktop and the laptop none, which their rows say.
    QCOMPARE(t->rowCount(), 4);
    const int nuc = row_of(t, "NUC"), jetson = row_of(t, "Jetson TX2");
    QVERIFY(nuc >= 0 && jetson >= 0);
    for (const QString& platform :
         {QStringLiteral("Desktop (Alienware Area-51)"), QStringLiteral("Laptop (MacBook Pro 14,3)")}) {
      const int r = row_of(t, platform);
      QVERIFY2(r >= 0, qPrintable(platform));
      QCOMPARE(t->item(r, 1)->text(), QString("No efficiency figure: no power log of this platform"));
      QCOMPARE(t->columnSpan(r, 1), t->columnCount() - 1);
    }
    const int paper = column_starting(t, "GFLOPS/W paper"), power = column_starting(t, "Mean power (W)"),
              peak = column_starting(t, "Peak (GFLOPS)"), from = column_starting(t, "Peak from"),
              supply = column_starting(t, "Supply (V)"), at_mean = column_starting(t, "GFLOPS/W\npeak / mean"),
              energy = column_starting(t, "Energy (J/GFLOP)");
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
    // The chart: two variants x two platforms, values equal to the table's, platforms on the axis. Issue #33.4: the
    // NUC's figures come from its flagged 5.25 TFLOPS: drawn at their value, hatched, labelled with ⚠, and the
    // reason in the figure's note; the Jetson's are plain bars.
    QCustomPlot* plot = view.plot();
    const auto bar_at = [&](double key, double value, bool* flagged) {
      for (int i = 0; i < plot->plottableCount(); ++i)
        if (auto* b = qobject_cast<QCPBars*>(plot->plottable(i)))
          for (auto it = b->data()->constBegin(); it != b->data()->constEnd(); ++it)
            if (std::abs(it->key - key) < 0.3 && std::round(it->value * 100) / 100 == value) {
              *flagged = bs::ui::is_flagged_bars(b);
              return true;
            }
      return false;
    };
    bool flagged = false;
    QVERIFY(bar_at(nuc + 1, 104.64, &flagged));
    QVERIFY(flagged);
    QVERIFY(bar_at(jetson + 1, 41.26, &flagged));
    QVERIFY(!flagged);
    bool warned = false;
    for (int i = 0; i < plot->itemCount(); ++i)
      if (auto* label = qobject_cast<QCPItemText*>(plot->item(i))) warned |= label->text() == "104.64 \u26A0";
    QVERIFY(warned);
    QVERIFY(plot->yAxis->label().contains("GFLOPS/W"));
    QVERIFY(plot->legend->visible());
    QCOMPARE(plot->legend->itemCount(), 3);  // two variants and the hatching
    // Exported at an IEEE column: the note under the legend says why the NUC is flagged, nothing overlaps.
    bs::ui::FigureOptions o;
    o.width_mm = 88.9;
    const bs::ui::FigureOptions sized = bs::ui::layout_figure(*plot, o);
    QVERIFY(bs::ui::legend_note(*plot).contains("NUC"));
    const QStringList problems = bs::test::figure_problems(*plot, sized);
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
  }

  // Without logs no figure, and every platform says so in its row.
  void no_logs_no_figures() {
    auto [runs, traces, pipelines] = bs::test::load_paper_sample();
    bs::ui::EfficiencyView view;
    view.set_data(runs, {});
    QCOMPARE(view.rows().size(), std::size_t{0});
    QCOMPARE(view.table()->rowCount(), 4);
    for (int r = 0; r < view.table()->rowCount(); ++r)
      QVERIFY(view.table()->item(r, 1)->text().endsWith("no power log of this platform"));
    QCOMPARE(qobject_cast<QCPBars*>(view.plot()->plottable(0))->dataCount(), 0);
  }
};

QTEST_MAIN(TestEfficiencyView)
#include "test_efficiency_view.moc"
