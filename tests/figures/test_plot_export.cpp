// SPDX-License-Identifier: GPL-3.0-or-later
// File > Export figure for a plot on screen: the files come out at the chosen journal width and dpi with the
// figure's font size, and the view gets its own look back afterwards.
#include <qcustomplot.h>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "paper_figures.h"
#include "plot_export.h"

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
      QCustomPlot probe;  // prepare_export on a copy of the situation: what the export lays out
      probe.resize(1200, 700);
      for (int g = 0; g < 14; ++g) probe.addGraph()->setName(plot.graph(g)->name());
      probe.legend->setVisible(true);
      const bs::ui::FigureOptions sized = bs::ui::prepare_export(probe, o);
      QVERIFY(sized.height_mm > 122 * 0.62);  // the legend's rows are added below the axes
      QCOMPARE(probe.plotLayout()->rowCount(), 2);
      QCOMPARE(probe.plotLayout()->element(1, 0), static_cast<QCPLayoutElement*>(probe.legend));
      QCOMPARE(probe.axisRect()->insetLayout()->elementCount(), 0);
      QVERIFY(probe.legend->columnCount() > 1);  // in columns, as many as fit the width
      const double width_pt = 122 / 25.4 * 72;
      QVERIFY(probe.legend->minimumOuterSizeHint().width() <= width_pt);
      // Laid out at the figure's size, the legend is entirely below the axes.
      probe.setViewport(QRect(0, 0, static_cast<int>(width_pt), static_cast<int>(sized.height_mm / 25.4 * 72)));
      probe.plotLayout()->update(QCPLayoutElement::upPreparation);
      probe.plotLayout()->update(QCPLayoutElement::upMargins);
      probe.plotLayout()->update(QCPLayoutElement::upLayout);
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
