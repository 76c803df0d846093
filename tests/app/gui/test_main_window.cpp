// SPDX-License-Identifier: GPL-3.0-or-later
// Opens the paper's sample data in the main window, offscreen, as a user would, and checks what is plotted.
#include <qcustomplot.h>
#include <QAbstractItemModel>
#include <QApplication>
#include <QCoreApplication>
#include <QDockWidget>
#include <QFile>
#include <QInputDialog>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QSignalSpy>
#include <QSplitter>
#include <QStandardItemModel>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTimer>
#include <map>
#include <set>

#include <QTableWidget>
#include "export_figure_dialog.h"
#include "main_window.h"
#include "overlay_geometry.h"
#include "peaks/flops_plot.h"
#include "peaks/peak_overlay.h"
#include "peaks/peak_table.h"
#include "plot_export.h"
#include "power/power_view.h"
#include "workspace/import_controller.h"
#include "workspace/workspace_tree.h"

class TestMainWindow : public QObject {
  Q_OBJECT
 private slots:
  void opens_sample_data_and_plots_every_run() {
    QTemporaryDir dir;
    const QString ws = dir.filePath("paper.bsw");
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(ws));
    w.import_paths_now({BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018"});
    // As a 1600x1000 screen opens it: the offscreen screen is 800x600, and a first start fits the window to its
    // screen (issue #50.5), too small a plot for every peak's label.
    w.resize(1400, 900);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));

    QCOMPARE(w.tree()->run_count(), 13);
    QCOMPARE(w.flops_plot()->series_count(), 13);
    QCOMPARE(w.flops_plot()->plot()->legend->itemCount(), 13);  // bands and peak markers stay out of the legend
    QCOMPARE(w.flops_plot()->value_axis_label(), QString("Performance (TFLOPS)"));
    QCOMPARE(w.peak_table()->model()->rowCount(), 13);
    // Sorted by peak (numerically), the top row is the GTX1080Ti under CUDA at the paper's 9.34 TFLOPS.
    w.peak_table()->sortByColumn(bs::ui::PeakTableModel::Peak, Qt::DescendingOrder);
    const QAbstractItemModel* table = w.peak_table()->model();
    QCOMPARE(table->index(0, bs::ui::PeakTableModel::Peak).data().toString(), QString("9.34 TFLOPS"));
    QCOMPARE(table->index(0, bs::ui::PeakTableModel::Device).data().toString(), QString("GTX1080Ti"));
    QCOMPARE(table->index(0, bs::ui::PeakTableModel::Backend).data().toString(), QString("CUDA"));
    QCOMPARE(table->index(12, bs::ui::PeakTableModel::Peak).data().toString(), QString("4.69 GFLOPS"));

    // Issue #23.4: colour is the device, the marker along the curve the backend: the GTX1080Ti's CUDA and OpenCL
    // curves (one device, one D) look different.
    {
      std::map<std::pair<QString, int>, std::set<int>> shapes_by_colour_and_style;
      for (const QCPGraph* g : w.flops_plot()->series_graphs())
        shapes_by_colour_and_style[{g->pen().color().name(), static_cast<int>(g->pen().style())}].insert(
            static_cast<int>(g->scatterStyle().shape()));
      bool cuda_and_opencl_apart = false;
      for (const auto& [key, shapes] : shapes_by_colour_and_style) cuda_and_opencl_apart |= shapes.size() >= 2;
      QVERIFY(cuda_and_opencl_apart);
      for (const QCPGraph* g : w.flops_plot()->series_graphs())
        QVERIFY(g->scatterStyle().shape() != QCPScatterStyle::ssNone);
    }
    // The legend is inside the plot and, once laid out, hides no data; peaks carry labels.
    QCustomPlot* plot = w.flops_plot()->plot();
    plot->replot();
    QTest::qWait(50);  // a queued replot follows when the legend needed room
    plot->replot();
    QCOMPARE(plot->legend->layout(), plot->axisRect()->insetLayout());
    std::vector<QPolygonF> curves;
    for (const QCPGraph* g : w.flops_plot()->series_graphs()) {
      QPolygonF pixels;
      for (auto it = g->data()->constBegin(); it != g->data()->constEnd(); ++it)
        pixels << QPointF(plot->xAxis->coordToPixel(it->key), plot->yAxis->coordToPixel(it->value));
      curves.push_back(pixels);
    }
    QVERIFY2(bs::ui::covered_length(plot->legend->outerRect(), curves) < 1.0,
             qPrintable(QString::number(bs::ui::covered_length(plot->legend->outerRect(), curves))));
    QVERIFY(w.flops_plot()->overlay()->shown_label_count() >= 8);
    bool top_label = false;
    for (const QCPItemText* label : w.flops_plot()->overlay()->labels())
      top_label = top_label || (label->visible() && label->text() == "9.34 TFLOPS");
    QVERIFY(top_label);

    // Hiding a run removes its series and its table row.
    const qint64 first = *w.tree()->visible_runs().begin();
    w.tree()->set_run_visible(first, false);
    QCOMPARE(w.flops_plot()->series_count(), 12);
    QCOMPARE(w.peak_table()->model()->rowCount(), 12);
    w.tree()->set_run_visible(first, true);
    QCOMPARE(w.flops_plot()->series_count(), 13);

    // Axis toggles switch the ticker.
    w.flops_plot()->set_log_y(false);
    QCOMPARE(w.flops_plot()->plot()->yAxis->scaleType(), QCPAxis::stLinear);
    QVERIFY(w.flops_plot()->plot()->yAxis->ticker().dynamicCast<QCPAxisTickerLog>().isNull());
    w.flops_plot()->set_log_y(true);
    QVERIFY(!w.flops_plot()->plot()->yAxis->ticker().dynamicCast<QCPAxisTickerLog>().isNull());
    w.flops_plot()->set_log_x(false);
    QVERIFY(w.flops_plot()->plot()->xAxis->ticker().dynamicCast<QCPAxisTickerLog>().isNull());
    QCOMPARE(w.flops_plot()->plot()->xAxis->scaleType(), QCPAxis::stLinear);
    w.flops_plot()->set_log_x(true);
    QVERIFY(!w.flops_plot()->plot()->xAxis->ticker().dynamicCast<QCPAxisTickerLog>().isNull());
  }

  void power_tab_shows_the_paper_numbers() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("w.bsw")));
    w.import_paths_now({BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018"});
    bs::ui::PowerView* view = w.power_view();
    QCOMPARE(view->trace_count(), 2);
    QCOMPARE(view->plot()->graphCount(), 2);
    QStringList rows;
    for (int r = 0; r < view->table()->rowCount(); ++r) {
      QStringList cells;
      for (int c = 0; c < view->table()->columnCount(); ++c) cells << view->table()->item(r, c)->text();
      rows << cells.join(" | ");
    }
    const QString all = rows.join("\n");
    QVERIFY2(all.contains("40.52") && all.contains("104.64") && all.contains("84.36"), qPrintable(all));
    QVERIFY2(all.contains("9.48") && all.contains("41.26") && all.contains("360.48"), qPrintable(all));
    // Zooming into the first 10 s changes the statistics to that range.
    view->plot()->xAxis->setRange(0, 10);
    QVERIFY(view->table()->item(0, 1)->text() != "1,200");
  }

  void tree_lists_every_kind_and_edits_are_undoable() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("w.bsw")));
    w.import_paths_now({BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018"});
    using K = bs::ui::TreeItemRef::Kind;
    bs::ui::WorkspaceTree* tree = w.tree();
    QCOMPARE(tree->item_count(K::PowerLog), 2);
    QVERIFY(tree->item_count(K::PipelineRun) > 0);
    QVERIFY(tree->item_count(K::Frame) > 0);
    // Find the first power log row and remove it (its import goes, with everything the file brought).
    auto* model = qobject_cast<QStandardItemModel*>(tree->model());
    bs::ui::TreeItemRef log;
    QString log_tip;
    for (int r = 0; r < model->rowCount() && log.kind == K::None; ++r)
      for (int c = 0; c < model->item(r)->rowCount(); ++c) {
        const auto ref = tree->ref_at(model->item(r)->child(c)->index());
        if (ref.kind == K::PowerLog) {
          log = ref;
          log_tip = model->item(r)->child(c)->toolTip();
          break;
        }
      }
    QVERIFY(log.kind == K::PowerLog && log.import_id > 0);
    QVERIFY2(log_tip.contains("samples"), qPrintable(log_tip));
    emit tree->remove_requested(log);
    QCOMPARE(w.power_view()->trace_count(), 1);
    QCOMPARE(tree->item_count(K::PowerLog), 1);
    QAction* undo = nullptr;
    for (QAction* a : w.findChildren<QAction*>())
      if (a->text().startsWith("&Undo")) undo = a;
    QVERIFY(undo);
    QVERIFY2(undo->isEnabled() && undo->text().contains("remove import"), qPrintable(undo->text()));
    undo->trigger();
    QCOMPARE(w.power_view()->trace_count(), 2);
    QCOMPARE(tree->item_count(K::PowerLog), 2);
    // Rename a platform through the dialog; every view follows, and undo brings the old name back.
    QTimer::singleShot(0, [] {
      auto* dialog = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
      QVERIFY(dialog);
      dialog->setTextValue("Intel NUC");
      dialog->accept();
    });
    bs::ui::TreeItemRef platform;
    platform.kind = K::Platform;
    platform.name = "NUC";
    emit tree->rename_requested(platform);
    bool renamed = false;
    for (const auto& r : w.workspace()->runs()) renamed |= r.run.platform == "Intel NUC";
    QVERIFY(renamed);
    QCOMPARE(model->item(0)->text() == "Intel NUC" || model->item(1)->text() == "Intel NUC" ||
                 model->item(2)->text() == "Intel NUC" || model->item(3)->text() == "Intel NUC",
             true);
    undo->trigger();
    for (const auto& r : w.workspace()->runs()) QVERIFY(r.run.platform != "Intel NUC");
    // A device's colour is picked from the palette in the tree; every view follows; undo restores it.
    bs::ui::TreeItemRef device;
    for (int r = 0; r < model->rowCount() && device.kind == K::None; ++r)
      if (model->item(r)->hasChildren()) device = tree->ref_at(model->item(r)->child(0)->index());
    QVERIFY(device.kind == K::Device && device.color_index >= 0);
    const int old_index = device.color_index, new_index = (old_index + 7) % 15;
    emit tree->color_requested(device, new_index);
    const auto color_of = [&] {
      for (const auto& d : w.workspace()->devices())
        if (d.platform == device.platform.toStdString() && d.device == device.name.toStdString()) return d.color_index;
      return -1;
    };
    QCOMPARE(color_of(), new_index);
    undo->trigger();
    QCOMPARE(color_of(), old_index);
  }

  void hover_reads_out_the_nearest_point() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("w.bsw")));
    w.import_paths_now({BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/gpu-hd630.json"});
    w.resize(1200, 800);
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QCustomPlot* plot = w.flops_plot()->plot();
    plot->replot();
    const QCPGraph* g = plot->graph(0);
    const auto it = g->data()->findBegin(100000);
    const QPointF pixel(plot->xAxis->coordToPixel(it->key), plot->yAxis->coordToPixel(it->value));
    const QString text = w.flops_plot()->read_out_at(pixel);
    QVERIFY2(text.contains("Intel HD Graphics 630") && text.contains("TFLOPS") && text.contains("n = 1"),
             qPrintable(text));
    QVERIFY(w.flops_plot()->read_out_at(QPointF(-500, -500)).isEmpty());
  }

  void repeated_runs_get_an_error_band() {
    QTemporaryDir dir;
    bs::ui::MainWindow w;
    QVERIFY(w.open_workspace(dir.filePath("w.bsw")));
    w.import_paths_now({BENCHSCOPE_TEST_DATA_DIR "/importers/run-json/two-runs.json"});
    // Run 1 has 3 and 2 repetitions per point: upper + lower band graphs, the series, its peak marker.
    // Run 2 has one repetition: the series and its peak marker only.
    QCOMPARE(w.flops_plot()->series_count(), 2);
    QCOMPARE(w.flops_plot()->plot()->graphCount(), 6);
    int filled = 0;
    for (int i = 0; i < w.flops_plot()->plot()->graphCount(); ++i)
      filled += w.flops_plot()->plot()->graph(i)->channelFillGraph() != nullptr;
    QCOMPARE(filled, 1);
  }

  void background_import_reports_per_file() {
    QTemporaryDir dir;
    QFile bad(dir.filePath("bad.json"));
    QVERIFY(bad.open(QIODevice::WriteOnly));
    bad.write("{\"format\": \"benchscope-run\", \"version\": 1, \"runs\": [");
    bad.close();
    QWidget parent;
    bs::ui::ImportController controller(&parent);
    QSignalSpy done(&controller, &bs::ui::ImportController::finished);
    controller.start(dir.filePath("w.bsw"),
                     {BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018", dir.filePath("bad.json")});
    QVERIFY(controller.busy());
    QVERIFY(done.wait(60000));
    QVERIFY(!controller.busy());
    const auto report = done.first().at(0).value<bs::ui::ImportReport>();
    QCOMPARE(report.imported, 10);  // 5 run files + 2 current logs + 2 pipeline timing files + the synthetic capture
    QCOMPARE(report.failures.size(), 1);
    QVERIFY(report.failures[0].contains("bad.json") && report.failures[0].contains("truncated"));
    QVERIFY(report.skipped.size() >= 1);  // the folder's README is not a data file
    QVERIFY(!report.cancelled);
    // A cancelled import stops before the next file and stores nothing more.
    bs::CancelToken cancel;
    cancel.cancel();
    const auto cancelled = bs::ui::ImportController::import_now(
        dir.filePath("w2.bsw"), {BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018"}, cancel);
    QVERIFY(cancelled.cancelled);
    QCOMPARE(cancelled.imported, 0);
  }

  // Issue #22.5: the peak table lives in the FLOPS tab, not in a dock under every view; the split and the docks are
  // remembered; View > Reset layout brings the first-start layout back.
  void peak_table_in_flops_tab_and_layout_remembered() {
    QSettings().remove("main-window");
    QList<int> moved;
    {
      bs::ui::MainWindow w;
      auto* tabs = qobject_cast<QTabWidget*>(w.centralWidget());
      QVERIFY(tabs);
      QVERIFY(tabs->widget(0)->findChild<bs::ui::PeakTableView*>() != nullptr);
      for (QDockWidget* d : w.findChildren<QDockWidget*>()) QVERIFY(d->windowTitle() != "Peak FLOPS");
      auto* split = w.findChild<QSplitter*>("flopsSplit");
      QVERIFY(split);
      w.show();
      QVERIFY(QTest::qWaitForWindowExposed(&w));
      const QList<int> first = split->sizes();
      split->setSizes({first[0] + first[1] - 120, 120});
      moved = split->sizes();
      QVERIFY(w.close());  // saves the layout
    }
    {
      bs::ui::MainWindow w;
      w.show();
      QVERIFY(QTest::qWaitForWindowExposed(&w));
      auto* split = w.findChild<QSplitter*>("flopsSplit");
      QCOMPARE(split->sizes(), moved);
      w.reset_layout();
      QVERIFY(split->sizes() != moved);
      QVERIFY(!QSettings().contains("main-window/state"));
    }
  }

  // Issue #23.10: F1 lists the views and every shortcut, read from the menus themselves.
  void f1_lists_views_and_shortcuts() {
    bs::ui::MainWindow w;
    QAction* help = nullptr;
    for (QAction* a : w.findChildren<QAction*>())
      if (a->text().remove('&') == "Views and shortcuts") help = a;
    QVERIFY(help);
    QCOMPARE(help->shortcut(), QKeySequence(Qt::Key_F1));
    QString text;
    QTimer::singleShot(0, &w, [&] {
      for (QWidget* top : QApplication::topLevelWidgets())
        if (auto* box = qobject_cast<QDialog*>(top); box && box->objectName() == "help") {
          if (auto* page = box->findChild<QTextBrowser*>()) text = page->toPlainText();
          box->accept();
        }
    });
    help->trigger();
    QVERIFY(text.contains("Battery"));
    QVERIFY(text.contains("Platforms"));
    QVERIFY(text.contains(QKeySequence(Qt::CTRL | Qt::Key_E).toString(QKeySequence::NativeText)));
    QVERIFY(text.contains("Export figure"));
  }

  void figure_and_report_actions_are_in_the_file_menu() {
    bs::ui::MainWindow w;
    QMap<QString, QKeySequence> expected{{"Export figure", QKeySequence(Qt::CTRL | Qt::Key_E)},
                                         {"Reproduce paper figures", QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_E)},
                                         {"Export report", QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_R)}};
    for (QAction* a : w.findChildren<QAction*>()) {
      const QString text = a->text().remove('&').remove(QString::fromUtf8("…"));
      if (expected.contains(text)) {
        QCOMPARE(a->shortcut(), expected.take(text));
        QVERIFY(!a->toolTip().isEmpty());
      }
    }
    QVERIFY2(expected.isEmpty(), qPrintable(expected.keys().join(", ")));
  }

  void export_dialog_defaults_to_lncs() {
    QSettings().remove("figure-export");
    bs::ui::ExportFigureDialog d(bs::ui::ExportFigureDialog::Target::FileStem, "/tmp/flops");
    const bs::ui::FigureOptions o = d.options();
    QCOMPARE(o.width_mm, 122.0);
    QCOMPARE(o.font_pt, 8.0);
    QCOMPARE(o.dpi, 300);
    QCOMPARE(o.formats, (QStringList{"pdf", "png"}));
    if (const QByteArray dir = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !dir.isEmpty()) {
      d.show();
      QVERIFY(QTest::qWaitForWindowExposed(&d));
      d.grab().save(QString::fromLocal8Bit(dir) + "/export-figure-dialog.png");
    }
    d.set_preset("ieee");
    QCOMPARE(d.options().width_mm, 88.9);
    d.set_destination("/tmp/x/fig.pdf");
    QCOMPARE(d.destination(), QString("/tmp/x/fig"));
  }

  // Issue #23.1: the export dialog shows what will be written, and follows the size chosen.
  void export_dialog_previews_the_figure() {
    QSettings().remove("figure-export");
    QCustomPlot plot;
    plot.resize(900, 600);
    for (int g = 0; g < 6; ++g) plot.addGraph()->setName(QStringLiteral("series %1").arg(g));
    plot.legend->setVisible(true);
    bs::ui::ExportFigureDialog d(bs::ui::ExportFigureDialog::Target::FileStem, "/tmp/flops");
    int renders = 0;
    QSize last;
    d.set_preview([&](const bs::ui::FigureOptions& o) {
      ++renders;
      QImage image = bs::ui::render_export_preview(plot, o, 400);
      last = image.size();
      return image;
    });
    QCOMPARE(renders, 1);
    QVERIFY(d.preview_label()->pixmap().width() > 0);
    const double lncs_aspect = double(last.height()) / last.width();
    d.set_preset("lncs-half");  // narrower: the legend needs more rows, so the figure is relatively taller
    QTRY_COMPARE(renders, 2);
    QVERIFY(double(last.height()) / last.width() > lncs_aspect);
    QCOMPARE(plot.axisRect()->insetLayout()->elementCount(), 1);  // the view's legend is back where it was
    if (const QByteArray dir = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !dir.isEmpty()) {
      d.set_preset("lncs");
      QTRY_COMPARE(renders, 3);
      d.show();
      QVERIFY(QTest::qWaitForWindowExposed(&d));
      d.grab().save(QString::fromLocal8Bit(dir) + "/export-figure-preview.png");
    }
  }

  void no_qt5_library_is_loaded() {
    // OpenCV's highgui or Debian's VTK Qt modules would pull Qt 5 in beside Qt 6.
    QFile maps("/proc/self/maps");
    QVERIFY(maps.open(QIODevice::ReadOnly));
    QVERIFY(!maps.readAll().contains("libQt5"));
  }

  void bad_workspace_gives_an_error_not_a_crash() {
    QTemporaryDir dir;
    QFile f(dir.filePath("not.bsw"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("plain text");
    f.close();
    bs::ui::MainWindow w;
    QTimer::singleShot(0, [] {
      for (QWidget* top : QApplication::topLevelWidgets())
        if (auto* box = qobject_cast<QMessageBox*>(top)) box->accept();
    });
    QVERIFY(!w.open_workspace(dir.filePath("not.bsw")));
  }
};

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
