// SPDX-License-Identifier: GPL-3.0-or-later
// One rule in every chart that can carry a flagged value (issue #33.4): the value is drawn where it is, marked
// (a hatched bar or a hollow marker, and a visible label with "⚠"), never replaced. The paper's sample data has one:
// the NUC GPU's 5.25 TFLOPS, 5.9x the Iris Plus 650's spec peak. Each chart is drawn with it and read back from
// the plot: the FLOPS tab, the paper's fig1a/fig1b, the Efficiency tab, the report's page-one chart, the Roofline
// tab and the candidates figure (a published row flagged by hand). The Platforms tab has no chart (its table marks
// the cell, test_platform_view), and the Power and Battery tabs plot no value derived from a FLOPS peak.
#include <qcustomplot.h>
#include <QTest>

#include "../../support/figure_checks.h"
#include "../../support/paper_sample.h"
#include "candidates_figure.h"
#include "chart_marks.h"
#include "paper_figures.h"
#include "peaks/flops_plot.h"
#include "peaks/roofline_view.h"
#include "platform/efficiency_view.h"
#include "report/figure_template.h"
#include "report_chart.h"

namespace {

const QString kWarn = QStringLiteral("\u26A0");

// Graphs with a hollow marker at (key, value) (value within 0.5 %).
int hollow_points_at(QCustomPlot& plot, double key, double value) {
  int n = 0;
  for (int i = 0; i < plot.graphCount(); ++i) {
    const QCPGraph* g = plot.graph(i);
    if (!bs::ui::is_flagged_points(g)) continue;
    for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it)
      if (std::abs(it->key - key) <= 1e-9 * std::max(1.0, std::abs(key)) &&
          std::abs(it->value - value) <= 0.005 * std::abs(value))
        ++n;
  }
  return n;
}

// Hatched bars holding `value` (within 0.5 %).
int hatched_bars_of(QCustomPlot& plot, double value) {
  int n = 0;
  for (int i = 0; i < plot.plottableCount(); ++i)
    if (const auto* b = qobject_cast<const QCPBars*>(plot.plottable(i)); b && bs::ui::is_flagged_bars(b))
      for (auto it = b->data()->constBegin(); it != b->data()->constEnd(); ++it)
        if (std::abs(it->value - value) <= 0.005 * std::abs(value)) ++n;
  return n;
}

// The visible text items holding "⚠" and `number`, after the plot was drawn (labels are placed when drawn).
QStringList warning_labels(QCustomPlot& plot, const QString& number) {
  plot.toPixmap(plot.width() > 0 ? plot.width() : 800, plot.height() > 0 ? plot.height() : 500);
  QStringList found;
  for (int i = 0; i < plot.itemCount(); ++i)
    if (const auto* t = qobject_cast<const QCPItemText*>(plot.item(i));
        t && t->visible() && t->text().contains(kWarn) && t->text().contains(number))
      found << t->text();
  return found;
}

bs::test::PaperSample sample() { return bs::test::load_paper_sample(); }

// The NUC GPU at D = 4: its 5.25 TFLOPS.
bool is_nuc_gpu(const bs::FlopsRun& r) {
  return r.platform == "NUC" && r.device_kind == bs::DeviceKind::Gpu && r.dims == 4;
}

}  // namespace

class TestChartFlags : public QObject {
  Q_OBJECT
 private slots:
  void flops_tab() {
    const auto s = sample();
    std::vector<bs::StoredRun> stored;
    for (std::size_t i = 0; i < s.runs.size(); ++i)
      stored.push_back(
          {static_cast<std::int64_t>(i + 1), 1, static_cast<std::int64_t>(i + 1), static_cast<int>(i), s.runs[i]});
    std::vector<const bs::StoredRun*> shown;
    for (const auto& r : stored) shown.push_back(&r);
    bs::ui::FlopsPlot view;
    view.resize(1200, 700);
    view.set_runs(shown);
    view.show();  // the view places its peak labels when it is laid out on screen
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    QCustomPlot& plot = *view.plot();
    plot.replot();
    // The flagged peak, hollow, at its measured value , and its label with the sign.
    const auto nuc = std::find_if(s.runs.begin(), s.runs.end(), is_nuc_gpu);
    QVERIFY(nuc != s.runs.end());
    const auto peak = bs::find_peak(*nuc);
    QVERIFY(peak.has_value());
    // The axis is in a unit of 10^(3k) FLOPS chosen for the highest peak.
    int hollow = 0;
    for (double unit : {1e9, 1e12, 1e15}) hollow += hollow_points_at(plot, peak->workers, peak->flops / unit);
    QVERIFY(hollow >= 1);
    QVERIFY(std::abs(peak->flops - 5.25e12) < 0.01e12);
    QStringList all;
    for (int i = 0; i < plot.itemCount(); ++i)
      if (const auto* t = qobject_cast<const QCPItemText*>(plot.item(i)))
        all << t->text() + (t->visible() ? " (shown)" : " (hidden)");
    QVERIFY2(!warning_labels(plot, "5.25").isEmpty(), qPrintable(all.join(", ")));
  }

  void paper_figures_fig1a_fig1b() {
    const auto s = sample();
    bs::ui::FigureData d;
    d.runs = s.runs;
    d.traces = s.traces;
    const auto templates = bs::load_figure_templates(bs::ui::paper_template_path().toStdString());
    int checked = 0;
    for (const bs::FigureTemplate& t : templates) {
      if (t.id != "fig1a" && t.id != "fig1b") continue;
      QCustomPlot plot;
      QJsonArray left_out;
      const auto figure = bs::ui::figure_plot(plot, t, d, bs::ui::FigureOptions{}, left_out);
      bs::test::draw_at_figure_size(plot, figure.sized);
      int hollow = 0;
      for (int i = 0; i < plot.graphCount(); ++i) hollow += bs::ui::is_flagged_points(plot.graph(i)) ? 1 : 0;
      QVERIFY2(hollow >= 1, t.id.c_str());
      // fig1 plots TFLOPS: the NUC's 5.25 is drawn at 5.25, not at a capped value.
      bool at_value = false;
      for (int i = 0; i < plot.graphCount(); ++i)
        if (bs::ui::is_flagged_points(plot.graph(i)) && !plot.graph(i)->data()->isEmpty())
          at_value |= std::abs(plot.graph(i)->data()->constBegin()->value - 5.25) < 0.01;
      QVERIFY2(at_value, t.id.c_str());
      const QSizeF size = bs::ui::figure_size_pt(figure.sized);
      plot.toPixmap(static_cast<int>(size.width()), static_cast<int>(size.height()));
      bool labelled = false;
      for (int i = 0; i < plot.itemCount(); ++i)
        if (const auto* x = qobject_cast<const QCPItemText*>(plot.item(i));
            x && x->visible() && x->text().startsWith("5.25") && x->text().contains(kWarn))
          labelled = true;
      QVERIFY2(labelled, t.id.c_str());
      ++checked;
    }
    QCOMPARE(checked, 2);
  }

  void efficiency_tab() {
    const auto s = sample();
    bs::ui::EfficiencyView view;
    view.resize(1400, 800);
    view.set_data(s.runs, s.traces);
    QCustomPlot& plot = *view.plot();
    QVERIFY(hatched_bars_of(plot, 104.64) >= 1);  // the NUC's GFLOPS/W from the flagged peak, the paper's number
    QVERIFY(!warning_labels(plot, "104.64").isEmpty());
  }

  void report_page_one_chart() {
    const auto s = sample();
    const auto rows = bs::compare_platforms(s.runs, s.traces, {});
    const auto verdicts = bs::recommend(rows, {});
    QCustomPlot plot;
    plot.resize(800, 500);
    bs::ui::comparison_chart(plot, rows, verdicts, {}, bs::ui::FigureOptions{});
    // The chart plots GFLOPS: the NUC at 5250, hatched, not at its device's spec.
    QVERIFY(hatched_bars_of(plot, 5250.0) >= 1);
    QVERIFY(!warning_labels(plot, "5").isEmpty());
  }

  void roofline_tab() {
    const auto s = sample();
    bs::ui::RooflineView view;
    view.resize(1200, 700);
    std::map<std::pair<std::string, std::string>, int> colors;
    for (const auto& r : s.runs) colors.try_emplace({r.platform, r.device}, static_cast<int>(colors.size()));
    view.set_data(s.runs, {}, colors);
    QCustomPlot& plot = *view.plot();
    // The NUC GPU's runs at their peaks: the flagged one hollow, at its measured FLOPS.
    int hollow = 0;
    for (int i = 0; i < plot.graphCount(); ++i)
      if (bs::ui::is_flagged_points(plot.graph(i)) && !plot.graph(i)->data()->isEmpty() &&
          std::abs(plot.graph(i)->data()->constBegin()->value - 5.25e12) < 0.01e12)
        ++hollow;
    QVERIFY(hollow >= 1);
    QVERIFY(!warning_labels(plot, "5.25").isEmpty());
  }

  void candidates_figure() {
    bs::Candidate own;
    own.platform = "NUC";
    own.origin = bs::DataOrigin::Measured;
    own.throughput_per_s = 40;
    own.power_w = 30;
    bs::Candidate published = own;
    published.platform = "Orin";
    published.origin = bs::DataOrigin::Published;
    published.throughput_per_s = 4000;
    published.power_w = 2;
    published.flags.push_back({"above_spec_peak", "4000 inferences per second at 2 W is above its spec"});
    bs::CandidateClass k{"resnet50", "SingleStream", "fp32", "", {own, published}};
    QCustomPlot plot;
    plot.resize(800, 500);
    const QString note = bs::ui::draw_candidates(plot, std::span<const bs::CandidateClass>(&k, 1));
    QCOMPARE(hollow_points_at(plot, 2, 4000), 1);  // drawn at its value, hollow
    QCOMPARE(hollow_points_at(plot, 30, 40), 0);   // the measured row: filled
    QCOMPARE(warning_labels(plot, "Orin").size(), 1);
    QVERIFY(warning_labels(plot, "NUC").isEmpty());
    QVERIFY2(note.contains("Orin") && note.contains("above its spec"), qPrintable(note));
  }
};

QTEST_MAIN(TestChartFlags)
#include "test_chart_flags.moc"
