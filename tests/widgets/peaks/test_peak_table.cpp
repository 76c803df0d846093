// SPDX-License-Identifier: GPL-3.0-or-later
// The peak table model: what each column shows, numeric sorting through the proxy, TSV copy.
#include <QAbstractItemModel>
#include <QClipboard>
#include <QSortFilterProxyModel>
#include <QTest>

#include "../../support/paper_sample.h"
#include "device_palette.h"
#include "peaks/peak_table.h"

namespace {

bs::PeakRow row(const char* device, const char* backend, int dims, double peak, std::int64_t workers) {
  bs::PeakRow r;
  r.platform = "Test platform";
  r.device = device;
  r.backend = backend;
  r.variant = "paper";
  r.dims = dims;
  r.iterations = 40000;
  r.peak.flops = peak;
  r.peak.workers = workers;
  r.peak.at_peak.n = 1;
  r.peak.at_peak.mean = peak;
  r.origin = bs::DataOrigin::Reconstructed;
  r.source_file = "/data/test.json";
  return r;
}

QString cell(const QAbstractItemModel* m, int r, int c) { return m->index(r, c).data().toString(); }

}  // namespace

class TestPeakTable : public QObject {
  Q_OBJECT
 private slots:
  void columns_show_units_ratios_and_origin() {
    using M = bs::ui::PeakTableModel;
    bs::PeakRow gpu = row("NUC GPU", "OpenCL", 4, 5.25e12, 761856);
    gpu.reported_flops = 0.88e12;
    gpu.ratio_to_reported = 5.25 / 0.88;
    gpu.theoretical_flops = 7.0e12;
    gpu.fraction_of_theoretical = 0.75;
    bs::PeakRow cpu = row("i7-7800X", "CPU SIMD (AVX/SSE)", 4, 49.68e9, 1345);
    cpu.peak.at_peak.n = 5;
    cpu.peak.at_peak.sd = 1.5e9;
    cpu.variant = "float16x4";
    M model;
    model.set_rows({gpu, cpu}, {3, 0});
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.columnCount(), int(M::ColumnCount));
    QCOMPARE(cell(&model, 0, M::Peak), QString("5.25 TFLOPS"));
    QCOMPARE(cell(&model, 0, M::Reported), QString("880.00 GFLOPS"));
    QCOMPARE(cell(&model, 0, M::Ratio), QString("5.97×"));
    QCOMPARE(cell(&model, 0, M::OfTheoretical), QString("75.0 %"));
    QCOMPARE(cell(&model, 0, M::Origin), QString("reconstructed"));
    QCOMPARE(cell(&model, 0, M::Workers), QLocale().toString(761856));
    // Repeated measurements show mean ± SD; missing figures show a dash, never 0.
    QCOMPARE(cell(&model, 1, M::Peak), QString("49.68 ± 1.50 GFLOPS"));  // one prefix: short enough never to elide
    QCOMPARE(cell(&model, 1, M::Reported), QString("–"));
    QCOMPARE(cell(&model, 1, M::Ratio), QString("–"));
    QCOMPARE(cell(&model, 1, M::Backend), QString("CPU SIMD (AVX/SSE) (float16x4)"));
    // The device swatch has the device's palette colour; the tooltip names the source file.
    QCOMPARE(model.index(0, M::Device).data(Qt::DecorationRole).value<QColor>(), bs::ui::device_color(3));
    QVERIFY(model.index(0, M::Peak).data(Qt::ToolTipRole).toString().contains("/data/test.json"));
  }

  void sorts_numerically_not_alphabetically() {
    using M = bs::ui::PeakTableModel;
    bs::ui::PeakTableView view;
    // As text "9.34 TFLOPS" < "49.68 GFLOPS" < "5.25 TFLOPS" is wrong three ways; by value it is 49.68 G < 5.25 T <
    // 9.34 T.
    view.peak_model()->set_rows(
        {row("A", "CUDA", 4, 9.34e12, 408576), row("B", "CPU", 4, 49.68e9, 1345), row("C", "OpenCL", 4, 5.25e12, 2048)},
        {0, 1, 2});
    view.sortByColumn(M::Peak, Qt::DescendingOrder);
    const QAbstractItemModel* m = view.model();
    QCOMPARE(cell(m, 0, M::Peak), QString("9.34 TFLOPS"));
    QCOMPARE(cell(m, 1, M::Peak), QString("5.25 TFLOPS"));
    QCOMPARE(cell(m, 2, M::Peak), QString("49.68 GFLOPS"));
    view.sortByColumn(M::Workers, Qt::AscendingOrder);  // 1,345 < 2,048 < 408,576 (as text 408,576 < 2,048)
    QCOMPARE(cell(m, 0, M::Device), QString("B"));
    QCOMPARE(cell(m, 1, M::Device), QString("C"));
    QCOMPARE(cell(m, 2, M::Device), QString("A"));
  }

  void groups_by_platform_explains_ratios_and_shows_a_new_row() {
    using M = bs::ui::PeakTableModel;
    bs::ui::PeakTableView view;
    auto a = row("A", "CUDA", 4, 9.34e12, 408576);
    a.platform = "Desktop";
    a.reported_flops = 10.61e12;
    a.ratio_to_reported = 9.34 / 10.61;
    a.fraction_of_theoretical = 0.5;
    auto b = row("B", "CPU", 1, 49.68e9, 1345);
    b.platform = "NUC";
    auto c = row("C", "CPU", 4, 20e9, 1000);
    c.platform = "Desktop";
    view.peak_model()->set_rows({a, b, c}, {0, 1, 2});
    const QAbstractItemModel* m = view.model();
    // Desktop's two rows together, in their order, then the NUC; each row's colour follows it.
    QCOMPARE(cell(m, 0, M::Device), QString("A"));
    QCOMPARE(cell(m, 1, M::Device), QString("C"));
    QCOMPARE(cell(m, 2, M::Device), QString("B"));
    QCOMPARE(cell(m, 1, M::Platform), QString("Desktop"));
    QCOMPARE(m->index(1, M::Device).data(Qt::DecorationRole).value<QColor>(), bs::ui::device_color(2));
    // The ratio cells say what they divide, with both numbers.
    const QString ratio_tip = m->index(0, M::Ratio).data(Qt::ToolTipRole).toString();
    QVERIFY2(ratio_tip.contains("9.34 TFLOPS") && ratio_tip.contains("10.61 TFLOPS") && ratio_tip.contains("0.880"),
             qPrintable(ratio_tip));
    const QString theo_tip = m->index(0, M::OfTheoretical).data(Qt::ToolTipRole).toString();
    QVERIFY2(theo_tip.contains("18.68 TFLOPS") && theo_tip.contains("theoretical"), qPrintable(theo_tip));
    // A run that just landed is selected and brought into view.
    QVERIFY(view.show_row("NUC", "B", "CPU", 1));
    QCOMPARE(view.selectionModel()->selectedRows().size(), 1);
    QCOMPARE(view.selectionModel()->selectedRows().at(0).row(), 2);
    QVERIFY(!view.show_row("NUC", "B", "CPU", 4));
  }

  void copies_the_selection_as_tsv() {
    using M = bs::ui::PeakTableModel;
    bs::ui::PeakTableView view;
    view.peak_model()->set_rows({row("A", "CUDA", 4, 9.34e12, 408576), row("B", "CPU", 1, 49.68e9, 1345)}, {0, 1});
    view.selectRow(1);
    const QStringList lines = view.selection_as_tsv().split('\n');
    QCOMPARE(lines.size(), 2);  // header + the one selected row
    QCOMPARE(lines[0].split('\t').size(), int(M::ColumnCount));
    QCOMPARE(lines[0].split('\t')[M::Peak], QString("Peak (mean ± SD)"));
    const QStringList cells = lines[1].split('\t');
    QCOMPARE(cells[M::Device], QString("B"));
    QCOMPARE(cells[M::Dims], QString("1"));
    QCOMPARE(cells[M::Peak], QString("49.68 GFLOPS"));
    // Ctrl+C puts the same text on the clipboard.
    QTest::keyClick(&view, Qt::Key_C, Qt::ControlModifier);
    QCOMPARE(QGuiApplication::clipboard()->text(), view.selection_as_tsv());
  }

  // The paper's data through bs::peak_table(): the NUC GPU's 5.25 TFLOPS (5.9x the Iris Plus 650's 883.2 GFLOPS)
  // is marked, tinted and explained in the tooltip; the GTX 1080 Ti's 9.14 TFLOPS (81 % of 11.34 TFLOPS) is not.
  void marks_the_flagged_row() {
    using M = bs::ui::PeakTableModel;
    const auto sample = bs::test::load_paper_sample();
    std::vector<bs::PeakRow> rows = bs::peak_table(sample.runs);
    std::vector<std::string> devices;  // one colour per device, as in the GUI
    std::vector<int> colors;
    for (const bs::PeakRow& r : rows) {
      auto it = std::find(devices.begin(), devices.end(), r.device);
      if (it == devices.end()) it = devices.insert(devices.end(), r.device);
      colors.push_back(static_cast<int>(it - devices.begin()));
    }
    bs::ui::PeakTableView view;
    view.peak_model()->set_rows(rows, colors);
    const QAbstractItemModel* m = view.model();
    int nuc = -1, gtx = -1;
    for (int r = 0; r < m->rowCount(); ++r) {
      if (cell(m, r, M::Device) == "NUC GPU (Iris Plus 650)" && cell(m, r, M::Dims) == "4") nuc = r;
      if (cell(m, r, M::Device) == "GTX1080Ti" && cell(m, r, M::Backend) == "OpenCL") gtx = r;
    }
    QVERIFY(nuc >= 0 && gtx >= 0);
    QVERIFY(m->index(nuc, M::Peak).data(M::kFlaggedRole).toBool());
    QCOMPARE(cell(m, nuc, M::Peak), QString("⚠ 5.25 TFLOPS"));
    QCOMPARE(cell(m, nuc, M::OfSpec), QString("594.4 %"));
    for (int c = 0; c < M::ColumnCount; ++c) {  // the whole row is tinted and explains itself
      QVERIFY(m->index(nuc, c).data(Qt::BackgroundRole).value<QColor>().isValid());
      const QString tip = m->index(nuc, c).data(Qt::ToolTipRole).toString();
      QVERIFY2(tip.startsWith("⚠") && tip.contains("Iris Plus Graphics 650") && tip.contains("compiler") &&
                   tip.contains("asynchronous"),
               qPrintable(tip));
    }
    QVERIFY(!m->index(gtx, M::Peak).data(M::kFlaggedRole).toBool());
    QCOMPARE(cell(m, gtx, M::Peak), QString("9.14 TFLOPS"));
    QCOMPARE(cell(m, gtx, M::OfSpec), QString("80.6 %"));
    QVERIFY(!m->index(gtx, M::Peak).data(Qt::BackgroundRole).isValid());
    QVERIFY(m->index(gtx, M::Peak).data(Qt::ToolTipRole).toString().contains("11.34 TFLOPS"));
    // scripts/screenshots sets this to collect the table for the docs.
    if (const QByteArray dir = qgetenv("BENCHSCOPE_SCREENSHOT_DIR"); !dir.isEmpty()) {
      view.resize(1100, 300);
      QVERIFY(view.grab().save(QString::fromUtf8(dir) + "/peak-table-flags.png", "PNG", 0));
    }
  }
};

QTEST_MAIN(TestPeakTable)
#include "test_peak_table.moc"
