// SPDX-License-Identifier: GPL-3.0-or-later
// File > Export figure for a plot on screen: the files come out at the chosen journal width and dpi with the
// figure's font size, and the view gets its own look back afterwards.
#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <qcustomplot.h>

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
