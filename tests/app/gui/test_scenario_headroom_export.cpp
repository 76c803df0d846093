// SPDX-License-Identifier: GPL-3.0-or-later
// Issue #50.5 (item 4), as a person meets it: a cyclictest histogram of two threads imported, the Headroom tab
// opened, Ctrl+E answered at an IEEE column's width, the PDF read back with pdftotext. On main the figure had no
// legend (the tab's title row took the cell the export put the legend in) and the deadline's label was cut at the
// axes' left edge (right-aligned to a line near the axis' start). Now every curve is named in the legend under the
// axes, every line of the deadline label is in the PDF, and at the export's own layout the label lies inside the
// axes; the title, cut at both edges at a column's width, wraps and is whole.
#include <qcustomplot.h>
#include <QFontMetricsF>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include "../../support/figure_checks.h"
#include "../../support/pdf_readback.h"
#include "../../support/scenario_window.h"
#include "export_figure_dialog.h"
#include "headroom/headroom_view.h"

namespace {

// The deadline's label: the text item that starts "deadline".
QCPItemText* deadline_label(QCustomPlot& plot) {
  for (int i = 0; i < plot.itemCount(); ++i)
    if (auto* t = qobject_cast<QCPItemText*>(plot.item(i)); t && t->text().startsWith("deadline")) return t;
  return nullptr;
}

// The box the label's lines cover in pixels, as QCPItemText draws them (every line, padding, alignment).
QRectF drawn_box(const QCPItemText* t) {
  const QMarginsF pad = t->padding();
  const QSizeF size = QFontMetricsF(t->font()).boundingRect(QRectF(), int(t->textAlignment()), t->text()).size() +
                      QSizeF(pad.left() + pad.right(), pad.top() + pad.bottom());
  QPointF at = t->position->pixelPosition();
  const Qt::Alignment a = t->positionAlignment();
  if (a & Qt::AlignRight) at.rx() -= size.width();
  if (a & Qt::AlignHCenter) at.rx() -= size.width() / 2;
  if (a & Qt::AlignBottom) at.ry() -= size.height();
  if (a & Qt::AlignVCenter) at.ry() -= size.height() / 2;
  return QRectF(at, size);
}

}  // namespace

class TestScenarioHeadroomExport : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    QSettings().clear();  // the export dialog's remembered choices from an earlier run
    if (QStandardPaths::findExecutable("pdftotext").isEmpty())
      QSKIP("pdftotext (poppler-utils) is needed to read the exported figure back");
  }

  void ctrl_e_names_every_curve_and_keeps_the_deadline_label_whole() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("headroom.bsw")));
    w.import_paths_now({BENCHSCOPE_TEST_DATA_DIR "/headroom/cyclictest-2.6-H20-2thr-overflows.txt"});
    QVERIFY(bs::test::show_at(w));
    QWidget* tab = bs::test::open_tab(w, "Headroom");
    QVERIFY(tab);
    QCustomPlot* plot = bs::test::exported_plot(w);
    QVERIFY2(plot, "the Headroom tab draws no histogram");
    const QStringList names = bs::test::legend_names(*plot);
    QCOMPARE(names.size(), 2);  // one curve per thread
    QCPItemText* label = deadline_label(*plot);
    QVERIFY2(label, "no deadline line");
    const QStringList lines = label->text().split('\n');
    QCOMPARE(lines.size(), 3);  // the deadline, then each thread's cycles beyond it
    auto* title = qobject_cast<QCPTextElement*>(plot->plotLayout()->element(0, 0));
    QVERIFY2(title, "the histogram has no title");
    const QString title_text = title->text();
    bs::test::screenshot(&w, "headroom-tab-1600x1000");
    w.resize(1280, 800);
    QTest::qWait(50);
    bs::test::screenshot(&w, "headroom-tab-1280x800");

    const QString stem = dir.filePath("headroom");
    QVERIFY(bs::test::export_current_tab(w, stem, "ieee"));
    QVERIFY2(QFile::exists(stem + ".pdf"), "no PDF written");
    bs::test::keep_for_looking(stem + ".pdf", "export-headroom.pdf");
    const QString text = bs::test::pdf_flat_text(stem + ".pdf");
    // As pdftotext gives it: NFKC (the micro sign µ reads as the Greek mu), every run of white space one space.
    const auto in_pdf = [&text](const QString& s) {
      return text.contains(s.simplified().normalized(QString::NormalizationForm_KC));
    };
    QStringList problems;
    for (const QString& name : names)
      if (!in_pdf(name)) problems << QStringLiteral("curve '%1' is not named in the figure").arg(name);
    for (const QString& line : lines)
      if (!in_pdf(line)) problems << QStringLiteral("the deadline label's line '%1' is not in the figure").arg(line);
    if (!in_pdf(title_text)) problems << QStringLiteral("the title '%1' is not whole in the figure").arg(title_text);
    const auto pages = bs::test::pdf_words(stem + ".pdf");
    QCOMPARE(pages.size(), std::size_t{1});
    problems << bs::test::figure_layout_problems(pages.front());

    // The export's own layout at the same width: the legend under the axes (off the data), the label inside them.
    bs::ui::ExportFigureDialog options(bs::ui::ExportFigureDialog::Target::FileStem, stem);
    options.set_preset("ieee");
    const bs::ui::FigureOptions sized = bs::ui::layout_figure(*plot, options.options());
    bs::test::draw_at_figure_size(*plot, sized);
    const QRectF axes = plot->axisRect()->rect();
    if (!plot->legend->visible() || plot->legend->layout() != plot->plotLayout())
      problems << QStringLiteral("the legend is not under the axes");
    else if (QRectF(plot->legend->outerRect()).intersects(axes.adjusted(1, 1, -1, -1)))
      problems << QStringLiteral("the legend covers the axes");
    if (QCPItemText* shown = deadline_label(*plot); shown && !axes.adjusted(-1, -1, 1, 1).contains(drawn_box(shown))) {
      const QRectF box = drawn_box(shown);
      problems << QStringLiteral("the deadline label (%1..%2 px) is cut by the axes (%3..%4 px)")
                      .arg(box.left(), 0, 'f', 0)
                      .arg(box.right(), 0, 'f', 0)
                      .arg(axes.left(), 0, 'f', 0)
                      .arg(axes.right(), 0, 'f', 0);
    }
    for (const QString& p : problems) qWarning("%s", qPrintable(p));  // every one, not only what QVERIFY2 shows
    QVERIFY2(problems.isEmpty(),
             qPrintable(QStringLiteral("%1 problem(s), the first: %2").arg(problems.size()).arg(problems.value(0))));
  }
};

QTEST_MAIN(TestScenarioHeadroomExport)
#include "test_scenario_headroom_export.moc"
