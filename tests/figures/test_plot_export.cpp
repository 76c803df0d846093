// SPDX-License-Identifier: GPL-3.0-or-later
// File > Export figure for a plot on screen: the files come out at the chosen journal width and dpi with the
// figure's font size, and the view gets its own look back afterwards.
#include <qcustomplot.h>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "../support/figure_checks.h"
#include "../support/paper_sample.h"
#include "analysis/peaks/flops.h"
#include "paper_figures.h"
#include "peaks/roofline_view.h"
#include "plot_export.h"
#include "plot_labels.h"
#include "power/battery_view.h"
#include "power/power_view.h"

class TestPlotExport : public QObject {
  Q_OBJECT
 private slots:
  void ieee_column_png_and_pdf_then_restored() {
    QCustomPlot plot;
    plot.resize(800, 500);
    plot.addGraph()->setData({1, 2, 3}, {2, 4, 3});
    plot.graph(0)->setName("series");
    plot.xAxis->setLabel("Workers W");
    QFont screen = plot.xAxis->labelFont();
    screen.setPointSizeF(13);
    plot.xAxis->setLabelFont(screen);
    QPen pen = plot.graph(0)->pen();
    pen.setWidthF(3);
    plot.graph(0)->setPen(pen);

    QTemporaryDir dir;
    bs::ui::FigureOptions o;
    o.width_mm = 88.9;
    o.height_mm = 60;
    o.dpi = 600;
    o.font_pt = 8;
    o.formats = {"png", "pdf", "svg"};
    QStringList files;
    bs::ui::export_plot(plot, dir.filePath("flops"), o, "FLOPS", files);
    QCOMPARE(files.size(), 3);
    const QImage png(dir.filePath("flops.png"));
    QVERIFY(std::abs(png.width() - 88.9 / 25.4 * 600) <= 3);
    QVERIFY(std::abs(png.height() - 60 / 25.4 * 600) <= 3);
    QFile pdf(dir.filePath("flops.pdf"));
    QVERIFY(pdf.open(QIODevice::ReadOnly));
    QVERIFY(pdf.readAll().startsWith("%PDF-"));
    QFile svg(dir.filePath("flops.svg"));
    QVERIFY(svg.open(QIODevice::ReadOnly));
    const QByteArray svg_text = svg.readAll();
    QVERIFY(svg_text.contains("Workers W"));
    QVERIFY(svg_text.contains("font-size=\"8") || svg_text.contains("font-size:8"));  // the figure's font size

    QCOMPARE(plot.xAxis->labelFont().pointSizeF(), 13.0);  // the view's own look is back
    QCOMPARE(plot.graph(0)->pen().widthF(), 3.0);
  }

  // Issue #23.1: a view's legend sits over its axes (14 entries on the paper's FLOPS tab). An exported figure has it
  // below the axes in columns, never over data; automatic height grows by the legend; the view gets it back.
  void legend_goes_below_the_axes_and_comes_back() {
    QCustomPlot plot;
    plot.resize(1200, 700);
    for (int g = 0; g < 14; ++g) {
      plot.addGraph()->setData({1, 10, 100}, {1.0 * g, 2.0 * g, 3.0 * g});
      plot.graph(g)->setName(QStringLiteral("GPU %1, D = 4").arg(g));
    }
    plot.legend->setVisible(true);
    plot.axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
    plot.rescaleAxes();
    plot.replot();

    bs::ui::FigureOptions o;
    o.width_mm = 122;
    o.height_mm = 0;
    {
      QCustomPlot probe;  // layout_figure on a copy of the situation: what the export lays out
      probe.resize(1200, 700);
      for (int g = 0; g < 14; ++g) probe.addGraph()->setName(plot.graph(g)->name());
      probe.legend->setVisible(true);
      const bs::ui::FigureOptions sized = bs::ui::layout_figure(probe, o);
      QVERIFY(sized.height_mm > 122 * 0.62);  // the legend's rows are added below the axes
      QCOMPARE(probe.plotLayout()->rowCount(), 2);
      QCOMPARE(probe.plotLayout()->element(1, 0), static_cast<QCPLayoutElement*>(probe.legend));
      QCOMPARE(probe.axisRect()->insetLayout()->elementCount(), 0);
      QVERIFY(probe.legend->columnCount() > 1);  // in columns, as many as fit the width
      const double width_pt = 122 / 25.4 * 72;
      QVERIFY(probe.legend->minimumOuterSizeHint().width() <= width_pt);
      // Drawn at the figure's size, the legend is entirely below the axes and nothing overlaps.
      QVERIFY2(bs::test::figure_problems(probe, sized).isEmpty(),
               qPrintable(bs::test::figure_problems(probe, sized).join('\n')));
      QVERIFY(probe.legend->outerRect().top() >= probe.axisRect()->outerRect().bottom() - 1);
    }

    QTemporaryDir dir;
    o.formats = {"png"};
    o.dpi = 100;
    QStringList files;
    bs::ui::export_plot(plot, dir.filePath("flops"), o, "FLOPS", files);
    const QImage png(dir.filePath("flops.png"));
    QVERIFY(png.height() > 122 * 0.62 / 25.4 * 100 + 10);  // taller than the axes alone: the legend's rows
    // The view's legend is back over its axes, in its corner, in one column.
    QCOMPARE(plot.plotLayout()->rowCount(), 1);
    QCOMPARE(plot.axisRect()->insetLayout()->elementCount(), 1);
    QCOMPARE(plot.axisRect()->insetLayout()->elementAt(0), static_cast<QCPLayoutElement*>(plot.legend));
    QCOMPARE(plot.axisRect()->insetLayout()->insetAlignment(0), Qt::AlignTop | Qt::AlignLeft);
    QCOMPARE(plot.legend->columnCount(), 1);
  }

  // Issue #33.2: eight sweeps of one series read and look alike: one legend entry "(8 runs)". Twenty more series
  // than a reader can take in at a column's width: at most kMaxLegendRows rows, the rest named in a note under
  // the legend. At LNCS and IEEE widths alike.
  void legend_sized_to_content() {
    for (const double width_mm : {122.0, 88.9}) {
      QCustomPlot plot;
      plot.resize(1000, 600);
      for (int g = 0; g < 8; ++g) {
        plot.addGraph()->setData({1, 10, 100}, {1.0 + g, 2.0, 3.0});
        plot.graph(g)->setName("AMD EPYC · CPU SIMD · D=4 (throughput)");
        plot.graph(g)->setPen(QPen(Qt::blue));
      }
      for (int g = 0; g < 24; ++g) {
        QCPGraph* graph = plot.addGraph();
        graph->setData({1, 10, 100}, {0.5 * g, 1.0 * g, 1.5 * g});
        graph->setName(QStringLiteral("Device %1 · OpenCL · D=%2").arg(g).arg(1 + g % 3));
        graph->setPen(QPen(QColor::fromHsv(g * 15, 200, 200)));
      }
      plot.legend->setVisible(true);
      bs::ui::FigureOptions o;
      o.width_mm = width_mm;
      const bs::ui::FigureOptions sized = bs::ui::layout_figure(plot, o);
      QStringList names;
      for (int i = 0; i < plot.legend->itemCount(); ++i)
        names << static_cast<QCPPlottableLegendItem*>(plot.legend->item(i))->plottable()->name();
      QCOMPARE(names.count("AMD EPYC · CPU SIMD · D=4 (throughput) (8 runs)"), 1);
      QVERIFY(!names.contains("AMD EPYC · CPU SIMD · D=4 (throughput)"));
      QVERIFY(plot.legend->rowCount() <= bs::ui::kMaxLegendRows);
      const QString note = bs::ui::legend_note(plot);
      QVERIFY2(note.startsWith("Also drawn ("), qPrintable(note));
      // The rest is named, or counted when more than three lines would be needed: never silently dropped.
      QVERIFY2(note.contains("Device 23") || note.contains(" more."), qPrintable(note));
      qInfo("%s", qPrintable(note));
      const QStringList problems = bs::test::figure_problems(plot, sized);
      QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
    }
  }

  // Peak labels that would collide: the higher keeps its label, the lesser is dropped, none overlap, at LNCS and
  // IEEE widths; the view's zoom that cut a curve off does not reach the figure, and comes back after the export.
  void labels_apart_and_nothing_clipped() {
    for (const double width_mm : {122.0, 88.9}) {
      QCustomPlot plot;
      plot.resize(1000, 600);
      auto* labels = new bs::ui::AnchoredLabels(&plot);
      const std::vector<double> peaks = {9.34, 9.14, 9.3, 5.25, 2.71, 2.4, 1.42, 0.49};
      for (std::size_t g = 0; g < peaks.size(); ++g) {
        QCPGraph* graph = plot.addGraph();
        graph->setData({256, 1e3, 1e4, 1e5, 1e6}, {0.1, peaks[g] / 3, peaks[g] * 0.9, peaks[g], peaks[g] * 0.99});
        graph->setName(QStringLiteral("series %1").arg(g));
        labels->add_curve(graph);
      }
      for (std::size_t g = 0; g < peaks.size(); ++g)  // highest first
        labels->add(1e5, peaks[g], QStringLiteral("%1 TFLOPS").arg(peaks[g], 0, 'f', 2), Qt::darkBlue);
      plot.legend->setVisible(true);
      plot.xAxis->setScaleType(QCPAxis::stLogarithmic);
      plot.xAxis->setRange(256, 1e6);
      plot.yAxis->setRange(0, 6);  // zoomed: the top three curves are cut off on screen
      bs::ui::FigureOptions o;
      o.width_mm = width_mm;
      o.formats = {"png"};
      o.dpi = 150;
      QTemporaryDir dir;
      QStringList files;
      {
        QCustomPlot& p = plot;
        bs::ui::FigureOptions sized = bs::ui::layout_figure(p, o);
        const QStringList problems = bs::test::figure_problems(p, sized);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join('\n')));
        QVERIFY(p.yAxis->range().upper >= 9.34);
        int shown = 0;
        for (QCPItemText* t : labels->labels()) shown += t->visible();
        QVERIFY(shown >= 3);
        QVERIFY(labels->labels().front()->visible());  // the highest peak keeps its label
      }
    }
    // export_plot restores the view's range afterwards.
    QCustomPlot view;
    view.resize(800, 500);
    view.addGraph()->setData({1, 2, 3}, {1, 10, 2});
    view.yAxis->setRange(0, 4);
    QTemporaryDir dir;
    bs::ui::FigureOptions o;
    o.formats = {"png"};
    o.dpi = 72;
    QStringList files;
    bs::ui::export_plot(view, dir.filePath("v"), o, "v", files);
    QCOMPARE(view.yAxis->range().upper, 4.0);
  }

  // Ctrl+E on the Power, Battery and Roofline tabs with the paper's sample data (two current logs, every FLOPS run),
  // at LNCS and IEEE column widths: no label over another or cut by the axes, the legend below the axes, no curve
  // clipped. With BENCHSCOPE_EXPORT_DIR set, the PDFs are also written there to be looked at
  // (pdftoppm -r 100 power-122mm.pdf ...).
  void power_battery_roofline_tabs_fit() {
    const auto sample = bs::test::load_paper_sample();
    std::vector<bs::StoredPowerTrace> stored;
    for (const auto& t : sample.traces)
      stored.push_back({static_cast<std::int64_t>(stored.size() + 1), 1, t, {}, true});
    std::map<std::pair<std::string, std::string>, int> colors;
    for (const auto& r : sample.runs) colors.try_emplace({r.platform, r.device}, static_cast<int>(colors.size()));
    const QString look = qEnvironmentVariable("BENCHSCOPE_EXPORT_DIR");
    for (const double width_mm : {122.0, 88.9}) {
      bs::ui::PowerView power;
      power.resize(1280, 800);
      power.set_data(stored, bs::peak_table(sample.runs), {});
      bs::ui::BatteryView battery;
      battery.resize(1280, 800);
      battery.set_data(sample.traces);
      bs::ui::RooflineView roofline;
      roofline.resize(1280, 800);
      roofline.set_data(sample.runs, {}, colors);
      QVERIFY(power.plot()->graphCount() >= 2 && battery.plot()->graphCount() >= 2 &&
              roofline.plot()->graphCount() >= 2);
      for (const auto& [name, plot] : {std::pair<QString, QCustomPlot*>{"power", power.plot()},
                                       std::pair<QString, QCustomPlot*>{"battery", battery.plot()},
                                       std::pair<QString, QCustomPlot*>{"roofline", roofline.plot()}}) {
        bs::ui::FigureOptions o;
        o.width_mm = width_mm;
        o.formats = {"pdf"};
        if (!look.isEmpty()) {
          QStringList files;
          bs::ui::export_plot(*plot, QStringLiteral("%1/%2-%3mm").arg(look, name).arg(width_mm), o, name, files);
        }
        const bs::ui::FigureOptions sized = bs::ui::layout_figure(*plot, o);
        const QStringList problems = bs::test::figure_problems(*plot, sized);
        QVERIFY2(problems.isEmpty(),
                 qPrintable(name + " at " + QString::number(width_mm) + " mm: " + problems.join('\n')));
      }
    }
  }

  void unknown_format_is_refused() {
    QCustomPlot plot;
    QTemporaryDir dir;
    bs::ui::FigureOptions o;
    o.formats = {"bmp"};
    QStringList files;
    QVERIFY_THROWS_EXCEPTION(std::runtime_error, bs::ui::export_plot(plot, dir.filePath("x"), o, "x", files));
  }
};

QTEST_MAIN(TestPlotExport)
#include "test_plot_export.moc"
